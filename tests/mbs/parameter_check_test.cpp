// Constructors of bodies, force elements and time functions reject non-physical parameters
// (negative stiffness, damping or inertance, a zero direction, NaN, ±∞) with inerta::InvalidArgument
// naming the element, the parameter and the value (include/inerta/mbs/parameter_check.hpp); the
// limits that are physical (zero stiffness, massless bodies, a zero piston mass) are accepted.
#include "inerta/mbs/parameter_check.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "inerta/error.hpp"
#include "inerta/mbs/applied_forces.hpp"
#include "inerta/mbs/model.hpp"
#include "inerta/mbs/network_strut.hpp"
#include "inerta/mbs/struts.hpp"
#include "inerta/mbs/time_function.hpp"
#include "inerta/network/network.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_mbs_parameter_check {

namespace {

using inerta::InvalidArgument;
namespace mbs = inerta::mbs;
namespace network = inerta::network;
using mbs::Vec2;
using mbs::Vec3;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// The InvalidArgument that `make` must throw: its parameter, and a message that names the element
// and contains `part` (typically the value).
void expect_invalid(const std::function<void()>& make, const std::string& parameter, const std::string& element,
                    const std::string& part) {
  try {
    make();
  } catch (const InvalidArgument& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.parameter(), parameter) << what;
    EXPECT_NE(what.find(element), std::string::npos) << what << "\nwanted: " << element;
    EXPECT_NE(what.find(part), std::string::npos) << what << "\nwanted: " << part;
    EXPECT_NE(std::string(e.problem()).find(part), std::string::npos) << e.problem();
    return;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected inerta::InvalidArgument, got: " << e.what();
    return;
  }
  ADD_FAILURE() << "expected inerta::InvalidArgument for " << parameter << ", nothing was thrown";
}

const Vec2 kA(0.5, 0), kB(-0.5, 0);

network::Network spring_damper(double k, double c) {
  return network::simplify(network::assign(network::parse("k|c"), {{"k", k}, {"c", c}}));
}

TEST(ParameterCheck, MessageNamesElementParameterAndValue) {
  try {
    mbs::Spring("k1", -1, kA, 0, kB, -5, 1);
    FAIL() << "a negative stiffness must be refused";
  } catch (const InvalidArgument& e) {
    EXPECT_STREQ(e.what(), "spring 'k1': k: must be >= 0 (N/m), got -5");
    EXPECT_EQ(e.parameter(), "k");
    EXPECT_STREQ(e.problem(), "must be >= 0 (N/m), got -5");
  }
  // An InvalidArgument that is not about one parameter keeps its message as the problem.
  const InvalidArgument plain("unknown handle 7");
  EXPECT_EQ(plain.parameter(), "");
  EXPECT_STREQ(plain.problem(), "unknown handle 7");
}

TEST(ParameterCheck, SpringRejectsNegativeNaNAndInfiniteValues) {
  EXPECT_NO_THROW(mbs::Spring("k", -1, kA, 0, kB, 0.0, 0.0));  // zero stiffness and free length are physical
  expect_invalid([] { mbs::Spring("k", -1, kA, 0, kB, -1.0, 1.0); }, "k", "spring 'k'", "got -1");
  expect_invalid([] { mbs::Spring("k", -1, kA, 0, kB, kNaN, 1.0); }, "k", "spring 'k'", "got nan");
  expect_invalid([] { mbs::Spring("k", -1, kA, 0, kB, kInf, 1.0); }, "k", "spring 'k'", "got inf");
  expect_invalid([] { mbs::Spring("k", -1, kA, 0, kB, 100.0, -0.5); }, "free_length", "spring 'k'", "got -0.5");
  expect_invalid([] { mbs::Spring("k", -1, kA, 0, kB, 100.0, kNaN); }, "free_length", "spring 'k'", "got nan");
}

