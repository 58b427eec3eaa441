#pragma once
// Small helpers shared by the YAML readers of catenary and study files: every error is a
// ModelError "file:line: 'key': what is wrong; expected ...".
#include <fmt/format.h>
#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <string>
#include <unordered_set>

#include "inerta/error.hpp"
#include "inerta/io/files.hpp"

namespace inerta::io {

[[noreturn]] inline void yaml_fail(const std::string& file, const YAML::Node& at, const std::string& key,
                                   const std::string& what) {
  std::string where = file;
  if (at.IsDefined() && at.Mark().line >= 0) where += fmt::format(":{}", at.Mark().line + 1);
  throw ModelError(fmt::format("{}: '{}': {}", where, key, what));
}

/// ModelError "file:line: 'key': duplicate key in SECTION; give each key once" for the first mapping (at
/// any depth) that holds a key twice (yaml-cpp keeps one of them silently). SECTION is the path of the
/// mapping (`contact_wire`, `bodies[2].markers`); a top-level key says "at the top level".
inline void check_unique_keys(const std::string& file, const YAML::Node& n, const std::string& section = "",
                              int depth = 0) {
  if (depth > 200) yaml_fail(file, n, section, "nested more than 200 levels deep");
  if (n.IsMap()) {
    std::unordered_set<std::string> seen;
    for (auto it = n.begin(); it != n.end(); ++it) {
      const std::string k = it->first.IsScalar() ? it->first.Scalar() : std::string();
      if (!k.empty() && !seen.insert(k).second)
        yaml_fail(file, it->first, k,
                  fmt::format("duplicate key {}; give each key once", section.empty() ? "at the top level" : "in " + section));
      check_unique_keys(file, it->second, section.empty() ? k : section + "." + k, depth + 1);
    }
  } else if (n.IsSequence()) {
    std::size_t i = 0;
    for (const auto& x : n) check_unique_keys(file, x, fmt::format("{}[{}]", section, i++), depth + 1);
  }
}

/// ModelError "file:line: YAML syntax error: …" of a parser error; nesting beyond the parser's depth
/// (yaml-cpp says "bad file") is named as such (issue 38).
[[noreturn]] inline void yaml_syntax_error(const std::string& file, const YAML::ParserException& e) {
  if (dynamic_cast<const YAML::DeepRecursion*>(&e))
    throw ModelError(fmt::format("{}:{}: YAML nested too deeply to read (lists or mappings within one another, "
                                 "thousands of levels); Inerta's files nest a few levels",
                                 file, e.mark.line + 1));
  throw ModelError(fmt::format("{}:{}: YAML syntax error: {}", file, e.mark.line + 1, e.msg));
}

/// Reads a YAML file: ModelError "file: cannot open the <what>" or "file:line: YAML syntax error: …".
inline YAML::Node yaml_load_file(const std::string& path, const std::string& what) {
  const std::string text = read_input_text(path, what);
  try {
    YAML::Node root = YAML::Load(text);
    check_unique_keys(path, root);
    return root;
  } catch (const YAML::ParserException& e) {
    yaml_syntax_error(path, e);
  }
}

/// true or false (yaml-cpp's spellings: true/false, yes/no, on/off).
inline bool yaml_bool(const std::string& file, const YAML::Node& n, const std::string& key) {
  try {
    if (n.IsScalar()) return n.as<bool>();
  } catch (const YAML::Exception&) {
  }
  yaml_fail(file, n, key, fmt::format("'{}': expected true or false", n.IsScalar() ? n.Scalar() : std::string("a list or map")));
}

/// A finite number (.nan and .inf are refused; a missing key is "missing; expected a number").
inline double yaml_number(const std::string& file, const YAML::Node& n, const std::string& key) {
  if (!n.IsDefined() || n.IsNull()) yaml_fail(file, n, key, "missing; expected a number");
  double v = 0;
  try {
    v = n.as<double>();
  } catch (const YAML::Exception&) {
    yaml_fail(file, n, key, fmt::format("'{}' is not a number", n.IsScalar() ? n.Scalar() : std::string("a list or map")));
  }
  if (!std::isfinite(v)) yaml_fail(file, n, key, fmt::format("{} is not a finite number", n.Scalar()));
  return v;
}

/// A finite number in [lo, hi]; `range` says the expected range and unit, e.g. "> 0 (m)".
inline double yaml_number_in(const std::string& file, const YAML::Node& n, const std::string& key, double lo, double hi,
                             const std::string& range) {
  const double v = yaml_number(file, n, key);
  if (!(v >= lo && v <= hi)) yaml_fail(file, n, key, fmt::format("{}; expected {}", n.Scalar(), range));
  return v;
}

/// A whole number in [lo, hi], range-checked before the cast (issue 15).
inline long yaml_integer(const std::string& file, const YAML::Node& n, const std::string& key, long lo, long hi) {
  const double v = yaml_number(file, n, key);
  if (v != std::floor(v)) yaml_fail(file, n, key, fmt::format("{} is not a whole number", n.Scalar()));
  if (!(v >= static_cast<double>(lo) && v <= static_cast<double>(hi)))
    yaml_fail(file, n, key, fmt::format("{}; expected a whole number from {} to {}", n.Scalar(), lo, hi));
  return static_cast<long>(v);
}

/// A whole number in [lo, hi] ("expected a whole number from lo to hi, got v": the study files' words).
inline int yaml_whole(const std::string& file, const YAML::Node& n, const std::string& key, int lo, int hi) {
  const double v = yaml_number(file, n, key);
  if (!(v >= lo && v <= hi) || v != std::floor(v))
    yaml_fail(file, n, key, fmt::format("expected a whole number from {} to {}, got {}", lo, hi, n.Scalar()));
  return static_cast<int>(v);
}

}  // namespace inerta::io
