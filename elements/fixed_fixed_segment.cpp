#include <fmt/format.h>

#include <cmath>
#include <utility>

#include "flexure/elements/prbm_element.h"
#include "flexure/solver/common/status.h"

namespace flexure {

FixedFixedSegment::FixedFixedSegment(FixedPinnedConstants constants, double end_angle)
    : constants_(std::move(constants)), end_angle_(end_angle) {
  constants_.validate();
  require_finite(end_angle, "prescribed end angle theta0");
}

PrbGeometry FixedFixedSegment::geometry() const {
  return {constants_.gamma, constants_.gamma, end_link(), 0.0, 2};
}

double FixedFixedSegment::stiffness_coefficient() const {
  return 2.0 * constants_.gamma * constants_.K_theta;
}

TipPose FixedFixedSegment::tip(double Theta, double theta0) const {
  const double e = end_link();
  const double g = constants_.gamma;
  return {e + g * std::cos(Theta) + e * std::cos(theta0),
          g * std::sin(Theta) + e * std::sin(theta0),
          theta0};
}

TipPose FixedFixedSegment::tip(double Theta) const { return tip(Theta, end_angle_); }

double FixedFixedSegment::generalized_load(double Theta, const EndLoad& load) const {
  return link_force_work(constants_.gamma, Theta, load);
}

double FixedFixedSegment::spring_moment(double Theta) const {
  // Springs psi1 = Theta (clamp side), psi2 = theta0 - Theta (tip side): K psi1 - K psi2.
  const double K = stiffness_coefficient();
  return K * Theta + K * (Theta - end_angle_);
}

ValidityLimits FixedFixedSegment::limits() const {
  return {constants_.theta_max_gamma,
          constants_.theta_max_K,
          "no published limit for §5.7; fixed-pinned limits of " + constants_.source};
}

double FixedFixedSegment::max_moment(double Theta, const EndLoad& load) const {
  // Couple needed to hold theta0: zero generalised force of the end link (eq. 6.222).
  const double K = stiffness_coefficient();
  const double reaction = K * (end_angle_ - Theta) - link_force_work(end_link(), end_angle_, load);
  const TipPose t = tip(Theta);
  return reaction + t.a_over_l * load.Fy - t.b_over_l * load.Fx;
}

FixedFixedEquilibrium FixedFixedSegment::solve_free_end(const EndLoad& load) const {
  require_finite(load.Fx, "tip force Fx");
  require_finite(load.Fy, "tip force Fy");
  require_finite(load.mu, "tip moment mu");
  constexpr double kTolerance = 1e-13;  // on both generalised forces, nondimensional
  constexpr double kStep = 1e-6;        // central differences for the 2x2 Jacobian
  constexpr double kMaxStep = 0.25;     // rad, keeps Newton on the branch from the unloaded state
  constexpr int kMaxIterations = 100;
  const double K = stiffness_coefficient();
  const double g = constants_.gamma;
  const double e = end_link();
  // Generalised forces Q = F dz/dq + mu dtheta0/dq - dV/dq for q = (Theta, theta0).
  const auto Q = [&](double Theta, double theta0, double& q1, double& q2) {
    q1 = link_force_work(g, Theta, load) - K * Theta + K * (theta0 - Theta);
    q2 = link_force_work(e, theta0, load) + load.mu - K * (theta0 - Theta);
  };
  FixedFixedEquilibrium result;
  double x = 0.0, y = 0.0, q1 = 0.0, q2 = 0.0;
  Q(x, y, q1, q2);
  for (int i = 0; i < kMaxIterations; ++i) {
    result.iterations = i;
    if (std::max(std::abs(q1), std::abs(q2)) <= kTolerance) break;
    double a1, a2, b1, b2, c1, c2, d1, d2;
    Q(x + kStep, y, a1, a2);
    Q(x - kStep, y, b1, b2);
    Q(x, y + kStep, c1, c2);
    Q(x, y - kStep, d1, d2);
    const double j11 = (a1 - b1) / (2 * kStep), j21 = (a2 - b2) / (2 * kStep);
    const double j12 = (c1 - d1) / (2 * kStep), j22 = (c2 - d2) / (2 * kStep);
    const double det = j11 * j22 - j12 * j21;
    if (!std::isfinite(det) || det == 0.0) break;
    double dx = (-q1 * j22 + q2 * j12) / det;
    double dy = (-q2 * j11 + q1 * j21) / det;
    const double scale = std::max(1.0, std::max(std::abs(dx), std::abs(dy)) / kMaxStep);
    x += dx / scale;
    y += dy / scale;
    Q(x, y, q1, q2);
  }
  result.Theta = x;
  result.theta0 = y;
  result.residual = std::max(std::abs(q1), std::abs(q2));
  result.set_converged(std::isfinite(result.residual) && result.residual <= kTolerance);
  result.tip = tip(x, y);
  result.message = result.converged()
                       ? fmt::format("generalised forces {:.2e} <= {:.0e} after {} Newton steps",
                                     result.residual,
                                     kTolerance,
                                     result.iterations)
                       : fmt::format(
                             "no equilibrium: generalised force {:.3e} at Theta = {:.6f}, "
                             "theta0 = {:.6f} after {} steps",
                             result.residual,
                             x,
                             y,
                             result.iterations);
  return result;
}

}  // namespace flexure
