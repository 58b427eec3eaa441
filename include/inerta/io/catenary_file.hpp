#pragma once
// Catenary files (docs/model-format.md#catenary-files): the lumped catenary of spec/05 §5.1 and
// the contact law, with command-line overrides "catenary.kc0=5000", "contact.stiffness=1e5".
#include <string>
#include <vector>

#include "inerta/catenary/coupling.hpp"

namespace inerta::io {

struct CatenaryFile {
  catenary::LumpedCatenary catenary;
  catenary::Contact contact;
};

/// Reads a catenary file and applies `overrides` (each "section.key=value"; keys kc0..kc3,
/// mc0..mc3, cc0..cc3, span; contact.type=bilateral|penalty, contact.stiffness, contact.damping).
/// Errors are ModelError with file:line or the override text.
CatenaryFile load_catenary(const std::string& path, const std::vector<std::string>& overrides = {});

}  // namespace inerta::io
