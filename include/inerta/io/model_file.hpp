#pragma once
// YAML model files (docs/model-format.md). Every error names the file, line, key and what was
// expected, as an inerta::ModelError.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "inerta/mbs/model.hpp"
#include "inerta/pantograph/lumped.hpp"
#include "inerta/pantograph/pantograph.hpp"

namespace inerta::io {

/// Reads and validates a model file. "initial" free lengths and angles are measured in the
/// assembled initial configuration (so the model is assembled once while loading).
/// `overrides` ("NAME.KEY=VALUE", docs/model-format.md#overrides) replace numbers in the file
/// before it is read: NAME is a force element, a body or a joint, KEY a numeric key of it (a dotted
/// path for nested keys, e.g. actuator.params.k; a joint's motion keys directly, drive.speed; a list
/// item as KEY[i]); e.g. c2.c=70, kf_cf.k=700, head.mass=5.5. An override that matches nothing is
/// a ModelError naming it.
mbs::Model load_model(const std::string& path, const std::vector<std::string>& overrides = {});

/// Same, from text; `source` names the text in messages.
mbs::Model parse_model(const std::string& text, const std::string& source,
                       const std::vector<std::string>& overrides = {});

/// A pantograph: the model and its `pantograph:` section (contact marker, rig joint). ModelError
/// if the file has no such section.
pantograph::Pantograph load_pantograph(const std::string& path, const std::vector<std::string>& overrides = {});
/// The model and its `pantograph:` section if it has one (contact_marker = rig_joint = −1 otherwise).
pantograph::Pantograph load_model_file(const std::string& path, const std::vector<std::string>& overrides = {});
pantograph::Pantograph parse_model_file(const std::string& text, const std::string& source,
                                        const std::vector<std::string>& overrides = {});
pantograph::Pantograph parse_pantograph(const std::string& text, const std::string& source,
                                        const std::vector<std::string>& overrides = {});

/// A file whose top level has `lumped_pantograph:` is a lumped n-mass pantograph
/// (docs/model-format.md#lumped-pantograph-files): every function above reads it
/// (pantograph::make_lumped_pantograph), with overrides "lumped_pantograph.KEY=VALUE" (static_uplift,
/// masses[i], stiffness[i], damping[i], aerodynamic.a|b|c). This gives its data; ModelError if
/// the file is not one.
pantograph::LumpedPantographData load_lumped_pantograph_data(const std::string& path,
                                                             const std::vector<std::string>& overrides = {});

/// Splits overrides between the model file at `path` (first: NAME is one of its force elements or
/// bodies, a joint whose motion has KEY, or `lumped_pantograph` in a lumped pantograph file) and a
/// catenary file (second: everything else), as the CLI's --set does when a command reads both.
std::pair<std::vector<std::string>, std::vector<std::string>> split_overrides(const std::string& path,
                                                                              const std::vector<std::string>& overrides);

/// The number at an override key ("c2.c", "kf_cf.k", "actuator.params.k") in model text, or
/// nullopt for a `params` value the file leaves to its layout's default. ModelError as for overrides.
std::optional<double> model_value(const std::string& text, const std::string& source, const std::string& key);

}  // namespace inerta::io
