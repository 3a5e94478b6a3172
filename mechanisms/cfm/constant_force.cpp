#include "flexure/mechanisms/cfm/constant_force.h"

#include <algorithm>
#include <cmath>

#include "flexure/solver/common/status.h"

namespace flexure::mechanism {

ConstantForceMeasure constant_force_measure(const std::vector<double>& force) {
  if (force.empty()) throw InvalidInput("percent constant force of an empty force curve");
  ConstantForceMeasure m;
  const auto [lo, hi] = std::minmax_element(force.begin(), force.end());
  m.min_force = *lo;
  m.max_force = *hi;
  double abs_min = INFINITY, abs_max = 0.0;
  for (double f : force) {
    abs_min = std::min(abs_min, std::abs(f));
    abs_max = std::max(abs_max, std::abs(f));
  }
  // Between a negative and a positive sample the (continuous) force passes through zero.
  m.changes_sign = m.min_force < 0.0 && m.max_force > 0.0;
  m.vanishes = m.changes_sign || abs_min <= kForceVanishesRelative * abs_max;
  // Eq. 5.22 on the magnitudes: for the usual positive force this is 100 min/max; a force of one
  // negative sign (pulling throughout) is as constant as its mirror image.
  m.percent = m.vanishes ? 0.0 : 100.0 * abs_min / abs_max;
  return m;
}

}  // namespace flexure::mechanism
