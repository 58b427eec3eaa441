// Fuzz target: numeric CSV tables (io::CsvTable::parse, docs/cli.md#identify): parse, then ask for
// every column of the header and a missing one, and check the row count.
#include <exception>

#include "fuzz_common.hpp"
#include "inerta/io/csv_table.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    const auto table = inerta::io::CsvTable::parse(inerta::fuzz::as_text(data, size), "fuzz.csv");
    for (std::size_t r = 0; r < table.rows(); ++r) (void)table.line(r);
    for (const auto& name : table.names()) {
      try {
        (void)table.column(name);
      } catch (const std::exception&) {
      }
    }
    try {
      (void)table.column("no such column");
    } catch (const std::exception&) {
    }
    table.require_rows(2, "fuzzing");
  } catch (const std::exception&) {
  }
  return 0;
}
