// The kind of an input file from its top-level keys (io/file_kind.hpp).
#include "inerta/io/file_kind.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "inerta/io/yaml_errors.hpp"

namespace inerta::io {

FileKind file_kind(const std::string& path) {
  const YAML::Node root = yaml_load_file(path, "file");
  if (!root.IsMap())
    yaml_fail(path, root, "", "expected a mapping of sections (a model, lumped pantograph or catenary file)");
  auto has = [&](std::initializer_list<const char*> keys) {
    for (const char* k : keys)
      if (root[k].IsDefined()) return true;
    return false;
  };
  if (has({"lumped_pantograph"})) return FileKind::LumpedPantograph;
  if (has({"bodies", "joints", "forces", "outputs", "ground", "assembly", "pantograph", "dimension", "options"}))
    return FileKind::Model;
  if (has({"type", "profile", "line", "messenger", "contact_wire", "droppers"}) ||
      (root["catenary"].IsDefined() && root["catenary"].IsMap()))
    return FileKind::Catenary;
  std::string found;
  for (auto it = root.begin(); it != root.end(); ++it)
    found += (found.empty() ? "" : ", ") + (it->first.IsScalar() ? it->first.Scalar() : std::string("?"));
  if (has({"layouts", "speeds", "search"}) || (root["model"].IsDefined() && root["catenary"].IsDefined()))
    throw ModelError(fmt::format("{}: a study file (keys: {}); `inerta optimise` reads it — check takes a model, "
                                 "lumped pantograph or catenary file",
                                 path, found));
  throw ModelError(fmt::format("{}: not a file that Inerta reads: expected a model file (top-level 'bodies', "
                               "'joints', 'forces', ...), a lumped pantograph file ('lumped_pantograph') or a catenary "
                               "file ('type', 'catenary', 'profile', or the finite-element sections 'line', "
                               "'messenger', ...); found keys: {}",
                               path, found.empty() ? "none" : found));
}

}  // namespace inerta::io
