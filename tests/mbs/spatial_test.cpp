// Spatial engine (spec/01 §1.4–1.5): Euler-parameter kinematics and joint rows against finite
// differences, the inerter force against eq. 3.10, the 3D two-bar against the 2D one, a spinning
// constant-length inerter, and energy balance of conservative 3D systems.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "inerta/error.hpp"
#include "inerta/io/model_file.hpp"
#include "inerta/mbs/linearisation.hpp"
#include "inerta/mbs/struts.hpp"
#include "support/run.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_mbs_spatial {

using namespace inerta;
using namespace inerta::mbs;
using inerta::testing::run;

namespace {
std::mt19937 rng(7);
double uni(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
Vec3 rand3(double s) { return Vec3(uni(-s, s), uni(-s, s), uni(-s, s)); }

// A random spatial state of one body with pᵀp = 1, pᵀṗ = 0 and pᵀp̈ + ṗᵀṗ = 0, so that along
// q(τ) = q + q̇ τ + ½ q̈ τ² the normalisation holds to O(τ³) and finite differences are exact to O(τ).
struct BodyMotion {
  Vec7 q, qd, qdd;
};
BodyMotion random_motion() {
  BodyMotion m;
  Vec4 p = Vec4(uni(-1, 1), uni(-1, 1), uni(-1, 1), uni(-1, 1)).normalized();
  Vec4 pd = Vec4(uni(-1, 1), uni(-1, 1), uni(-1, 1), uni(-1, 1));
  pd -= p * p.dot(pd);
  Vec4 pdd = Vec4(uni(-1, 1), uni(-1, 1), uni(-1, 1), uni(-1, 1));
  pdd -= p * (p.dot(pdd) + pd.squaredNorm());
  m.q << rand3(1), p;
  m.qd << rand3(1), pd;
  m.qdd << rand3(1), pdd;
  return m;
}
Vec7 along(const BodyMotion& m, double tau) { return m.q + m.qd * tau + 0.5 * m.qdd * tau * tau; }
// Position of a body point from the rotation matrix alone (independent of G and the bias terms).
Vec3 position(const Vec7& q, const Vec3& u, bool point) {
  return (point ? Vec3(q.head<3>()) : Vec3::Zero()) + rotation(q.tail<4>()) * u;
}
}  // namespace

TEST(Spatial, RotationIsOrthonormalAndMatchesAxisAngle) {
  for (int trial = 0; trial < 10; ++trial) {
    const Vec3 axis = rand3(1).normalized();
    const double angle = uni(-3, 3);
    const Mat3 A = rotation(quaternion(axis, angle));
    EXPECT_LT((A * A.transpose() - Mat3::Identity()).norm(), 1e-14);
    EXPECT_NEAR(A.determinant(), 1.0, 1e-14);
    EXPECT_LT((A - Eigen::AngleAxisd(angle, axis).toRotationMatrix()).norm(), 1e-14);
  }
}

TEST(Spatial, PointAndDirectionKinematicsAgainstFiniteDifferences) {
  const double tau = 1e-4;
  for (int trial = 0; trial < 20; ++trial) {
    const BodyMotion m = random_motion();
    const Vec3 u = rand3(0.5);
    for (bool point : {true, false}) {
      const SpatialVector v = spatial_vector(SpatialFrame::of(m.q, m.qd), u, point);
      auto r_at = [&](double t) { return position(along(m, t), u, point); };
      const Vec3 rd_fd = (r_at(tau) - r_at(-tau)) / (2 * tau);
      const Vec3 rdd_fd = (r_at(tau) - 2 * r_at(0) + r_at(-tau)) / (tau * tau);
      EXPECT_LT((v.v - r_at(0)).norm(), 1e-14);
      EXPECT_LT((rd_fd - v.vd).norm(), 1e-7);
      EXPECT_LT((rd_fd - v.G_mul(m.qd)).norm(), 1e-7);  // ṙ = G q̇ (eq. 3.22)
      EXPECT_LT((rdd_fd - (v.G_mul(m.qdd) + v.bias)).norm(), 1e-4) << "r̈ = G q̈ + bias (eq. 3.25)";
      // Gᵀ x is the transpose of G q̇: x·(G q̇) = (Gᵀ x)·q̇ for random x, q̇.
      const Vec3 x = rand3(1);
      EXPECT_NEAR(x.dot(v.G_mul(m.qdd)), v.Gt(x).dot(m.qdd), 1e-13);
    }
  }
}

TEST(Spatial, StrutJacobianAndLddotAgainstFiniteDifferences) {
  const double tau = 1e-4, h = 1e-6;
  for (int trial = 0; trial < 20; ++trial) {
    BodyMotion mi = random_motion(), mj = random_motion();
    mj.q.head<3>() += Vec3(2, 0, 0);
    const Vec3 ui = rand3(0.5), uj = rand3(0.5);
    const StrutKinematics s = strut_kinematics(SpatialFrame::of(mi.q, mi.qd), ui, SpatialFrame::of(mj.q, mj.qd), uj);
    auto l_of = [&](const Vec7& qi, const Vec7& qj) {
      return (position(qj, uj, true) - position(qi, ui, true)).norm();
    };
    // J = ∂l/∂q on the tangent space of the normalisation: compare along random admissible directions.
    for (int k = 0; k < 5; ++k) {
      BodyMotion di = random_motion(), dj = random_motion();
      Vec7 dqi = di.qd, dqj = dj.qd;
      dqi.tail<4>() -= mi.q.tail<4>() * mi.q.tail<4>().dot(dqi.tail<4>());
      dqj.tail<4>() -= mj.q.tail<4>() * mj.q.tail<4>().dot(dqj.tail<4>());
      const double fd = (l_of(mi.q + h * dqi, mj.q + h * dqj) - l_of(mi.q - h * dqi, mj.q - h * dqj)) / (2 * h);
      EXPECT_NEAR(fd, s.J.head<7>().dot(dqi) + s.J.tail<7>().dot(dqj), 1e-8);
    }
    auto l_at = [&](double t) { return l_of(along(mi, t), along(mj, t)); };
    EXPECT_NEAR((l_at(tau) - l_at(-tau)) / (2 * tau), s.l_dot, 1e-7);
    const double ldd_fd = (l_at(tau) - 2 * l_at(0) + l_at(-tau)) / (tau * tau);
    const double ldd = s.J.head<7>().dot(mi.qdd) + s.J.tail<7>().dot(mj.qdd) + s.a_n_axial + s.centripetal;
    EXPECT_NEAR(ldd_fd, ldd, 2e-4) << "l̈ = J q̈ + ê·a_n + centripetal (eq. 3.20)";
    EXPECT_GE(s.centripetal, 0.0);
  }
}

TEST(Spatial, JointRowsAgainstFiniteDifferences) {
  // Every 3D joint type: Ċ = C_q q̇ + C_t and C̈ = C_q q̈ − γ along a random trajectory.
  const double tau = 1e-4;
  std::vector<Joint> joints;
  for (JointType type : {JointType::Spherical, JointType::Revolute, JointType::Prismatic, JointType::Fixed,
                         JointType::Driving, JointType::Distance}) {
    Joint jt;
    jt.type = type;
    jt.spatial = true;
    jt.body_i = 0, jt.body_j = 1;
    jt.p_i = rand3(0.5), jt.p_j = rand3(0.5);
    for (int k = 0; k < 3; ++k) jt.a_i[k] = rand3(1).normalized(), jt.a_j[k] = rand3(1).normalized();
    jt.component = 1;
    jt.motion = TimeFunction::sine(0.3, 0.7, 0.2, 0.0);
    jt.length0 = 1.0;
    joints.push_back(jt);
  }
  for (int trial = 0; trial < 5; ++trial) {
    BodyMotion mi = random_motion(), mj = random_motion();
    const double t0 = uni(0, 1);
    for (const Joint& jt : joints) {
      ConstraintRow3 rows[6], rp[6], rm[6];
      const int nr = evaluate_joint_3d(jt, t0, SpatialFrame::of(mi.q, mi.qd), SpatialFrame::of(mj.q, mj.qd), rows);
      ASSERT_EQ(nr, jt.rows());
      auto C_at = [&](double t, ConstraintRow3* out) {
        evaluate_joint_3d(jt, t0 + t, SpatialFrame::of(along(mi, t), Vec7::Zero()),
                          SpatialFrame::of(along(mj, t), Vec7::Zero()), out);
      };
      ConstraintRow3 r0[6];
      C_at(tau, rp);
      C_at(0, r0);
      C_at(-tau, rm);
      for (int r = 0; r < nr; ++r) {
        const double Cd_fd = (rp[r].C - rm[r].C) / (2 * tau);
        const double Cdd_fd = (rp[r].C - 2 * r0[r].C + rm[r].C) / (tau * tau);
        const double Cq_qd = rows[r].gi.dot(mi.qd) + rows[r].gj.dot(mj.qd);
        const double Cq_qdd = rows[r].gi.dot(mi.qdd) + rows[r].gj.dot(mj.qdd);
        EXPECT_NEAR(Cd_fd, Cq_qd + rows[r].Ct, 1e-7) << "joint type " << static_cast<int>(jt.type) << " row " << r;
        EXPECT_NEAR(Cdd_fd, Cq_qdd - rows[r].gamma, 3e-4) << "joint type " << static_cast<int>(jt.type) << " row " << r;
      }
    }
  }
}

namespace {
// Two free spatial bodies joined by an inerter (and a spring, so that q̈ is not trivial).
Model two_bodies_with_inerter(bool centripetal) {
  return io::parse_model(fmt::format(R"(
dimension: 3
options: {{gravity: [0, 0, -9.81], centripetal: {}}}
bodies:
  - {{name: a, mass: 2, inertia: [0.1, 0.2, 0.3], position: [0, 0, 0], markers: {{p: [0.2, -0.1, 0.3]}}}}
  - {{name: b, mass: 3, inertia: [0.3, 0.1, 0.25], position: [1, 0.5, -0.2], markers: {{q: [-0.1, 0.2, 0.1]}}}}
forces:
  - {{name: k, type: spring, markers: [a.cm, b.cm], k: 50, free_length: 0.5}}
  - {{name: b, type: inerter, markers: [a.p, b.q], b: 7}}
)",
                                     centripetal ? "true" : "false"),
                         "two_bodies.yaml");
}
}  // namespace

