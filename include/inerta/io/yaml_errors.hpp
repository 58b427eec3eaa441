#pragma once
// Small helpers shared by the YAML readers of catenary and study files: every error is a
// ModelError "file:line: 'key': what is wrong; expected ...".
#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <string>

#include "inerta/error.hpp"

namespace inerta::io {

[[noreturn]] inline void yaml_fail(const std::string& file, const YAML::Node& at, const std::string& key,
                                   const std::string& what) {
  std::string where = file;
  if (at.IsDefined() && at.Mark().line >= 0) where += fmt::format(":{}", at.Mark().line + 1);
  throw ModelError(fmt::format("{}: '{}': {}", where, key, what));
}

/// Reads a YAML file: ModelError "file: cannot open the <what>" or "file:line: YAML syntax error: …".
inline YAML::Node yaml_load_file(const std::string& path, const std::string& what) {
  try {
    return YAML::LoadFile(path);
  } catch (const YAML::BadFile&) {
    throw ModelError(fmt::format("{}: cannot open the {}", path, what));
  } catch (const YAML::ParserException& e) {
    throw ModelError(fmt::format("{}:{}: YAML syntax error: {}", path, e.mark.line + 1, e.msg));
  }
}

inline double yaml_number(const std::string& file, const YAML::Node& n, const std::string& key) {
  try {
    return n.as<double>();
  } catch (const YAML::Exception&) {
    yaml_fail(file, n, key, "expected a number");
  }
}

}  // namespace inerta::io
