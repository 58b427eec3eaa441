#pragma once
// `layouts: all` and `networks: {...}` of study files (docs/networks.md#study-files), shared by the
// J2 and model study readers.
#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>
#include <vector>

#include "inerta/network/enumeration.hpp"

namespace inerta::io {

/// If root's `layouts` is the word `all`: the enumeration options of root's `networks` map (which
/// must then name max_elements), else nullopt (and `networks` must be absent). ModelError with
/// file:line:key for a bad key or value.
std::optional<network::EnumerationOptions> read_all_layouts(const std::string& path, const YAML::Node& root);

/// root's `admittance`: a list of degrees 1 … 4 (each once), or empty if absent.
std::vector<int> read_admittance_degrees(const std::string& path, const YAML::Node& root);

}  // namespace inerta::io
