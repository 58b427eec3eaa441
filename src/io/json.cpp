#include "inerta/io/json.hpp"

#include "inerta/io/files.hpp"

namespace inerta::io {

namespace {

bool is_container(const Json& v) { return v.is_object() || v.is_array(); }

bool scalars_only(const Json& v) {
  for (const auto& e : v)
    if (is_container(e)) return false;
  return true;
}

// One scalar (or a key) as nlohmann writes it: escaped, shortest round-trip doubles.
std::string scalar_text(const Json& v) { return v.dump(-1, ' ', false, Json::error_handler_t::replace); }

void append(std::string& out, const Json& v, int depth) {
  if (!is_container(v)) {
    out += scalar_text(v);
    return;
  }
  const bool object = v.is_object();
  const char open = object ? '{' : '[', close = object ? '}' : ']';
  if (v.empty()) {
    out += open, out += close;
    return;
  }
  const bool one_line = depth >= 2 || (depth > 0 && scalars_only(v));
  const std::string indent(static_cast<std::size_t>(2 * (depth + 1)), ' ');
  out += open;
  bool first = true;
  for (auto it = v.begin(); it != v.end(); ++it) {
    if (!first) out += one_line ? ", " : ",";
    first = false;
    if (!one_line) out += '\n', out += indent;
    if (object) out += scalar_text(Json(it.key())), out += ": ";
    append(out, it.value(), depth + 1);
  }
  if (!one_line) out += '\n', out += std::string(static_cast<std::size_t>(2 * depth), ' ');
  out += close;
}

}  // namespace

Json json_rows(const Eigen::MatrixXd& m) {
  Json rows = Json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    Json row = Json::array();
    for (Eigen::Index j = 0; j < m.cols(); ++j) row.push_back(m(i, j));
    rows.push_back(std::move(row));
  }
  return rows;
}

std::string json_text(const Json& value) {
  std::string out;
  append(out, value, 0);
  return out + '\n';
}

void write_json(const std::string& path, const Json& value) { write_text_file(path, json_text(value)); }

}  // namespace inerta::io
