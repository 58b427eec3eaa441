// The lumped catenary (spec/05 §5.1) and its coupling to a pantograph (spec/05 §5.2).
#include "inerta/catenary/lumped.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "inerta/mbs/applied_forces.hpp"
#include "support/run.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_catenary_catenary {

using namespace inerta;
using namespace inerta::catenary;

namespace {
// The catenary alone, pushed up by a constant force F from t = 0 (released at its unloaded height).
mbs::Model wire_alone(const LumpedCatenary& cat, double F) {
  mbs::Model m;
  m.name = "wire";
  m.options.gravity = false;
  int b = add_catenary(m, cat, 50.0, 0.0, 5.0);
  m.forces.push_back(std::make_shared<mbs::PointForce>("F", b, mbs::Vec2::Zero(), mbs::Vec2(0, 1),
                                                       mbs::TimeFunction::constant(F)));
  mbs::Output y;
  y.name = "y";
  y.kind = mbs::Output::Kind::Coordinate;
  y.index = b;
  y.component = 1;
  m.outputs.push_back(y);
  m.finalize();
  return m;
}
}  // namespace

TEST(Catenary, StaticDeflectionAndNaturalFrequencyWithoutHarmonics) {
  LumpedCatenary cat;
  cat.k = {7000, 0, 0, 0};
  cat.c = {0, 0, 0, 0};
  const double F = 70;
  mbs::Model m = wire_alone(cat, F);
  // Static: F / k_c0.
  mbs::State x = mbs::assemble(m, 0.0);
  mbs::static_equilibrium(m, 0.0, x);
  EXPECT_NEAR(x.q[1] - 5.0, F / 7000, 1e-12);
  // Undamped free vibration about it after a step load: y(t) = F/k (1 − cos ω t).
  solve::IntegratorOptions opt;
  opt.rtol = 1e-10;
  opt.atol = 1e-13;
  auto s = inerta::testing::run(m, 10, 1e-3, opt);
  const double w = 2 * M_PI * cat.natural_frequency();
  EXPECT_NEAR(cat.natural_frequency(), std::sqrt(7000 / 177.3) / (2 * M_PI), 1e-12);
  EXPECT_NEAR(cat.natural_frequency(), 1.0, 0.01);  // ≈ 1 Hz (spec/05 §5.1)
  double err = 0;
  for (std::size_t i = 0; i < s.t.size(); ++i)
    err = std::max(err, std::abs(s[0][i] - 5.0 - F / 7000 * (1 - std::cos(w * s.t[i]))));
  EXPECT_LT(err, 1e-7);
}

TEST(Catenary, StiffnessIsMaximalAtTheMast) {
  LumpedCatenary cat;
  const double fp = 50.0 / cat.span;
  double kmax = 0, tmax = -1;
  for (int i = 0; i <= 1000; ++i) {
    double t = i / (1000 * fp), k = LumpedCatenary::harmonic(cat.k, fp, t);
    if (k > kmax) kmax = k, tmax = t;
  }
  EXPECT_NEAR(tmax, 0.0, 1e-12);
  EXPECT_NEAR(kmax, 7000 + 2100 + 350 + 140, 1e-9);
  EXPECT_LT(LumpedCatenary::harmonic(cat.k, fp, 0.5 / fp), 7000 - 1500);  // soft at mid-span
}

namespace {
// A minimal "pantograph": a head mass on a vertical slider pushed up by a constant force, its
// top point `head.top` touching the wire; the rig joint `contact` holds it when uncoupled.
const char* kMini = R"(
ground: {markers: {G: [0, 0]}}
bodies:
  - {name: head, mass: 10, inertia: 0.1, position: [0, 5], markers: {top: [0, 0.1]}}
joints:
  - {name: slide, type: prismatic, markers: [ground.G, head.cm], axis: [0, 1]}
  - {name: contact, type: driving, body: head, coordinate: y, motion: 0}
forces:
  - {name: lift, type: point_force, marker: head.cm, direction: [0, 1], value: 168.1}
  - {name: k, type: spring, markers: [ground.G, head.cm], k: 2000}
  - {name: c, type: damper, markers: [ground.G, head.cm], c: 40}
outputs:
  - {name: y_head, type: coordinate, body: head, component: y}
  - {name: F_contact, type: reaction, joint: contact, component: y, scale: -1}
)";

// The mini model as a pantograph: contact point head.top, rig joint `contact`.
pantograph::Pantograph on_rig(const mbs::Model& m) { return {m, m.find_marker("head.top"), m.find_joint("contact"), {}}; }

