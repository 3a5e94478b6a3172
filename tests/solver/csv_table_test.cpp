// The reader of the data tables (solver/common/csv_table.h): comments, header, named columns,
// numbers and "-" cells, and the messages for a malformed table, which must name the file, the
// line and row, and the column.
#include "flexure/solver/common/csv_table.h"

#include <gtest/gtest.h>

#include <string>

namespace flexure {
namespace {

constexpr const char* kTable =
    "# Title\n"
    "#   units: R dimensionless\n"
    "\n"
    "class, d ,R,K1,ok\n"
    "1A,16,0.8274,-,yes\n"
    "# a comment between rows\n"
    "2A,40,0.4323,0.2237,no\r\n";

// The message of the InvalidInput that `f` throws ("" if it throws none).
template <class F>
std::string message_of(F f) {
  try {
    f();
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

TEST(CsvTable, ReadsCommentsHeaderAndNamedCells) {
  const CsvTable t = CsvTable::parse(kTable, "data/example.csv");
  EXPECT_EQ(t.source(), "data/example.csv");
  ASSERT_EQ(t.comments().size(), 3u);
  EXPECT_EQ(t.comments()[0], "Title");
  EXPECT_EQ(t.comments()[1], "  units: R dimensionless");
  ASSERT_EQ(t.column_names().size(), 5u);
  EXPECT_EQ(t.column_names()[1], "d");  // trimmed
  EXPECT_TRUE(t.has_column("K1"));
  EXPECT_FALSE(t.has_column("K2"));
  ASSERT_EQ(t.row_count(), 2u);
  EXPECT_EQ(t.text(0, "class"), "1A");
  EXPECT_EQ(t.number(0, "d"), 16.0);
  EXPECT_EQ(t.integer(1, "d"), 40);
  EXPECT_EQ(t.number(0, "R"), 0.8274);  // the same double as the literal
  EXPECT_FALSE(t.optional_number(0, "K1").has_value());
  EXPECT_EQ(t.number_or(0, "K1", -1.0), -1.0);
  EXPECT_EQ(t.optional_number(1, "K1"), 0.2237);
  EXPECT_TRUE(t.yes_no(0, "ok"));
  EXPECT_FALSE(t.yes_no(1, "ok"));  // the CR of a CRLF line end is dropped
}

TEST(CsvTable, UnparsableValueNamesFileLineRowAndColumn) {
  const std::string text = "# t\nname,R\nlpp-a,0.8274\nlpp-b,O.8853\n";
  const CsvTable t = CsvTable::parse(text, "data/bad.csv");
  const std::string m = message_of([&] { t.number(1, "R"); });
  EXPECT_NE(m.find("data/bad.csv"), std::string::npos) << m;
  EXPECT_NE(m.find("line 4"), std::string::npos) << m;
  EXPECT_NE(m.find("row 2"), std::string::npos) << m;
  EXPECT_NE(m.find("column 'R'"), std::string::npos) << m;
  EXPECT_NE(m.find("'O.8853' is not a finite number"), std::string::npos) << m;
  // Trailing characters, an empty cell, "-" where a number is required, non-finite values.
  for (const char* cell : {"0.8274x", "", "-", "inf", "nan", "1e999"}) {
    const CsvTable u = CsvTable::parse(std::string("R,K1\n") + cell + ",1\n", "data/u.csv");
    EXPECT_NE(message_of([&] { u.number(0, "R"); }).find("data/u.csv, line 2 (row 1), column 'R'"),
              std::string::npos)
        << cell;
  }
  const CsvTable v = CsvTable::parse("p,flag\n1.5,maybe\n", "data/v.csv");
  EXPECT_NE(message_of([&] { v.integer(0, "p"); }).find("column 'p': '1.5' is not an integer"),
            std::string::npos);
  EXPECT_NE(message_of([&] { v.yes_no(0, "flag"); }).find("column 'flag'"), std::string::npos);
}

TEST(CsvTable, MissingColumnNamesFileAndColumn) {
  const CsvTable t = CsvTable::parse("# t\nR,K1\n1,2\n", "data/cols.csv");
  const std::string m = message_of([&] { t.number(0, "K2"); });
  EXPECT_NE(m.find("data/cols.csv"), std::string::npos) << m;
  EXPECT_NE(m.find("no column 'K2'"), std::string::npos) << m;
  EXPECT_NE(m.find("R, K1"), std::string::npos) << m;  // the columns there are
}

TEST(CsvTable, MalformedTablesAreRefusedWithLineAndRow) {
  std::string m = message_of([] { CsvTable::parse("R,K1\n1,2\n3\n", "data/short.csv"); });
  EXPECT_NE(m.find("data/short.csv, line 3 (row 2): 1 fields, the header names 2 columns"),
            std::string::npos)
      << m;
  m = message_of([] { CsvTable::parse("R,K1\n1,2,3\n", "data/long.csv"); });
  EXPECT_NE(m.find("data/long.csv, line 2 (row 1): 3 fields"), std::string::npos) << m;
  m = message_of([] { CsvTable::parse("# only comments\n\n", "data/empty.csv"); });
  EXPECT_NE(m.find("data/empty.csv: no header row"), std::string::npos) << m;
  m = message_of([] { CsvTable::parse("R,K1,R\n", "data/twice.csv"); });
  EXPECT_NE(m.find("column 'R' is named twice"), std::string::npos) << m;
  m = message_of([] { CsvTable::parse("R,,K1\n", "data/unnamed.csv"); });
  EXPECT_NE(m.find("column 2 of the header row has no name"), std::string::npos) << m;
}

TEST(CsvTable, CellErrorUsesTheSameForm) {
  const CsvTable t = CsvTable::parse("name\nlpp-c\n", "data/names.csv");
  EXPECT_EQ(std::string(t.cell_error(0, "name", "not a sub-class").what()),
            "data/names.csv, line 2 (row 1), column 'name': not a sub-class");
}

}  // namespace
}  // namespace flexure
