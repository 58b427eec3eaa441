// Derivatives against finite differences: H and a_n of eqs. 3.18–3.19, l̈ of eq. 3.20, the
// constraint Jacobian C_q, C_t and γ = Q_d of eqs. 4.2–4.4 for every joint type.
#include "inerta/mbs/kinematics.hpp"

#include <gtest/gtest.h>

#include <random>

#include "inerta/io/model_file.hpp"
#include "inerta/mbs/dynamics.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_mbs_kinematics {

using namespace inerta;
using namespace inerta::mbs;

namespace {
std::mt19937 rng(12345);
double uni(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
Vec3 rand3(double s) { return Vec3(uni(-s, s), uni(-s, s), uni(-s, s)); }

// q(τ) = q + q̇ τ + ½ q̈ τ² : a trajectory through (q, q̇) with acceleration q̈.
Vec3 along(const Vec3& q, const Vec3& qd, const Vec3& qdd, double tau) { return q + qd * tau + 0.5 * qdd * tau * tau; }
}  // namespace

TEST(StrutKinematics, HAndAnAgainstFiniteDifferences) {
  for (int trial = 0; trial < 20; ++trial) {
    Vec3 qi = rand3(1), qj = rand3(1) + Vec3(2, 0, 0), qdi = rand3(2), qdj = rand3(2), qddi = rand3(3), qddj = rand3(3);
    Vec2 ui(uni(-0.5, 0.5), uni(-0.5, 0.5)), uj(uni(-0.5, 0.5), uni(-0.5, 0.5));
    auto r_of = [&](const Vec3& a, const Vec3& b) {
      return Vec2(point_kinematics(b, Vec3::Zero(), uj).r - point_kinematics(a, Vec3::Zero(), ui).r);
    };
    StrutKinematics s = strut_kinematics(BodyFrame::of(qi, qdi), ui, BodyFrame::of(qj, qdj), uj);
    // H (eq. 3.18) by central differences of r, and J = êᵀH = ∂l/∂q.
    Eigen::Matrix<double, 2, 6> H_fd;
    Vec6 J_fd;
    const double h = 1e-6;
    for (int k = 0; k < 6; ++k) {
      Vec3 dqi = Vec3::Zero(), dqj = Vec3::Zero();
      (k < 3 ? dqi[k] : dqj[k - 3]) = h;
      Vec2 rp = r_of(qi + dqi, qj + dqj), rm = r_of(qi - dqi, qj - dqj);
      H_fd.col(k) = (rp - rm) / (2 * h);
      J_fd[k] = (rp.norm() - rm.norm()) / (2 * h);
    }
    EXPECT_LT((J_fd - s.J).cwiseAbs().maxCoeff(), 1e-8);
    const Vec2 e = r_of(qi, qj).normalized();
    EXPECT_LT((H_fd.transpose() * e - s.J).cwiseAbs().maxCoeff(), 1e-8);
    // ṙ = H q̇ and r̈ = H q̈ + a_n (eq. 3.19), along a trajectory by central differences.
    const double tau = 1e-4;
    auto r_at = [&](double t) { return r_of(along(qi, qdi, qddi, t), along(qj, qdj, qddj, t)); };
    Vec2 rd_fd = (r_at(tau) - r_at(-tau)) / (2 * tau);
    Vec2 rdd_fd = (r_at(tau) - 2 * r_at(0) + r_at(-tau)) / (tau * tau);
    Vec6 qd, qdd;
    qd << qdi, qdj;
    qdd << qddi, qddj;
    EXPECT_LT((rd_fd - H_fd * qd).norm(), 1e-6);
    EXPECT_NEAR(rd_fd.dot(e), s.l_dot, 1e-6);
    PointKinematics pi = point_kinematics(qi, qdi, ui), pj = point_kinematics(qj, qdj, uj);
    Vec2 a_n = pj.a_bias - pi.a_bias;  // eq. 3.19: θ̇_i² A_i ū_i − θ̇_j² A_j ū_j
    EXPECT_LT((rdd_fd - (H_fd * qdd + a_n)).norm(), 2e-4);
    // l̈ = J q̈ + ê·a_n + centripetal (eq. 3.20 / b).
    auto l_at = [&](double t) { return r_at(t).norm(); };
    double ldd_fd = (l_at(tau) - 2 * l_at(0) + l_at(-tau)) / (tau * tau);
    EXPECT_NEAR(ldd_fd, s.J.dot(qdd) + s.a_n_axial + s.centripetal, 2e-4);
    EXPECT_GE(s.centripetal, 0.0);
  }
}

namespace {
const char* kJointModels[] = {
    "{type: revolute, markers: [b1.p, b2.q]}",
    "{type: revolute, markers: [ground.G, b2.q]}",
    "{type: prismatic, markers: [b1.p, b2.q], axis: [1, 0.3]}",
    "{type: prismatic, markers: [ground.G, b2.q], axis: [0.2, 1]}",
    "{type: fixed, bodies: [b1, b2]}",
    "{type: fixed, bodies: [ground, b2]}",
    "{type: driving, body: b2, coordinate: theta, motion: {type: sine, amplitude: 0.3, frequency: 2}}",
    "{type: driving, body: b2, coordinate: x, motion: {type: sine, amplitude: 0.1, frequency: 1, phase: 0.4}}",
    "{type: driving, marker: b2.q, coordinate: y, motion: {type: sine, amplitude: 0.2, frequency: 1.5}}",
};

Model joint_model(const std::string& joint) {
  // joint is a flow mapping "{type: ..., ...}"; it becomes joint J of a two-body model.
  std::string text =
      "options: {gravity: false}\n"
      "ground: {markers: {G: [0.5, 0]}}\n"
      "bodies:\n"
      "  - {name: b1, mass: 1, inertia: 0.1, position: [0, 0], markers: {p: [0.5, 0]}}\n"
      "  - {name: b2, mass: 1, inertia: 0.1, position: [1, 0], markers: {q: [-0.5, 0]}}\n"
      "joints:\n"
      "  - {name: J, " +
      joint.substr(1) + "\n";
  return io::parse_model(text, "joint-test.yaml");
}
}  // namespace

TEST(Constraints, JacobianCtAndGammaAgainstFiniteDifferences) {
  for (const char* spec : kJointModels) {
    SCOPED_TRACE(spec);
    Model model = joint_model(spec);
    const int n = model.n_coords(), m = model.n_constraints();
    ASSERT_EQ(n, 6);
    ASSERT_GT(m, 0);
    Workspace ws(model);
    for (int trial = 0; trial < 10; ++trial) {
      State x{Eigen::VectorXd(n), Eigen::VectorXd(n), {}};
      x.q << rand3(1), rand3(1) + Vec3(1, 0, 0);
      x.qd << rand3(2), rand3(2);
      Eigen::VectorXd qdd(n);
      qdd << rand3(3), rand3(3);
      const double t = uni(0, 1);
      evaluate_constraints(model, t, x, ws);
      const Eigen::MatrixXd Cq = ws.Cq;
      const Eigen::VectorXd Ct = ws.Ct, gamma = ws.gamma;
      auto C_at = [&](const Eigen::VectorXd& q, double time) {
        State s{q, Eigen::VectorXd::Zero(n), {}};
        Workspace w(model);
        evaluate_constraints(model, time, s, w);
        return Eigen::VectorXd(w.C);
      };
      const double h = 1e-6;
      for (int k = 0; k < n; ++k) {
        Eigen::VectorXd qp = x.q, qm = x.q;
        qp[k] += h, qm[k] -= h;
        EXPECT_LT(((C_at(qp, t) - C_at(qm, t)) / (2 * h) - Cq.col(k)).cwiseAbs().maxCoeff(), 1e-8) << "column " << k;
      }
      EXPECT_LT(((C_at(x.q, t + h) - C_at(x.q, t - h)) / (2 * h) - Ct).cwiseAbs().maxCoeff(), 1e-7);
      // d²C/dt² along q(τ) = C_q q̈ − γ  (eq. 4.3).
      const double tau = 1e-4;
      auto C_tau = [&](double s) { return C_at(x.q + x.qd * s + 0.5 * qdd * s * s, t + s); };
      Eigen::VectorXd Cdd = (C_tau(tau) - 2 * C_tau(0) + C_tau(-tau)) / (tau * tau);
      EXPECT_LT((Cdd - (Cq * qdd - gamma)).cwiseAbs().maxCoeff(), 5e-4);
    }
  }
}
}  // namespace test_mbs_kinematics
