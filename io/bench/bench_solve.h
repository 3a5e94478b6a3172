#pragma once
// One solve of one benchmark load by one method, method-independent (what the runner times).
#include <string>

#include "io/bench/bench_types.h"
#include "solver/common/end_load.h"

namespace flexure::bench {

struct PointSolution {
  int status = kStatusError;  // kStatusConverged, kStatusNotConverged or kStatusError
  TipPose tip;
  int iterations = 0;
  int inside_validity = -1;  // PRBM: 1 when Theta <= min(Theta_max position, force), else 0
  std::string message;
};

// Never throws: exceptions of the solvers become kStatusError with their message.
PointSolution solve_point(const BenchMethod& method,
                          const BenchProblem& problem,
                          const LoadPoint& load);

// The reference method: shooting on CVODES at its tightest tolerance (rtol 1e-12, atol 1e-14).
BenchMethod reference_shooting_method();

}  // namespace flexure::bench
