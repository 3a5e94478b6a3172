#include "flexure/mechanisms/prbm_virtual_work.h"

#include <fmt/format.h>

#include <cmath>

#include "flexure/solver/common/status.h"

namespace flexure::mechanism {

VirtualWorkState virtual_work_state(double r2,
                                    double r3,
                                    const std::array<double, 3>& k,
                                    double displacement) {
  if (!std::isfinite(r2) || !std::isfinite(r3) || r2 <= 0.0 || r3 <= 0.0) {
    throw InvalidInput(
        fmt::format("r2 and r3 must be finite and > 0 (got r2 = {}, r3 = {})", r2, r3));
  }
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(k[i]) || k[i] < 0.0) {
      throw InvalidInput(fmt::format("k{} must be finite and >= 0 (got {})", i + 1, k[i]));
    }
  }
  const double r_tot = r2 + r3;
  const double dx = displacement;
  if (!std::isfinite(dx) || dx <= 0.0 || dx >= r_tot) {
    throw InvalidInput(fmt::format(
        "Delta x must be in (0, r2 + r3 = {:.6g}) m (got {:.6g})", r_tot, displacement));
  }
  // Pivot 2 = intersection of the circles of radius r2 about the ground pivot (origin) and r3
  // about the slider pivot (r1, 0), above the axis. r2 - x2 is written without cancellation:
  // r2 - x2 = (r3^2 - (r1 - r2)^2)/(2 r1) = Delta x (2 r3 - Delta x)/(2 r1).
  const double r1 = r_tot - dx;
  const double r2_minus_x2 = dx * (2.0 * r3 - dx) / (2.0 * r1);
  const double x2 = r2 - r2_minus_x2;
  const double y2 = std::sqrt(std::max(0.0, r2_minus_x2 * (2.0 * r2 - r2_minus_x2)));
  // Past the toggle position the crank (x2 < 0) or the coupler (x2 > r1) has turned beyond the
  // perpendicular to the slider axis: the straight-start branch has ended.
  const double slack = 1e-12 * r_tot;
  if (x2 < -slack || r1 - x2 < -slack) {
    throw InvalidInput(fmt::format(
        "Delta x = {:.6g} m is past the toggle position of r2 = {:.6g} m, r3 = {:.6g} m",
        dx,
        r2,
        r3));
  }
  VirtualWorkState s;
  s.theta2 = std::atan2(y2, x2);
  s.theta3 = std::atan2(-y2, r1 - x2);
  // Loop-closure rates (derivation in the header).
  const double denom = std::sin(s.theta2 - s.theta3);
  const double dtheta2 = std::cos(s.theta3) / (r2 * denom);
  const double dtheta3 = -std::cos(s.theta2) / (r3 * denom);
  // Second derivatives: with D = sin(theta2 - theta3), D' = cos(theta2 - theta3) (theta2' -
  // theta3'), the quotient rule on the rates above gives
  //   theta2'' = (-sin theta3 theta3' D - cos theta3 D') / (r2 D^2),
  //   theta3'' = ( sin theta2 theta2' D + cos theta2 D') / (r3 D^2).
  const double ddenom = std::cos(s.theta2 - s.theta3) * (dtheta2 - dtheta3);
  const double d2theta2 =
      (-std::sin(s.theta3) * dtheta3 * denom - std::cos(s.theta3) * ddenom) / (r2 * denom * denom);
  const double d2theta3 =
      (std::sin(s.theta2) * dtheta2 * denom + std::cos(s.theta2) * ddenom) / (r3 * denom * denom);
  s.psi = {s.theta2, s.theta2 - s.theta3, -s.theta3};
  s.dpsi = {dtheta2, dtheta2 - dtheta3, -dtheta3};
  s.d2psi = {d2theta2, d2theta2 - d2theta3, -d2theta3};
  for (int i = 0; i < 3; ++i) {
    s.force += k[i] * s.psi[i] * s.dpsi[i];
    s.energy += 0.5 * k[i] * s.psi[i] * s.psi[i];
    s.unloaded_stiffness += k[i] * s.dpsi[i] * s.dpsi[i];
    s.stiffness += k[i] * (s.dpsi[i] * s.dpsi[i] + s.psi[i] * s.d2psi[i]);
  }
  return s;
}

}  // namespace flexure::mechanism
