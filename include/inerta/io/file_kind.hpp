#pragma once
// What kind of Inerta input a YAML file is, from its top-level keys (for `inerta check`).
#include <string>

namespace inerta::io {

enum class FileKind {
  Model,             ///< a multibody model file: bodies, joints, forces, … (model_file.hpp)
  LumpedPantograph,  ///< a lumped n-mass pantograph: lumped_pantograph (model_file.hpp loads it too)
  Catenary,          ///< a catenary file: type, catenary, profile, or the finite-element sections (catenary_file.hpp)
};

/// The kind of the file at `path`. ModelError if it cannot be read, is not YAML, or has none of the
/// top-level keys of a known kind: the message lists what each kind starts with and the keys found
/// (a study file is named as such, with the command that reads it).
FileKind file_kind(const std::string& path);

}  // namespace inerta::io
