#include "inerta/analysis/state_space.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <numbers>

#include "inerta/error.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/numerics/lyapunov.hpp"

namespace inerta::analysis {

using cd = std::complex<double>;
using std::numbers::pi;

namespace {
// A term of output i on input j counts if it exceeds roundoff of the output's other terms.
bool nonzero(const StateSpace& ss, const Eigen::MatrixXd& M, Eigen::Index i, Eigen::Index j) {
  const double scale = 1 + ss.C.row(i).cwiseAbs().maxCoeff() * ss.B.col(j).cwiseAbs().maxCoeff() + std::abs(ss.D(i, j));
  return std::abs(M(i, j)) > 1e-9 * scale;
}
}  // namespace

bool StateSpace::has_rate_feedthrough() const {
  for (Eigen::Index i = 0; i < D1.rows(); ++i)
    for (Eigen::Index j = 0; j < D1.cols(); ++j)
      if (nonzero(*this, D1, i, j) || nonzero(*this, D2, i, j)) return true;
  return false;
}

StateSpace state_space(const mbs::Model& model, const mbs::State& x, const std::vector<std::string>& inputs,
                       const std::vector<std::string>& outputs, double t) {
  StateSpace ss;
  ss.model = model.name;
  ss.system = mbs::linearise(model, x, inputs, outputs, t);
  const mbs::LinearSystem& s = ss.system;
  ss.states = mbs::state_names(model, s.lin);
  ss.inputs = inputs;
  ss.outputs = outputs;
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    std::string unit = "N or N·m";
    if (s.joint[k] >= 0) unit = model.joints[static_cast<std::size_t>(s.joint[k])].component == 2 ? "rad" : "m";
    ss.input_units.push_back(unit);
  }
  ss.A = s.lin.A;
  ss.T1 = s.B2;
  ss.T0 = s.B1 + ss.A * s.B2;
  ss.B = s.B0 + ss.A * ss.T0;
  ss.C = s.Cy;
  ss.D = s.Cy * ss.T0 + s.D0;
  ss.D1 = s.Cy * ss.T1 + s.D1;
  ss.D2 = s.D2;
  return ss;
}

StateSpace state_space(const mbs::Model& model, const std::vector<std::string>& inputs,
                       const std::vector<std::string>& outputs) {
  mbs::State x = mbs::assemble(model, 0.0);
  mbs::static_equilibrium(model, 0.0, x);
  return state_space(model, x, inputs, outputs, 0.0);
}

std::vector<Eigen::MatrixXcd> frequency_response(const StateSpace& ss, const std::vector<double>& f_hz) {
  std::vector<Eigen::MatrixXcd> H(f_hz.size());
  const Eigen::Index n = ss.A.rows();
  tbb::parallel_for(std::size_t{0}, f_hz.size(), [&](std::size_t k) {
    const cd s(0, 2 * pi * f_hz[k]);
    Eigen::MatrixXcd sIA = -ss.A.cast<cd>();
    sIA.diagonal().array() += s;
    H[k] = ss.C.cast<cd>() * sIA.partialPivLu().solve(ss.B.cast<cd>()) + ss.D.cast<cd>() + s * ss.D1.cast<cd>() +
           s * s * ss.D2.cast<cd>();
    if (n == 0) H[k] = ss.D.cast<cd>() + s * ss.D1.cast<cd>() + s * s * ss.D2.cast<cd>();
  });
  return H;
}

namespace {
RandomResponse covariance_of(const std::vector<std::string>& outputs, const Eigen::MatrixXd& C, const Eigen::MatrixXd& P) {
  RandomResponse r;
  r.outputs = outputs;
  r.covariance = C * P * C.transpose();
  r.rms = r.covariance.diagonal().cwiseMax(0).cwiseSqrt();
  return r;
}

// The direct terms that make the variance infinite: D, D1, D2 under white noise on u; D1, D2 on a
// road (white noise on u̇; its D term is finite, road_response).
void finite_variance(const StateSpace& ss, Eigen::Index j, const char* why, bool with_D = true) {
  for (Eigen::Index i = 0; i < ss.D.rows(); ++i)
    for (const Eigen::MatrixXd* M : {&ss.D, &ss.D1, &ss.D2})
      if ((with_D || M != &ss.D) && nonzero(ss, *M, i, j))
        throw InvalidArgument(fmt::format("output '{}' responds directly to {} '{}' ({} term {:.6g}): its variance under {} "
                                          "is infinite; choose an output that does not (e.g. a displacement or a force "
                                          "through a spring)",
                                          ss.outputs[static_cast<std::size_t>(i)], "input", ss.inputs[static_cast<std::size_t>(j)],
                                          M == &ss.D ? "D" : M == &ss.D1 ? "D1 (rate)" : "D2 (acceleration)", (*M)(i, j), why));
}
}  // namespace

