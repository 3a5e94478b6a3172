#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "flexure/elements/prbm_element.h"
#include "flexure/solver/common/status.h"

namespace flexure {

EndMomentSegment::EndMomentSegment(EndMomentConstants constants) : constants_(constants) {
  if (!(constants_.gamma > 0.0 && constants_.gamma <= 1.0)) {
    throw InvalidInput(
        fmt::format("end-moment gamma = {} is outside the allowed range (0, 1]", constants_.gamma));
  }
  if (!(constants_.c_theta > 0.0) || !(constants_.K_theta > 0.0) ||
      !(constants_.theta0_max_deg > 0.0 && constants_.theta0_max_deg <= 360.0)) {
    throw InvalidInput(fmt::format(
        "end-moment constants c_theta = {}, K_theta = {} must be > 0 and theta0_max = {} deg in "
        "(0, 360]",
        constants_.c_theta,
        constants_.K_theta,
        constants_.theta0_max_deg));
  }
}

PrbGeometry EndMomentSegment::geometry() const {
  return {constants_.gamma, constants_.gamma, 1.0 - constants_.gamma, 0.0, 1};
}

double EndMomentSegment::stiffness_coefficient() const {
  return constants_.gamma * constants_.K_theta;  // eq. 5.111; equals c_theta (eq. 5.112)
}

TipPose EndMomentSegment::tip(double Theta) const {
  const double g = constants_.gamma;
  return {1.0 - g * (1.0 - std::cos(Theta)), g * std::sin(Theta), constants_.c_theta * Theta};
}

double EndMomentSegment::generalized_load(double /*Theta*/, const EndLoad& load) const {
  if (load.Fx != 0.0 || load.Fy != 0.0) {
    throw InvalidInput(fmt::format(
        "tip force (Fx = {}, Fy = {}) on the end-moment segment, which models a pure end moment "
        "only (use the fixed-pinned or fixed-fixed element)",
        load.Fx,
        load.Fy));
  }
  return load.mu;  // the rigid link turns by Theta, so the couple does mu dTheta of work
}

double EndMomentSegment::spring_moment(double Theta) const {
  return stiffness_coefficient() * Theta;
}

ValidityLimits EndMomentSegment::limits() const {
  const double theta_max =
      constants_.theta0_max_deg * std::numbers::pi / 180.0 / constants_.c_theta;
  return {theta_max, theta_max, "eq. 5.108: theta0 < 124.4 deg, Theta = theta0 / c_theta"};
}

}  // namespace flexure