TEST(Spatial, InerterForceEqualsEq310FromTerminalKinematics) {
  for (bool corr : {true, false}) {
    const Model model = two_bodies_with_inerter(corr);
    const auto& inerter = static_cast<const Inerter&>(*model.forces[static_cast<std::size_t>(model.find_force("b"))]);
    const Vec3 ui = model.markers[static_cast<std::size_t>(model.find_marker("a.p"))].u3;
    const Vec3 uj = model.markers[static_cast<std::size_t>(model.find_marker("b.q"))].u3;
    Workspace ws(model);
    for (int trial = 0; trial < 10; ++trial) {
      BodyMotion m[2] = {random_motion(), random_motion()};
      m[1].q.head<3>() += Vec3(1.5, 0, 0);
      State x{Eigen::VectorXd(14), Eigen::VectorXd(14), {}};
      x.q << m[0].q, m[1].q;
      x.qd << m[0].qd, m[1].qd;
      accelerations(model, 0.0, x, ws);
      const double F = inerter.force(model, 0.0, x, ws);
      // Terminal kinematics r, ṙ, r̈ by finite differences of positions along q + q̇τ + ½q̈τ², q̈ the engine's.
      auto r_at = [&](double t) {
        const Eigen::VectorXd q = x.q + x.qd * t + 0.5 * ws.qdd * t * t;
        return Vec3(position(q.segment<7>(7), uj, true) - position(q.segment<7>(0), ui, true));
      };
      const double tau = 1e-4;
      const Vec3 r = r_at(0), rd = (r_at(tau) - r_at(-tau)) / (2 * tau),
                 rdd = (r_at(tau) - 2 * r + r_at(-tau)) / (tau * tau);
      // eq. 3.10 (and eq. 3.8 without the correction)
      const double l2 = r.squaredNorm(), l = std::sqrt(l2);
      const double F310 = 7 / l * (rdd.dot(r) + (corr ? rd.squaredNorm() - std::pow(rd.dot(r), 2) / l2 : 0.0));
      EXPECT_NEAR(F, F310, 2e-4 * (1 + std::abs(F310))) << "trial " << trial << " centripetal " << corr;
    }
  }
}

