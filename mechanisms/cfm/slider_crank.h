#pragma once
// Kinematics and force function of the PRBM slider-crank with three torsional springs
// (Weight 2001 eqs. 2.1-2.3 and 2.14; Howell eqs. 10.1-10.4 and 10.14), nondimensional with the
// crank r2 = 1, coupler r3 = R and slider displacement u = Delta x/(r2 + r3).
//
// Angle convention (docs/cfm.md §3 item 1): the printed equations (thesis eqs. 2.9, 2.14, 2.19;
// Howell eqs. 10.4, 10.14) write the spring rotations as (2 pi + theta2 - theta3) and
// (2 pi - theta3), which is right only with theta3 measured in (3 pi/2, 2 pi] (as the thesis code
// of App. B.1.3 does). Here theta3 is the principal value theta3p = asin(-sin(theta2)/R)
// <= 0 and the spring rotations are psi1 = theta2, psi2 = theta2 - theta3p, psi3 = -theta3p; all
// three are zero in the straight (undeflected) position. sin(theta2 - theta3) and cos(theta3)
// do not change under the 2 pi shift.

namespace flexure::cfm {

struct SliderCrankPose {
  double u = 0.0;       // slider displacement Delta x/(r2 + r3)
  double r1 = 0.0;      // ground-to-slider distance / r2 (eq. 2.15)
  double theta2 = 0.0;  // crank angle (eq. 2.1), 0 <= theta2 <= pi/2 on the valid branch
  double theta3 = 0.0;  // principal coupler angle theta3p (eq. 2.2), -pi/2 <= theta3 <= 0
  // cos(theta2) and cos(theta3), computed once here: the force function (eq. 2.14) and the loop
  // closure (eq. 2.3) both need them, and cos was a third of a thesis-sampled stroke's time.
  double cos_theta2 = 1.0;
  double cos_theta3 = 1.0;
  // Spring rotations at pivots 1 (ground), 2 (middle), 3 (slider); zero when straight.
  double psi1() const { return theta2; }
  double psi2() const { return theta2 - theta3; }
  double psi3() const { return -theta3; }
};

// Pose at slider displacement u (0 <= u <= toggle limit) of the mechanism with coupler ratio R.
// theta2 is computed from 1 - cos(theta2) in factored form so that it stays accurate as u -> 0.
SliderCrankPose slider_crank_pose(double R, double u);

// Loop-closure residual |r1 - (cos theta2 + R cos theta3)| of eq. 2.3 (lengths / r2).
double loop_closure_residual(double R, const SliderCrankPose& pose);

// Largest stroke, in % of r2 + r3, for which the asin branch of eq. 2.2 is the mechanism's
// configuration (thesis code App. B.1.3 `rimin`; docs/cfm.md §1.3):
//  R < 1: until the coupler is perpendicular to the slider axis, 100 (1 - sqrt((1-R)/(1+R)));
//  R > 1: until the crank is perpendicular (theta2 = 90 deg), 100 (1 - sqrt((R-1)/(R+1)));
//  R = 1: 100 (the mechanism folds flat onto the ground pivot).
double toggle_stroke_percent(double R);

// Nondimensional slider force Phi = F r2/k1 (thesis eq. 2.14 with the principal-angle spring
// rotations). With reference_k2 (class 1B, k1 = 0, eq. 2.19) the ground-spring term is dropped
// and Phi' = F r2/k2, with K1 the (unit) middle spring and K2 the slider spring.
double force_function_phi(
    double R, double K1, double K2, bool reference_k2, const SliderCrankPose& pose);

}  // namespace flexure::cfm
