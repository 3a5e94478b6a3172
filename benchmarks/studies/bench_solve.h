#pragma once
// One solve of one benchmark load by one method, method-independent (what the runner times).
#include <optional>
#include <string>

#include "flexure/benchmarks/studies/bench_types.h"
#include "flexure/mechanisms/mechanism_exact.h"
#include "flexure/solver/common/end_load.h"

namespace flexure::bench {

struct PointSolution {
  int status = kStatusError;  // kStatusConverged, kStatusNotConverged or kStatusError
  TipPose tip;
  int iterations = 0;
  int inside_validity = -1;  // PRBM: 1 when Theta <= min(Theta_max position, force), else 0
  double force = 0.0;        // mechanism problems: slider input force, N
  std::string message;
};

// Never throws: exceptions of the solvers become kStatusError with their message.
PointSolution solve_point(const BenchMethod& method,
                          const BenchProblem& problem,
                          const LoadPoint& load);

// One stroke of a mechanism problem, traced in order of increasing displacement. The exact model
// starts each point from the last accepted solution (Newton from the neighbouring point, as
// mechanism::exact_stroke does), so repeated solves of one point are identical and time one
// continuation step; the PRBM is closed form. Never throws from solve().
class CfmStrokeSolver {
 public:
  // Throws InvalidInput for an unknown built-in design.
  explicit CfmStrokeSolver(const std::string& mechanism);
  // `family` is kPrbm or kMechanismExact; the exact solution is kept for accept_last().
  PointSolution solve(MethodFamily family, double displacement);
  // Makes the last converged exact solution the start of the next point.
  void accept_last();

 private:
  mechanism::ExactMechanismSolver exact_;
  std::optional<mechanism::ExactPoint> previous_;  // start of the next exact solve
  std::optional<mechanism::ExactPoint> last_;      // last converged exact solve
};

// The reference method: shooting on CVODES at its tightest tolerance (rtol 1e-12, atol 1e-14).
BenchMethod reference_shooting_method();

}  // namespace flexure::bench
