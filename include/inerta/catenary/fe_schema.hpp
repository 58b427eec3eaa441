#pragma once
// One declaration of every key of a finite-element line file (docs/model-format.md "Finite-element
// catenary"): its path, type, unit, range, default, a one-line doc and where its value lives in
// FeCatenaryData. The file reader, `--set`, FeCatenaryData::validate's range checks, `inerta check`
// and the key tables of docs/model-format.md all read it (a test compares the tables with it).
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "inerta/catenary/fe_data.hpp"
#include "inerta/error.hpp"

namespace inerta::catenary {

/// Where a value is: the tension section (−1: the line's own), the key's path (messenger.tension,
/// overlap.incoming), an index into its list (−1: none). Readers find the file's node from it.
struct FeLocation {
  int section = -1;
  std::string key;
  int index = -1;
};

/// An InvalidArgument about one key of a line's data, located (what() "finite-element catenary:
/// <section>: <key>[i]: <problem>").
struct FeKeyError : InvalidArgument {
  FeKeyError(FeLocation where, const std::string& problem);
  FeLocation at;
};

/// A CSV profile read by a key: its file, x (m) and one value column.
struct FeCsvRef {
  std::string* file;
  std::vector<double>* x;
  std::vector<double>* value;
  const char* column;  ///< the value column's name
};
/// The analysis section's first and last span.
struct FeSpanRef {
  int *first, *last;
};
using FeRef = std::variant<double*, int*, bool*, std::uint64_t*, std::vector<double>*, FeCatenaryData::Solver*, FeCsvRef,
                           FeSpanRef, std::vector<FeIrregularity::PointMass>*>;

struct FeKey {
  enum class Type { Number, Whole, Bool, Choice, Numbers, Csv, SpanRange, PointMasses };
  std::string path;          ///< <section>.<key>, e.g. messenger.tension, stitch.droppers.EA
  Type type;
  std::string unit;          ///< SI ("" for none)
  double min, max;           ///< the range (±inf: open-ended)
  bool min_open;             ///< min itself excluded
  bool required;             ///< in its section, when the section is given
  std::string default_text;  ///< its value when not given ("" if required)
  std::string doc;           ///< one line
  bool in_sections;          ///< a tension section may give its own value (tension_sections[k].<path>)
  FeRef (*ref)(FeCatenaryData&);
  std::string note = {};     ///< appended to a range error: why the range
  std::vector<std::string> choices = {};  ///< Choice: the values
  std::string section() const;  ///< the path before its last '.' (messenger, stitch.droppers)
  std::string name() const;     ///< the path's last part (tension, EA)
  std::string range_text() const;  ///< "> 0", "0 … 0.1", "any" (docs' tables, check)
  /// "" if v is in the range, else "must be > 0 (N), got -5" (without the note).
  std::string check(double v) const;
  /// Its value in d as text with its unit ("21000 N", "modal", "[5, 20] m", "none").
  std::string value_text(const FeCatenaryData& d) const;
};

/// Every key, in the order of docs/model-format.md.
const std::vector<FeKey>& fe_keys();
/// The key of a path (no index), or null.
const FeKey* find_fe_key(const std::string& path);

/// A top-level section of the file: required or not; `present` (stitch) records that the file gives it.
struct FeSection {
  std::string name;
  bool required;
  std::string doc;
  bool* (*present)(FeCatenaryData&) = nullptr;
};
const std::vector<FeSection>& fe_sections();

/// The range of every number key of d (FeCatenaryData::validate); FeKeyError for the first out of range.
void check_fe_ranges(const FeCatenaryData& d);

}  // namespace inerta::catenary
