#pragma once
// Study files (docs/model-format.md#study-files): a pantograph, a catenary with its variants, the
// speeds, the layouts and the search options of a structure-based suspension design (spec/07).
#include <string>

#include "inerta/optim/study.hpp"

namespace inerta::io {

/// Reads a study file; paths in it are relative to the file. ModelError with file:line:key.
/// `operating_lengths`: also the actuator's length at each catenary's static equilibrium
/// (Study::operating_length, optim::operating_lengths — what optimising needs; false: the file
/// read and checked only, without coupling anything: the fuzz target, docs/fuzzing.md).
optim::Study load_study(const std::string& path, bool operating_lengths = true);

}  // namespace inerta::io
