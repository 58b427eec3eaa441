// Linear analysis of any model (spec/02 §2.5): state space from named inputs to outputs against
// matrices derived by hand, frequency responses against time simulation, random response by
// Lyapunov against closed forms and frequency-domain integrals.
#include "inerta/analysis/state_space.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <numbers>

#include "inerta/error.hpp"
#include "inerta/io/model_file.hpp"
#include "inerta/mbs/assembly.hpp"
#include "inerta/numerics/lyapunov.hpp"
#include "support/run.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_analysis_state_space {

using namespace inerta;
using std::numbers::pi;
using cd = std::complex<double>;

namespace {

// m, c, k oscillator along y driven by the point force F.
std::string oscillator(double m, double c, double k) {
  return fmt::format(
      "name: osc\noptions: {{gravity: false}}\nground: {{markers: {{O: [0, 0]}}}}\n"
      "bodies:\n  - {{name: mass, mass: {}, inertia: 0, position: [0, 1]}}\n"
      "joints:\n  - {{name: guide, type: prismatic, markers: [ground.O, mass.cm], axis: [0, 1]}}\n"
      "forces:\n  - {{name: k, type: spring, markers: [ground.O, mass.cm], k: {}}}\n"
      "  - {{name: c, type: damper, markers: [ground.O, mass.cm], c: {}}}\n"
      "  - {{name: F, type: point_force, marker: mass.cm, direction: [0, 1], value: 0}}\n"
      "outputs:\n  - {{name: x, type: coordinate, body: mass, component: y}}\n"
      "  - {{name: v, type: velocity, marker: mass.cm, component: y}}\n"
      "  - {{name: a, type: acceleration, marker: mass.cm, component: y}}\n",
      m, k, c);
}

mbs::Model quarter_car(const std::vector<std::string>& sets = {}) {
  return io::load_model(inerta::testing::model_path("quarter_car.yaml"), sets);
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

constexpr double ms = 250, mu = 35, ks = 16000, cs = 1000, kt = 160000;

}  // namespace

TEST(StateSpace, OneDofOscillatorIsTheTextbookModel) {
  const double m = 2, c = 3, k = 50;
  const mbs::Model model = io::parse_model(oscillator(m, c, k), "osc.yaml");
  const analysis::StateSpace ss = analysis::state_space(model, {"F"}, {"x", "v", "a"});
  ASSERT_EQ(ss.states, (std::vector<std::string>{"mass.y", "mass.y_dot"}));
  Eigen::MatrixXd A(2, 2), B(2, 1), C(3, 2), D(3, 1);
  A << 0, 1, -k / m, -c / m;
  B << 0, 1 / m;
  C << 1, 0, 0, 1, -k / m, -c / m;
  D << 0, 0, 1 / m;
  EXPECT_LT((ss.A - A).norm(), 1e-6 * A.norm());
  EXPECT_LT((ss.B - B).norm(), 1e-9);
  EXPECT_LT((ss.C - C).norm(), 1e-6 * C.norm());
  EXPECT_LT((ss.D - D).norm(), 1e-9);
  EXPECT_FALSE(ss.has_rate_feedthrough());
  EXPECT_EQ(ss.input_units[0], "N or N·m");
  EXPECT_EQ(ss.system.joint, std::vector<int>{-1});  // a load: no driving joint
}

TEST(StateSpace, QuarterCarRoadInputMatchesTheHandDerivedMatrices) {
  // States [wheel.y, body.y, rates]; the road enters through the tyre spring only (B1 = B2 = 0).
  const analysis::StateSpace ss = analysis::state_space(quarter_car(), {"road"}, {"a_body", "travel", "tyre_force"});
  ASSERT_EQ(ss.states, (std::vector<std::string>{"wheel.y", "body.y", "wheel.y_dot", "body.y_dot"}));
  Eigen::MatrixXd A(4, 4), B(4, 1), C(3, 4), D(3, 1);
  A << 0, 0, 1, 0,  //
      0, 0, 0, 1,   //
      -(ks + kt) / mu, ks / mu, -cs / mu, cs / mu, ks / ms, -ks / ms, cs / ms, -cs / ms;
  B << 0, 0, kt / mu, 0;
  C << ks / ms, -ks / ms, cs / ms, -cs / ms,  // a_body
      -1, 1, 0, 0,                            // travel = y_body − y_wheel (+ const)
      kt, 0, 0, 0;                            // tyre tension k_t (y_wheel − y_road − L0)
  D << 0, 0, -kt;
  EXPECT_LT((ss.A - A).norm(), 1e-6 * A.norm());
  EXPECT_LT((ss.B - B).norm(), 1e-6 * B.norm());
  EXPECT_LT((ss.C - C).norm(), 1e-6 * C.norm());
  EXPECT_LT((ss.D - D).norm(), 1e-6 * kt);
  EXPECT_EQ(ss.T0.norm(), 0.0);
  EXPECT_EQ(ss.input_units[0], "m");
  EXPECT_EQ(ss.system.joint, std::vector<int>{quarter_car().find_joint("road")});  // the handle, found once
}

TEST(StateSpace, ADrivenDamperShiftsTheStateAndKeepsTheExactTransferFunction) {
  // A tyre damper c_t: the road's rate enters (B1 ≠ 0); the proper model's H(jω) must equal the
  // hand-written (−ω² M + jω C + K)⁻¹ (k_t + jω c_t) of the 2-DOF system.
  std::string text = read_text(inerta::testing::model_path("quarter_car.yaml"));
  text.replace(text.find("  - {name: F_body"), 0, "  - {name: c_t, type: damper, markers: [surface.top, wheel.bottom], c: 300}\n");
  const mbs::Model model = io::parse_model(text, "qc.yaml");
  const analysis::StateSpace ss = analysis::state_space(model, {"road"}, {"y_wheel", "a_body", "tyre_force"});
  EXPECT_GT(ss.T0.norm(), 0.0);
  const double ct = 300;
  const std::vector<double> f = {0.5, 1.2, 4, 11, 25};
  const auto H = analysis::frequency_response(ss, f);
  for (std::size_t k = 0; k < f.size(); ++k) {
    const double w = 2 * pi * f[k];
    Eigen::Matrix2cd Z;
    Z << -w * w * mu + cd(0, w) * (cs + ct) + ks + kt, -cd(0, w) * cs - ks,  //
        -cd(0, w) * cs - ks, -w * w * ms + cd(0, w) * cs + ks;
    const Eigen::Vector2cd X = Z.partialPivLu().solve(Eigen::Vector2cd(kt + cd(0, w) * ct, 0));
    const cd tyre = kt * (X[0] - 1.0);  // the spring only (force output of k_t)
    EXPECT_LT(std::abs(H[k](0, 0) - X[0]), 1e-6 * std::abs(X[0])) << f[k];
    EXPECT_LT(std::abs(H[k](1, 0) + w * w * X[1]), 1e-6 * w * w * std::abs(X[1])) << f[k];
    EXPECT_LT(std::abs(H[k](2, 0) - tyre), 1e-6 * std::abs(tyre)) << f[k];
  }
}

TEST(StateSpace, TransferFunctionEqualsTheFourierRatioOfATimeSimulation) {
  // Road sine of 1 mm at 3 Hz from the static equilibrium; after the transient the Fourier component
  // of the body acceleration and the travel over the road's equals H(j 2π 3).
  mbs::Model model = quarter_car();
  const analysis::StateSpace ss = analysis::state_space(model, {"road"}, {"a_body", "travel"});
  const double f = 3, amp = 1e-3;
  const int j = model.find_joint("road");
  model.joints[static_cast<std::size_t>(j)].motion = mbs::TimeFunction::sine(amp, f);
  solve::IntegratorOptions opt;
  opt.rtol = 1e-10;
  opt.atol = 1e-12;
  const auto s = inerta::testing::run(model, 20.0, 1.0 / (f * 200), opt);
  const auto H = analysis::frequency_response(ss, {f});
  for (int o = 0; o < 2; ++o) {
    const int idx = o == 0 ? 2 : 3;  // a_body, travel in the model's output list
    cd acc = 0;
    int n = 0;
    for (std::size_t k = 0; k < s.t.size(); ++k)
      if (s.t[k] >= 10 - 1e-9 && s.t[k] < 20 - 1e-9) acc += s[idx][k] * std::exp(cd(0, -2 * pi * f * s.t[k])), ++n;
    const cd ratio = (2.0 * acc / double(n)) / cd(0, -amp);  // the road is amp sin = Im-part phasor −j amp
    EXPECT_LT(std::abs(ratio - H[0](o, 0)), 2e-3 * std::abs(H[0](o, 0))) << o;
  }
}

TEST(StateSpace, UnknownInputsAndOutputsListTheKnownNames) {
  const mbs::Model model = quarter_car();
  try {
    analysis::state_space(model, {"roud"}, {"a_body"});
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("no input 'roud'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("F_body, road"), std::string::npos) << e.what();
  }
  try {
    analysis::state_space(model, {"k_s"}, {"a_body"});  // a spring is not an input
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("no input 'k_s'"), std::string::npos) << e.what();
  }
  try {
    analysis::state_space(model, {"road"}, {"a_bdy"});
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("no output 'a_bdy'; outputs: y_body, y_wheel, a_body"), std::string::npos)
        << e.what();
  }
}

