#pragma once
// YAML model files (docs/model-format.md). Every error names the file, line, key and what was
// expected, as an inerta::ModelError.
#include <string>

#include "inerta/mbs/model.hpp"

namespace inerta::io {

/// Reads and validates a model file. "initial" free lengths and angles are measured in the
/// assembled initial configuration (so the model is assembled once while loading).
mbs::Model load_model(const std::string& path);

/// Same, from text; `source` names the text in messages.
mbs::Model parse_model(const std::string& text, const std::string& source);

}  // namespace inerta::io
