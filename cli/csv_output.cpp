#include "cli/csv_output.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <limits>

#include "flexure/io/csv_table.h"
#include "flexure/io/platform/mpi_world.h"
#include "flexure/io/platform/output_path.h"
#include "flexure/solver/common/status.h"

namespace flexure::cli {
bool is_csv_path(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  return ext == ".csv" || ext == ".CSV";
}

void refuse_csv_out(const std::string& out, const std::string& why) {
  if (!is_csv_path(out)) return;
  throw InvalidInput(
      fmt::format("--out '{}' names a CSV file, but this command writes HDF5 only ({}); give "
                  "--out FILE.h5",
                  out,
                  why));
}

std::vector<io::CsvColumn> csv_columns_from_records(
    const Json& records, const std::map<std::string, std::string>& units) {
  std::vector<io::CsvColumn> columns;
  if (!records.is_array() || records.empty()) return columns;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto unit_of = [&](const std::string& key) {
    const auto it = units.find(key);
    return it == units.end() ? std::string("1") : it->second;
  };
  const auto number = [&](const Json& v) {
    if (v.is_boolean()) return v.get<bool>() ? 1.0 : 0.0;
    return v.is_number() ? v.get<double>() : nan;
  };
  for (const auto& [key, first] : records.front().items()) {
    if (first.is_object()) continue;
    if (first.is_string()) {
      io::CsvColumn c{key, "text", {}, {}};
      for (const Json& r : records) c.texts.push_back(r.value(key, std::string()));
      columns.push_back(std::move(c));
    } else if (first.is_array()) {
      std::size_t width = 0;
      bool numeric = true;
      for (const Json& r : records) {
        if (!r.contains(key) || !r[key].is_array()) continue;
        width = std::max(width, r[key].size());
        for (const Json& v : r[key]) numeric = numeric && (v.is_number() || v.is_null());
      }
      if (!numeric) continue;
      for (std::size_t i = 0; i < width; ++i) {
        io::CsvColumn c{fmt::format("{}_{}", key, i + 1), unit_of(key), {}, {}};
        for (const Json& r : records) {
          const bool has = r.contains(key) && r[key].is_array() && i < r[key].size();
          c.numbers.push_back(has ? number(r[key][i]) : nan);
        }
        columns.push_back(std::move(c));
      }
    } else {
      io::CsvColumn c{key, unit_of(key), {}, {}};
      for (const Json& r : records) c.numbers.push_back(r.contains(key) ? number(r[key]) : nan);
      columns.push_back(std::move(c));
    }
  }
  return columns;
}

void require_out_or_csv(const std::string& out, const std::string& csv) {
  if (out.empty() && csv.empty()) {
    throw InvalidInput(
        "no output file: give --out FILE.h5 (HDF5), --out FILE.csv or --csv FILE.csv (the table "
        "as CSV), or --out and --csv both");
  }
}

void add_csv_option(CLI::App* cmd, std::string& csv) {
  cmd->add_option("--csv",
                  csv,
                  "Also write the table as CSV (a header line of names and [units], one row per "
                  "point; docs/cli.md \"CSV output\")");
}

CsvOutput::CsvOutput(const std::string& out, const std::string& csv)
    : out_(out), hdf5_(out), csv_(csv) {
  if (is_csv_path(out)) {
    if (!csv.empty()) {
      throw InvalidInput(
          fmt::format("--out {} is a CSV file already; give --csv only with an "
                      "HDF5 --out",
                      out));
    }
    csv_ = out;
    io::check_output_path(csv_, "--out");
    const std::filesystem::path target(out);
    hdf5_ = (target.parent_path() / fmt::format(".{}.h5", target.filename().string())).string();
    temporary_ = true;
  } else if (!csv_.empty()) {
    if (out.empty()) {
      // No HDF5 file asked for: the table goes through a temporary one next to the CSV.
      io::check_output_path(csv_, "--csv");
      const std::filesystem::path target(csv_);
      hdf5_ = (target.parent_path() / fmt::format(".{}.h5", target.filename().string())).string();
      temporary_ = true;
      return;
    }
    io::check_output_path(csv_, "--csv");
  }
}

// The temporary HDF5 file is the same on every MPI rank (the ranks write it together); rank 0,
// which writes the CSV, removes it.
CsvOutput::~CsvOutput() {
  if (temporary_ && parallel::launched_rank() == 0) std::remove(hdf5_.c_str());
}

void CsvOutput::write(const std::vector<std::string>& axes,
                      const std::vector<std::string>& skip) const {
  if (csv_.empty() || parallel::launched_rank() != 0) return;
  io::write_csv(csv_, io::csv_columns_from_hdf5(hdf5_, axes, skip), temporary_ ? "--out" : "--csv");
}

}  // namespace flexure::cli
