// Design studies on any model (optim/model_study.hpp): Den Hartog's tuned mass damper recovered by
// the H∞ and H2 objectives, an inerter-based absorber at least as good, and every study-file error.
#include "inerta/optim/model_study.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "inerta/error.hpp"
#include "inerta/io/model_file.hpp"
#include "inerta/io/model_study_file.hpp"
#include "inerta/network/layouts.hpp"
#include "support/run.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_optim_model_study {

using namespace inerta;

namespace {

constexpr double m = 100, k = 1e5, mu = 0.05, ma = 5;

optim::ModelStudy tmd_study(optim::Objective::Kind kind) {
  optim::ModelStudy s;
  s.model = io::load_model(inerta::testing::model_path("tmd.yaml"));
  s.strut = s.model.find_force("absorber");
  s.objective.kind = kind;
  s.objective.outputs = {{"x", 1.0}};
  if (kind == optim::Objective::Kind::Hinf) {
    s.objective.input = "F";
    for (int i = 0; i < 4001; ++i) s.objective.frequencies.push_back(3.5 + 3.0 * i / 4000);
  } else {
    s.objective.noise_inputs = {"F"};
    s.objective.noise_intensity = {1.0};
  }
  s.search.starts = 2;
  s.search.min_step = 1e-4;
  s.lo = 1, s.hi = 1e6;
  return s;
}

// Tuning ratio f_a/f and damping ratio ζ = c / (2 m_a ω_a) of a spring–damper absorber.
std::pair<double, double> tuning(const network::Params& p) {
  const double w = std::sqrt(k / m), wa = std::sqrt(p.at("k") / ma);
  return {wa / w, p.at("c") / (2 * ma * wa)};
}

}  // namespace

TEST(ModelStudy, HinfRecoversDenHartogsTunedMassDamper) {
  // Den Hartog: f = 1/(1+μ), ζ = sqrt(3μ/(8(1+μ)³)), peak |x k/F| = sqrt(1 + 2/μ). His tuning is
  // the fixed-point approximation, so the optimum is at least as good and close to it.
  const optim::ModelStudy s = tmd_study(optim::Objective::Kind::Hinf);
  const auto r = optim::optimise_layout(s, "k|c");
  const auto [f, zeta] = tuning(r.values);
  EXPECT_NEAR(f, 1 / (1 + mu), 0.01 / (1 + mu));
  EXPECT_NEAR(zeta, std::sqrt(3 * mu / (8 * std::pow(1 + mu, 3))), 0.1 * std::sqrt(3 * mu / (8 * std::pow(1 + mu, 3))));
  EXPECT_NEAR(r.cost.J * k, std::sqrt(1 + 2 / mu), 0.02 * std::sqrt(1 + 2 / mu));
  const double w = std::sqrt(k / m), wa = w / (1 + mu), zd = std::sqrt(3 * mu / (8 * std::pow(1 + mu, 3)));
  const double J_dh = optim::evaluate(s, network::resolve("k|c", {{"k", ma * wa * wa}, {"c", 2 * zd * ma * wa}})).J;
  EXPECT_LE(r.cost.J, J_dh * (1 + 1e-9));
  // An inerter in parallel with the absorber (same mass) does at least as well.
  const auto rb = optim::optimise_layout(s, "k|c|b", {}, {r.values});  // warm-started from the k|c optimum
  EXPECT_LE(rb.cost.J, r.cost.J);
}

TEST(ModelStudy, H2RecoversTheWhiteNoiseOptimumOfTheTunedMassDamper) {
  // White-noise force on an undamped primary: f = sqrt(1 + μ/2)/(1 + μ),
  // ζ = sqrt(μ (1 + 3μ/4) / (4 (1 + μ)(1 + μ/2))) (Warburton; Asami et al.).
  const optim::ModelStudy s = tmd_study(optim::Objective::Kind::Rms);
  const auto r = optim::optimise_layout(s, "k|c");
  const auto [f, zeta] = tuning(r.values);
  EXPECT_NEAR(f, std::sqrt(1 + mu / 2) / (1 + mu), 2e-3);
  EXPECT_NEAR(zeta, std::sqrt(mu * (1 + 0.75 * mu) / (4 * (1 + mu) * (1 + mu / 2))), 0.02 * zeta);
  const auto rb = optim::optimise_layout(s, "k|c|b", {}, {r.values});
  EXPECT_LE(rb.cost.J, r.cost.J);
}

