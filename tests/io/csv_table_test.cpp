// Numeric CSV input: every error names the file, the line and the column.
#include "inerta/io/csv_table.hpp"

#include <gtest/gtest.h>

#include "inerta/error.hpp"

// One namespace a file: a unity build compiles several test files as one unit.
namespace test_io_csv_table {

using namespace inerta;

namespace {
std::string error_of(const std::string& text, const std::string& column) {
  try {
    io::CsvTable::parse(text, "data.csv").column(column);
  } catch (const ModelError& e) {
    return e.what();
  }
  return "no error";
}
}  // namespace

TEST(CsvTable, ReadsColumnsSkippingCommentsAndBlankLines) {
  const auto t = io::CsvTable::parse("# comment\nv, force\n\n0.001,5520.5\n-2e-3 ,+5400\n", "data.csv");
  EXPECT_EQ(t.rows(), 2u);
  EXPECT_EQ(t.line(1), 5);
  EXPECT_EQ(t.column("v"), (std::vector<double>{0.001, -0.002}));
  EXPECT_EQ(t.column("force"), (std::vector<double>{5520.5, 5400}));
  EXPECT_TRUE(t.has("force"));
  EXPECT_FALSE(t.has("t"));
}

TEST(CsvTable, ErrorsNameFileLineAndColumn) {
  EXPECT_EQ(error_of("v,force\n1,2\n3,abc\n", "force"), "data.csv:3: column 'force': 'abc' is not a finite number");
  EXPECT_EQ(error_of("v,force\n1,nan\n", "force"), "data.csv:2: column 'force': 'nan' is not a finite number");
  EXPECT_EQ(error_of("v,force\n1,\n", "force"), "data.csv:2: column 'force': '' is not a finite number");
  EXPECT_EQ(error_of("v,force\n1,2\n", "t"), "data.csv: missing column 't'; the header has: v, force");
  EXPECT_EQ(error_of("v,force\n1,2\n3\n", "v"), "data.csv:3: 1 field(s), but the header has 2 column(s)");
  EXPECT_EQ(error_of("", "v"), "data.csv: empty file; expected a header row and data rows");
  EXPECT_EQ(error_of("v,v\n", "v"), "data.csv:1: header: column 'v' appears twice");
  EXPECT_EQ(error_of("v,force\n1,2\n", "v"), "no error");  // the helper's control: a good column passes
}

TEST(CsvTable, RequireRows) {
  const auto t = io::CsvTable::parse("v,force\n1,2\n", "data.csv");
  EXPECT_NO_THROW(t.require_rows(1, "x"));
  try {
    t.require_rows(4, "the fit");
    FAIL() << "no error";
  } catch (const ModelError& e) {
    EXPECT_EQ(std::string(e.what()), "data.csv: 1 data row(s); the fit needs at least 4");
  }
}
}  // namespace test_io_csv_table
