#pragma once
// Catenary files (docs/model-format.md#catenary-files): the catenary type and the contact law, with
// command-line overrides "catenary.kc0=5000", "contact.stiffness=1e5", "profile.span=60".
//   type: lumped        (default) the lumped catenary of spec/05 §5.1: section `catenary:`
//   type: wire_profile  a rigid wire of prescribed heights: section `profile:` (catenary/wire_profile.hpp)
#include <memory>
#include <string>
#include <vector>

#include "inerta/catenary/catenary.hpp"

namespace inerta::io {

struct CatenaryFile {
  std::string name;
  std::shared_ptr<const catenary::Catenary> catenary;
  catenary::Contact contact;
};

/// Reads a catenary file and applies `overrides` (each "section.key=value"; lumped: catenary.kc0..kc3,
/// mc0..mc3, cc0..cc3, span; wire profile: profile.span; both: contact.type=bilateral|penalty,
/// contact.stiffness, contact.damping). Errors are ModelError with file:line or the override text.
CatenaryFile load_catenary(const std::string& path, const std::vector<std::string>& overrides = {});

}  // namespace inerta::io
