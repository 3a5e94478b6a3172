#pragma once
// The stress power law of a constant-force mechanism's primary pivot, alpha_p = M d^n (Weight 2001
// §4.1.2, eq. 4.28; Ch. 7 tables; docs/design.md "Stress power law"): alpha_p = kappa_p psi_p is
// the stress parameter of eq. 4.16 along the stroke, d the slider displacement in % of r_tot.
// Chapter 8 sizes a mechanism for stress with it (eq. 8.5).
//
// Two fits, as the thesis made them:
//  * fit_stress_power_law: the Ch. 7 / App. D values -- nonlinear least squares of the residuals
//    M d_k^n - alpha_p(d_k) over the stroke points of the model's sampling (the thesis code's
//    lsqcurvefit, App. B.1.3), the primary pivot being the one at the end of the stroke;
//  * fit_stress_power_law_loglog: Table 4.2's values -- a straight line through (ln d, ln alpha_p)
//    on the integer grid d = 1, 2, ..., floor(d_max) (a spreadsheet power trend line).
#include "flexure/mechanisms/cfm/cfm_model.h"

namespace flexure::cfm {

struct StressPowerLaw {
  double M = 0.0;
  double n = 0.0;
  int primary_pivot = 0;      // p of the fitted alpha_p
  double rms_residual = 0.0;  // of M d^n - alpha_p over the fitted points
  int points = 0;
};

// Throws InvalidInput as CfmModel::evaluate does, and NoConvergence if the least-squares
// iteration does not settle (never seen on the 68 sub-classes).
StressPowerLaw fit_stress_power_law(const CfmParameters& parameters,
                                    const CfmOptions& options = {});

// Table 4.2's log-log regression (needs d >= 2 so that the grid has two points).
StressPowerLaw fit_stress_power_law_loglog(const CfmParameters& parameters);

}  // namespace flexure::cfm