TEST(ModelStudy, ARmsLimitIsHonouredOrReported) {
  optim::ModelStudy s;
  s.model = io::load_model(inerta::testing::model_path("quarter_car.yaml"));
  s.strut = s.model.find_force("suspension");
  s.objective.outputs = {{"a_body", 1.0}};
  analysis::Road road;
  road.speed = 25;
  road.inputs = {"road"};
  s.objective.road = road;
  s.objective.limits = {{"travel", 1e9}};
  const double travel = optim::evaluate(s, optim::default_network(s)).limit_values[0];
  s.objective.limits[0].limit = 0.8 * travel;
  s.search.starts = 1;
  s.lo = 1, s.hi = 1e6;
  const auto r = optim::optimise_layout(s, "c");
  // A softer damper improves comfort but raises the travel: the limit holds at the optimum.
  EXPECT_TRUE(r.cost.feasible);
  EXPECT_LE(r.cost.limit_values[0], s.objective.limits[0].limit * (1 + 1e-9));
  EXPECT_EQ(r.cost.penalised, r.cost.J);
}

namespace {
std::string study_error(const std::string& text) {
  const std::string path = (inerta::testing::temp_dir() / "study.yaml").string();
  std::ofstream(path) << text;
  try {
    io::load_model_study(path);
  } catch (const ModelError& e) {
    return e.what();
  }
  return "";
}
const std::string kModel = "model: " + inerta::testing::model_path("tmd.yaml") + "\n";
}  // namespace

TEST(ModelStudyFile, EveryErrorNamesTheLineAndKey) {
  const std::string ok = kModel + "strut: absorber\nobjective: {type: hinf, input: F, outputs: {x: 1}, band: {from: 3, to: 8}}\nlayouts: [\"k|c\"]\n";
  EXPECT_EQ(study_error(ok), "");
  auto expect = [&](const std::string& text, const std::string& part) {
    const std::string msg = study_error(text);
    EXPECT_NE(msg.find(part), std::string::npos) << msg << "\n---\n" << text;
  };
  expect(ok + "serach: {}\n", ":5: 'serach': unknown key; expected one of: name, model, set, strut");
  expect(kModel + "strut: k\nobjective: {type: hinf, input: F, outputs: {x: 1}, band: {from: 3, to: 8}}\nlayouts: [k]\n",
         ":2: 'strut': 'k' is not a network strut of the model; network struts: absorber");
  expect(kModel + "strut: absorber\nobjective: {type: hinf, input: F, outputs: {y: 1}, band: {from: 3, to: 8}}\nlayouts: [k]\n",
         "'y': no output of that name in the model; outputs: x, x_absorber, stroke, a");
  expect(kModel + "strut: absorber\nobjective: {type: h2}\nlayouts: [k]\n", "'type': unknown objective 'h2'; expected rms, hinf or peak");
  expect(kModel + "strut: absorber\nobjective: {type: hinf, input: G, outputs: {x: 1}, band: {from: 3, to: 8}}\nlayouts: [k]\n",
         "cannot evaluate the model's own strut");
  expect(kModel + "strut: absorber\nobjective: {type: hinf, input: F, outputs: {x: 1}, band: {from: 8, to: 3}}\nlayouts: [k]\n",
         "'band': expected from < to");
  expect(kModel + "strut: absorber\nobjective: {type: hinf, input: F, outputs: {x: -1}, band: {from: 3, to: 8}}\nlayouts: [k]\n",
         "'x': must be a finite number > 0 (weight)");
  expect(ok + "search: {starts: 2.5}\n", "'starts': expected a whole number from 1 to 1000, got 2.5");
  expect(ok + "search: {lo: 10, hi: 1}\n", "'search': expected lo < hi");
  expect(kModel + "strut: absorber\nobjective: {type: hinf, input: F, outputs: {x: 1}, band: {from: 3, to: 8}}\nlayouts: [S9]\n",
         "'S9' is neither a network expression");
  expect(kModel + "strut: absorber\nobjective: {type: rms, outputs: {x: 1}}\nlayouts: [k]\n", "give exactly one excitation");
  expect(kModel + "strut: absorber\nobjective: {type: rms, outputs: {x: 1}, road: {class: J, speed: 20, inputs: [F]}}\nlayouts: [k]\n",
         "'class': expected an ISO 8608 class A to H, got 'J'");
  expect(kModel + "strut: absorber\nobjective: {type: rms, outputs: {x: 1}, white_noise: {F: 1}, limits: {x_absorber: 0}}\nlayouts: [k]\n",
         "'x_absorber': must be a finite number > 0");
  expect(kModel + "strut: absorber\nobjective: {type: rms, outputs: {a: 1}, white_noise: {F: 1}}\nlayouts: [k]\n",
         "output 'a' responds directly to input 'F'");
  expect(kModel + "strut: absorber\nobjective: {type: peak, outputs: {x: 1}, t_end: 0}\nlayouts: [k]\n", "'t_end': must be a finite number > 0 (s)");
  expect("model: nowhere.yaml\nstrut: a\n", "'model': ");
  const std::string rms = kModel + "strut: absorber\nobjective: {type: rms, outputs: {x: 1}, ";
  expect(rms + "road: {class: C, speed: 20, inputs: [F], delays: [0, 1]}}\nlayouts: [k]\n", "'delays': expected 1 delay(s) in s");
  expect(rms + "road: {class: C, speed: 20, inputs: [F], pade_order: 30}}\nlayouts: [k]\n", "'pade_order': expected a whole number from 1 to 20");
  expect(rms + "road: {class: C, inputs: [F]}}\nlayouts: [k]\n", "'speed': missing; expected the speed in m/s");
  expect(rms + "road: {class: C, speed: 20}}\nlayouts: [k]\n", "'inputs': missing");
  expect(rms + "road: {class: C, gd0: 1e-4, speed: 20, inputs: [F]}}\nlayouts: [k]\n", "give one of class (ISO 8608, A to H) and gd0");
  expect(rms + "road: {class: C, speed: 20, inputs: [F]}}\nlayouts: [k]\n", "'F' is a load, not a driving joint");
  expect(rms + "white_noise: [F]}\nlayouts: [k]\n", "'white_noise': expected {INPUT: intensity, ...}");
  expect(kModel + "strut: absorber\nobjective: {type: hinf, input: F, outputs: {x: 1}, band: {from: 3, to: 8, spacing: cubic}}\nlayouts: [k]\n",
         "'spacing': expected linear or log");
  expect(kModel + "strut: absorber\nobjective: {type: hinf, input: F, outputs: {x: 1}, band: {from: 3, to: 8, points: 1}}\nlayouts: [k]\n",
         "'points': expected a whole number from 2 to 100000");
  expect(kModel + "strut: absorber\nobjective: {type: peak, outputs: {x: 1}, t_end: 10, sample: 1e-7}\nlayouts: [k]\n",
         "'sample': more than 1e7 samples");
  expect(kModel + "set: [absorber.params.k=-1]\nstrut: absorber\nobjective: {type: hinf, input: F, outputs: {x: 1}, band: {from: 3, to: 8}}\nlayouts: [k]\n",
         "'model': ");
  expect(kModel + "strut: absorber\nobjective: {type: hinf, input: F, outputs: {x: 1}, band: {from: 3, to: 8}, extra: 1}\nlayouts: [k]\n",
         "'extra': unknown key in objective");
}

