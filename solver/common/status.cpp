#include "flexure/solver/common/status.h"

namespace flexure {

std::string_view termination_name(Termination termination) {
  switch (termination) {
    case Termination::kConverged:
      return "converged";
    case Termination::kNoConvergence:
      return "no_convergence";
    case Termination::kLimitPoint:
      return "limit_point";
    case Termination::kInvalidInput:
      return "invalid_input";
  }
  return "no_convergence";
}

}  // namespace flexure
