// The prescribed wire-profile catenary (issue 11) and the coupling API with several pantographs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "inerta/analysis/contact_statistics.hpp"
#include "inerta/analysis/simulate.hpp"
#include "inerta/catenary/lumped.hpp"
#include "inerta/catenary/wire_profile.hpp"
#include "inerta/error.hpp"
#include "inerta/io/catenary_file.hpp"
#include "inerta/io/model_file.hpp"
#include "inerta/mbs/dynamics.hpp"
#include "support/run.hpp"
#include "support/temp.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_catenary_wire_profile {

using namespace inerta;
using std::numbers::pi;

namespace {
// A two-mass pantograph: frame m1 on k1 (to ground), head m2 on k2 (to the frame), both on
// vertical sliders, lifted by a constant force on the frame; the rig joint holds the head.
// Static stiffness at the head k_eq = k1 k2 / (k1 + k2).
constexpr double m1 = 10, m2 = 5, k1 = 4000, k2 = 8000, lift = 200, g = 9.81;
// Held at the tabulated head height, the frame settles where lift − m1 g = (k1 + k2) d1 (the springs
// are unstressed as tabulated), so the rig force is k2 d1 − m2 g.
constexpr double k_eq = k1 * k2 / (k1 + k2), F0 = k2 * (lift - m1 * g) / (k1 + k2) - m2 * g;
const char* kTwoMass = R"(
ground: {markers: {G: [0, 0]}}
bodies:
  - {name: frame, mass: 10, inertia: 1, position: [0, 1.0]}
  - {name: head, mass: 5, inertia: 1, position: [0, 1.5]}
joints:
  - {name: frame_slide, type: prismatic, markers: [ground.G, frame.cm], axis: [0, 1]}
  - {name: head_slide, type: prismatic, markers: [ground.G, head.cm], axis: [0, 1]}
  - {name: rig, type: driving, body: head, coordinate: y, motion: 0}
forces:
  - {name: lift, type: point_force, marker: frame.cm, direction: [0, 1], value: 200}
  - {name: k1, type: spring, markers: [ground.G, frame.cm], k: 4000}
  - {name: c1, type: damper, markers: [ground.G, frame.cm], c: 40}
  - {name: k2, type: spring, markers: [frame.cm, head.cm], k: 8000}
  - {name: c2, type: damper, markers: [frame.cm, head.cm], c: 20}
outputs:
  - {name: y_head, type: coordinate, body: head, component: y}
pantograph: {contact: head.cm, rig_joint: rig}
)";

pantograph::Pantograph two_mass() { return io::parse_pantograph(kTwoMass, "two-mass.yaml"); }

catenary::Contact penalty(double k) { return {catenary::Contact::Kind::Penalty, k, 0.0}; }

// h(x) = a sin(2π x / λ), tabulated every dx over one wavelength (periodic).
catenary::WireProfile sine(double a, double lambda, double dx) {
  catenary::WireProfile p;
  const int n = static_cast<int>(std::lround(lambda / dx));
  for (int i = 0; i <= n; ++i) {
    p.x.push_back(i * lambda / n);
    p.h.push_back(i == n ? 0.0 : a * std::sin(2 * pi * i / n));
  }
  return p;
}

std::pair<double, double> min_max(const std::vector<double>& v, std::size_t from = 0) {
  double lo = INFINITY, hi = -INFINITY;
  for (std::size_t i = from; i < v.size(); ++i) lo = std::min(lo, v[i]), hi = std::max(hi, v[i]);
  return {lo, hi};
}
}  // namespace

TEST(WireProfile, FlatProfileWithAStiffPenaltyGivesTheStaticContactForce) {
  catenary::WireProfile flat;
  flat.x = {0, 60};
  flat.h = {0.3, 0.3};
  const catenary::WireProfileCatenary cat(flat);
  const double ks = 1e7;
  analysis::CoupledOptions o;
  o.spans = 2;
  o.integrator.rtol = 1e-10, o.integrator.atol = 1e-13;  // k_s δ resolves the integrator's error on δ
  const auto r = analysis::simulate_coupled({{two_mass(), 0.0, penalty(ks)}}, cat, 20.0, o);
  // The head rises into the wire by δ = F/k_s, unloading the pantograph by k_eq δ: F = F0 / (1 + k_eq/k_s).
  const double F = F0 / (1 + k_eq / ks);
  EXPECT_NEAR(r.contacts[0].stats.mean, F, 1e-6 * F);
  EXPECT_LT(r.contacts[0].stats.std, 1e-5 * F);
  EXPECT_EQ(r.contacts[0].lost_samples, 0);
  EXPECT_EQ(r.histories[0].names.back(), "F_contact");
}

