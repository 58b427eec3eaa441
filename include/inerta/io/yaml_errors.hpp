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

inline double yaml_number(const std::string& file, const YAML::Node& n, const std::string& key) {
  try {
    return n.as<double>();
  } catch (const YAML::Exception&) {
    yaml_fail(file, n, key, "expected a number");
  }
}

}  // namespace inerta::io
