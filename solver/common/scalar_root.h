#pragma once
// Bracketed scalar root finding (Brent-Dekker: inverse quadratic / secant steps safeguarded by
// bisection). Used by every one-dimensional solve in flexure so that no solve can wander off its
// bracket or loop forever.
#include <functional>

#include "flexure/solver/common/status.h"

namespace flexure {

struct ScalarRootOptions {
  double x_tolerance = 1e-15;  // absolute tolerance on x, added to 2 eps |x|
  int max_iterations = 200;
};

struct ScalarRootResult : SolveStatus {
  double x = 0.0;
  double f = 0.0;
  // iterations: function evaluations made inside the bracket
};

// Finds a root of f in [a, b] given f(a) = fa and f(b) = fb of opposite sign (or one of them zero).
// Returns converged() false if the values do not bracket a root or the iteration limit is hit.
ScalarRootResult brent_root(const std::function<double(double)>& f,
                            double a,
                            double b,
                            double fa,
                            double fb,
                            const ScalarRootOptions& options = {});

}  // namespace flexure