TEST(Modes, QuarterCarUndampedFrequenciesAreThoseOfMAndK) {
  const mbs::Model model = quarter_car();
  mbs::State x = mbs::assemble(model, 0.0);
  const mbs::LinearModel lin = mbs::linearise(model, x);
  const auto und = mbs::undamped_modes(model, lin);
  ASSERT_EQ(und.size(), 2u);
  // det(K − ω² M) = 0 for M = diag(m_u, m_s), K = [[k_s + k_t, −k_s], [−k_s, k_s]].
  const double a = mu * ms, b = -(ms * (ks + kt) + mu * ks), c = ks * kt;
  const double w1 = std::sqrt((-b - std::sqrt(b * b - 4 * a * c)) / (2 * a)), w2 = std::sqrt((-b + std::sqrt(b * b - 4 * a * c)) / (2 * a));
  EXPECT_NEAR(und[0].frequency_hz, w1 / (2 * pi), 1e-7 * w1);
  EXPECT_NEAR(und[1].frequency_hz, w2 / (2 * pi), 1e-7 * w2);
  // The damped modes: λ of the hand matrix A, Im λ / 2π and |λ| / 2π, shapes with their largest entry +1.
  const auto ms_ = mbs::modes(model, lin);
  ASSERT_EQ(ms_.size(), 2u);
  Eigen::Matrix4d A;
  A << 0, 0, 1, 0, 0, 0, 0, 1, -(ks + kt) / mu, ks / mu, -cs / mu, cs / mu, ks / ms, -ks / ms, cs / ms, -cs / ms;
  Eigen::EigenSolver<Eigen::Matrix4d> es(A);
  std::vector<cd> lam;
  for (int i = 0; i < 4; ++i)
    if (es.eigenvalues()[i].imag() > 0) lam.push_back(es.eigenvalues()[i]);
  std::sort(lam.begin(), lam.end(), [](cd p, cd q) { return std::abs(p) < std::abs(q); });
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR(ms_[i].damped_frequency_hz, lam[i].imag() / (2 * pi), 1e-6 * std::abs(lam[i]));
    EXPECT_NEAR(ms_[i].frequency_hz, std::abs(lam[i]) / (2 * pi), 1e-6 * std::abs(lam[i]));
    EXPECT_NEAR(ms_[i].shape.maxCoeff(), 1.0, 1e-12);
  }
  // The bounce mode's damped frequency differs from the undamped one (ζ ≈ 0.24).
  EXPECT_GT(std::abs(ms_[0].damped_frequency_hz - und[0].frequency_hz), 0.01 * und[0].frequency_hz);
}

