#pragma once
// The convergence history of a constant-force design search (`flexure design cfm --out`;
// docs/hdf5-schema.md "flexure design cfm --out"): the problem and the optimum as root attributes,
// /history with every distinct PRBM model evaluation in order, and with a refinement against the
// exact model /exact_history with every exact stroke.
//
// The file is opened when the writer is made (a path that cannot be written fails before the
// search) and appears whole or not at all (hdf5_file.h AtomicHdf5File): write() fills and commits
// it. No HDF5 type is visible here.
#include <memory>
#include <string>

#include "flexure/mechanisms/design/cfm_synthesis.h"

namespace flexure::io {

class AtomicHdf5File;

class DesignHistoryFile {
 public:
  // Creates the temporary file next to `path`; throws InvalidInput saying why it cannot.
  explicit DesignHistoryFile(const std::string& path);
  ~DesignHistoryFile();
  DesignHistoryFile(DesignHistoryFile&&) noexcept;
  DesignHistoryFile& operator=(DesignHistoryFile&&) noexcept;

  // Writes the search (run with SynthesisOptions::record_history) and, when given, its refinement
  // against the exact model; `seed` is the search's seed. Renames the file into place. Once only.
  void write(const design::CfmDesignProblem& problem,
             const design::CfmSynthesisResult& synthesis,
             const design::CfmExactRefinement* exact,
             unsigned long seed);

  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::unique_ptr<AtomicHdf5File> file_;
};

}  // namespace flexure::io