RandomResponse white_noise_response(const StateSpace& ss, const Eigen::MatrixXd& W) {
  const Eigen::Index ni = ss.B.cols();
  if (W.rows() != ni || W.cols() != ni)
    throw InvalidArgument(fmt::format("white noise: the intensity matrix is {}×{}; expected {}×{} (one row per input)",
                                      W.rows(), W.cols(), ni, ni));
  for (Eigen::Index j = 0; j < ni; ++j)
    if (W.row(j).cwiseAbs().maxCoeff() > 0) finite_variance(ss, j, "white noise");
  const Eigen::MatrixXd P = numerics::lyapunov(ss.A, ss.B * W * ss.B.transpose());
  return covariance_of(ss.outputs, ss.C, P);
}

double road_velocity_intensity(double gd0, double speed) {
  const double n0 = 0.1;  // cycles/m, ISO 8608
  return 2 * pi * pi * n0 * n0 * gd0 * speed;
}

namespace {
// (e^{−ŝ} − 1)/ŝ by the [p/p] Padé approximant of e^{−ŝ}, ŝ = s τ, in companion form (strictly proper).
void delay_difference(int p, Eigen::MatrixXd& A, Eigen::VectorXd& B, Eigen::RowVectorXd& C) {
  std::vector<double> c(static_cast<std::size_t>(p + 1));
  c[0] = 1;
  for (int i = 1; i <= p; ++i) c[static_cast<std::size_t>(i)] = c[static_cast<std::size_t>(i - 1)] * (p - i + 1) / (i * (2.0 * p - i + 1));
  // Den D(ŝ) = Σ c_i ŝ^i; (N − D)/ŝ = −2 Σ_{i odd} c_i ŝ^{i−1}; monic by c_p.
  const double cp = c[static_cast<std::size_t>(p)];
  A = Eigen::MatrixXd::Zero(p, p);
  for (int i = 0; i + 1 < p; ++i) A(i, i + 1) = 1;
  for (int i = 0; i < p; ++i) A(p - 1, i) = -c[static_cast<std::size_t>(i)] / cp;
  B = Eigen::VectorXd::Zero(p);
  B[p - 1] = 1;
  C = Eigen::RowVectorXd::Zero(p);
  for (int i = 1; i <= p; i += 2) C[i - 1] = -2 * c[static_cast<std::size_t>(i)] / cp;
}
}  // namespace