TEST(ParameterCheck, StrutNeedsTwoBodiesAndFiniteTerminals) {
  expect_invalid([] { mbs::Spring("k", 0, kA, 0, kB, 1.0, 1.0); }, "markers", "strut 'k'", "same body");
  expect_invalid([] { mbs::Damper("c", -1, kA, -1, kB, 1.0); }, "markers", "strut 'c'", "same body");
  expect_invalid([] { mbs::Damper("c", -1, Vec2(kNaN, 0), 0, kB, 1.0); }, "markers", "strut 'c'", "finite");
  expect_invalid([] { mbs::Damper("c", -1, kA, 0, Vec3(1, 0, 0), 1.0); }, "markers", "strut 'c'", "planar");
}

TEST(ParameterCheck, DamperInerterAndAxialForce) {
  EXPECT_NO_THROW(mbs::Damper("c", -1, kA, 0, kB, 0.0));
  expect_invalid([] { mbs::Damper("c", -1, kA, 0, kB, -2.0); }, "c", "damper 'c'", "got -2");
  expect_invalid([] { mbs::Damper("c", -1, kA, 0, kB, kNaN); }, "c", "damper 'c'", "got nan");
  EXPECT_NO_THROW(mbs::Inerter("b", -1, kA, 0, kB, 0.0));
  expect_invalid([] { mbs::Inerter("b", -1, kA, 0, kB, -3.0); }, "b", "inerter 'b'", "got -3");
  expect_invalid([] { mbs::Inerter("b", -1, kA, 0, kB, kNaN); }, "b", "inerter 'b'", "got nan");
  EXPECT_NO_THROW(mbs::AxialForce("F", -1, kA, 0, kB, -5374.0));  // pushing: any sign
  expect_invalid([] { mbs::AxialForce("F", -1, kA, 0, kB, kNaN); }, "force", "axial force 'F'", "got nan");
  expect_invalid([] { mbs::AxialForce("F", -1, kA, 0, kB, -kInf); }, "force", "axial force 'F'", "got -inf");
}

TEST(ParameterCheck, NetworkStrutNeedsARealisableNetworkAndFreeLength) {
  const network::Network net = spring_damper(100, 10);
  EXPECT_NO_THROW(mbs::NetworkStrut("s", -1, kA, 0, kB, net, 0.0));
  expect_invalid([&] { mbs::NetworkStrut("s", -1, kA, 0, kB, net, -1.0); }, "free_length", "network strut 's'",
                 "got -1");
  expect_invalid([&] { mbs::NetworkStrut("s", -1, kA, 0, kB, net, kNaN); }, "free_length", "network strut 's'",
                 "got nan");
  expect_invalid([] { mbs::NetworkStrut("s", -1, kA, 0, kB, spring_damper(0, 0), 1.0); }, "network",
                 "network strut 's'", "is open");
  expect_invalid([] { mbs::NetworkStrut("s", -1, kA, 0, kB, spring_damper(kInf, 1), 1.0); }, "network",
                 "network strut 's'", "is rigid");
  network::Network negative = net;  // built by hand, past assign()'s check
  negative.children[0].value = -100;
  expect_invalid([&] { mbs::NetworkStrut("s", -1, kA, 0, kB, negative, 1.0); }, "params", "network strut 's'",
                 "'k' = -100");
}

