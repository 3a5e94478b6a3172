#pragma once
// Shared by the CFM table tests: how far a computed quantity may move when the printed inputs
// (R, K1, K2 with 4 decimals) move by half a unit of their last digit. Written independently of
// mechanisms/cfm_comparison.cpp so that the tests do not judge the library with its own rule.
#include <algorithm>
#include <cmath>
#include <functional>

#include "flexure/mechanisms/cfm/cfm_model.h"

namespace flexure::cfm::testing {

// The thesis prints R, K1, K2 to 4 decimals.
constexpr double kHalfUnitInput = 0.5e-4;

// Sum over the free design variables of the largest change of `q` under a +-half-unit change.
inline double input_band(const CfmModel& model,
                         const CfmParameters& p,
                         const std::function<double(const CfmResult&)>& q) {
  const double q0 = q(model.evaluate(p));
  double band = 0.0;
  for (int variable = 0; variable < 3; ++variable) {
    if ((variable == 1 && !p.K1) || (variable == 2 && !p.K2)) continue;
    double worst = 0.0;
    for (double sign : {-1.0, 1.0}) {
      CfmParameters v = p;
      const double h = sign * kHalfUnitInput;
      if (variable == 0) v.R += h;
      if (variable == 1) v.K1 = *v.K1 + h;
      if (variable == 2) v.K2 = std::max(0.0, *v.K2 + h);
      worst = std::max(worst, std::abs(q(model.evaluate(v)) - q0));
    }
    band += worst;
  }
  return band;
}

}  // namespace flexure::cfm::testing
