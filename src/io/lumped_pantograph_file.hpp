#pragma once
// Lumped n-mass pantograph files (docs/model-format.md#lumped-pantograph-files), internal to
// src/io: the model-file entry points (model_file.cpp) hand a file whose top level has
// `lumped_pantograph:` to these functions. Every error is "file:line: 'key': ...".
#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>
#include <vector>

#include "inerta/pantograph/lumped.hpp"

namespace inerta::io::detail {

/// The file's top level is a mapping with the key `lumped_pantograph`.
bool is_lumped_pantograph(const YAML::Node& root);
/// The data of the `lumped_pantograph:` section (after any overrides), checked.
pantograph::LumpedPantographData read_lumped_pantograph_data(const YAML::Node& root, const std::string& source);
/// The pantograph (pantograph::make_lumped_pantograph) with the file's name and options.
pantograph::Pantograph read_lumped_pantograph(const YAML::Node& root, const std::string& source);
/// Overrides "lumped_pantograph.KEY=VALUE" (KEY: static_uplift, masses[i], stiffness[i], damping[i],
/// aerodynamic.a|b|c) applied to the tree; ModelError "source: override '...': ..." otherwise.
void apply_lumped_overrides(YAML::Node& root, const std::vector<std::string>& overrides, const std::string& source);
/// The number at such a key (for identify's --fit), nullopt for an aerodynamic coefficient the
/// file leaves at its default 0.
std::optional<double> lumped_value(const YAML::Node& root, const std::string& source, const std::string& key);

}  // namespace inerta::io::detail