TEST(Lyapunov, SolvesTheEquationAndRefusesAnUnstableMatrix) {
  Eigen::MatrixXd A(3, 3), Q(3, 3);
  A << -1, 2, 0, -3, -0.5, 1, 0.2, 0, -2;
  Q << 2, 0.3, 0, 0.3, 1, 0.1, 0, 0.1, 0.5;
  const Eigen::MatrixXd P = numerics::lyapunov(A, Q);
  EXPECT_LT((A * P + P * A.transpose() + Q).norm(), 1e-12 * Q.norm());
  Eigen::MatrixXd U = A;
  U(2, 2) = 0.5;
  EXPECT_THROW(numerics::lyapunov(U, Q), NumericalError);
  EXPECT_THROW(numerics::lyapunov(A, Eigen::MatrixXd::Identity(2, 2)), InvalidArgument);
}

TEST(RandomResponse, OneDofUnderWhiteNoiseForceHasTheClosedFormVariance) {
  // σ_x² = π S0 / (k c), σ_v² = π S0 / (m c) for a two-sided force PSD S0 per rad/s (W = 2π S0).
  const double m = 3, c = 40, k = 2e4, S0 = 0.7;
  const mbs::Model model = io::parse_model(oscillator(m, c, k), "osc.yaml");
  const analysis::StateSpace ss = analysis::state_space(model, {"F"}, {"x", "v"});
  const auto r = analysis::white_noise_response(ss, Eigen::MatrixXd::Constant(1, 1, 2 * pi * S0));
  EXPECT_NEAR(r.rms[0], std::sqrt(pi * S0 / (k * c)), 1e-9 * r.rms[0]);
  EXPECT_NEAR(r.rms[1], std::sqrt(pi * S0 / (m * c)), 1e-9 * r.rms[1]);
  EXPECT_NEAR(r.covariance(0, 1), 0.0, 1e-9 * r.rms[0] * r.rms[1]);  // x and ẋ are uncorrelated
  // The acceleration responds directly to the force: infinite variance, refused.
  const analysis::StateSpace sa = analysis::state_space(model, {"F"}, {"a"});
  EXPECT_THROW(analysis::white_noise_response(sa, Eigen::MatrixXd::Identity(1, 1)), InvalidArgument);
}

