// The model-file registries (src/io/element_registry.hpp): every force-element, joint and output
// type is registered once with a builder and its keys, and the parser's messages list exactly
// what is registered.
#include "io/element_registry.hpp"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <string>

#include "inerta/error.hpp"
#include "inerta/io/model_file.hpp"
#include "io/model_forces.hpp"
#include "io/model_joints.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_io_element_registry {

namespace {

using inerta::ModelError;
using inerta::io::detail::force_element_types;
using inerta::io::detail::joint_types;

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

std::string error_of(const std::string& text) {
  try {
    inerta::io::parse_model(text, "reg.yaml");
  } catch (const ModelError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected a ModelError";
  return {};
}

// A pinned bar and a sliding block (as in model_file_test.cpp), ready for one force element.
const std::string kModel = R"(options: {gravity: false}
ground: {markers: {O: [0, 0], P: [2, 0]}}
bodies:
  - {name: bar, mass: 1, inertia: 0.1, position: [0.5, 0], markers: {a: [-0.5, 0], b: [0.5, 0]}}
  - {name: blk, mass: 2, inertia: 0.2, position: [2, 1]}
joints:
  - {name: pin, type: revolute, markers: [ground.O, bar.a]}
  - {name: slide, type: prismatic, markers: [ground.P, blk.cm], axis: [0, 1]}
)";

const std::vector<std::string> kForceTypes{"spring",
                                           "damper",
                                           "inerter",
                                           "axial_force",
                                           "network",
                                           "actuator",
                                           "rotational_spring",
                                           "rotational_damper",
                                           "rotational_spring_damper",
                                           "point_force",
                                           "point_torque"};

TEST(ElementRegistry, EveryForceTypeHasABuilderAndKeys) {
  const auto& reg = force_element_types();
  EXPECT_EQ(reg.kind(), "force element");
  std::vector<std::string> types;
  for (const auto& e : reg.entries()) {
    SCOPED_TRACE(e.type);
    types.push_back(e.type);
    EXPECT_NE(e.build, nullptr);
    EXPECT_FALSE(e.keys.empty());
    EXPECT_EQ(reg.find(e.type), &e);
    const std::set<std::string> unique(e.keys.begin(), e.keys.end());
    EXPECT_EQ(unique.size(), e.keys.size());
    EXPECT_FALSE(unique.count("name") || unique.count("type"));
  }
  EXPECT_EQ(types, kForceTypes);  // the documented types, in the documented order
  EXPECT_EQ(reg.find("gravity"), nullptr);  // switched in options, not a force element type
  EXPECT_EQ(reg.find("bungee"), nullptr);
}

TEST(ElementRegistry, EveryJointTypeHasABuilderAndKeys) {
  for (bool spatial : {false, true}) {
    SCOPED_TRACE(spatial ? "3D" : "2D");
    const auto& reg = joint_types(spatial);
    EXPECT_EQ(reg.kind(), "joint");
    for (const auto& e : reg.entries()) {
      EXPECT_NE(e.build, nullptr) << e.type;
      EXPECT_FALSE(e.keys.empty()) << e.type;
    }
    EXPECT_EQ(reg.type_list(), spatial ? "spherical, revolute, prismatic, fixed or driving"
                                       : "revolute, prismatic, fixed or driving");
  }
}

TEST(ElementRegistry, UnknownForceTypeListsEveryRegisteredType) {
  const std::string msg = error_of(kModel + "forces:\n  - {name: s, type: bungee, markers: [bar.b, blk.cm]}\n");
  EXPECT_TRUE(contains(msg, "reg.yaml:10: 'type': unknown force element type 'bungee'; expected ")) << msg;
  EXPECT_TRUE(contains(msg, force_element_types().type_list())) << msg;
  for (const std::string& t : kForceTypes) EXPECT_TRUE(contains(msg, t)) << t << " missing in: " << msg;
  EXPECT_TRUE(contains(msg, "point_force or point_torque")) << msg;
}

TEST(ElementRegistry, UnknownKeyOfEachForceTypeListsItsRegisteredKeys) {
  for (const auto& e : force_element_types().entries()) {
    SCOPED_TRACE(e.type);
    std::string accepted = "name, type";
    for (const std::string& k : e.keys) accepted += ", " + k;
    const std::string msg = error_of(kModel + "forces:\n  - name: x\n    type: " + e.type + "\n    bogus: 1\n");
    EXPECT_TRUE(contains(msg, "reg.yaml:12: 'bogus': unknown key in force element 'x'; expected one of: " + accepted))
        << msg;
  }
}

TEST(ElementRegistry, ProgrammingErrorsAreRefused) {
  using Registry = inerta::io::detail::ElementRegistry<void (*)()>;
  void (*build)() = [] {};
  Registry r("thing");
  r.add("a", {"k"}, build);
  EXPECT_THROW(r.add("a", {"k"}, build), std::logic_error);         // twice
  EXPECT_THROW(r.add("", {"k"}, build), std::logic_error);          // no name
  EXPECT_THROW(r.add("b", {"k"}, nullptr), std::logic_error);       // no builder
  EXPECT_THROW(r.add("c", {}, build), std::logic_error);            // no keys
  EXPECT_THROW(r.add("d", {"name"}, build), std::logic_error);      // implied key
  EXPECT_THROW(r.add("e", {"k", "k"}, build), std::logic_error);    // key twice
  r.add("f", {"k"}, build).add("g", {"k"}, build);
  EXPECT_EQ(r.type_list(), "a, f or g");
}

}  // namespace
}  // namespace test_io_element_registry
