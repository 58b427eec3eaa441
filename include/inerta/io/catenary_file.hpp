#pragma once
// Catenary files (docs/model-format.md#catenary-files): the catenary type and the contact law, with
// command-line overrides "catenary.kc0=5000", "contact.stiffness=1e5", "profile.span=60",
// "messenger.tension=17000".
//   type: lumped          (default) the lumped catenary of spec/05 §5.1: section `catenary:`
//   type: wire_profile    a rigid wire of prescribed heights: section `profile:` (catenary/wire_profile.hpp)
//   type: finite_element  messenger, contact wire, droppers, supports (catenary/fe_catenary.hpp): sections
//                         line, messenger, contact_wire, droppers, supports, registration, and optional
//                         mesh, damping, integration, section; the contact must be a penalty contact
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "inerta/catenary/catenary.hpp"
#include "inerta/catenary/fe_catenary.hpp"

namespace inerta::io {

struct CatenaryFile {
  std::string name;
  std::shared_ptr<const catenary::Catenary> catenary;
  catenary::Contact contact;
  /// type: finite_element: the data the catenary was made from (checked by FeCatenaryData::validate).
  std::optional<catenary::FeCatenaryData> fe;
  std::string path;                    ///< load_catenary: the file it was read from
  std::vector<std::string> overrides;  ///< and the overrides applied (to read it again elsewhere)
};

/// Reads a catenary file and applies `overrides` (each "section.key=value"; lumped: catenary.kc0..kc3,
/// mc0..mc3, cc0..cc3, span; wire profile: profile.span; finite element: every number of the file by
/// its section and key, e.g. messenger.tension, droppers.EA, droppers.presag[4], damping.rayleigh_mass,
/// integration.time_step, mesh.element_length, section.spans=4:7; all: contact.type=bilateral|penalty,
/// contact.stiffness, contact.damping). Errors are ModelError with file:line or the override text.
CatenaryFile load_catenary(const std::string& path, const std::vector<std::string>& overrides = {});

/// The same, everything checked, but without making a finite-element catenary (its form-finding and
/// factorisation): `catenary` is null for type finite_element, `fe` holds its data. For inspection
/// (`inerta check`).
CatenaryFile read_catenary_file(const std::string& path, const std::vector<std::string>& overrides = {});

/// The data of a finite-element catenary file (overrides applied, validated); ModelError if the
/// file is of another type.
catenary::FeCatenaryData read_fe_catenary_data(const std::string& path, const std::vector<std::string>& overrides = {});

}  // namespace inerta::io
