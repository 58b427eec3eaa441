#pragma once
// The model-file parser's state while it reads one file (internal to src/io): the Reader that
// turns every problem into "file:line: 'key': ...", the model being built, and the lookups that
// the sections share. Each section is read in its own file (model_options.cpp, model_bodies.cpp,
// model_joints.cpp, model_forces.cpp, model_outputs.cpp, model_pantograph.cpp); model_file.cpp
// reads them in the order of docs/model-format.md#top-level.
#include <yaml-cpp/yaml.h>

#include <Eigen/Dense>
#include <string>
#include <utility>
#include <vector>

#include "inerta/mbs/model.hpp"
#include "inerta/pantograph/pantograph.hpp"
#include "model_reader.hpp"

namespace inerta::io::detail {

struct Loader {
  Reader rd;
  mbs::Model model;

  // Lookups (model_bodies.cpp). Each fails with file:line for an unknown name.
  int marker(const YAML::Node& n, const std::string& key) const;  ///< "body.point" → marker index
  int body(const YAML::Node& n, const std::string& key) const;    ///< body index, kGround for "ground"
  /// `markers: [i.P, j.P]` of a two-terminal item.
  std::pair<int, int> marker_pair(const YAML::Node& map, const std::string& what) const;
  const mbs::Marker& mk(int k) const { return model.markers[static_cast<std::size_t>(k)]; }
  /// Planar coordinates [x y θ] of body b in q (zeros for ground).
  mbs::Vec3 q_of(const Eigen::VectorXd& q, int b) const {
    return b < 0 ? mbs::Vec3::Zero() : mbs::Vec3(q.segment<3>(3 * b));
  }
  /// Every item of `list` is a mapping with a `name`, and the names are unique.
  void names_unique(const YAML::Node& list, const std::string& what) const;

  // Sections, in reading order.
  void options(const YAML::Node& n);                                // model_options.cpp
  void ground(const YAML::Node& n);                                 // model_bodies.cpp
  void bodies(const YAML::Node& n);                                 // model_bodies.cpp
  void joints(const YAML::Node& n);                                 // model_joints.cpp
  void assembly(const YAML::Node& n);                               // model_joints.cpp
  void forces(const YAML::Node& n, const Eigen::VectorXd& q_init);  // model_forces.cpp (after assembly)
  void outputs(const YAML::Node& n);                                // model_outputs.cpp
  /// The `pantograph:` section: the contact marker and rig joint indices (−1 where absent) and the
  /// aerodynamic uplift on the contact marker's body (model_pantograph.cpp).
  pantograph::Pantograph pantograph(const YAML::Node& n);
};

/// Whether an override NAME.KEY belongs to the model file: NAME a force element or body, or a joint
/// whose motion has KEY (or KEY = motion.…) (model_overrides.cpp).
bool names_model_item(const YAML::Node& root, const std::string& name, const std::string& key);

/// Applies "NAME.KEY=VALUE" overrides to the YAML tree before it is read (model_overrides.cpp).
void apply_overrides(YAML::Node& root, const std::vector<std::string>& overrides, const std::string& source);

}  // namespace inerta::io::detail