TEST(WireProfile, SlowSinusoidalProfileGivesTheQuasiStaticForceOfTheStaticStiffness) {
  // 10 mm, 60 m wavelength at 5 m/s: 0.083 Hz against the pantograph's modes above 2 Hz. Starting
  // at a crest (h′ = 0) the head starts at rest. Quasi-statically F = F̄ − k_eff (h − h(x0)), with
  // the pantograph's static stiffness k_eq in series with the contact's k_s.
  const double a = 0.01, lambda = 60, ks = 1e6, v = 5;
  const catenary::WireProfileCatenary cat(sine(a, lambda, 0.5));
  analysis::CoupledOptions o;
  o.spans = 2;
  const auto r = analysis::simulate_coupled({{two_mass(), lambda / 4, penalty(ks)}}, cat, v, o);
  const double k_eff = k_eq * ks / (k_eq + ks);
  const auto& F = r.histories[0].columns.back();
  const auto [lo, hi] = min_max(F, F.size() / 2);  // the second span
  EXPECT_NEAR((hi - lo) / 2, k_eff * a, 0.01 * k_eff * a);
  // And sample by sample over the second span, against the wire height under the head.
  for (std::size_t i = F.size() / 2; i < F.size(); i += 50) {
    const double x = lambda / 4 + v * r.histories[0].t[i];
    const double expected = F0 / (1 + k_eq / ks) - k_eff * (a * std::sin(2 * pi * x / lambda) - a);
    EXPECT_NEAR(F[i], expected, 0.01 * k_eff * a) << "t = " << r.histories[0].t[i];
  }
  EXPECT_EQ(r.contacts[0].lost_samples, 0);
}

TEST(WireProfile, ContactLossIsReportedWhereTheWireDropsFasterThanTheHeadCanFollow) {
  // A 50 mm drop over 1 m at x = 100 m: at 40 m/s the wire drives the head down at ≈ 2 m/s and then
  // stops; the head, held up only by the pantograph's force, overshoots below the wire.
  catenary::WireProfile step;
  step.x = {0, 50, 99, 99.5, 100, 101, 150, 250};
  step.h = {0, 0, 0, -0.025, -0.05, -0.05, -0.05, -0.05};
  step.periodic = false;
  step.span = 50;
  const catenary::WireProfileCatenary cat(step);
  analysis::CoupledOptions o;
  o.t_end = 1.0;
  const auto fast = analysis::simulate_coupled({{two_mass(), 80.0, penalty(1e5)}}, cat, 40.0, o);
  EXPECT_GT(fast.contacts[0].lost_samples, 0);
  EXPECT_GT(fast.contacts[0].first_loss_x, 100.0);
  EXPECT_LT(fast.contacts[0].first_loss_x, 105.0);
  EXPECT_NEAR(fast.contacts[0].first_loss_t, (fast.contacts[0].first_loss_x - 80.0) / 40.0, 1e-9);
  EXPECT_EQ(*std::min_element(fast.histories[0].columns.back().begin(), fast.histories[0].columns.back().end()), 0.0);
  // Slowly, the head follows: no loss.
  o.t_end = 60.0;
  const auto slow = analysis::simulate_coupled({{two_mass(), 80.0, penalty(1e5)}}, cat, 0.5, o);
  EXPECT_EQ(slow.contacts[0].lost_samples, 0);
  // Leaving the table is an error with the time and the position, not an extrapolation.
  o.t_end = 20.0;
  try {
    analysis::simulate_coupled({{two_mass(), 80.0, penalty(1e5)}}, cat, 40.0, o);
    FAIL() << "expected the run to stop at the end of the profile";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("outside the wire profile"), std::string::npos) << e.what();
  }
}