TEST(Spatial, SpinningConstantLengthInerterExertsNoForce) {
  // A bob on a spherical joint at the pivot, an inerter from the pivot to the bob: constant length.
  const Model model = io::load_model(inerta::testing::model_path("spherical_inerter.yaml"));
  const int pivot = model.find_force("b_pivot");
  State x = assemble(model, 0.0);
  Workspace ws(model);
  accelerations(model, 0.0, x, ws);
  const double F = model.forces[static_cast<std::size_t>(pivot)]->force(model, 0.0, x, ws);
  EXPECT_LT(std::abs(F), 1e-9);
  // Without the correction: F = b r̈·ê = −b |ṙ_⊥|²/l for a constant length (eq. 3.8 vs 3.9).
  Model off = model;
  off.options.centripetal = false;
  Workspace ws2(off);
  accelerations(off, 0.0, x, ws2);
  const double v2 = x.qd.head<3>().squaredNorm();  // the bob's centre moves perpendicular to the rod
  EXPECT_NEAR(off.forces[static_cast<std::size_t>(pivot)]->force(off, 0.0, x, ws2), -50 * v2 / 1.0, 1e-6 * 50 * v2);
  // And over a 3 s precessing run with the correction the force stays at integrator noise.
  auto s = run(model, 3.0, 0.01);
  double Fmax = 0;
  for (double f : s[3]) Fmax = std::max(Fmax, std::abs(f));
  EXPECT_LT(Fmax, 0.02) << "vs 50 kg × |ṙ|²/l ≈ 112 N without the correction";
}

