#pragma once
// One row of `flexure mechanism validate` (docs/validation.md "Mechanisms"): a built-in design's
// stroke by the PRBM and the exact model, a second opinion on the last exact point by Howell's
// chain algorithm, the row's status and the numbers of the --out table. The table over a set of
// designs, divided over MPI ranks and written to one file, is io/mechanism_validation_file.h.
#include <optional>
#include <string>
#include <vector>

#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/mechanisms/mechanism_exact.h"

namespace flexure::mechanism {

// Elements per chain of the chain-algorithm check (corrected variant: O(N^-3), 1e-9-1e-5 r2 on
// the built-in designs at N = 100; under 1 ms per check, BM_ChainCheck100).
inline constexpr int kValidationChainCheckElements = 100;

struct MechanismValidationOptions {
  int points = 50;  // stroke points (AnalysisOptions::points)
  // Stroke of every design = this fraction of its toggle stroke, in [1e-6, 1); none: the design's.
  std::optional<double> toggle_fraction;
  // Spring rule of the designs with fixed-fixed segments (builtin_designs.h); none: the design's.
  std::optional<SpringRule> spring_rule;
  int chain_check_elements = kValidationChainCheckElements;

  // Throws InvalidInput naming the first field outside its range.
  void validate() const;
};

// The status column of the table (docs/hdf5-schema.md "flexure mechanism validate --out").
enum class ValidationStatus : int {
  kExactConverged = 0,          // the exact model converged (and so did the chain check)
  kExactNotConverged = 1,       // the exact model did not converge
  kPrbmOnly = 2,                // the configuration has no exact model
  kChainCheckNotConverged = 3,  // the chain-algorithm check did not converge
};

struct MechanismValidationRow {
  // The stroke (exact stresses not computed: the table reports the PRBM's). analysis.design is the
  // design as validated: the stroke of --toggle-fraction and the spring rule applied.
  MechanismAnalysis analysis;
  bool exact = false;            // the exact model ran and converged
  bool exact_stability = false;  // exact and its stability verdicts were computed
  // Howell's chain algorithm on the last exact point (chain_check_elements per chain); none where
  // the exact model did not converge or is missing.
  std::optional<ChainCheck> chain_check;
  int chain_check_elements = kValidationChainCheckElements;
  ValidationStatus status = ValidationStatus::kPrbmOnly;
  // The numeric columns of the table, in validation_columns() order (NaN where a column does not
  // apply, -1 for a validity limit never reached).
  std::vector<double> values;
  // Warnings of the stroke (mechanism_warnings.h): a force that vanishes, an unstable exact stroke.
  std::vector<std::string> warnings;
};

// Name, units and meaning of each numeric column (the datasets of the --out file).
struct ValidationColumn {
  const char* name;
  const char* units;
  const char* description;
};
const std::vector<ValidationColumn>& validation_columns();

// Validates one design. Throws InvalidInput or NoConvergence from the analysis with the design's
// name in front of the message (a table runs many designs).
MechanismValidationRow validate_mechanism(MechanismDesign design,
                                          const MechanismValidationOptions& options);

}  // namespace flexure::mechanism
