#include "cli/csv_output.h"

#include <fmt/format.h>

#include <cstdio>
#include <filesystem>

#include "flexure/io/csv_table.h"
#include "flexure/io/output_path.h"
#include "flexure/io/parallel/mpi_world.h"
#include "flexure/solver/common/errors.h"

namespace flexure::cli {
namespace {

bool ends_with_csv(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  return ext == ".csv" || ext == ".CSV";
}

}  // namespace

void add_csv_option(CLI::App* cmd, std::string& csv) {
  cmd->add_option("--csv",
                  csv,
                  "Also write the table as CSV (a header line of names and [units], one row per "
                  "point; docs/cli.md \"CSV output\")");
}

CsvOutput::CsvOutput(const std::string& out, const std::string& csv) : hdf5_(out), csv_(csv) {
  if (ends_with_csv(out)) {
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