TEST(Coupling, SeveralPantographsRunOnAProfileAndAreRefusedByAPointModel) {
  const double a = 0.003, lambda = 60, ks = 1e6, v = 5;
  const catenary::WireProfileCatenary profile(sine(a, lambda, 0.5));
  // Crest and trough: both start with h′ = 0; the quasi-static forces are in antiphase.
  const std::vector<catenary::PantographOnLine> train = {{two_mass(), lambda / 4, penalty(ks)},
                                                         {two_mass(), 3 * lambda / 4, penalty(ks)}};
  auto sys = profile.couple(train, v);
  ASSERT_EQ(sys->n_contacts(), 2);
  EXPECT_THROW(sys->contact(2), InvalidArgument);
  sys->equilibrate();
  std::vector<double> F[2], t[2];
  sys->advance(lambda / v, lambda / v / 200, {}, [&](const catenary::Sample& s) {
    F[s.contact.index].push_back(s.force);
    t[s.contact.index].push_back(s.t);
    EXPECT_NEAR(s.x_contact, train[static_cast<std::size_t>(s.contact.index)].x0 + v * s.t, 1e-9);
  });
  ASSERT_EQ(F[0].size(), F[1].size());
  const double k_eff = k_eq * ks / (k_eq + ks), Fs = F0 / (1 + k_eq / ks);
  for (std::size_t i = 0; i < F[0].size(); i += 20) {
    const double s = std::sin(2 * pi * (lambda / 4 + v * t[0][i]) / lambda);  // h(x2) = −h(x1)
    EXPECT_NEAR(F[0][i], Fs - k_eff * (a * s - a), 0.01 * k_eff * a);
    EXPECT_NEAR(F[1][i], Fs - k_eff * (-a * s + a), 0.01 * k_eff * a);
  }
  // The statistics of a sweep are per contact.
  analysis::RunOptions o;
  o.min_spans = 2, o.fixed_spans = true;
  const auto r = analysis::sweep(train, profile, {v}, o);
  ASSERT_EQ(r[0].contacts.size(), 2u);
  // Over a wavelength the crest-starter's mean is F̄ + k_eff a, the trough-starter's F̄ − k_eff a.
  EXPECT_NEAR(r[0].contacts[0].mean - r[0].contacts[1].mean, 2 * k_eff * a, 0.02 * k_eff * a);

  // A point model has no distance: two pantographs on the lumped catenary are refused.
  const catenary::Lumped lumped{catenary::LumpedCatenary{}};
  try {
    lumped.couple({{two_mass(), 0.0, {}}, {two_mass(), 0.0, {}}}, 50.0);
    FAIL() << "two pantographs on a point model";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("point model has no distance"), std::string::npos) << e.what();
  }
  // A rigid wire needs a penalty contact.
  EXPECT_THROW(profile.couple(two_mass(), catenary::Contact{}, v), ModelError);
}

TEST(WireProfile, EnergyBalanceIncludesTheWorkOfTheMovingWire) {
  // d/dt(T + Σ energy) = Σ power, with the profile contact's power −(F − kδ) ẏ_P − kδ ẏ_w.
  const catenary::WireProfileCatenary cat(sine(0.02, 30, 0.5));
  auto sys = cat.couple(two_mass(), penalty(2e5), 10.0);
  sys->equilibrate();
  const mbs::Model& m = sys->model(sys->contact(0));
  std::vector<double> t, E, P;
  solve::IntegratorOptions opt;
  opt.rtol = 1e-10, opt.atol = 1e-12;
  sys->advance(3.0, 1e-3, opt, [&](const catenary::Sample& s) {
    t.push_back(s.t);
    E.push_back(mbs::kinetic_energy(m, s.state) + mbs::stored_energy(m, s.t, s.state));
    P.push_back(mbs::element_power(m, s.t, s.state));
  });
  double W = 0, worst = 0, scale = 0;
  for (std::size_t i = 1; i < t.size(); ++i) {
    W += 0.5 * (P[i] + P[i - 1]) * (t[i] - t[i - 1]);
    worst = std::max(worst, std::abs(E[i] - E[0] - W));
    scale = std::max(scale, std::abs(W));
  }
  EXPECT_GT(scale, 0.1);  // the wire does work
  EXPECT_LT(worst, 1e-4 * scale);
}

