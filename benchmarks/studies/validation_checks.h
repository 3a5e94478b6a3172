#pragma once
// `flexure validate` as a library function: every beam method available in this build against the
// reference problems of validation_problems.h, one row per compared quantity, with the time per
// solve (docs/validation.md).
#include <limits>
#include <string>
#include <vector>

#include "flexure/solver/common/status.h"

namespace flexure {

// One row of the results table.
struct ValidationCheck {
  std::string problem;
  std::string method;
  std::string quantity;
  double computed = std::numeric_limits<double>::quiet_NaN();  // NaN: the solve failed
  double reference = 0.0;
  double rel_error = std::numeric_limits<double>::quiet_NaN();
  double tolerance = 0.0;
  bool passed = false;
  double seconds_per_solve = 0.0;
  std::string message;  // the method's message when the solve failed or did not converge
};

// Runs every check. A solve that throws or does not converge is a failed check, never an
// exception. Each solve is repeated for about 2 ms to time it.
std::vector<ValidationCheck> run_validation_checks();

// The whole of `flexure validate`: the checks, and whether every one passed. Converged when all
// passed; otherwise kNoConvergence with a message naming how many failed (the tool's exit 1).
struct ValidationReport : SolveStatus {
  std::vector<ValidationCheck> checks;
  bool all_passed = false;
};

// Runs run_validation_checks() and summarises it.
ValidationReport run_validation();

}  // namespace flexure