TEST(Spatial, TwoBar3DReproducesThePlanarTwoBar) {
  for (bool corr : {true, false}) {
    Model m2 = io::load_model(inerta::testing::model_path("twobar.yaml"));
    Model m3 = io::load_model(inerta::testing::model_path("twobar3d.yaml"));
    m2.options.centripetal = m3.options.centripetal = corr;
    solve::IntegratorOptions opt;
    opt.rtol = 1e-9;
    opt.atol = 1e-11;
    auto s2 = run(m2, 20.0, 0.01, opt), s3 = run(m3, 20.0, 0.01, opt);
    ASSERT_EQ(s2.t.size(), s3.t.size());
    double err = 0, amp = 0, z = 0;
    for (std::size_t i = 0; i < s2.t.size(); ++i) {
      err = std::max({err, std::abs(s2[1][i] - s3[1][i]), std::abs(s2[0][i] - s3[0][i])});
      amp = std::max(amp, std::abs(s2[1][i] - s2[1][0]));
      z = std::max(z, std::abs(s3[2][i]));
    }
    EXPECT_GT(amp, 0.05);
    EXPECT_LT(err, 1e-6) << "max |C_3D − C_2D| over 20 s, centripetal " << corr;
    EXPECT_LT(z, 1e-12);
  }
}