struct Stats {
  double mean, sd;
};
Stats stats(const inerta::testing::Series& s, std::size_t k, double t0) {
  double sum = 0, sq = 0;
  long n = 0;
  for (std::size_t i = 0; i < s.t.size(); ++i)
    if (s.t[i] >= t0) sum += s[k][i], sq += s[k][i] * s[k][i], ++n;
  double mean = sum / n;
  return {mean, std::sqrt(std::max(0.0, sq / n - mean * mean))};
}
}  // namespace

TEST(Coupling, StaticContactForceAndConstantForceWithoutHarmonics) {
  mbs::Model panto = io::parse_model(kMini, "mini.yaml");
  // Rig: the held head feels lift − weight = 168.1 − 98.1 = 70 N of contact force.
  {
    mbs::State x = mbs::assemble(panto, 0.0);
    mbs::static_equilibrium(panto, 0.0, x);
    mbs::Workspace ws(panto);
    mbs::accelerations(panto, 0.0, x, ws);
    EXPECT_NEAR(mbs::evaluate_output(panto.outputs[1], panto, 0.0, x, ws), 70.0, 1e-9);
  }
  LumpedCatenary flat;
  flat.k = {7000, 0, 0, 0};
  flat.c = {111, 0, 0, 0};
  for (auto kind : {Contact::Kind::Bilateral, Contact::Kind::Penalty}) {
    Contact contact;
    contact.kind = kind;
    mbs::Model m = couple_lumped(on_rig(panto), flat, contact, 180 / 3.6).model;
    ASSERT_EQ(m.outputs.back().name, "F_contact");
    ASSERT_EQ(m.find_joint("contact") >= 0, kind == Contact::Kind::Bilateral);
    mbs::State x = mbs::assemble(m, 0.0);
    mbs::static_equilibrium(m, 0.0, x);
    mbs::Workspace ws(m);
    mbs::accelerations(m, 0.0, x, ws);
    // Static contact force with a spring-supported head: lift − weight − k Δy with the uplift.
    const double F0 = mbs::evaluate_output(m.outputs.back(), m, 0.0, x, ws);
    // Head spring, wire and (penalty) contact spring in series share the 70 N preload.
    const double series = 2000.0 / 7000.0 + (kind == Contact::Kind::Penalty ? 2000.0 / contact.stiffness : 0.0);
    EXPECT_NEAR(F0, 70.0 / (1 + series), 1e-6);
    EXPECT_LT(ws.qdd.cwiseAbs().maxCoeff(), 1e-8);         // starts at rest: no jolt
    // Without harmonics nothing varies: the contact force stays at its static value.
    solve::IntegratorOptions opt;
    opt.method = solve::Method::Bdf;
    std::vector<double> F;
    solve::integrate(m, x, 0.0, 5.0, 0.01, opt, [&](double t, const mbs::State& s, const mbs::Workspace& w) {
      F.push_back(mbs::evaluate_output(m.outputs.back(), m, t, s, w));
    });
    for (double f : F) EXPECT_NEAR(f, F0, 1e-6);
  }
}

TEST(Coupling, PenaltyConvergesToBilateralAsContactStiffens) {
  mbs::Model panto = io::parse_model(kMini, "mini.yaml");
  LumpedCatenary cat;  // default harmonics
  auto sigma = [&](const Contact& c) {
    mbs::Model m = couple_lumped(on_rig(panto), cat, c, 180 / 3.6).model;
    mbs::State x = mbs::assemble(m, 0.0);
    mbs::static_equilibrium(m, 0.0, x);
    solve::IntegratorOptions opt;
    opt.method = solve::Method::Bdf;
    opt.rtol = 1e-8;
    opt.atol = 1e-10;
    inerta::testing::Series s;
    s.out.resize(1);
    solve::integrate(m, x, 0.0, 20.0, 0.002, opt, [&](double t, const mbs::State& xs, const mbs::Workspace& w) {
      s.t.push_back(t);
      s.out[0].push_back(mbs::evaluate_output(m.outputs.back(), m, t, xs, w));
    });
    EXPECT_GT(*std::min_element(s.out[0].begin(), s.out[0].end()), 0.0);  // never loses contact
    return stats(s, 0, 8.0).sd;
  };
  const double sd_bil = sigma(Contact{});
  EXPECT_GT(sd_bil, 1.0);
  double previous = INFINITY;
  for (double ks : {5e4, 5e5, 5e6}) {
    Contact pen{Contact::Kind::Penalty, ks, 0.0};
    const double d = std::abs(sigma(pen) - sd_bil) / sd_bil;
    EXPECT_LT(d, previous) << "k_s = " << ks;
    previous = d;
  }
  EXPECT_LT(previous, 0.01);
}
}  // namespace test_catenary_catenary
