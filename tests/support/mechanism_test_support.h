#pragma once
// Shared by the mechanism tests: the work of the slider force over part of the stroke, integrated
// from the exact model's force by Simpson's rule (for the energy balance W = Delta U; the rule is
// written here, independently of the library, so that the tests do not judge it with its own code).
#include <gtest/gtest.h>

#include <vector>

#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_exact.h"

namespace flexure::mechanism::testing {

// Integral of F_exact dDelta x from a to b, Simpson's rule on `intervals` (even) intervals.
inline double simpson_work(const MechanismDesign& d, double a, double b, int intervals) {
  std::vector<double> x(intervals + 1);
  for (int k = 0; k <= intervals; ++k) x[k] = a + (b - a) * k / intervals;
  const ExactStrokeResult r = exact_stroke(d, x);
  EXPECT_TRUE(r.converged()) << r.message;
  if (!r.converged()) return 0.0;
  double sum = 0.0;
  for (int k = 0; k <= intervals; ++k) {
    const double w = (k == 0 || k == intervals) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
    sum += w * r.points[k].force;
  }
  return sum * (b - a) / (3.0 * intervals);
}

}  // namespace flexure::mechanism::testing
