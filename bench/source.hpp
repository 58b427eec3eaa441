#pragma once
// A path in the source tree (models/, studies/): what every benchmark loads.
#include <string>

inline std::string src(const std::string& rel) { return std::string(INERTA_SOURCE_DIR) + "/" + rel; }
