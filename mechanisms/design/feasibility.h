#pragma once
// The closed-form design equations of Weight (2001) ch. 4 and 8 that turn a sub-class's
// nondimensional numbers (beta, lambda, kappa, K, M, n from the PRBM model) into dimensions:
// stroke, stress, force, the other flexures' sections and the feasibility screens (docs/design.md
// "Dimensional design"). SI units throughout; d is in % of r_tot.
#include "flexure/mechanisms/cfm/cfm_model.h"

namespace flexure::design {

// Eq. 8.6 solved for d: d = 100 disp lambda/l_tot (disp: slider travel, l_tot: total length of
// the flexible and rigid links of one half, lambda = l_tot/r_tot).
double stroke_percent_for(double displacement, double l_tot, double lambda);

// Eq. 8.5: the bending stress of the primary flexure at the end of the stroke,
// sigma = E lambda M d^n h_p/(2 l_tot).
double primary_stress(
    double E, double lambda, double M, double n, double d, double h_p, double l_tot);

// Eq. 8.5 solved for h_p at sigma = S_y/SF (eqs. 4.30, 8.18): h_max = 2 Omega l_tot/(SF lambda M
// d^n) with Omega = S_y/E (eq. 4.18).
double max_primary_thickness(
    double omega, double safety_factor, double lambda, double M, double n, double d, double l_tot);

// Eq. 8.5 with d from eq. 8.6 solved for l_tot (thesis example 2's "length needed"):
// l^(1+n) = h_p SF lambda M (100 disp lambda)^n/(2 Omega).
double length_for_stress(double omega,
                         double safety_factor,
                         double lambda,
                         double M,
                         double n,
                         double h_p,
                         double displacement);

// Eq. 8.17: the largest M a sub-class may have to be stress-feasible (Method 1 screen, Table
// 8.2): M = 2 Omega l_tot/(SF lambda h d^n).
double stress_screen_M(
    double omega, double safety_factor, double lambda, double n, double h, double d, double l_tot);

// The force design equation 8.2 (class 1B: eq. 8.3) in the form F = c E b_p h_p^3/l_tot^2 with
// c = lambda^2 kappa_p beta/(12 kappa_ref K_{p-1}) (K_0 = 1; kappa_ref = kappa_1, or kappa_2 for
// class 1B whose reference spring is k2, eq. 2.19).
struct ForceCoefficient {
  double c = 0.0;
  int primary_pivot = 0;
};
ForceCoefficient force_coefficient(const cfm::CfmResult& model);
double design_force(const ForceCoefficient& f, double E, double b_p, double h_p, double l_tot);
// Eq. 8.2 solved for one of h_p, b_p, l_tot.
double thickness_for_force(const ForceCoefficient& f, double F, double E, double b_p, double l_tot);
double width_for_force(const ForceCoefficient& f, double F, double E, double h_p, double l_tot);
double length_for_force(const ForceCoefficient& f, double F, double E, double b_p, double h_p);

// Eq. 8.7: I_i/I_p = K_{i-1} kappa_p/(K_{p-1} kappa_i) (= D_equal_i, eq. 5.36); 0 for a pin.
double second_moment_ratio(const cfm::CfmResult& model, int pivot);

}  // namespace flexure::design