RandomResponse road_response(const StateSpace& ss, const Road& road) {
  if (!(road.gd0 > 0 && std::isfinite(road.gd0)))
    throw InvalidArgument("road", "gd0", fmt::format("must be > 0 (m³), got {}", road.gd0));
  if (!(road.speed > 0 && std::isfinite(road.speed)))
    throw InvalidArgument("road", "speed", fmt::format("must be > 0 (m/s), got {}", road.speed));
  if (road.pade_order < 1 || road.pade_order > 20)
    throw InvalidArgument("road", "pade_order", fmt::format("must be 1 to 20, got {}", road.pade_order));
  if (road.inputs.empty()) throw InvalidArgument("road", "inputs", "name at least one driving joint that sees the road");
  if (!road.delays.empty() && road.delays.size() != road.inputs.size())
    throw InvalidArgument("road", "delays", fmt::format("{} delay(s) for {} input(s)", road.delays.size(), road.inputs.size()));
  const Eigen::Index n = ss.A.rows(), no = ss.C.rows();
  std::vector<Eigen::Index> idx;
  std::vector<double> tau;
  for (std::size_t k = 0; k < road.inputs.size(); ++k) {
    const auto it = std::find(ss.inputs.begin(), ss.inputs.end(), road.inputs[k]);
    if (it == ss.inputs.end())
      throw InvalidArgument("road", "inputs", fmt::format("'{}' is not an input of the state space", road.inputs[k]));
    const auto j = it - ss.inputs.begin();
    if (!ss.system.motion[static_cast<std::size_t>(j)])
      throw InvalidArgument("road", "inputs", fmt::format("'{}' is a load, not a driving joint", road.inputs[k]));
    const double d = road.delays.empty() ? 0.0 : road.delays[k];
    if (!(d >= 0 && std::isfinite(d))) throw InvalidArgument("road", "delays", fmt::format("must be >= 0 (s), got {}", d));
    idx.push_back(j);
    tau.push_back(d);
    finite_variance(ss, j, "a random road (white-noise velocity)", false);
  }
  // u = e u_r + δ, δ_k = u_r(t − τ_k) − u_r(t); Ỹ = Y + A⁻¹ B e u_r removes the road's random walk:
  //   dỸ/dt = A Ỹ + B δ + A⁻¹ B e w,   y = C Ỹ + (D − C A⁻¹ B) e u_r + D δ,
  // finite only if the static gain (D − C A⁻¹ B) e of every output is zero.
  Eigen::VectorXd Be = Eigen::VectorXd::Zero(n), De = Eigen::VectorXd::Zero(no);
  for (Eigen::Index j : idx) Be += ss.B.col(j), De += ss.D.col(j);
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(ss.A);
  const Eigen::VectorXd AiBe = n ? Eigen::VectorXd(lu.solve(Be)) : Eigen::VectorXd(0);
  const Eigen::VectorXd g0 = De - ss.C * AiBe;
  for (Eigen::Index i = 0; i < no; ++i) {
    const double scale = (ss.C.row(i).cwiseAbs() * AiBe.cwiseAbs())(0) + std::abs(De[i]);
    if (std::abs(g0[i]) > 1e-6 * scale && std::abs(g0[i]) > 1e-12)
      throw InvalidArgument(fmt::format("output '{}' follows the road displacement statically (gain {:.6g}): its rms under "
                                        "a random road grows without bound; use a relative output (a deflection, a travel, "
                                        "an acceleration or a force)",
                                        ss.outputs[static_cast<std::size_t>(i)], g0[i]));
  }
  int na = static_cast<int>(n);
  for (double d : tau)
    if (d > 0) na += road.pade_order;
  Eigen::MatrixXd Aa = Eigen::MatrixXd::Zero(na, na), Ca = Eigen::MatrixXd::Zero(no, na);
  Eigen::VectorXd Ba = Eigen::VectorXd::Zero(na);
  Aa.topLeftCorner(n, n) = ss.A;
  Ca.leftCols(n) = ss.C;
  Ba.head(n) = AiBe;
  Eigen::MatrixXd Ap;
  Eigen::VectorXd Bp;
  Eigen::RowVectorXd Cp;
  delay_difference(road.pade_order, Ap, Bp, Cp);
  int at = static_cast<int>(n);
  for (std::size_t k = 0; k < idx.size(); ++k) {
    if (!(tau[k] > 0)) continue;
    const int p = road.pade_order;
    // ζ̇ = (Â ζ + B̂ w)/τ, δ = τ Ĉ ζ.
    Aa.block(at, at, p, p) = Ap / tau[k];
    Ba.segment(at, p) = Bp / tau[k];
    Aa.block(0, at, n, p) = ss.B.col(idx[k]) * (tau[k] * Cp);
    Ca.block(0, at, no, p) = ss.D.col(idx[k]) * (tau[k] * Cp);
    at += p;
  }
  const double W = road_velocity_intensity(road.gd0, road.speed);
  const Eigen::MatrixXd P = numerics::lyapunov(Aa, W * Ba * Ba.transpose());
  return covariance_of(ss.outputs, Ca, P);
}

}  // namespace inerta::analysis
