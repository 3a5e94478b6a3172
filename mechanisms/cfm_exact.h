#pragma once
// The exact (elastica) model of a nondimensional constant-force mechanism (issue 5, `flexure cfm
// --exact`): the design variables (configuration, R, K1, K2, stroke d) are turned into an
// equivalent dimensional MechanismDesign -- r2 + r3 = 1, E = 1, unit widths, flexible segments
// sized by the PRBM rules of thesis Table 8.1 (an l segment r/gamma long, an s pivot 0.1 r long,
// mechanism.h) with flexural rigidities in the ratios K1 = k2/k1, K2 = k3/k1 imply (thesis eqs.
// 2.11-2.12; class 1B: k2 is the reference, eq. 2.19) -- and solved over the stroke both ways, the
// PRBM (mechanism_analysis.h) and the exact model (mechanism_exact.h), starting from the straight
// position. Forces are reported in the nondimensional form of the PRBM, Phi = F r2/k1 (class 1B:
// F r2/k2; thesis eq. 2.13), so Phi_exact is directly comparable with CfmResult::Phi.
//
// The thesis optimised the PRBM only, so the exact values differ from the tabulated ones; the
// differences are listed in docs/validation.md.
#include <string>
#include <vector>

#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/solver/common/status.h"

namespace flexure::cfm {

// The equivalent design of a nondimensional CFM (see the top of this file); stroke_percent is the
// effective stroke (after the toggle clamp). Throws InvalidInput as MechanismDesign::finalise.
mechanism::MechanismDesign cfm_equivalent_design(
    const std::string& config, double R, double K1, double K2, double stroke_percent);

struct CfmExactOptions {
  int points = 50;  // equally spaced stroke points Delta x = k d (r2 + r3)/points, k = 1..points
  mechanism::ExactMechanismOptions solver;  // the exact model's solver settings
  // Called after every exact stroke point, (done, points); empty: no calls (a progress display:
  // `cfm --table --exact` runs 68 strokes).
  mechanism::StrokeProgress progress;

  // Throws InvalidInput naming the first field outside its range.
  void validate() const;
};

struct CfmExactResult : SolveStatus {
  mechanism::MechanismDesign design;    // the equivalent design (r2 + r3 = 1, E = 1)
  double reference_stiffness = 0.0;     // k1 (class 1B: k2) of the design, to scale F to Phi
  std::vector<double> stroke_percent;   // 100 Delta x/(r2 + r3) of every point
  std::vector<double> Phi_prbm;         // PRBM F r2/k_ref per point (dimensional PRBM, rescaled)
  std::vector<double> Phi_exact_curve;  // exact F r2/k_ref per point
  double Phi_prbm_mean = 0.0;           // mean of Phi_prbm (equals CfmModel with kUniform)
  // 100 min/max of Phi_prbm and of Phi_exact_curve; 0 where that force vanishes or changes sign
  // within the stroke (mechanisms/cfm/constant_force.h; the exact force of a class 1A mechanism
  // clamped at the toggle turns negative before it: -5.33 % for lpp, R = 0.8853).
  double percent_constant_force_prbm = 0.0;
  double Phi_exact = 0.0;  // mean of Phi_exact_curve
  double percent_constant_force_exact = 0.0;
  bool force_vanishes_exact = false;        // Phi_exact_curve is zero within the stroke
  bool force_changes_sign_exact = false;    // Phi_exact_curve takes both signs
  double max_force_error = 0.0;             // max over the stroke of |F_prbm - F_exact|/|F_exact|
  double max_force_error_at_percent = 0.0;  // stroke (% of r2 + r3) of that maximum
  // converged(): every exact point converged
  // iterations: shooting Newton iterations over the stroke
  // residual: largest exact-point residual
};

// Solves the mechanism of `prbm` (its config, R, K1, K2 as used and effective stroke) with the
// PRBM and the exact model. Never throws for non-convergence (converged = false, message says at
// which point it stopped); throws InvalidInput for options.points outside [2, 100000].
CfmExactResult solve_cfm_exact(const CfmResult& prbm, const CfmExactOptions& options);

}  // namespace flexure::cfm