TEST(ParameterCheck, ActuatorParameters) {
  const network::Network net = spring_damper(141e3, 10.44e3);
  auto make = [&](mbs::Actuator::Params p, int rod_body = 0) {
    return [=] { mbs::Actuator("a", -1, kA, rod_body, kB, net, 1.0, p); };
  };
  mbs::Actuator::Params p;
  EXPECT_NO_THROW(make(p)());  // the defaults: no piston mass, no friction
  p.constant_force = -5374, p.piston_mass = 3.45, p.friction = 20;
  EXPECT_NO_THROW(make(p)());
  mbs::Actuator::Params bad = p;
  bad.piston_mass = -1;
  expect_invalid(make(bad), "piston_mass", "actuator 'a'", "got -1");
  bad = p, bad.piston_mass = kNaN;
  expect_invalid(make(bad), "piston_mass", "actuator 'a'", "got nan");
  bad = p, bad.friction = -3;
  expect_invalid(make(bad), "friction", "actuator 'a'", "got -3");
  bad = p, bad.friction_velocity = 0;  // the tanh regularisation divides by it
  expect_invalid(make(bad), "friction_velocity", "actuator 'a'", "must be > 0 (m/s), got 0");
  bad = p, bad.constant_force = kInf;
  expect_invalid(make(bad), "constant_force", "actuator 'a'", "got inf");
  expect_invalid(make(p, -1), "markers", "strut 'a'", "same body");  // cylinder and rod end both on ground
  mbs::Actuator::Params on_ground = p;
  expect_invalid([&] { mbs::Actuator("a", 0, kA, -1, kB, net, 1.0, on_ground); }, "piston_mass", "actuator 'a'",
                 "rod end");
  on_ground.piston_mass = 0;
  EXPECT_NO_THROW(mbs::Actuator("a", 0, kA, -1, kB, net, 1.0, on_ground));
}

TEST(ParameterCheck, RotationalSpringDamper) {
  EXPECT_NO_THROW(mbs::RotationalSpringDamper("r", -1, 0, 0.0, 0.0, 0.0));
  expect_invalid([] { mbs::RotationalSpringDamper("r", -1, 0, -10.0, 0.0, 1.0); }, "k", "rotational spring-damper 'r'",
                 "got -10");
  expect_invalid([] { mbs::RotationalSpringDamper("r", -1, 0, 10.0, 0.0, -1.0); }, "c", "rotational spring-damper 'r'",
                 "got -1");
  expect_invalid([] { mbs::RotationalSpringDamper("r", -1, 0, 10.0, kNaN, 1.0); }, "angle0",
                 "rotational spring-damper 'r'", "got nan");
  mbs::RotationalSpringDamper::Spatial sp;
  sp.h_i = Vec3::Zero();
  expect_invalid([&] { mbs::RotationalSpringDamper("r", -1, 0, 10.0, 0.0, 1.0, sp); }, "joint",
                 "rotational spring-damper 'r'", "non-zero");
}

TEST(ParameterCheck, PointForceTorqueAndGravity) {
  const auto f = mbs::TimeFunction::constant(5);
  EXPECT_NO_THROW(mbs::PointForce("F", 0, kA, Vec2(0, 2), f));
  expect_invalid([&] { mbs::PointForce("F", 0, kA, Vec2::Zero(), f); }, "direction", "point force 'F'", "non-zero");
  expect_invalid([&] { mbs::PointForce("F", 0, kA, Vec2(kNaN, 1), f); }, "direction", "point force 'F'", "finite");
  expect_invalid([&] { mbs::PointForce("F", 0, Vec3(0, 0, 0), Vec3::Zero(), f, std::true_type{}); }, "direction",
                 "point force 'F'", "non-zero");
  mbs::TimeFunction hand_made;  // assembled by hand: checked by the element
  hand_made.kind = mbs::TimeFunction::Kind::Sine;
  hand_made.amplitude = 1, hand_made.frequency = -2;
  expect_invalid([&] { mbs::PointForce("F", 0, kA, Vec2(0, 1), hand_made); }, "value", "point force 'F'",
                 "frequency: must be >= 0 (Hz), got -2");
  expect_invalid([&] { mbs::PointTorque("T", 0, Vec3::Zero(), f); }, "axis", "point torque 'T'", "non-zero");
  expect_invalid([&] { mbs::PointTorque("T", 0, Vec3(0, 0, 1), hand_made); }, "value", "point torque 'T'",
                 "frequency");
  EXPECT_NO_THROW(mbs::Gravity(Vec2(0, -9.81)));
  expect_invalid([] { mbs::Gravity(Vec2(0, kNaN)); }, "g", "gravity", "finite");
  expect_invalid([] { mbs::Gravity(Vec3(0, -kInf, 0)); }, "g", "gravity", "finite");
}

