#pragma once
// Method `auto`: the cheapest model whose error for this load is within the tolerance
// ("model no more than a scene needs": the cheapest model that meets the tolerance).
//
// Order of preference (cheapest model first): the PRBM fixed-pinned segment (one pivot, one
// spring), the exact elliptic solution, the shooting solver. The PRBM is taken only when
//   * the load is one Howell's fixed-pinned element models (free cantilever, tip force, mu = 0,
//     -5 <= n <= 10 from Table 5.1),
//   * its PRB angle is inside the validity limits Theta_max(gamma) and Theta_max(K_theta)
//     (Howell eqs. 5.47, 5.63), and
//   * the error measured by `flexure bench` (cantilever_force/prbm, the accuracy map of
//     docs/benchmarks.md) at the neighbouring measured loads is within the tolerance.
// The elliptic solution (error ~1e-14) serves every other free cantilever with dead loads; the
// shooting solver (rtol 1e-12; measured error below 1e-9) every other chain and end condition.
#include <string>

#include "flexure/benchmarks/studies/beam_method.h"

namespace flexure::bench {

struct AutoMethodRequest {
  double load_ratio_n = 0.0;
  double alpha2 = 0.0;  // NaN when the load is not given (inverse problems)
  double mu = 0.0;
  bool plain_cantilever = true;  // free end, dead loads, uniform straight beam
  double tolerance = 1e-6;       // relative error allowed (tip position error / deflection)
};

struct AutoMethodChoice {
  BeamMethod method = BeamMethod::kElliptic;  // kPrbm, kElliptic or kShooting
  std::string reason;                         // one sentence: why this method and not a cheaper one
};

// Throws InvalidInput unless the tolerance is finite and > 0.
AutoMethodChoice choose_beam_method(const AutoMethodRequest& request);

// The PRBM's relative tip-position error measured by `flexure bench` for the fixed-pinned segment
// at (n, alpha2): 1.5 times the largest value at the measured loads around it
// (data/method_auto_error_map.csv, compiled into the library). NaN outside the measured range
// (-2 <= n <= 3, 0.5 <= alpha2 <= 20).
double prbm_measured_error(double load_ratio_n, double alpha2);

}  // namespace flexure::bench
