#pragma once
// Design-study files on any model (docs/studies.md): a model, the strut whose network is replaced,
// an objective (rms | hinf | peak), layouts and search options. A study file with `catenary:` is
// the pantograph J2 study of study_file.hpp.
#include <string>

#include "inerta/optim/model_study.hpp"

namespace inerta::io {

/// True if the study file has an `objective:` other than `j2` (a model study); false for a
/// pantograph J2 study. ModelError if the file cannot be read.
bool is_model_study(const std::string& path);

/// Reads a model study; paths in it are relative to the file. ModelError with file:line:key for
/// every bad key, value, input, output or layout; the baseline (the strut's own network) is
/// evaluated once, so an objective that cannot be computed fails here — unless `evaluate_baseline`
/// is false (the file read and checked only: the fuzz target, whose inputs' baselines would cost a
/// model's analysis each).
optim::ModelStudy load_model_study(const std::string& path, bool evaluate_baseline = true);

}  // namespace inerta::io