TEST(ParameterCheck, TimeFunctions) {
  EXPECT_NO_THROW(mbs::TimeFunction::sine(1, 0));  // a zero frequency is a constant
  expect_invalid([] { mbs::TimeFunction::constant(kNaN); }, "value", "constant function", "got nan");
  expect_invalid([] { mbs::TimeFunction::sine(1, -1); }, "frequency", "sine function", "got -1");
  expect_invalid([] { mbs::TimeFunction::sine(kInf, 1); }, "amplitude", "sine function", "got inf");
  expect_invalid([] { mbs::TimeFunction::sine(1, 1, kNaN); }, "phase", "sine function", "got nan");
  expect_invalid([] { mbs::TimeFunction::sine(1, 1, 0, kNaN); }, "offset", "sine function", "got nan");
  EXPECT_NO_THROW(mbs::TimeFunction::table({0}, {1}));
  expect_invalid([] { mbs::TimeFunction::table({}, {}); }, "points", "table function", "at least one");
  expect_invalid([] { mbs::TimeFunction::table({0, 1}, {1}); }, "points", "table function", "2 times but 1 values");
  expect_invalid([] { mbs::TimeFunction::table({0, 1, 1}, {0, 2, 3}); }, "points[2]", "table function",
                 "times must be strictly increasing (t = 1 after t = 1)");
  expect_invalid([] { mbs::TimeFunction::table({0, 1}, {0, kNaN}); }, "points[1]", "table function", "got nan");
}

mbs::Body body(double mass, double inertia, const char* name = "b") {
  return mbs::Body{.name = name, .mass = mass, .inertia = inertia};
}

TEST(ParameterCheck, BodyMassInertiaAndInitialState) {
  EXPECT_NO_THROW(body(0, 0).validate());  // massless bodies are allowed where the joints constrain them
  expect_invalid([] { body(-1, 1).validate(); }, "mass", "body 'b'", "must be >= 0 (got -1)");
  expect_invalid([] { body(kNaN, 1).validate(); }, "mass", "body 'b'", "got nan");
  expect_invalid([] { body(1, -0.5).validate(); }, "inertia", "body 'b'", "must be >= 0 (got -0.5)");
  expect_invalid([] { body(1, kInf).validate(); }, "inertia", "body 'b'", "got inf");
  expect_invalid(
      [] {
        mbs::Body b = body(1, 0);
        b.q0.x() = kNaN;
        b.validate();
      },
      "position", "body 'b'", "finite");
  expect_invalid(
      [] {
        mbs::Body b = body(1, 0);
        b.qd0.z() = kInf;
        b.validate();
      },
      "angular_velocity", "body 'b'", "got inf");
  // 3D inertia tensors: symmetric, positive semi-definite, I1 + I2 >= I3.
  mbs::Body b3 = body(1, 0);
  b3.inertia3 = Vec3(1, 1, 1.5).asDiagonal();
  EXPECT_NO_THROW(b3.validate());
  b3.inertia3 = Vec3(1, 1, 3).asDiagonal();
  expect_invalid([&] { b3.validate(); }, "inertia", "body 'b'", "triangle inequality");
  b3.inertia3 = Vec3(1, 1, 1).asDiagonal();
  b3.inertia3(0, 1) = 0.1;
  expect_invalid([&] { b3.validate(); }, "inertia", "body 'b'", "symmetric");
  b3.inertia3 = Vec3(-1, 1, 1).asDiagonal();
  expect_invalid([&] { b3.validate(); }, "inertia", "body 'b'", "positive semi-definite");
}

TEST(ParameterCheck, ModelFinalizeChecksEveryBody) {
  mbs::Model m;
  m.bodies.push_back(body(1, 0.1));
  EXPECT_NO_THROW(m.finalize());
  m.bodies.push_back(body(-2, 0.1, "heavy"));
  expect_invalid([&] { m.finalize(); }, "mass", "body 'heavy'", "got -2");
}

}  // namespace
}  // namespace test_mbs_parameter_check
