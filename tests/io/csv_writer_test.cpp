// What is checked: the CSV writer (io/csv_table.h) against hand-written expected text (header of
// names and [units], 17 significant digits that read back to the same double, NaN as an empty
// field, RFC 4180 quoting), and the table of an HDF5 file against the values written into it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "flexure/io/csv_table.h"
#include "flexure/io/platform/hdf5_file.h"
#include "flexure/io/platform/provenance.h"

namespace flexure::io {
namespace {

TEST(CsvTable, HeaderUnitsNumbersNanAndQuoting) {
  const double third = 1.0 / 3.0;
  const std::vector<CsvColumn> columns = {
      {"name", "text", {}, {"a", "b, \"c\""}},
      {"theta0", "rad", {third, std::numeric_limits<double>::quiet_NaN()}, {}},
      {"force", "N", {-0.0, 1e-300}, {}},
  };
  EXPECT_EQ(csv_text(columns),
            "name [text],theta0 [rad],force [N]\n"
            "a,0.33333333333333331,-0\n"
            "\"b, \"\"c\"\"\",,1e-300\n");
  // 17 significant digits read back to the same double.
  EXPECT_EQ(std::strtod("0.33333333333333331", nullptr), third);
}

TEST(CsvTable, RefusesColumnsOfDifferentLengths) {
  EXPECT_THROW(csv_text({{"a", "1", {1.0, 2.0}, {}}, {"b", "1", {1.0}, {}}}),
               std::invalid_argument);
}

TEST(CsvTable, TableOfAnHdf5GridExpandsTheAxesRowMajor) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "flexure_csv_writer_test.h5";
  {
    AtomicHdf5File file(path.string());
    Hdf5Group& root = file.root();
    root.write_dataset("x", std::vector<double>{1.0, 2.0}, "m", "first axis");
    root.write_dataset("y", std::vector<double>{10.0, 20.0, 30.0}, "1", "second axis");
    Hdf5Group g = root.create_group("model");
    g.write_dataset("value", std::vector<double>{0, 1, 2, 3, 4, 5}, {2, 3}, "N", "grid values");
    root.write_dataset("other", std::vector<double>{7.0}, "1", "not of the grid's shape");
    write_provenance(root, {});
    file.commit();
  }
  const std::vector<CsvColumn> c = csv_columns_from_hdf5(path.string(), {"x", "y"});
  std::filesystem::remove(path);
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c[0].name, "x");
  EXPECT_EQ(c[0].unit, "m");
  EXPECT_EQ(c[0].numbers, (std::vector<double>{1, 1, 1, 2, 2, 2}));
  EXPECT_EQ(c[1].numbers, (std::vector<double>{10, 20, 30, 10, 20, 30}));
  EXPECT_EQ(c[2].name, "model/value");
  EXPECT_EQ(c[2].unit, "N");
  EXPECT_EQ(c[2].numbers, (std::vector<double>{0, 1, 2, 3, 4, 5}));
}

// A mechanism's force columns say whose force they are (docs/cli.md "CSV output"): the unit N
// becomes "N (half)" or "N (whole)" by the file's root attribute force_of; other units stay.
TEST(CsvTable, ForceColumnsSayWhoseForce) {
  EXPECT_EQ(force_unit("one half"), "N (half)");
  EXPECT_EQ(force_unit("whole"), "N (whole)");
  EXPECT_THROW(force_unit("both halves"), std::invalid_argument);
  std::vector<CsvColumn> columns = {{"force_prbm", "N", {1.0}, {}}, {"stress", "Pa", {2.0}, {}}};
  mark_force_columns(columns, "whole symmetric mechanism");
  EXPECT_EQ(csv_text(columns), "force_prbm [N (whole)],stress [Pa]\n1,2\n");
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "flexure_csv_writer_force_of_test.h5";
  for (const char* of : {"one half", "whole symmetric mechanism", ""}) {
    {
      AtomicHdf5File file(path.string());
      Hdf5Group& root = file.root();
      if (*of != '\0') root.set_attribute("force_of", of);
      root.write_dataset("displacement", std::vector<double>{1.0, 2.0}, "m", "axis");
      root.write_dataset("force_exact", std::vector<double>{3.0, 4.0}, "N", "a force");
      write_provenance(root, {});
      file.commit();
    }
    const std::vector<CsvColumn> c = csv_columns_from_hdf5(path.string(), {"displacement"});
    std::filesystem::remove(path);
    ASSERT_EQ(c.size(), 2u);
    EXPECT_EQ(c[0].unit, "m");
    EXPECT_EQ(c[1].unit,
              std::string(of) == "one half" ? "N (half)"
              : *of != '\0'                 ? "N (whole)"
                                            : "N");
  }
}

}  // namespace
}  // namespace flexure::io
