#pragma once
// A self-contained HTML report (issue 53): inline CSS and SVG, no script run and no network access;
// the verdict first, then sections of tables and figures, the provenance, and the numbers record
// (report/record.hpp) as an inert JSON block that `inerta verify-report` reads back.
#include <string>
#include <string_view>
#include <vector>

#include "inerta/report/provenance.hpp"
#include "inerta/report/record.hpp"

namespace inerta::report {

/// Text made safe inside HTML/SVG text and attributes (& < > " ').
std::string escape(std::string_view text);

struct Table {
  std::string id;                         ///< the <table id> (tests read tables by it); may be empty
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;  ///< plain text, escaped when written
  std::vector<std::string> row_class;     ///< per row: "pass", "fail", "na" or ""
};

class Document {
 public:
  explicit Document(std::string title);
  /// The verdict banner at the top: status "PASS", "FAIL", "NOT ASSESSED" (or any other word) and lines under it.
  void verdict(const std::string& status, const std::vector<std::string>& lines);
  void heading(const std::string& text);      ///< <h2>
  void paragraph(const std::string& text);    ///< escaped <p>
  void table(const Table& table);
  void figure(const std::string& svg, const std::string& caption);  ///< svg: trusted markup from this program
  void provenance(const Provenance& p);
  /// The whole page with `record` embedded (its provenance is p given above, if any).
  std::string html(const Record& record) const;

 private:
  std::string title_, banner_, body_;
};

}  // namespace inerta::report
