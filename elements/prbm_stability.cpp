#include "flexure/elements/prbm_stability.h"

#include <cmath>

#include "flexure/elements/prbm_element.h"
#include "flexure/solver/common/status.h"

namespace flexure {

PrbmEnergyCurvature prbm_energy_curvature(const PrbmElement& element,
                                          double Theta,
                                          const EndLoad& load) {
  require_finite(Theta, "PRB angle Theta");
  require_finite(load.Fx, "PRBM tip load Fx");
  require_finite(load.Fy, "PRBM tip load Fy");
  require_finite(load.mu, "PRBM tip moment mu");
  // The springs' stiffness: spring_moment is linear in Theta for every element here, so the
  // central difference is exact (to rounding) at any step.
  constexpr double kStep = 1e-4;
  PrbmEnergyCurvature out;
  out.spring_stiffness =
      (element.spring_moment(Theta + kStep) - element.spring_moment(Theta - kStep)) / (2 * kStep);
  double load_slope = 0.0;  // d(generalized_load)/dTheta
  if (dynamic_cast<const FixedPinnedSegment*>(&element) != nullptr ||
      dynamic_cast<const FixedGuidedSegment*>(&element) != nullptr) {
    // generalized_load = gamma (-Fx sin Theta + Fy cos Theta) (link_force_work, Howell eq. 6.103).
    const double gamma = element.geometry().gamma;
    load_slope = -gamma * (load.Fx * std::cos(Theta) + load.Fy * std::sin(Theta));
  } else if (dynamic_cast<const EndMomentSegment*>(&element) != nullptr) {
    load_slope = 0.0;  // generalized_load = mu: the couple's work is linear in Theta
  } else {
    load_slope = (element.generalized_load(Theta + kStep, load) -
                  element.generalized_load(Theta - kStep, load)) /
                 (2 * kStep);
  }
  out.second_derivative = out.spring_stiffness - load_slope;
  return out;
}

Stability prbm_stability(const PrbmElement& element,
                         double Theta,
                         const EndLoad& load,
                         double critical_tolerance) {
  const PrbmEnergyCurvature c = prbm_energy_curvature(element, Theta, load);
  if (!(c.spring_stiffness > 0.0)) {
    return not_checked_stability("the PRB element has no spring stiffness to measure against");
  }
  const double margin = c.second_derivative / c.spring_stiffness;
  return classify_stability(
      margin < -critical_tolerance ? 1 : 0, margin, critical_tolerance, "the PRBM");
}

}  // namespace flexure