namespace {
// ∫ over f of the one-sided road-displacement PSD G_d(n0) n0² v / f² times a weight w(f) (log grid
// to 2 kHz, then the tail with w held: a deflection's or a spring force's |H| tends to a constant).
template <class W>
double road_integral(double gd0, double v, W weight, bool tail = true) {
  double sum = 0;
  const int n = 200000;
  const double l0 = std::log(1e-4), l1 = std::log(2e3);
  for (int i = 0; i < n; ++i) {
    const double f = std::exp(l0 + (i + 0.5) * (l1 - l0) / n), df = f * (l1 - l0) / n;
    sum += weight(f) * gd0 * 0.01 * v / (f * f) * df;
  }
  const double fmax = std::exp(l1);  // the tail beyond fmax with the weight held (|H| → its limit)
  return sum + (tail ? weight(fmax) * gd0 * 0.01 * v / fmax : 0.0);
}
}  // namespace

TEST(RandomResponse, QuarterCarOnAnIsoRoadEqualsTheFrequencyDomainIntegral) {
  const mbs::Model model = quarter_car();
  const analysis::StateSpace ss = analysis::state_space(model, {"road"}, {"a_body", "travel", "tyre_force"});
  analysis::Road road;
  road.gd0 = 256e-6;
  road.speed = 25;
  road.inputs = {"road"};
  const auto r = analysis::road_response(ss, road);
  for (int o = 0; o < 3; ++o) {
    const double var = road_integral(road.gd0, road.speed, [&](double f) {
      return std::norm(analysis::frequency_response(ss, {f})[0](o, 0));
    });
    EXPECT_NEAR(r.rms[o], std::sqrt(var), 1e-4 * std::sqrt(var)) << ss.outputs[static_cast<std::size_t>(o)];
  }
  // An absolute position follows the road: unbounded, refused with a hint.
  const analysis::StateSpace sy = analysis::state_space(model, {"road"}, {"y_body"});
  try {
    analysis::road_response(sy, road);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("'y_body' follows the road displacement statically"), std::string::npos) << e.what();
  }
}

