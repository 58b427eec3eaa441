#pragma once
// A strut carrying a spring–damper–inerter network (spec/03 §3.1), and the HSX pneumatic
// actuator built on it (spec/03 §3.3).
//
// Tension F = d2·l̈ + d1·l̇ + d0·(l − l_ref) + C z,  ż = A z + B (l − l_ref)   (network/realisation.hpp)
// The d2 term is an inerter across the terminals: it uses the exact l̈ of eq. 3.20 (same
// centripetal switches as Inerter) and enters the mass matrix as d2·JᵀJ (eq. 3.33).
#include "inerta/mbs/struts.hpp"
#include "inerta/network/network.hpp"
#include "inerta/network/realisation.hpp"

namespace inerta::mbs {

class NetworkStrut : public Strut {
 public:
  /// `net` must be simplified and neither open nor rigid, with finite values >= 0, and l_ref >= 0 (m)
  /// (InvalidArgument otherwise); z occupies State::z[state_offset() ...], placed by Model::finalize.
  NetworkStrut(std::string name, int bi, StrutEnd ui, int bj, StrutEnd uj, const network::Network& net, double l_ref,
               bool centripetal = true);
  const network::Network& network() const { return net_; }
  const network::Realisation& realisation() const { return r_; }
  double reference_length() const { return l_ref_; }
  bool centripetal(const Model& model) const;
  bool centripetal_switch() const { return centripetal_; }  ///< this element's own switch

  void add(const Model& model, double t, const State& x, Workspace& ws) const override;
  double energy(const Model&, double t, const State& x) const override;  // ½ d2 l̇² + ½ d0 u²
  double power(const Model& model, double t, const State& x) const override;
  double force(const Model& model, double t, const State& x, const Workspace& ws) const override;
  int n_states() const override { return r_.n_states(); }
  std::shared_ptr<const ForceElement> with_state_offset(int offset) const override;
  void relax(const Model& model, State& x) const override;
  const network::Network* strut_network() const override { return &net_; }
  std::shared_ptr<const ForceElement> with_network(const network::Network& net, double reference_length) const override;

 protected:
  /// Replaces the network (checked as by the constructor) and, unless NaN, the reference length (m);
  /// for with_network of this and derived classes.
  void replace_network(const network::Network& net, double reference_length);
  /// Tension without the d2·l̈ part, i.e. d1 l̇ + d0 u + C z, and (into zd) ż.
  double network_tension(const StrutKinematics& s, const State& x) const;

 private:
  network::Network net_;
  network::Realisation r_;
  double l_ref_;
  bool centripetal_;
};

/// HSX base pneumatic actuator (spec/03 §3.3): tension
///   F = F_c + F_r tanh(l̇ / v_r) + network(l)
/// between the cylinder (marker i) and the rod end (marker j), plus the piston mass m_p carried as
/// a point mass at the rod end (it moves with the rod end). F_c < 0 pushes. Coulomb friction F_r is
/// regularised by tanh with v_r (default 1 mm/s); off (F_r = 0) by default as in the thesis.
class Actuator : public NetworkStrut {
 public:
  /// Checked by the constructor (InvalidArgument): all finite, m_p ≥ 0 (and 0 if the rod end is on
  /// ground), F_r ≥ 0, v_r > 0.
  struct Params {
    double constant_force = 0;        ///< F_c, N (tension positive)
    double piston_mass = 0;           ///< m_p, kg (≥ 0)
    double friction = 0;              ///< F_r, N (≥ 0)
    double friction_velocity = 1e-3;  ///< v_r, m/s (> 0)
  };
  Actuator(std::string name, int bi, Vec2 ui, int bj, Vec2 uj, const network::Network& net, double l_ref, Params p,
           bool centripetal = true);
  const Params& params() const { return p_; }
  std::shared_ptr<const ForceElement> with_state_offset(int offset) const override;
  std::shared_ptr<const ForceElement> with_network(const network::Network& net, double reference_length) const override;

  void add(const Model& model, double t, const State& x, Workspace& ws) const override;
  double energy(const Model& model, double t, const State& x) const override;  // + F_c l, + piston ½ m v², − m_p g·r
  double power(const Model& model, double t, const State& x) const override;  // + friction
  double force(const Model& model, double t, const State& x, const Workspace& ws) const override;

 private:
  Params p_;
  int rod_body_;
  Vec2 rod_u_;
};

}  // namespace inerta::mbs
