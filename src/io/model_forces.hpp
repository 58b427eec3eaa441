#pragma once
// Force-element types of model files (docs/model-format.md#force-elements): the registry that
// maps each `type:` to its accepted keys and its builder.
#include <string>

#include "element_registry.hpp"
#include "inerta/mbs/state.hpp"
#include "model_loader.hpp"

namespace inerta::io::detail {

/// What a force-element builder reads and where it writes: the element's mapping (its keys
/// already checked against the registry), its name, its description "force element '<name>'" for
/// messages, the assembled initial configuration ("initial" free lengths and angles are measured
/// there; velocities zero) and the loader, whose model receives the element (or, for a rigid
/// network, a distance joint). The builder runs inside Reader::guard, so an InvalidArgument from
/// an element constructor becomes "file:line: '<key>': ... in force element '<name>'".
struct ForceSite {
  Loader& ld;
  const YAML::Node& node;
  const std::string& name;
  const std::string& what;
  const mbs::State& x0;
};
using ForceBuilder = void (*)(const ForceSite&);
using ForceRegistry = ElementRegistry<ForceBuilder>;

/// Every force-element type a model file accepts (gravity is not one: it is switched in options).
const ForceRegistry& force_element_types();

}  // namespace inerta::io::detail