TEST(RandomResponse, AWheelbaseDelayGivesTheCrossSpectrumOfTheDelayedRoad) {
  // Two 1-DOF wheels on one road, the rear one τ later: the variances and the covariance of their
  // displacements against ∫ Re(H_f conj(H_r e^{−jωτ})) G df, the error falling with the Padé order.
  const std::string text =
      "name: two_axles\noptions: {gravity: false}\nground: {markers: {O: [0, 0]}}\nbodies:\n"
      "  - {name: road_f, mass: 0, inertia: 0, position: [0, 0]}\n"
      "  - {name: road_r, mass: 0, inertia: 0, position: [1, 0]}\n"
      "  - {name: front, mass: 40, inertia: 0, position: [0, 1]}\n"
      "  - {name: rear, mass: 60, inertia: 0, position: [1, 1]}\n"
      "joints:\n"
      "  - {name: gf, type: prismatic, markers: [ground.O, road_f.cm], axis: [0, 1]}\n"
      "  - {name: gr, type: prismatic, markers: [ground.O, road_r.cm], axis: [0, 1]}\n"
      "  - {name: hf, type: prismatic, markers: [ground.O, front.cm], axis: [0, 1]}\n"
      "  - {name: hr, type: prismatic, markers: [ground.O, rear.cm], axis: [0, 1]}\n"
      "  - {name: road_front, type: driving, body: road_f, coordinate: y, motion: 0}\n"
      "  - {name: road_rear, type: driving, body: road_r, coordinate: y, motion: 0}\n"
      "forces:\n"
      "  - {name: kf, type: spring, markers: [road_f.cm, front.cm], k: 20000}\n"
      "  - {name: cf, type: damper, markers: [road_f.cm, front.cm], c: 300}\n"
      "  - {name: kr, type: spring, markers: [road_r.cm, rear.cm], k: 15000}\n"
      "  - {name: cr, type: damper, markers: [road_r.cm, rear.cm], c: 250}\n"
      "outputs:\n"
      "  - {name: df, type: length, element: kf}\n"
      "  - {name: dr, type: length, element: kr}\n";
  const mbs::Model model = io::parse_model(text, "two_axles.yaml");
  const analysis::StateSpace ss = analysis::state_space(model, {"road_front", "road_rear"}, {"df", "dr"});
  analysis::Road road;
  road.speed = 20;
  road.inputs = {"road_front", "road_rear"};
  road.delays = {0, 2.5 / road.speed};
  const double tau = road.delays[1];
  auto exact = [&](int i, int j) {
    return road_integral(road.gd0, road.speed, [&](double f) {
      const auto H = analysis::frequency_response(ss, {f})[0];
      const cd e = std::exp(cd(0, -2 * pi * f * tau));
      const cd hi = H(i, 0) + H(i, 1) * e, hj = H(j, 0) + H(j, 1) * e;  // each output sees both inputs
      return (hi * std::conj(hj)).real();
    }, i == j);  // a cross term's tail oscillates with e^{−jωτ}: it averages out
  };
  const double v00 = exact(0, 0), v11 = exact(1, 1), v01 = exact(0, 1);
  double previous = 1e300;
  for (int order : {2, 4, 8, 12}) {
    road.pade_order = order;
    const auto r = analysis::road_response(ss, road);
    const double err = std::abs(r.covariance(0, 1) - v01) / std::sqrt(v00 * v11);
    EXPECT_LT(err, previous) << order;
    previous = err;
    if (order == 12) {
      EXPECT_NEAR(r.covariance(0, 0), v00, 1e-4 * v00);
      EXPECT_NEAR(r.covariance(1, 1), v11, 1e-4 * v11);
      EXPECT_LT(err, 1e-3);
    }
  }
  // Without the delay the two wheels see one road: the covariance is that of τ = 0.
  road.delays = {0, 0};
  const auto r0 = analysis::road_response(ss, road);
  const double c0 = road_integral(road.gd0, road.speed, [&](double f) {
    const auto H = analysis::frequency_response(ss, {f})[0];
    return ((H(0, 0) + H(0, 1)) * std::conj(H(1, 0) + H(1, 1))).real();
  });
  EXPECT_NEAR(r0.covariance(0, 1), c0, 1e-4 * std::abs(c0));
}

TEST(RandomResponse, QuarterCarLyapunovRmsEqualsALongSeededRoadRun) {
  // The seeded ISO 8608 road (a sum of cosines, period 60 s) driven in the nonlinear model: the
  // rms over one period after the transient against the Lyapunov rms of the whole-band PSD; the
  // difference is the generator's band (0.011–1 cycles/m, 0.3–25 Hz) and its discrete spectrum.
  // The body acceleration and the travel live in that band; the tyre force's constant |H| → k_t
  // above it is not checked here (its tail is in QuarterCarOnAnIsoRoadEqualsTheFrequencyDomainIntegral).
  mbs::Model model = quarter_car({"road.motion.duration=60"});
  const analysis::StateSpace ss = analysis::state_space(model, {"road"}, {"a_body", "travel", "tyre_force"});
  analysis::Road road;
  road.speed = 25;
  road.inputs = {"road"};
  const auto r = analysis::road_response(ss, road);
  const auto s = inerta::testing::run(model, 70.0, 0.002);
  for (int o = 0; o < 2; ++o) {
    const int idx = 2 + o;  // a_body, travel, tyre_force in the model's outputs
    double sum = 0, sum2 = 0;
    int n = 0;
    for (std::size_t k = 0; k < s.t.size(); ++k)
      if (s.t[k] >= 10 - 1e-9 && s.t[k] < 70 - 1e-9) sum += s[idx][k], sum2 += s[idx][k] * s[idx][k], ++n;
    const double mean = sum / n, rms = std::sqrt(sum2 / n - mean * mean);
    EXPECT_NEAR(rms, r.rms[o], 0.05 * r.rms[o]) << ss.outputs[static_cast<std::size_t>(o)];
  }
}
}  // namespace test_analysis_state_space
