#pragma once
// JSON output, one writer for every JSON file Inerta writes (nlohmann-json). Objects keep their
// insertion order; strings are escaped and written as UTF-8 (invalid bytes become U+FFFD); doubles
// are written in the shortest form that reads back to the same double; NaN and ±∞ become null
// (write a string such as "inf" where a file format needs them).
//
// Layout, for tables that stay readable in a diff: the top level one member per line, its direct
// members one element per line, deeper containers and containers of scalars only on one line —
// so a matrix stored as a list of rows (json_rows) is written one row per line:
//   {
//     "N": [
//       [1.0, 0.0],
//       [0.0, 1.0]
//     ]
//   }
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>

namespace inerta::io {

using Json = nlohmann::ordered_json;

/// A matrix as a list of its rows (a row vector: one row).
Json json_rows(const Eigen::MatrixXd& m);

/// The text of `value` in the layout above, ending with a newline.
std::string json_text(const Json& value);

/// Writes json_text(value) to `path` (created or replaced). Throws std::runtime_error
/// "cannot write 'path'" if the file cannot be written.
void write_json(const std::string& path, const Json& value);

}  // namespace inerta::io
