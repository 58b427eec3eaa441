#include "inerta/optim/admittance_search.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "inerta/error.hpp"
#include "inerta/network/enumeration.hpp"

namespace inerta::optim {

namespace {
using network::Network;
using network::Poly;
using cd = std::complex<double>;

cd at(const Poly& p, cd s) {
  cd v = 0;
  for (std::size_t i = p.size(); i-- > 0;) v = v * s + p[i];
  return v;
}

// A frequency scale for the coefficients: the geometric mean of the magnitudes of the finite
// nonzero roots of num and den (from their companion matrices), else 2π rad/s.
double frequency_scale(const network::Rational& y) {
  double sum = 0;
  int count = 0;
  for (const Poly* p : {&y.num, &y.den}) {
    Poly q = *p;
    while (!q.empty() && q.back() == 0) q.pop_back();
    std::size_t lead = 0;
    while (lead < q.size() && q[lead] == 0) ++lead;  // roots at s = 0
    const int n = static_cast<int>(q.size() - lead) - 1;
    if (n < 1) continue;
    Eigen::MatrixXd C = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i) C(0, i) = -q[lead + static_cast<std::size_t>(n - 1 - i)] / q.back();
    for (int i = 1; i < n; ++i) C(i, i - 1) = 1;
    const Eigen::VectorXcd r = C.eigenvalues();
    for (Eigen::Index i = 0; i < r.size(); ++i)
      if (std::abs(r(i)) > 0 && std::isfinite(std::abs(r(i)))) sum += std::log(std::abs(r(i))), ++count;
  }
  return count ? std::exp(sum / count) : 2 * M_PI;
}
}  // namespace

int reactive_elements(const Network& bound) {
  const Network s = network::simplify(bound);
  if (s.kind == Network::Kind::Open || s.kind == Network::Kind::Rigid) return 0;
  if (s.kind == Network::Kind::Admittance)
    return static_cast<int>(std::max(s.num.size(), s.den.size())) - 1;
  const auto c = network::count_elements(network::canonical(s));  // b1-b2 in series is one inerter
  return c.springs + c.inerters;
}

AdmittanceResult optimise_admittance(int degree, const NetworkCost& cost, const NetworkCost& objective, const Network& warm,
                                     const numerics::Options& search, const numerics::Progress& progress) {
  if (degree < 1 || degree > 4) throw InvalidArgument(fmt::format("admittance: degree must be 1 … 4, not {}", degree));
  AdmittanceResult r;
  r.degree = degree;
  r.warm_from = network::to_string(warm, true);
  const Network ws = network::simplify(warm);
  network::Rational yw{{1.0}, {1.0}};
  if (ws.kind != Network::Kind::Open && ws.kind != Network::Kind::Rigid) yw = network::rational_admittance(ws);
  // Y(s) = Y0 · P(s/ω0) / Q(s/ω0): p_i = num_i ω0^i / (Y0 g), q_i = den_i ω0^i / g, g = max |den_i ω0^i|.
  const double w0 = frequency_scale(yw);
  const double Y0 = std::max(std::abs(at(yw.num, cd(0, w0)) / at(yw.den, cd(0, w0))), 1e-300);
  const std::size_t n = static_cast<std::size_t>(degree) + 1;
  std::vector<numerics::Variable> vars;
  for (const char* part : {"p", "q"})
    for (std::size_t i = 0; i < n; ++i) vars.push_back({fmt::format("{}{}", part, i), 1e-6, 1e6, true, false});
  auto rational = [&](const std::vector<double>& v) {
    network::Rational y;
    y.num.resize(n), y.den.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      y.num[i] = Y0 * v[i] / std::pow(w0, static_cast<double>(i));
      y.den[i] = v[n + i] / std::pow(w0, static_cast<double>(i));
    }
    return y;
  };
  auto leaf = [](const network::Rational& y) { return network::admittance_leaf(y.num, y.den); };
  auto J = [&](const std::vector<double>& v) -> double {
    const network::Rational y = rational(v);
    bool any_num = false, any_den = false;
    for (std::size_t i = 0; i < n; ++i) any_num |= y.num[i] > 0, any_den |= y.den[i] > 0;
    if (!any_num || !any_den) return INFINITY;
    if (!network::positive_real(y).positive_real) return INFINITY;  // passive networks only (exact test)
    try {
      return cost(leaf(y));
    } catch (const NumericalError&) {
      return INFINITY;
    }
  };
  numerics::Options o = search;
  o.grid_variables = 0;
  if (yw.num.size() <= n && yw.den.size() <= n) {  // the warm network's own coefficients
    double g = 0;
    for (std::size_t i = 0; i < yw.den.size(); ++i) g = std::max(g, std::abs(yw.den[i]) * std::pow(w0, static_cast<double>(i)));
    std::vector<double> v(2 * n, 0.0);
    for (std::size_t i = 0; i < yw.num.size(); ++i) v[i] = yw.num[i] * std::pow(w0, static_cast<double>(i)) / (Y0 * g);
    for (std::size_t i = 0; i < yw.den.size(); ++i) v[n + i] = yw.den[i] * std::pow(w0, static_cast<double>(i)) / g;
    o.initial_values.push_back(v);
  }
  const numerics::Result s = numerics::pattern_search(vars, J, o, progress);
  r.evaluations = s.evaluations;
  r.y = rational(s.values);
  while (r.y.num.size() > 1 && r.y.num.back() == 0) r.y.num.pop_back();
  while (r.y.den.size() > 1 && r.y.den.back() == 0) r.y.den.pop_back();
  r.cost = s.cost;
  r.pr = network::positive_real(r.y);
  if (!std::isfinite(s.cost)) return r;
  r.J = objective(leaf(r.y));
  try {
    r.synthesis = network::synthesise(r.y);
    r.J_realised = objective(r.synthesis->network);
  } catch (const std::exception& e) {
    r.synthesis_error = e.what();
  }
  return r;
}

