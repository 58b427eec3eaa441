#include "inerta/io/csv_table.hpp"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "inerta/error.hpp"
#include "inerta/io/files.hpp"

namespace inerta::io {

namespace {

std::string trim(const std::string& s) {
  std::size_t a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
  return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> f;
  std::size_t start = 0;
  for (;;) {
    std::size_t comma = line.find(',', start);
    f.push_back(trim(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) return f;
    start = comma + 1;
  }
}

}  // namespace

CsvTable CsvTable::parse(const std::string& text, const std::string& source) {
  CsvTable t;
  t.source_ = source;
  // A UTF-8 byte-order mark (spreadsheet exports) is not part of the first column's name.
  std::istringstream in(text.starts_with("\xEF\xBB\xBF") ? text.substr(3) : text);
  int lineno = 0;
  for (std::string line; std::getline(in, line);) {
    ++lineno;
    const std::string s = trim(line);
    if (s.empty() || s[0] == '#') continue;
    std::vector<std::string> fields = split(s);
    if (t.names_.empty()) {
      for (std::size_t k = 0; k < fields.size(); ++k) {
        if (fields[k].empty())
          throw ModelError(
              fmt::format("{}:{}: header: column {} has no name; expected a header row of names, e.g. "
                          "f_hz,P_ay_re,P_ay_im",
                          source, lineno, k + 1));
        for (std::size_t j = 0; j < k; ++j)
          if (fields[j] == fields[k])
            throw ModelError(fmt::format("{}:{}: header: column '{}' appears twice", source, lineno, fields[k]));
      }
      t.names_ = std::move(fields);
      continue;
    }
    if (fields.size() != t.names_.size())
      throw ModelError(fmt::format("{}:{}: {} field(s), but the header has {} column(s)", source, lineno, fields.size(),
                                   t.names_.size()));
    t.cells_.push_back(std::move(fields));
    t.lines_.push_back(lineno);
  }
  if (t.names_.empty()) throw ModelError(fmt::format("{}: empty file; expected a header row and data rows", source));
  return t;
}

CsvTable CsvTable::read(const std::string& path) {
  return parse(read_input_text(path, "CSV file"), path);
}

bool CsvTable::has(const std::string& column) const {
  for (const auto& n : names_)
    if (n == column) return true;
  return false;
}

std::vector<double> CsvTable::column(const std::string& name) const {
  std::size_t c = names_.size();
  for (std::size_t k = 0; k < names_.size(); ++k)
    if (names_[k] == name) c = k;
  if (c == names_.size()) {
    std::string list;
    for (const auto& n : names_) list += (list.empty() ? "" : ", ") + n;
    throw ModelError(fmt::format("{}: missing column '{}'; the header has: {}", source_, name, list));
  }
  std::vector<double> v(cells_.size());
  for (std::size_t r = 0; r < cells_.size(); ++r) {
    const std::string& s = cells_[r][c];
    const char* end = s.data() + s.size();
    // A leading '+' is allowed, but only before a digit or '.': "+-1" is not a number (issue 15).
    const bool plus = s.size() > 1 && s[0] == '+' && (std::isdigit(static_cast<unsigned char>(s[1])) || s[1] == '.');
    const char* begin = s.data() + (plus ? 1 : 0);
    auto res = std::from_chars(begin, end, v[r]);
    if (s.empty() || res.ec != std::errc() || res.ptr != end || !std::isfinite(v[r]))
      throw ModelError(fmt::format("{}:{}: column '{}': '{}' is not a finite number", source_, lines_[r], name, s));
  }
  return v;
}

void CsvTable::require_rows(std::size_t n, const std::string& what) const {
  if (rows() < n) throw ModelError(fmt::format("{}: {} data row(s); {} needs at least {}", source_, rows(), what, n));
}

}  // namespace inerta::io
