#pragma once
// Joint types of model files (docs/model-format.md#joints), one registry per dimension.
#include <Eigen/Dense>
#include <string>

#include "element_registry.hpp"
#include "model_loader.hpp"

namespace inerta::io::detail {

/// What a joint builder reads and fills in: the joint's mapping (keys already checked), its
/// description "joint '<name>'", the tabulated coordinates (joint data that refer to the initial
/// pose are taken from them) and the joint to complete (name set).
struct JointSite {
  Loader& ld;
  const YAML::Node& node;
  const std::string& what;
  const Eigen::VectorXd& q_tabulated;
  mbs::Joint& joint;
};
using JointBuilder = void (*)(const JointSite&);
using JointRegistry = ElementRegistry<JointBuilder>;

/// The joint types of planar (dimension 2) or spatial (dimension 3) models.
const JointRegistry& joint_types(bool spatial);

}  // namespace inerta::io::detail
