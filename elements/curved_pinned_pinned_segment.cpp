#include <fmt/format.h>

#include <cmath>
#include <utility>

#include "flexure/elements/prbm_curve_fits.h"
#include "flexure/elements/prbm_element.h"
#include "flexure/solver/common/status.h"

namespace flexure {

namespace {

void require_kappa(double kappa0) {
  if (!(kappa0 >= 0.5 && kappa0 <= 1.5)) {
    throw InvalidInput(fmt::format(
        "initial curvature kappa0 = {} is outside the range 0.5 <= kappa0 <= 1.5 of Table 5.3 and "
        "eqs. 5.138-5.142",
        kappa0));
  }
}

// Table 5.3 row interpolated linearly in kappa0.
CurvedPinnedPinnedTableRow interpolate_table_5_3(double kappa0) {
  require_kappa(kappa0);
  const auto& rows = table_5_3();
  for (std::size_t i = 1; i < rows.size(); ++i) {
    if (kappa0 > rows[i].kappa0) continue;
    const auto& lo = rows[i - 1];
    const auto& hi = rows[i];
    const double f = (kappa0 - lo.kappa0) / (hi.kappa0 - lo.kappa0);
    const auto mix = [f](double x, double y) { return x + f * (y - x); };
    return {kappa0,
            mix(lo.gamma, hi.gamma),
            mix(lo.rho, hi.rho),
            mix(lo.delta_theta_max_gamma, hi.delta_theta_max_gamma),
            mix(lo.K_theta, hi.K_theta),
            mix(lo.delta_theta_max_K, hi.delta_theta_max_K)};
  }
  return rows.back();
}

}  // namespace

CurvedPinnedPinnedConstants CurvedPinnedPinnedConstants::from_curve_fits(double kappa0) {
  const CurvedPinnedPinnedTableRow row = interpolate_table_5_3(kappa0);
  return {kappa0,
          pinned_pinned_gamma_curve_fit(kappa0),
          pinned_pinned_K_theta_curve_fit(kappa0),
          row.delta_theta_max_gamma,
          row.delta_theta_max_K,
          fmt::format("eqs. 5.138-5.139 and 5.142 at kappa0 = {} (limits from Table 5.3)", kappa0)};
}

CurvedPinnedPinnedConstants CurvedPinnedPinnedConstants::from_table(double kappa0) {
  const CurvedPinnedPinnedTableRow row = interpolate_table_5_3(kappa0);
  return {kappa0,
          row.gamma,
          row.K_theta,
          row.delta_theta_max_gamma,
          row.delta_theta_max_K,
          fmt::format("Table 5.3 at kappa0 = {}", kappa0)};
}

CurvedPinnedPinnedSegment::CurvedPinnedPinnedSegment(CurvedPinnedPinnedConstants constants)
    : constants_(std::move(constants)) {
  require_kappa(constants_.kappa0);
  if (!(constants_.gamma > 0.0 && constants_.gamma <= 1.0) || !(constants_.K_theta > 0.0) ||
      !(constants_.delta_theta_max_gamma > 0.0) || !(constants_.delta_theta_max_K > 0.0)) {
    throw InvalidInput(fmt::format(
        "curved pinned-pinned constants gamma = {} (allowed (0, 1]), K_theta = {}, limits {} and "
        "{} rad (allowed > 0)",
        constants_.gamma,
        constants_.K_theta,
        constants_.delta_theta_max_gamma,
        constants_.delta_theta_max_K));
  }
  const double k = constants_.kappa0;
  a_i_ = (2.0 / k) * std::sin(k / 2.0);          // eq. 5.135: chord of the arc
  b_i_ = (1.0 / k) * (1.0 - std::cos(k / 2.0));  // eq. 5.136: rise of the arc
  const double dx = a_i_ - (1.0 - constants_.gamma);
  Theta_i_ = std::atan2(2.0 * b_i_, dx);  // eq. 5.137
  rho_ = std::hypot(dx, 2.0 * b_i_);      // eq. 5.137
}

PrbGeometry CurvedPinnedPinnedSegment::geometry() const {
  return {constants_.gamma, rho_ / 2.0, (1.0 - constants_.gamma) / 2.0, 0.0, 2};
}

double CurvedPinnedPinnedSegment::stiffness_coefficient() const {
  return 2.0 * rho_ * constants_.K_theta;
}

TipPose CurvedPinnedPinnedSegment::tip(double Theta) const {
  return {1.0 - constants_.gamma + rho_ * std::cos(Theta), 0.0, 0.0};
}

double CurvedPinnedPinnedSegment::rise(double Theta) const { return 0.5 * rho_ * std::sin(Theta); }

double CurvedPinnedPinnedSegment::generalized_load(double Theta, const EndLoad& load) const {
  if (load.Fy != 0.0 || load.mu != 0.0) {
    throw InvalidInput(fmt::format(
        "load Fy = {}, mu = {} on a pinned-pinned segment, which carries only a force along the "
        "line of its pins (Fx)",
        load.Fy,
        load.mu));
  }
  return -load.Fx * rho_ * std::sin(Theta);  // F . d(pin B)/dTheta with a = 1 - gamma + rho cos
}

double CurvedPinnedPinnedSegment::spring_moment(double Theta) const {
  return 2.0 * stiffness_coefficient() * (Theta - Theta_i_);
}

ValidityLimits CurvedPinnedPinnedSegment::limits() const {
  return {Theta_i_ + constants_.delta_theta_max_gamma,
          Theta_i_ + constants_.delta_theta_max_K,
          "Table 5.3 (Delta Theta)_max added to Theta_i; " + constants_.source};
}

double CurvedPinnedPinnedSegment::max_moment(double Theta, const EndLoad& load) const {
  return -load.Fx * rise(Theta);  // eq. 5.147: M = F b with F = -Fx compressive
}

}  // namespace flexure
