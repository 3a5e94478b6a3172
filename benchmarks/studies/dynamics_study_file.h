#pragma once
// The HDF5 file of `flexure dynamics --out` (docs/hdf5-schema.md "flexure dynamics"): per drive
// frequency the mean, median, min, max and peak-to-peak input force and the percent constant
// force, the study's settings and its nominal forces and natural frequency as root attributes, and
// one period of the force history per --history frequency in /history/0, /history/1, ...
//
// The file is opened when the writer is made (a path that cannot be written fails before the
// study runs) and appears whole or not at all (io/platform/hdf5_file.h AtomicHdf5File): write()
// fills and commits it. No HDF5 type is visible here.
#include <memory>
#include <string>

#include "flexure/benchmarks/studies/dynamics_study.h"

namespace flexure {
namespace io {
class AtomicHdf5File;
}

class DynamicsStudyFile {
 public:
  // Creates the temporary file next to `path`; throws InvalidInput saying why it cannot.
  explicit DynamicsStudyFile(const std::string& path);
  ~DynamicsStudyFile();
  DynamicsStudyFile(DynamicsStudyFile&&) noexcept;
  DynamicsStudyFile& operator=(DynamicsStudyFile&&) noexcept;

  // Writes a converged study and renames the file into place. Once only.
  void write(const DynamicsStudy& study);

  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::unique_ptr<io::AtomicHdf5File> file_;
};

}  // namespace flexure