AdmittanceResult admittance_bound(const Study& study, int degree, const Network& warm, const numerics::Progress& progress) {
  auto cost = [&](const Network& net) {
    try {
      return evaluate(study, net).penalised();
    } catch (const NumericalError&) {
      return static_cast<double>(INFINITY);
    }
  };
  auto J = [&](const Network& net) {
    try {
      return evaluate(study, net).J;
    } catch (const NumericalError&) {
      return static_cast<double>(INFINITY);
    }
  };
  return optimise_admittance(degree, cost, J, warm, study.search, progress);
}

AdmittanceResult admittance_bound(const ModelStudy& study, int degree, const Network& warm, const numerics::Progress& progress) {
  auto cost = [&](const Network& net) {
    try {
      return evaluate(study, net).penalised;
    } catch (const NumericalError&) {
      return static_cast<double>(INFINITY);
    }
  };
  auto J = [&](const Network& net) {
    try {
      return evaluate(study, net).J;
    } catch (const NumericalError&) {
      return static_cast<double>(INFINITY);
    }
  };
  return optimise_admittance(degree, cost, J, warm, study.search, progress);
}

double AdmittanceBound::gap_pct() const {
  return best ? 100 * (best->J - result.J) / result.J : std::numeric_limits<double>::quiet_NaN();
}

std::vector<AdmittanceBound> admittance_bounds(std::vector<int> degrees, const std::vector<BoundCandidate>& candidates,
                                               const std::function<AdmittanceResult(int, const network::Network&)>& bound,
                                               const std::function<void(const AdmittanceBound&)>& done) {
  std::sort(degrees.begin(), degrees.end());
  std::vector<BoundCandidate> pool = candidates;
  std::vector<AdmittanceBound> out;
  for (int d : degrees) {
    auto best_of = [&](const std::vector<BoundCandidate>& from) {
      const BoundCandidate* b = nullptr;
      for (const auto& c : from)
        if (reactive_elements(c.net) <= d && std::isfinite(c.cost) && (!b || c.cost < b->cost)) b = &c;
      return b;
    };
    AdmittanceBound row;
    if (const BoundCandidate* b = best_of(candidates)) row.best = *b;  // the gap's reference
    const BoundCandidate* start = best_of(pool);                       // it, or a lower degree's bound if better
    const auto t0 = std::chrono::steady_clock::now();
    row.result = bound(d, start ? start->net : network::assign(network::parse("c"), {{"c", 1000.0}}));
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (std::isfinite(row.result.cost))
      pool.push_back({fmt::format("the degree-{} bound", d), network::admittance_leaf(row.result.y.num, row.result.y.den),
                      row.result.cost, row.result.J});
    out.push_back(std::move(row));
    if (done) done(out.back());
  }
  return out;
}

}  // namespace inerta::optim
