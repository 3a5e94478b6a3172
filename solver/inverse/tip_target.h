#pragma once
// Inverse problems of Howell's cantilever for any forward method (shooting, chain algorithm):
// the load alpha2 at which the tip angle theta0 or the tip deflection b/l reaches a target, with
// the load ratio n and the end moment mu fixed.
//
// The exact elliptic inverse answers first, in microseconds: it says whether the target is
// reachable at all (refused at once when not) and where, so the method's own forward solves are
// spent only on refining that load for the method's model (a discretised chain sits a little off
// the exact load). Only when the exact answer lies beyond the elliptic solver's range does the
// method scan the loads itself. Every returned load is checked: the method's forward solve at it
// reaches the target within the stated tolerance, or the solve fails with what was reached.
#include <functional>
#include <optional>
#include <string>

#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/status.h"

namespace flexure {

struct TipTarget {
  enum class Quantity { kTheta0, kBOverL };
  Quantity quantity = Quantity::kTheta0;
  double value = 0.0;         // theta0 [rad] or b/l
  double load_ratio_n = 0.0;  // n > 0 compressive (Howell eq. 2.67)
  double mu = 0.0;            // end moment M l/EI

  double of(const TipPose& tip) const {
    return quantity == Quantity::kTheta0 ? tip.theta0 : tip.b_over_l;
  }
  const char* name() const {
    return quantity == Quantity::kTheta0 ? "tip angle theta0" : "tip deflection b/l";
  }
};

struct TipTargetSolution : SolveStatus {
  // converged(): alpha2 reaches the target within `tolerance`
  double alpha2 = 0.0;   // the load found (or, when not converged, the closest reached)
  double reached = 0.0;  // the quantity at alpha2
  // residual: |reached - target|
  double tolerance = 0.0;  // the target tolerance used
  int forward_solves = 0;  // solves of the method (the exact guess not counted)
  // message: how the load was found, or why not
};

// `forward(alpha2)` solves the method at that load and returns the tip, or nullopt where it does
// not converge. `tolerance` is absolute on the quantity (times max(1, |target|)). Throws
// InvalidInput when the exact solution shows the target is unreachable for this n and mu.
TipTargetSolution solve_tip_target(
    const TipTarget& target,
    const std::function<std::optional<TipPose>(double alpha2)>& forward,
    double tolerance);

}  // namespace flexure
