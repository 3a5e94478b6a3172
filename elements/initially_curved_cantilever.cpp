#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <utility>

#include "flexure/elements/prbm_element.h"
#include "flexure/solver/common/status.h"

namespace flexure {

CurvedCantileverConstants CurvedCantileverConstants::from_table(double kappa0) {
  const auto& rows = table_5_2();
  if (!(kappa0 >= rows.front().kappa0 && kappa0 <= rows.back().kappa0)) {
    throw InvalidInput(fmt::format(
        "initial curvature kappa0 = {} is outside Table 5.2, which covers {} <= kappa0 <= {}",
        kappa0,
        rows.front().kappa0,
        rows.back().kappa0));
  }
  CurvedCantileverConstants c;
  c.kappa0 = kappa0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    if (kappa0 > rows[i].kappa0) continue;
    const double f = (kappa0 - rows[i - 1].kappa0) / (rows[i].kappa0 - rows[i - 1].kappa0);
    c.gamma = rows[i - 1].gamma + f * (rows[i].gamma - rows[i - 1].gamma);
    c.K_theta = rows[i - 1].K_theta + f * (rows[i].K_theta - rows[i - 1].K_theta);
    break;
  }
  c.source = fmt::format("Table 5.2 at kappa0 = {}", kappa0);
  return c;
}

CurvedCantileverConstants CurvedCantileverConstants::from_derivation(double kappa0,
                                                                     double n_min,
                                                                     double n_max) {
  const CurvedCantileverAverage a = derive_initially_curved_average(kappa0, n_min, n_max);
  if (!a.converged()) {
    throw NoConvergence("curved-cantilever constants could not be derived: " + a.message);
  }
  CurvedCantileverConstants c;
  c.kappa0 = kappa0;
  c.gamma = a.gamma;
  c.K_theta = a.K_theta;
  c.c_theta = a.c_theta;
  c.source =
      fmt::format("derived at kappa0 = {}, averaged over {} <= n <= {}", kappa0, n_min, n_max);
  return c;
}

InitiallyCurvedCantilever::InitiallyCurvedCantilever(CurvedCantileverConstants constants)
    : constants_(std::move(constants)) {
  const double k = constants_.kappa0;
  if (!std::isfinite(k) || k < 0.0 || k > 2.0 * std::numbers::pi) {
    throw InvalidInput(fmt::format(
        "initial curvature kappa0 = l/R_i = {} is outside the allowed range [0, 2 pi]", k));
  }
  if (!(constants_.gamma > 0.0 && constants_.gamma <= 1.0) || !(constants_.K_theta > 0.0) ||
      !(constants_.c_theta > 0.0)) {
    throw InvalidInput(fmt::format(
        "curved-cantilever constants gamma = {} (allowed (0, 1]), K_theta = {}, c_theta = {} "
        "(allowed > 0)",
        constants_.gamma,
        constants_.K_theta,
        constants_.c_theta));
  }
  // Eqs. 5.117-5.118; the series avoids 0/0 for a straight beam.
  if (k < 1e-6) {
    a_i_ = 1.0 - k * k / 6.0;
    b_i_ = k / 2.0;
  } else {
    a_i_ = std::sin(k) / k;
    b_i_ = (1.0 - std::cos(k)) / k;
  }
  const double dx = a_i_ - (1.0 - constants_.gamma);
  Theta_i_ = std::atan2(b_i_, dx);  // eq. 5.115
  rho_ = std::hypot(dx, b_i_);      // eq. 5.116
}

PrbGeometry InitiallyCurvedCantilever::geometry() const {
  // Eqs. 5.115-5.120 put the pivot at ((1 - gamma) l, 0), on the clamp's tangent, not on the arc.
  return {constants_.gamma, rho_, 1.0 - constants_.gamma, 0.0, 1};
}

double InitiallyCurvedCantilever::stiffness_coefficient() const {
  return rho_ * constants_.K_theta;
}

TipPose InitiallyCurvedCantilever::tip(double Theta) const {
  return {1.0 - constants_.gamma + rho_ * std::cos(Theta),
          rho_ * std::sin(Theta),
          constants_.kappa0 + constants_.c_theta * (Theta - Theta_i_)};
}

double InitiallyCurvedCantilever::generalized_load(double Theta, const EndLoad& load) const {
  if (load.mu != 0.0) {
    throw InvalidInput(fmt::format(
        "tip moment mu = {} on the initially curved cantilever, which models a tip force only "
        "(a moment in the sense of the curvature is a change of kappa0, Howell §5.7 case I)",
        load.mu));
  }
  return link_force_work(rho_, Theta, load);  // rho F_t, eq. 5.125
}

double InitiallyCurvedCantilever::spring_moment(double Theta) const {
  return stiffness_coefficient() * (Theta - Theta_i_);
}

ValidityLimits InitiallyCurvedCantilever::limits() const {
  const double deg = std::numbers::pi / 180.0;
  return {Theta_i_ + 64.3 * deg,
          Theta_i_ + 58.5 * deg,
          "no published limit for curved beams: straight-beam Table 5.1 n = 0 limits applied to "
          "Theta - Theta_i"};
}

}  // namespace flexure
