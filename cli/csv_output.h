#pragma once
// `--csv FILE` and `--out FILE.csv` of the commands that write a table (docs/cli.md "CSV
// output"): the command writes its HDF5 file as always (to a hidden temporary next to the CSV
// when --out names a .csv or only --csv is given), then the table of that file is written as CSV by
// the library (io/csv_table.h). Both paths are checked before any work (exit 2).
#include <CLI/CLI.hpp>
#include <map>
#include <string>
#include <vector>

#include "cli/cli_common.h"
#include "flexure/io/csv_table.h"

namespace flexure::cli {

// The columns of a table the command has as JSON records (e.g. the `designs` of `design
// mechanism`), in the key order of the first record: numbers, booleans (0/1) and strings become
// columns, an array of numbers one column per entry (`thicknesses_1`, `thicknesses_2`; NaN where
// a record has fewer), null NaN; nested objects are left out. `units` gives each key's unit
// (absent: "1").
std::vector<io::CsvColumn> csv_columns_from_records(
    const Json& records, const std::map<std::string, std::string>& units);

// True for a path whose extension is .csv (or .CSV): --out FILE.csv asks for a CSV table.
bool is_csv_path(const std::string& path);

// For the commands whose --out file has no one table (`validate`, `bench`): a FILE.csv --out would
// be an HDF5 file under a CSV name, so it is refused before any work (InvalidInput, exit 2) with
// `why` saying what the file holds.
void refuse_csv_out(const std::string& out, const std::string& why);

// For the commands that always write a file (`sweep beam`, `path`, `map cfm`, `models map`): the
// HDF5 --out, a CSV (--out FILE.csv or --csv FILE) or both; neither is refused before any work
// (InvalidInput, exit 2).
void require_out_or_csv(const std::string& out, const std::string& csv);

// Adds `--csv FILE` to `cmd`, storing the path in `csv`.
void add_csv_option(CLI::App* cmd, std::string& csv);

class CsvOutput {
 public:
  // `out`: the command's --out (may be empty, or end in .csv); `csv`: its --csv (may be empty).
  CsvOutput(const std::string& out, const std::string& csv);
  ~CsvOutput();
  CsvOutput(const CsvOutput&) = delete;
  CsvOutput& operator=(const CsvOutput&) = delete;

  bool wanted() const { return !csv_.empty(); }
  // The HDF5 path the command writes: --out, or the temporary when --out is a .csv file.
  const std::string& hdf5_path() const { return hdf5_; }
  // The CSV path ("" when none is wanted).
  const std::string& csv_path() const { return csv_; }
  // The file the user asked for, for messages: the HDF5 --out, or the CSV when there is none.
  const std::string& written_path() const { return temporary_ ? csv_ : hdf5_; }
  // The JSON keys "out" (the --out given, HDF5 or CSV; null without one) and "csv" (the CSV
  // written, or null).
  Json out_json() const { return out_.empty() ? Json(nullptr) : Json(out_); }
  Json csv_json() const { return csv_.empty() ? Json(nullptr) : Json(csv_); }
  // After the HDF5 file is complete: writes the CSV of its table (io::csv_columns_from_hdf5).
  void write(const std::vector<std::string>& axes, const std::vector<std::string>& skip = {}) const;

 private:
  std::string out_;
  std::string hdf5_;
  std::string csv_;
  bool temporary_ = false;
};

}  // namespace flexure::cli
