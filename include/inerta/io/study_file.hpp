#pragma once
// Study files (docs/model-format.md#study-files): a pantograph, a catenary with its variants, the
// speeds, the layouts and the search options of a structure-based suspension design (spec/07).
#include <string>

#include "inerta/optim/study.hpp"

namespace inerta::io {

/// Reads a study file; paths in it are relative to the file. ModelError with file:line:key.
optim::Study load_study(const std::string& path);

}  // namespace inerta::io
