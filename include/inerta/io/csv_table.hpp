#pragma once
// Numeric CSV input (measured data for `inerta identify`, docs/cli.md#identify): a header row of
// column names, then rows of numbers separated by commas. Blank lines and lines starting with '#'
// are skipped. Cells are converted when a column is asked for, so every error names the file, the
// line and the column: ModelError "file:line: column 'force': 'abc' is not a number".
#include <string>
#include <vector>

namespace inerta::io {

class CsvTable {
 public:
  /// Reads a file (ModelError if it cannot be opened, is empty or has ragged rows).
  static CsvTable read(const std::string& path);
  /// Same, from text; `source` names it in messages.
  static CsvTable parse(const std::string& text, const std::string& source);

  const std::string& source() const { return source_; }
  const std::vector<std::string>& names() const { return names_; }
  std::size_t rows() const { return cells_.size(); }
  /// File line (1-based) of data row r.
  int line(std::size_t r) const { return lines_[r]; }
  bool has(const std::string& column) const;
  /// The column as finite numbers; ModelError naming the file if it is missing (with the columns
  /// found) and file:line and the column for a cell that is not a finite number.
  std::vector<double> column(const std::string& name) const;
  /// ModelError "file: N data rows; <what> needs at least n" when rows() < n.
  void require_rows(std::size_t n, const std::string& what) const;

 private:
  std::string source_;
  std::vector<std::string> names_;
  std::vector<std::vector<std::string>> cells_;
  std::vector<int> lines_;
};

}  // namespace inerta::io