TEST(ModelStudyFile, LayoutsAllAndItsNetworkOptions) {
  const std::string head = kModel + "strut: absorber\nobjective: {type: hinf, input: F, outputs: {x: 1}, band: {from: 3, to: 8}}\n";
  EXPECT_EQ(study_error(head + "layouts: all\nnetworks: {max_elements: 2, elements: [k, c], static_load: required}\n"), "");
  {
    const optim::ModelStudy s = io::load_model_study(inerta::testing::write_study(
        "all.yaml", head + "layouts: all\nnetworks: {max_elements: 2, elements: [k, c], static_load: required}\n"));
    ASSERT_TRUE(s.all.has_value());
    EXPECT_EQ(s.layouts, (std::vector<std::string>{"k", "k|c"}));  // c and k-c have no spring path between the terminals
  }
  auto expect = [&](const std::string& text, const std::string& part) {
    const std::string msg = study_error(head + text);
    EXPECT_NE(msg.find(part), std::string::npos) << msg << "\n---\n" << text;
  };
  expect("layouts: all\n", ":4: 'networks': layouts: all needs networks: {max_elements: N");
  expect("layouts: all\nnetworks: {elements: [k]}\n", "'networks': missing max_elements");
  expect("layouts: all\nnetworks: {max_elements: 9}\n", ":5: 'max_elements': expected a whole number from 1 to 7, got 9");
  expect("layouts: all\nnetworks: {max_elements: 2.5}\n", "'max_elements': expected a whole number from 1 to 7, got 2.5");
  expect("layouts: all\nnetworks: {max_elements: 3, elements: [k, x]}\n", "'elements': 'x' is not an element type");
  expect("layouts: all\nnetworks: {max_elements: 3, static_load: yes}\n", "'static_load': expected any, required");
  expect("layouts: all\nnetworks: {max_elements: 3, max_inerter: 1}\n", "'max_inerter': unknown key in networks");
  expect("layouts: all\nnetworks: {max_elements: 3, max_inerters: -1}\n", "'max_inerters': expected a whole number from 0 to 7");
  expect("layouts: [k]\nnetworks: {max_elements: 3}\n", "'networks': only with layouts: all");
  expect("layouts: all\nnetworks: {max_elements: 2, elements: [c, b], static_load: required}\n",
         "'networks': no network satisfies these options");
  expect("layouts: everything\n", "'layouts': expected a list of layouts (network expressions or names), or all");
}
}  // namespace test_optim_model_study
