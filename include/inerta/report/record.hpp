#pragma once
// The numbers of a report, kept exactly (17 significant digits) in a JSON block of the HTML, with
// the provenance: what `inerta verify-report` re-runs and compares (docs/cli.md "Reports").
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "inerta/report/provenance.hpp"

namespace inerta::report {

struct Record {
  std::string command;  ///< sweep, simulate, check-reduction, optimise
  Provenance provenance;
  std::string verdict;  ///< PASS, FAIL, NOT ASSESSED or "" (no criteria)
  /// Every number the report shows, by a key naming it ("v=250 km/h/panto 1/f_std").
  std::vector<std::pair<std::string, double>> numbers;
  void add(std::string key, double value) { numbers.emplace_back(std::move(key), value); }
};

/// The record as JSON text (NaN and ±inf as strings; "</" escaped so it can sit in a <script> block).
std::string record_json(const Record& record);

/// The record embedded in a report's HTML text. ModelError naming `file` if there is none or it is damaged.
Record read_record(const std::string& html, const std::string& file);

/// A number that differs between two records, or is only in one (the other NaN, `missing` set).
struct Difference {
  std::string key;
  double reported = 0, now = 0;
  std::string missing;  ///< "" or "not in the re-run" / "not in the report"
};
/// Numbers of `b` compared with `a`'s, key by key: equal when bitwise equal or both NaN, or within
/// rtol relative (|a − b| ≤ rtol·max(|a|, |b|)).
std::vector<Difference> compare(const Record& a, const Record& b, double rtol = 0);

}  // namespace inerta::report