namespace {
// Integrates and returns max over samples of |E(t) − E(0) − ∫P dt| / (scale of E).
double energy_error(const Model& model, double t_end) {
  State x = assemble(model, 0.0);
  auto energy = [&](double t, const State& s) { return kinetic_energy(model, s) + stored_energy(model, t, s); };
  const double E0 = energy(0, x);
  double work = 0, t_prev = 0, P_prev = element_power(model, 0, x), err = 0, scale = std::abs(E0);
  solve::IntegratorOptions opt;
  opt.rtol = 1e-10;
  opt.atol = 1e-12;
  solve::integrate(model, x, 0.0, t_end, 1e-3, opt, [&](double t, const State& s, const Workspace&) {
    const double P = element_power(model, t, s);
    work += 0.5 * (P + P_prev) * (t - t_prev);  // trapezoidal ∫P dt
    P_prev = P, t_prev = t;
    const double E = energy(t, s);
    scale = std::max(scale, std::abs(kinetic_energy(model, s)));
    err = std::max(err, std::abs(E - E0 - work));
  });
  return err / scale;
}
}  // namespace

TEST(Spatial, EnergyBalanceOfConservativeSystems) {
  // Spherical pendulum with two inerters under gravity: T + V + Σ ½ b l̇² is constant.
  const Model sph = io::load_model(inerta::testing::model_path("spherical_inerter.yaml"));
  EXPECT_LT(energy_error(sph, 5.0), 1e-6);
  // Out-of-plane two-bar without damper: spring, rotational spring, inerter, forcing (work ∫F·v dt).
  Model tb = io::load_model(inerta::testing::model_path("twobar3d_outofplane.yaml"));
  std::vector<std::shared_ptr<const ForceElement>> kept;
  for (const auto& f : tb.forces)
    if (f->name() != "c") kept.push_back(f);
  tb.forces = kept;
  EXPECT_LT(energy_error(tb, 5.0), 1e-5);
}

TEST(Spatial, OutOfPlaneMotionAndTheCorrectionMatter) {
  // With the out-of-plane force the strut turns in space; the textbook inerter (no correction) gives a
  // different response (spec/01 §1.1): check that C_z moves and the two models differ.
  Model on = io::load_model(inerta::testing::model_path("twobar3d_outofplane.yaml"));
  Model off = on;
  off.options.centripetal = false;
  auto a = run(on, 10.0, 0.01), b = run(off, 10.0, 0.01);
  double zmax = 0, diff = 0;
  for (std::size_t i = 0; i < a.t.size(); ++i)
    zmax = std::max(zmax, std::abs(a[2][i])), diff = std::max(diff, std::abs(a[1][i] - b[1][i]));
  EXPECT_GT(zmax, 0.05);
  EXPECT_GT(diff, 0.01);
}

