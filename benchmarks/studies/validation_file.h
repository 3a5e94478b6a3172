#pragma once
// The results file of `flexure validate` (docs/hdf5-schema.md "flexure validate"): one row per
// check (problem, method, quantity, computed, reference, rel_error, tolerance, passed, status, ...)
// and the root attributes all_passed, count, rel_error_definition and the provenance.
//
// The file is opened when the writer is made, so that a path that cannot be written fails before
// the checks run, and it appears whole or not at all (io/platform/hdf5_file.h AtomicHdf5File):
// write() fills and commits it; a writer destroyed before write() leaves nothing behind. No HDF5
// type is visible here.
#include <memory>
#include <string>

#include "flexure/benchmarks/studies/validation_checks.h"

namespace flexure {
namespace io {
class AtomicHdf5File;
}

class ValidationFile {
 public:
  // Creates the temporary file next to `path`. Throws InvalidInput saying why when the file
  // cannot be written there (missing directory, no permission, ...).
  explicit ValidationFile(const std::string& path);
  ~ValidationFile();
  ValidationFile(ValidationFile&&) noexcept;
  ValidationFile& operator=(ValidationFile&&) noexcept;

  // Writes the report's rows and attributes and renames the file into place. Once only.
  void write(const ValidationReport& report);

  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::unique_ptr<io::AtomicHdf5File> file_;
};

}  // namespace flexure
