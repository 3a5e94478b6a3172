// The table of `flexure mechanism validate` run by the library (io/mechanism_validation_file.h)
// in one process, read back with the plain HDF5 C API: one entry per design of the set in the
// order of mechanism_designs(), every numeric column and the status equal to the row that the
// caller's format saw (bit for bit, NaN where the row has NaN), the root attributes as
// docs/hdf5-schema.md lists them. An --out that cannot be written fails before any design is
// analysed (format is never called) and leaves nothing behind.
#include "flexure/io/mechanism_validation_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "flexure/solver/common/status.h"
#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

using mechanism::DesignSet;
using mechanism::MechanismValidationOptions;
using mechanism::MechanismValidationRow;

TEST(MechanismValidationFile, ColumnsEqualTheRowsInTheOrderOfTheDesigns) {
  ScratchDir dir;
  const auto path = dir / "table.h5";
  MechanismValidationOptions o;
  o.points = 10;
  o.toggle_fraction = 0.3;
  o.spring_rule = mechanism::SpringRule::kTable2;
  std::map<std::string, MechanismValidationRow> seen;
  const std::vector<io::FormattedValidationRow> rows =
      io::validate_mechanisms(DesignSet::kThesis, o, path.string(), [&](const auto& row) {
        seen.emplace(row.analysis.design.name, row);
        return std::vector<std::string>{row.analysis.design.name, "second text"};
      });
  const std::vector<mechanism::MechanismDesign> designs =
      mechanism::mechanism_designs(DesignSet::kThesis);
  ASSERT_EQ(rows.size(), designs.size());
  ASSERT_EQ(seen.size(), designs.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].texts, (std::vector<std::string>{designs[i].name, "second text"}));
    EXPECT_EQ(rows[i].warnings, seen.at(designs[i].name).warnings);
  }
  ASSERT_EQ(dir.entries(), std::vector<std::string>{"table.h5"});
  const hid_t f = open_read_only(path);
  ASSERT_GE(f, 0);
  const std::vector<std::string> name = read_strings(f, "name");
  const std::vector<int> status = read_ints(f, "status");
  ASSERT_EQ(name.size(), designs.size());
  ASSERT_EQ(status.size(), designs.size());
  const auto& columns = mechanism::validation_columns();
  for (std::size_t c = 0; c < columns.size(); ++c) {
    const std::vector<double> v = read_doubles(f, columns[c].name);
    ASSERT_EQ(v.size(), designs.size()) << columns[c].name;
    for (std::size_t i = 0; i < designs.size(); ++i) {
      const double expected = seen.at(designs[i].name).values[c];
      if (std::isnan(expected)) {
        EXPECT_TRUE(std::isnan(v[i])) << columns[c].name << " " << designs[i].name;
      } else {
        EXPECT_EQ(v[i], expected) << columns[c].name << " " << designs[i].name;
      }
    }
  }
  for (std::size_t i = 0; i < designs.size(); ++i) {
    EXPECT_EQ(name[i], designs[i].name);
    EXPECT_EQ(status[i], static_cast<int>(seen.at(designs[i].name).status));
  }
  EXPECT_EQ(read_string_attribute(f, "/", "designs"), "thesis");
  EXPECT_EQ(read_int_attribute(f, "/", "points"), 10);
  EXPECT_EQ(read_int_attribute(f, "/", "mpi_ranks"), 1);
  EXPECT_EQ(read_double_attribute(f, "/", "toggle_fraction"), 0.3);
  EXPECT_EQ(read_string_attribute(f, "/", "spring_rule"), "table2");
  H5Fclose(f);
}

TEST(MechanismValidationFile, UnwritableOutFailsBeforeAnyDesignIsAnalysed) {
  int formatted = 0;
  MechanismValidationOptions o;
  o.points = 10;
  try {
    io::validate_mechanisms(
        DesignSet::kThesis, o, "/nonexistent/dir/table.h5", [&](const MechanismValidationRow&) {
          ++formatted;
          return std::vector<std::string>{};
        });
    FAIL() << "no exception";
  } catch (const InvalidInput& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("--out: ", 0), 0u) << m;
    EXPECT_NE(m.find("/nonexistent/dir"), std::string::npos) << m;
  }
  EXPECT_EQ(formatted, 0);
  ScratchDir dir;
  { io::MechanismValidationFile dropped((dir / "t.h5").string(), DesignSet::kAll, o, 3); }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(MechanismValidationFile, WithoutAFileEveryDesignComesBackFormatted) {
  MechanismValidationOptions o;
  o.points = 10;
  const auto rows = io::validate_mechanisms(DesignSet::kHowell, o, "", [](const auto& row) {
    return std::vector<std::string>{row.analysis.design.name};
  });
  const auto designs = mechanism::mechanism_designs(DesignSet::kHowell);
  ASSERT_EQ(rows.size(), designs.size());
  for (std::size_t i = 0; i < rows.size(); ++i) EXPECT_EQ(rows[i].texts.at(0), designs[i].name);
}

}  // namespace
}  // namespace flexure::test
