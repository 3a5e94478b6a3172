#include "flexure/mechanisms/cfm/slider_crank.h"

#include <algorithm>
#include <cmath>

namespace flexure::cfm {

SliderCrankPose slider_crank_pose(double R, double u) {
  SliderCrankPose pose;
  pose.u = u;
  const double r_tot = 1.0 + R;
  pose.r1 = r_tot * (1.0 - u);  // eq. 2.15 with r2 = 1
  // Eq. 2.1 rewritten: 1 - cos(theta2) = (R + 1 - r1)(R + r1 - 1)/(2 r1)
  //                                    = r_tot u (2R - r_tot u)/(2 r1),
  // and theta2 = 2 asin(sqrt((1 - cos theta2)/2)), which keeps full precision near u = 0 where
  // acos(1 - eps) loses half the digits.
  double half_versine = r_tot * u * (2.0 * R - r_tot * u) / (4.0 * pose.r1);
  half_versine = std::clamp(half_versine, 0.0, 1.0);
  pose.theta2 = 2.0 * std::asin(std::sqrt(half_versine));
  // Eq. 2.2, principal branch; the clamp only absorbs rounding at the toggle position itself.
  const double sin_theta3 = std::clamp(-std::sin(pose.theta2) / R, -1.0, 1.0);
  pose.theta3 = std::asin(sin_theta3);
  pose.cos_theta2 = std::cos(pose.theta2);
  pose.cos_theta3 = std::cos(pose.theta3);
  return pose;
}

double loop_closure_residual(double R, const SliderCrankPose& pose) {
  return std::abs(pose.r1 - (pose.cos_theta2 + R * pose.cos_theta3));
}

double toggle_stroke_percent(double R) {
  if (R == 1.0) return 100.0;
  return 100.0 * (1.0 - std::sqrt(std::abs(1.0 - R) / (1.0 + R)));
}

double force_function_phi(
    double R, double K1, double K2, bool reference_k2, const SliderCrankPose& pose) {
  const double c2 = pose.cos_theta2;
  const double c3 = pose.cos_theta3;
  const double ground = reference_k2 ? 0.0 : pose.psi1();  // eq. 2.19 drops the k1 term
  const double middle = K1 * pose.psi2();
  const double slider = K2 * pose.psi3();
  // Thesis eq. 2.14 / Howell eq. 10.14 with psi2 = theta2 - theta3p, psi3 = -theta3p.
  return (R * c3 * (ground + middle) + c2 * (middle + slider)) /
         (R * std::sin(pose.theta2 - pose.theta3));
}

}  // namespace flexure::cfm
