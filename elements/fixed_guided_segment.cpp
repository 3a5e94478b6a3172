#include <cmath>
#include <utility>

#include "flexure/elements/prbm_element.h"

namespace flexure {

FixedGuidedSegment::FixedGuidedSegment(FixedPinnedConstants constants)
    : constants_(std::move(constants)) {
  constants_.validate();
}

PrbGeometry FixedGuidedSegment::geometry() const {
  return {constants_.gamma, constants_.gamma, (1.0 - constants_.gamma) / 2.0, 0.0, 2};
}

double FixedGuidedSegment::stiffness_coefficient() const {
  return 2.0 * constants_.gamma * constants_.K_theta;
}

TipPose FixedGuidedSegment::tip(double Theta) const {
  const double g = constants_.gamma;
  return {1.0 - g * (1.0 - std::cos(Theta)), g * std::sin(Theta), 0.0};
}

double FixedGuidedSegment::generalized_load(double Theta, const EndLoad& load) const {
  return link_force_work(constants_.gamma, Theta, load);
}

double FixedGuidedSegment::spring_moment(double Theta) const {
  return 2.0 * stiffness_coefficient() * Theta;
}

ValidityLimits FixedGuidedSegment::limits() const {
  return {constants_.theta_max_gamma,
          constants_.theta_max_K,
          "fixed-pinned half: " + constants_.source};
}

double FixedGuidedSegment::max_moment(double Theta, const EndLoad& load) const {
  const TipPose t = tip(Theta);
  return 0.5 * (t.a_over_l * load.Fy - t.b_over_l * load.Fx);
}

}  // namespace flexure