TEST(WireProfileFile, ReadsHeightsOrACsvAndNamesTheLineOfAnError) {
  const auto dir = inerta::testing::temp_dir();
  const std::string csv = (dir / "inerta_heights.csv").string(), yaml = (dir / "inerta_profile.yaml").string();
  std::ofstream(csv) << "x,height\n0,0\n20,-0.02\n40,0\n";
  std::ofstream(yaml) << "type: wire_profile\nprofile:\n  file: inerta_heights.csv\n  periodic: true\n"
                         "contact: {type: penalty, stiffness: 1e5}\n";
  io::CatenaryFile f = io::load_catenary(yaml, {"profile.span=20"});
  EXPECT_EQ(f.catenary->span(), 20);
  EXPECT_EQ(f.catenary->point_model(), nullptr);  // no harmonic-balance fast path
  EXPECT_EQ(f.contact.kind, catenary::Contact::Kind::Penalty);
  EXPECT_THROW(io::load_catenary(yaml, {"catenary.kc0=5000"}), ModelError);  // a lumped key
  std::ofstream(yaml) << "type: wire_profile\nprofile:\n  heights: [[0, 0], [10, 0.01], [5, 0]]\n";
  try {
    io::load_catenary(yaml);
    FAIL();
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find(yaml + ":3:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("increase"), std::string::npos) << e.what();
  }
  std::ofstream(yaml) << "type: wire_profil\nprofile: {heights: [[0, 0], [10, 0]]}\n";
  EXPECT_THROW(io::load_catenary(yaml), ModelError);
  // The bundled profile loads and runs the HSX.
  const io::CatenaryFile bundled = io::load_catenary(inerta::testing::model_path("wire-profile.yaml"));
  EXPECT_EQ(bundled.catenary->span(), 60);
}

TEST(CatenaryConstructors, RejectNonPhysicalParametersWithATypedError) {
  EXPECT_THROW((catenary::Contact{catenary::Contact::Kind::Penalty, -1e5, 0}.validate()), InvalidArgument);
  EXPECT_THROW((catenary::Contact{catenary::Contact::Kind::Penalty, NAN, 0}.validate()), InvalidArgument);
  EXPECT_THROW((catenary::Contact{catenary::Contact::Kind::Penalty, 1e5, -1}.validate()), InvalidArgument);
  EXPECT_THROW(catenary::PenaltyContact("c", 0, {}, 1, {}, -1.0, 0.0, 0.0), InvalidArgument);
  catenary::LumpedCatenary p;
  p.m[0] = 0;
  EXPECT_THROW(catenary::Lumped{p}, InvalidArgument);
  p = {};
  p.k[0] = -7000;
  EXPECT_THROW(catenary::Lumped{p}, InvalidArgument);
  p = {};
  p.span = NAN;
  EXPECT_THROW(catenary::Lumped{p}, InvalidArgument);
  catenary::WireProfile w;
  w.x = {0, 10};
  w.h = {0, 0.1};  // periodic but does not close
  EXPECT_THROW(catenary::WireProfileCatenary{w}, InvalidArgument);
  w.periodic = false;  // not periodic: needs a span
  EXPECT_THROW(catenary::WireProfileCatenary{w}, InvalidArgument);
  w.span = 10;
  EXPECT_NO_THROW(catenary::WireProfileCatenary{w});
  // Coupling checks its arguments too.
  const catenary::WireProfileCatenary ok{w};
  EXPECT_THROW(ok.couple(two_mass(), penalty(1e5), 0.0), InvalidArgument);
  EXPECT_THROW(ok.couple(two_mass(), penalty(1e5), NAN), InvalidArgument);
  pantograph::Pantograph no_contact = two_mass();
  no_contact.contact_marker = -1;
  EXPECT_THROW(ok.couple(no_contact, penalty(1e5), 10.0), ModelError);
}

TEST(WireProfileFile, AnOpenPeriodicProfileOrAMissingSpanNamesTheLineAndKey) {
  const std::string yaml = (inerta::testing::temp_dir() / "inerta_profile_open.yaml").string();
  auto message = [&](const std::string& text) {
    std::ofstream(yaml) << text;
    try {
      io::load_catenary(yaml);
    } catch (const ModelError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string open = message("type: wire_profile\nprofile:\n  heights: [[0, 0], [10, 0.01]]\n");
  EXPECT_NE(open.find(yaml + ":3: 'heights': a periodic profile must end with its first height"), std::string::npos)
      << open;
  const std::string no_span = message("type: wire_profile\nprofile:\n  periodic: false\n  heights: [[0, 0], [10, 0.01]]\n");
  EXPECT_NE(no_span.find(yaml + ":3: 'span': missing"), std::string::npos) << no_span;
}
}  // namespace test_catenary_wire_profile
