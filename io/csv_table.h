#pragma once
// CSV tables for spreadsheets (docs/cli.md "CSV output"): one header line naming every column
// with its unit in brackets (`alpha2 [1]`, `displacement [m]`, `stress_exact_pivot1 [Pa]`), then
// one row per point. Numbers are printed with 17 significant digits, so that a value read back
// is the double that was computed (the JSON prints the same doubles); a NaN ("no solution at this
// point", docs/hdf5-schema.md) is an empty field. Text fields are quoted where they hold a comma,
// a quote or a line break (RFC 4180). Written whole or not at all (write_text_file).
#include <string>
#include <vector>

namespace flexure::io {

struct CsvColumn {
  std::string name;
  std::string unit;                // "1" for a dimensionless number, "text" for a text column
  std::vector<double> numbers;     // a number column
  std::vector<std::string> texts;  // a text column (unit "text")
  bool is_text() const { return unit == "text"; }
  std::size_t size() const { return is_text() ? texts.size() : numbers.size(); }
};

// A force's unit that says whose force it is, for the force columns of a symmetric mechanism
// (mechanisms/mechanism.h): "N (half)" for one half, "N (whole)" for the whole mechanism.
// `force_of` is the output key's value ("one half", "whole symmetric mechanism") or the option's
// ("half", "whole"); throws std::invalid_argument for anything else.
std::string force_unit(const std::string& force_of);

// Gives every column of unit "N" the unit force_unit(force_of) (the other columns unchanged).
void mark_force_columns(std::vector<CsvColumn>& columns, const std::string& force_of);

// The CSV text of `columns` (all of one length; throws std::invalid_argument otherwise).
std::string csv_text(const std::vector<CsvColumn>& columns);

// Writes csv_text(columns) to `path` atomically; a path that cannot be written throws
// InvalidInput naming `option` (exit 2).
void write_csv(const std::string& path,
               const std::vector<CsvColumn>& columns,
               const std::string& option = "--csv");

// The table an HDF5 file flexure wrote holds, as columns: `axes` (datasets, 1-D, e.g. {"R", "d",
// "K1", "K2"} of a map, {"alpha2"} of a 1-D sweep, {"name"} of a table of designs) span the grid
// [|axis 0|, |axis 1|, ...]; each row is one grid point (row-major, the last axis fastest) with
// the axes' values first, then every other dataset of the file whose shape is that grid, in name
// order (a dataset in a group is named by its path, `prbm/position_error`), with the `units`
// attribute of each. In a file whose root has the attribute `force_of` (a mechanism's forces: one
// half or the whole), the columns in N say whose force they are (mark_force_columns). Groups named
// in `skip` (e.g. "design", "special_points") are left out. Throws Hdf5Error when the file cannot
// be read or an axis is missing or not 1-D.
std::vector<CsvColumn> csv_columns_from_hdf5(const std::string& hdf5_path,
                                             const std::vector<std::string>& axes,
                                             const std::vector<std::string>& skip = {});

}  // namespace flexure::io
