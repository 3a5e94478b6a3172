#pragma once
// `flexure mechanism validate`: the table over a set of built-in designs (one
// mechanism::validate_mechanism row per design, mechanisms/mechanism_validation.h), divided over
// the ranks of an MPI run one design at a time (a design takes milliseconds to seconds: dynamic
// balancing, io/platform/work_distribution.h) and written to one HDF5 file (docs/hdf5-schema.md
// "flexure mechanism validate --out"; every rank writes the rows it computed, docs/scaling.md).
//
// The rows come back to rank 0 as the text that the caller's `format` made of them on the rank
// that computed them (a row holds a whole stroke analysis: text is what travels between ranks),
// with their warnings, in the order of the designs. No HDF5 type is visible here.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "flexure/mechanisms/mechanism_catalogue.h"
#include "flexure/mechanisms/mechanism_validation.h"

namespace flexure::io {

class AtomicHdf5File;

// The --out table of `mechanism validate`: opened (collectively: every rank of an MPI run calls
// the constructor, write_row for its rows and commit) when made, so that a path that cannot be
// written fails before any design is analysed; it appears whole or not at all.
class MechanismValidationFile {
 public:
  // Creates the temporary file next to `path` with the root attributes (designs, points,
  // mpi_ranks, toggle_fraction and spring_rule when given) and the datasets for `count` designs.
  // Throws InvalidInput "--out: <why>" when it cannot be written.
  MechanismValidationFile(const std::string& path,
                          mechanism::DesignSet designs,
                          const mechanism::MechanismValidationOptions& options,
                          std::size_t count);
  ~MechanismValidationFile();
  MechanismValidationFile(const MechanismValidationFile&) = delete;
  MechanismValidationFile& operator=(const MechanismValidationFile&) = delete;

  // Row `index` (the design's place in the table): the numeric columns and the status.
  void write_row(std::size_t index, const mechanism::MechanismValidationRow& row);
  // The design names (rank 0's are written), the provenance; renames the file into place.
  void commit(const std::vector<std::string>& names);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// What rank 0 gets back of one design: the texts that `format` returned for its row, and its
// warnings (mechanism_warnings.h) for the caller to print in the order of the designs.
struct FormattedValidationRow {
  std::vector<std::string> texts;
  std::vector<std::string> warnings;
};

using ValidationRowFormat =
    std::function<std::vector<std::string>(const mechanism::MechanismValidationRow&)>;

// Validates every design of `designs` (mechanism::mechanism_designs order) over the ranks; with a
// non-empty `out` (an HDF5 path), writes the table there (opened before any design is analysed).
// Every rank calls it with the same arguments. Returns one entry per design on rank 0, none on the
// other ranks. A design that fails throws (under MPI as parallel::RankFailure naming the design).
std::vector<FormattedValidationRow> validate_mechanisms(
    mechanism::DesignSet designs,
    const mechanism::MechanismValidationOptions& options,
    const std::string& out,
    const ValidationRowFormat& format);

}  // namespace flexure::io
