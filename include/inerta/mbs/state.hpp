#pragma once
// Mutable State (q, q̇) and Workspace (every buffer an evaluation needs; allocated once).
#include <Eigen/Dense>
#include <array>
#include <vector>

#include "inerta/mbs/kinematics.hpp"
#include "inerta/mbs/spatial.hpp"

namespace inerta::mbs {

struct Model;

struct State {
  Eigen::VectorXd q, qd;
  Eigen::VectorXd z;  ///< internal states of force elements (network struts), Model::n_states()
  // Per-body views go through the model's address table: Model::q_of, frame, sframe.
};

/// Scratch space of `accelerations` (eq. 4.12): sized for one model, reused for every call.
struct Workspace {
  explicit Workspace(const Model& model);

  /// Kinematics stage: every body's frame (coordinates, cos θ, sin θ) at x.
  void set_state(const State& x);
  const BodyFrame& frame(int body) const { return body < 0 ? ground_ : frames[static_cast<std::size_t>(body)]; }
  const SpatialFrame& sframe(int body) const { return body < 0 ? sground_ : sframes[static_cast<std::size_t>(body)]; }
  std::vector<BodyFrame> frames;      ///< 2D
  std::vector<SpatialFrame> sframes;  ///< 3D

  Eigen::MatrixXd M;      ///< M + M_I (eq. 3.33), n×n
  Eigen::VectorXd Q;      ///< Q_e + Q_Iv, n
  Eigen::VectorXd C, Ct;  ///< constraint values and ∂C/∂t, m
  Eigen::MatrixXd Cq;     ///< constraint Jacobian, m×n
  Eigen::VectorXd gamma;  ///< Q_d of eq. 4.3, m
  // Schur-complement solve of eq. 4.12 when M + M_I is positive definite (the usual case):
  Eigen::LLT<Eigen::MatrixXd> llt_M;  ///< M + M_I = L Lᵀ
  Eigen::MatrixXd YZ;                 ///< [Y z] = L⁻¹ [C_qᵀ Q], n×(m+1)
  Eigen::MatrixXd S;                  ///< C_q (M + M_I)⁻¹ C_qᵀ = Yᵀ Y, m×m
  Eigen::LLT<Eigen::MatrixXd> llt_S;
  Eigen::VectorXd z, c;  ///< L⁻¹ Q (n), constraint right-hand side (m)
  // Fallback for a singular M + M_I (e.g. a body without inertia whose rotation is constrained):
  Eigen::MatrixXd K;  ///< system matrix of eq. 4.12, (n+m)²
  Eigen::VectorXd rhs, sol;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  // M + M_I = D + Σ b J Jᵀ, D block-diagonal per body (dynamics.cpp, solve_blocks).
  struct Rank1 {
    int body_i, body_j;
    VecJ J;
    double b;
  };
  std::vector<Rank1> rank1;                        ///< the inerter terms of this evaluation (capacity reserved)
  std::vector<Eigen::LLT<Eigen::Matrix4d>> llt_p;  ///< per body, its rotational block M_pp = L Lᵀ
  Eigen::MatrixXd YB;                              ///< [Y z]
  Eigen::MatrixXd SB;  ///< storage of the Schur matrix with the inerter rows and its Cholesky factor
  Eigen::VectorXd lm;                          ///< [λ; μ]
  std::vector<int> column_nz;                  ///< scratch: the nonzero rows of a Cholesky column
  std::vector<std::array<int, 2>> row_bodies;  ///< the two bodies of each Schur row (−1: ground)
  Eigen::VectorXd inv_sqrt_d;                  ///< 2D: 1/√m, 1/√m, 1/√I a body (D = L Lᵀ is constant)
  std::vector<std::vector<int>> body_rows;     ///< per body, the Schur rows that touch it, ascending
  Eigen::VectorXd qdd;                         ///< result: accelerations
  Eigen::VectorXd zd;      ///< result: derivatives of the internal states (written by their elements)
  Eigen::VectorXd lambda;  ///< result: Lagrange multipliers

  /// Adds f to Q for a vector over [q_i; q_j] (6 in 2D, 14 in 3D; ground parts skipped).
  void add_Q(int body_i, int body_j, const VecJ& f);
  /// Adds b·J Jᵀ to M (rank-one inerter mass term, eq. 3.33).
  void add_M(int body_i, int body_j, const VecJ& J, double b);
  /// J · q̈_ij with q̈ = this->qdd.
  double J_dot_qdd(int body_i, int body_j, const VecJ& J) const;
  int body_coords() const { return nc_; }

 private:
  BodyFrame ground_;
  SpatialFrame sground_;
  int nc_ = 3;
};

}  // namespace inerta::mbs
