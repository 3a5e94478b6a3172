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
#include <utility>

#include "flexure/beam/beam_method.h"
#include "flexure/solver/common/status.h"

namespace flexure {

struct AutoMethodRequest {
  double load_ratio_n = 0.0;
  double alpha2 = 0.0;  // NaN when the load is not given (inverse problems)
  double mu = 0.0;
  bool plain_cantilever = true;  // free end, dead loads, uniform straight beam
  double tolerance = 1e-6;       // relative error allowed (tip position error / deflection)
  // Set when auto's pass over the model ladder (beam_auto_ladder.h) has judged the cheap models,
  // the 1R PRBM among them, at this load and taken none: why, for the reason; the PRBM is then not
  // considered again.
  std::string ladder_verdict;
};

struct AutoMethodChoice {
  BeamMethod method = BeamMethod::kElliptic;  // kPrbm, kElliptic or kShooting
  std::string reason;                         // one sentence: why this method and not a cheaper one
  double expected_error = 0.0;  // the error bound the choice rests on (relative tip error)
};

// The relative tip errors (|tip - exact tip| / tip displacement, the measure of the tolerance) the
// exact methods are known to stay within (docs/benchmarks.md). Forward problems: the elliptic
// solver's scalar solves converge to 1e-14 relative (bound 1e-13); the shooting method at rtol
// 1e-12 is measured below 1e-9 on the benchmark set. Inverse problems end when the tip quantity
// is within 1e-10 (elliptic) or 1e-8 (shooting) of its target (beam_problem.h), which bounds them.
inline constexpr double kEllipticErrorBound = 1e-13;
inline constexpr double kEllipticInverseErrorBound = 1e-10;
inline constexpr double kShootingErrorBound = 1e-9;
inline constexpr double kShootingInverseErrorBound = 1e-8;
// The bound of an exact method (kElliptic or kShooting; NaN for the others, whose error depends on
// the load and the discretisation).
double exact_method_error_bound(BeamMethod method, bool inverse);

// A tolerance below what every method that can answer reaches: the answer would miss it, so the
// problem is refused before any solve (exit code 2). Names the smallest tolerance that can be met.
class ToleranceBelowReach : public InvalidInput {
 public:
  ToleranceBelowReach(const std::string& message, double best_tolerance, std::string best_method)
      : InvalidInput(message),
        best_tolerance_(best_tolerance),
        best_method_(std::move(best_method)) {}
  double best_tolerance() const { return best_tolerance_; }
  const std::string& best_method() const { return best_method_; }  // "elliptic", "exact", ...

 private:
  double best_tolerance_;
  std::string best_method_;
};

// Throws ToleranceBelowReach when `tolerance` is below the bound of `method` (an exact method that
// auto falls back to).
void require_tolerance_within_reach(double tolerance, BeamMethod method, bool inverse);

// Throws InvalidInput unless the tolerance is finite and > 0, and ToleranceBelowReach when it is
// below the error bound of the most accurate method for this problem.
AutoMethodChoice choose_beam_method(const AutoMethodRequest& request);

// The PRBM's relative tip-position error measured by `flexure bench` for the fixed-pinned segment
// at (n, alpha2): 1.5 times the largest value at the measured loads around it
// (data/method_auto_error_map.csv, compiled into the library). NaN outside the measured range
// (-2 <= n <= 3, 0.5 <= alpha2 <= 20).
double prbm_measured_error(double load_ratio_n, double alpha2);

}  // namespace flexure

// Compatibility: the method choice was in namespace flexure::bench while it lived in the studies
// layer (issue 28 moved it to the beam layer). Existing code that names bench:: keeps compiling.
namespace flexure::bench {
using flexure::AutoMethodChoice;
using flexure::AutoMethodRequest;
using flexure::choose_beam_method;
using flexure::exact_method_error_bound;
using flexure::kEllipticErrorBound;
using flexure::kEllipticInverseErrorBound;
using flexure::kShootingErrorBound;
using flexure::kShootingInverseErrorBound;
using flexure::prbm_measured_error;
using flexure::require_tolerance_within_reach;
using flexure::ToleranceBelowReach;
}  // namespace flexure::bench
