#pragma once
// Reading helpers of the model-file parser (src/io/model_*.cpp): every problem becomes an
// inerta::ModelError "file:line: 'key': what is wrong; expected ...". Library constructors check
// physical values themselves (InvalidArgument); guard() turns their complaint into the same form,
// at the line of the key that the complaint names.
#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <string>
#include <vector>

#include "inerta/error.hpp"
#include "inerta/mbs/kinematics.hpp"
#include "inerta/mbs/time_function.hpp"

namespace inerta::io::detail {

class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}
  const std::string& file() const { return file_; }
  /// Where warning() puts its messages (the model's notes, printed by the CLI); none by default.
  void set_notes(std::vector<std::string>* notes) { notes_ = notes; }
  /// A warning "file:line: 'key': what" (nothing if no notes were set).
  void warning(const YAML::Node& at, const std::string& key, const std::string& what) const;

  /// "file:line: 'key': what" at node `at` (no line if it is undefined, no key if `key` is empty).
  [[noreturn]] void fail(const YAML::Node& at, const std::string& key, const std::string& what) const;
  /// An InvalidArgument from a constructor, at the key of `map` that its parameter names ("k" →
  /// map["k"], "angle0" → angle0 or angle0_deg, "points[2]" → map["points"][2]; the mapping itself
  /// if the file has no such key): "file:line: 'k': must be >= 0 (N/m), got -5 in <what>".
  [[noreturn]] void fail(const YAML::Node& map, const std::string& what, const InvalidArgument& e) const;

  /// Runs build() (which constructs library objects from values read out of `map`) and reports an
  /// InvalidArgument it throws with fail(map, what, e).
  template <class Build>
  decltype(auto) guard(const YAML::Node& map, const std::string& what, Build&& build) const {
    try {
      return build();
    } catch (const InvalidArgument& e) {
      fail(map, what, e);
    }
  }
  /// Same for a single value: any InvalidArgument is reported at `node` under `key`.
  template <class Build>
  decltype(auto) guard_value(const YAML::Node& node, const std::string& key, Build&& build) const {
    try {
      return build();
    } catch (const InvalidArgument& e) {
      fail(node, key, e.problem());
    }
  }

  /// `map` is a mapping whose keys are all in `allowed`, each given once; otherwise "unknown key in
  /// <what>; expected one of: <allowed>[; <hint>]".
  void keys(const YAML::Node& map, const std::string& what, std::initializer_list<const char*> allowed) const;
  void keys(const YAML::Node& map, const std::string& what, const std::vector<std::string>& allowed,
            const std::string& hint = {}) const;

  YAML::Node need(const YAML::Node& map, const char* key, const std::string& what) const;
  double number(const YAML::Node& n, const std::string& key) const;
  double number(const YAML::Node& map, const char* key, const std::string& what) const;
  double number_or(const YAML::Node& map, const char* key, double fallback) const;
  bool boolean(const YAML::Node& n, const std::string& key) const;
  std::string text(const YAML::Node& n, const std::string& key) const;
  std::string text(const YAML::Node& map, const char* key, const std::string& what) const;
  /// A list of finite numbers (ModelError at the item's line for .nan or .inf).
  mbs::Vec2 vec2(const YAML::Node& n, const std::string& key) const;
  mbs::Vec3 vec3(const YAML::Node& n, const std::string& key) const;
  mbs::Vec3 unit3(const YAML::Node& n, const std::string& key) const;  ///< non-zero, normalised
  /// Angle from `key` (rad) or `key_deg` (degrees), not both; `fallback` if neither is given.
  /// A value in rad above 2π in magnitude is a warning (degrees given as radians?).
  double angle(const YAML::Node& map, const std::string& key, double fallback) const;
  /// A path relative to the file's folder (as written if absolute, or if the file has no folder).
  std::string relative_path(const std::string& path) const;

 private:
  std::string file_;
  double finite_item(const YAML::Node& n, const std::string& key) const;
  std::vector<std::string>* notes_ = nullptr;
};

/// A time function (docs/model-format.md#time-functions): a number, or {type: constant|sine|table|
/// ramp|step|chirp|sum_of_sines|polynomial|road, ...}; its values are checked by TimeFunction's
/// factories. For a driving joint (`driving`) a function with corners (TimeFunction::smooth) is
/// refused unless the mapping says `accept_linear: true`.
mbs::TimeFunction time_function(const Reader& rd, const YAML::Node& n, const std::string& key, bool driving = false);

}  // namespace inerta::io::detail