TEST(Spatial, ModelFileErrors) {
  auto msg = [](const std::string& text) {
    try {
      io::parse_model(text, "bad.yaml");
    } catch (const ModelError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string head = "dimension: 3\nbodies:\n  - {name: a, mass: 1, inertia: [1, 1, 1], position: [0, 0, 0]";
  EXPECT_NE(msg("dimension: 4\nbodies: []\n").find("bad.yaml:1: 'dimension': expected 2 (planar) or 3"),
            std::string::npos);
  EXPECT_NE(msg("dimension: 3\nbodies:\n  - {name: a, mass: 1, inertia: [1, 1, 1], position: [0, 0]}\n")
                .find("bad.yaml:3: 'position': expected a list of three numbers"),
            std::string::npos);
  EXPECT_NE(msg("dimension: 3\nbodies:\n  - {name: a, mass: 1, inertia: [1, 1, 3], position: [0, 0, 0]}\n")
                .find("triangle inequality"),
            std::string::npos);
  EXPECT_NE(msg(head + ", quaternion: [1, 0, 0, 0.5]}\n").find("'quaternion': must be a unit quaternion"),
            std::string::npos);
  EXPECT_NE(msg(head + ", markers: {p: [1, 0, 0]}}\njoints:\n  - {name: j, type: revolute, markers: [ground.p, a.p]}\n")
                .find("unknown marker 'ground.p'"),
            std::string::npos);
  EXPECT_NE(msg(head + "}\nground: {markers: {p: [1, 0, 0]}}\njoints:\n  - {name: j, type: revolute, markers: "
                       "[ground.p, a.cm]}\n")
                .find("'axis': missing"),
            std::string::npos);
  EXPECT_NE(msg(head + "}\njoints:\n  - {name: j, type: hinge, bodies: [a, ground]}\n")
                .find("expected spherical, revolute, prismatic, fixed or driving"),
            std::string::npos);
  EXPECT_NE(msg(head + "}\nforces:\n  - {name: f, type: point_torque, body: a, axis: [0, 0, 0], value: 1}\n")
                .find("'axis': must be a non-zero vector"),
            std::string::npos);
  EXPECT_NE(msg("bodies:\n  - {name: a, mass: 1, inertia: 1, position: [0, 0]}\nforces:\n  - {name: f, type: "
                "point_torque, body: a, axis: [0, 0, 1], value: 1}\n")
                .find("point_torque is for 3D models"),
            std::string::npos);
  EXPECT_NE(msg(head + "}\n  - {name: b, mass: 1, inertia: [1, 1, 1], position: [1, 0, 0]}\nforces:\n  - {name: f, "
                       "type: actuator, markers: [a.cm, b.cm]}\n")
                .find("planar only"),
            std::string::npos);
}

TEST(Spatial, LinearisedTwoBar3DHasThePlanarModes) {
  // Linearisation works on the spatial coordinates (null space of C_q incl. the normalisation rows):
  // the 3D two-bar's modes are the 2D two-bar's.
  const Model m2 = io::load_model(inerta::testing::model_path("twobar.yaml"));
  const Model m3 = io::load_model(inerta::testing::model_path("twobar3d.yaml"));
  const auto modes2 = modes(m2, linearise(m2, assemble(m2, 0.0)));
  const auto modes3 = modes(m3, linearise(m3, assemble(m3, 0.0)));
  ASSERT_EQ(modes2.size(), modes3.size());
  ASSERT_GE(modes2.size(), 3u);
  for (std::size_t k = 0; k < modes2.size(); ++k) {
    EXPECT_NEAR(modes3[k].frequency_hz, modes2[k].frequency_hz, 1e-6 * modes2[k].frequency_hz);
    EXPECT_NEAR(modes3[k].damping_ratio, modes2[k].damping_ratio, 1e-6);
  }
}

TEST(Spatial, BlockSolveSatisfiesTheDenseSystem) {
  // accelerations() solves 3D models block by block with the inerters as extra Schur rows; the result
  // must satisfy the dense eq. 4.12 it replaces: (M + M_I) q̈ + C_qᵀ λ = Q and C_q q̈ = c (joint rows).
  for (const char* file : {"twobar3d.yaml", "twobar3d_outofplane.yaml", "spherical_inerter.yaml"}) {
    const Model model = io::load_model(inerta::testing::model_path(file));
    State x = assemble(model, 0.0);
    Workspace ws(model);
    for (int trial = 0; trial < 5; ++trial) {
      x.qd += Eigen::VectorXd::Random(x.qd.size()) * 0.5;  // any state: Baumgarte terms included
      accelerations(model, 0.3, x, ws);
      const int m = model.n_solved_rows();
      const Eigen::VectorXd r1 = ws.M * ws.qdd + ws.Cq.topRows(m).transpose() * ws.lambda - ws.Q;
      const Eigen::VectorXd r2 = ws.Cq.topRows(m) * ws.qdd - ws.c.head(m);
      EXPECT_LT(r1.norm(), 1e-9 * (1 + ws.Q.norm())) << file;
      EXPECT_LT(r2.norm(), 1e-9 * (1 + ws.c.norm())) << file;
      EXPECT_TRUE(ws.qdd.allFinite());
    }
  }
}
}  // namespace test_mbs_spatial
