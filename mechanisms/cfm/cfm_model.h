#pragma once
// Nondimensional PRBM model of a constant-force slider mechanism (Weight 2001 ch. 2, 4, 5 and
// App. B.1.3; Howell §10.1): force function Phi over a stroke, its mean, the percent constant force
// Xi' = 100 min F/max F, and the derived design quantities of the thesis tables (beta, lambda,
// kappa_i, primary pivot, Psi, d_N).
//
// Inputs are the thesis's design variables: configuration, R = r3/r2, K1 = k2/k1, K2 = k3/k1 and
// the stroke d in % of r2 + r3. Strokes past the toggle position are clamped as the thesis code
// does (App. B.1.3 `rimin`; docs/cfm.md §1.3); the result says so (stroke_clamped) and reports
// the effective stroke.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "flexure/mechanisms/cfm/cfm_configuration.h"
#include "flexure/solver/common/status.h"

namespace flexure::cfm {

struct CfmParameters {
  std::string config;            // configuration name: spp, lpp, psp, plp, ssp, slp, sps, lps, sss
  double R = 1.0;                // r3/r2 (thesis eq. 2.10), > 0
  std::optional<double> K1;      // k2/k1 (eq. 2.11); required when pivot 2 has a spring, except
                                 // class 1B where k2 is the reference and K1 = 1 (eq. 2.19)
  std::optional<double> K2;      // k3/k1 (eq. 2.12); required when pivot 3 has a spring
  double stroke_percent = 16.0;  // d: design stroke in % of r2 + r3, 0 < d <= 100
};

// How the stroke 0 < Delta x <= d (r2 + r3) is sampled for the mean and the min/max.
enum class StrokeSampling {
  // Weight's Matlab model (App. B.1.3, `deltax=0.001:0.001*ri*d:ri*d`, last point forced to ri*d):
  // the mechanism is scaled to l_tot = 1 (r_tot = 1/lambda), the first point is Delta x = 0.001
  // and the step is 0.001 r_tot d, i.e. about 1000 points. The Ch. 7 tables (68 sub-classes) use
  // this sampling, which is why the first point depends on lambda (psp-a and plp-a differ in the
  // fourth digit of Phi).
  kThesisCode,
  // `points` equally spaced points Delta x = k d (r2 + r3)/points, k = 1..points: Howell §10.1
  // "50 equally spaced points" (Table 10.1 = thesis Table 2.1); the 0/0 point Delta x = 0 is left
  // out.
  kUniform,
};

struct CfmOptions {
  StrokeSampling sampling = StrokeSampling::kThesisCode;  // see StrokeSampling
  int points = 50;  // number of points for kUniform (>= 1); ignored by kThesisCode
  // Evaluate only every stride-th point of the sampling (the 1st, 1 + stride-th, ...) and its
  // last point: a subset of the full sampling with the same first and last points, so its
  // Phi_min/Phi_max lie inside the full sampling's and its Xi' and C are never below them; the
  // mean Phi counts the points in between on straight lines, which keeps it within
  // O((stride step)^2) of the full sampling's. For the coarse phase of a synthesis
  // (mechanisms/design/cfm_synthesis.h); 1 = every point.
  int stride = 1;
  bool keep_curve = false;  // fill CfmResult::curve (costs one allocation)

  // Throws InvalidInput naming the first field outside its range.
  void validate() const;
};

// One stroke point.
struct CfmCurvePoint {
  double stroke_percent = 0.0;  // 100 Delta x/(r2 + r3)
  double theta2 = 0.0;          // crank angle, rad
  double theta3 = 0.0;          // principal coupler angle, rad (<= 0)
  double Phi = 0.0;             // F r2/k1 (class 1B: F r2/k2)
};

struct CfmResult : SolveStatus {
  std::string config;      // configuration name
  std::string class_name;  // 1A ... 3A
  double R = 0.0;
  double K1 = 0.0;  // as used (0 for a missing spring, 1 for class 1B)
  double K2 = 0.0;
  double requested_stroke_percent = 0.0;  // d as given
  double stroke_percent = 0.0;            // effective stroke after the toggle clamp
  double toggle_stroke_percent = 0.0;     // d_lim of the clamp (docs/cfm.md §1.3)
  bool stroke_clamped = false;            // requested stroke was past the toggle position
  double Phi = 0.0;      // mean of Phi over the sampled stroke (thesis `average_phi`)
  double Phi_min = 0.0;  // smallest sampled Phi
  double Phi_max = 0.0;  // largest sampled Phi
  double Xi = 0.0;       // Phi_max/Phi_min (eq. 2.17); unbounded when force_vanishes
  // Phi_min <= kForceVanishesRelative |Phi_max| (mechanisms/cfm/constant_force.h): the force is
  // zero within the stroke to rounding (a class 1A mechanism at its toggle position, where the
  // crank spring's moment has no lever along the slider) or changes sign; Xi is then meaningless.
  bool force_vanishes = false;
  double percent_constant_force = 0.0;  // Xi' = 100 Phi_min/Phi_max (eq. 5.22)
  double lambda = 0.0;                  // l_tot/r_tot, length parameter (thesis Table 5.1)
  double beta = 0.0;  // F r_tot^2/(E I_ref) averaged over the stroke (eq. 4.43; 1B eq. 4.55)
  std::array<double, 3> kappa{};  // kappa_i = gamma zeta K_theta/rho (eq. 4.51); 0 for a pin
  int primary_pivot = 0;          // pivot (1..3) with the highest stress at the end of the stroke
  std::array<double, 3> alpha_end{};  // stress parameter alpha_i (eq. 4.16) at the end of stroke
  double Psi_raw = 0.0;               // stiffness parameter (eq. 5.19) before normalisation
  // Psi_raw divided by the thesis's normaliser for the same design stroke: 0.4518 (code `fgoal`,
  // lpp-a) at d = 16 %, 0.1032 (back-computed from lpp-b's printed Psi = 1.002, Table 7.2) at
  // d = 40 %; empty otherwise.
  std::optional<double> Psi;
  // Thickness and width ratios of the non-primary flexures (thesis eqs. 5.31-5.36, Tables 7.7,
  // 7.10, 7.13); empty for a pin, 1 for the primary pivot:
  //  C_i = min over the sampled stroke of alpha_p/alpha_i (largest thickness ratio h_i/h_p at
  //        equal stress);
  //  D_equal_i = K_{i-1} kappa_p/(K_{p-1} kappa_i) (width ratio b_i/b_p at equal thickness);
  //  D_min_i = D_equal_i/C_i^3 (width ratio at the largest allowed thickness).
  std::array<std::optional<double>, 3> C;
  std::array<std::optional<double>, 3> D_equal;
  std::array<std::optional<double>, 3> D_min;
  // min over the sampled stroke of alpha_j/alpha_i for every pair (j, i) of distinct sprung
  // pivots (+inf on the diagonal, for a pin, and where alpha_i is never positive): C_i is
  // alpha_ratio_min[p - 1][i]. A synthesis asks what C would be were another pivot the primary
  // one (mechanisms/design/cfm_design_problem.h).
  std::array<std::array<double, 3>, 3> alpha_ratio_min{};
  double d_N_max = 0.0;  // normal displacement of pivot 2 at the end of the stroke, % r_tot
                         // (eq. 5.45)
  std::vector<CfmCurvePoint> curve;  // only with CfmOptions::keep_curve

  // converged(): closed form: true whenever every sampled Phi is finite
  // iterations: stroke points evaluated
  // residual: largest loop-closure residual of eq. 2.3 over the stroke, / r2
  // warnings: kStrokeClamped when the stroke was clamped, kForceVanishes with force_vanishes
};

// Length parameter lambda = l_tot/r_tot (thesis Table 5.1): a long segment replacing link i is
// r_i/gamma long; an s-pivot at the ground or slider end adds half its flexure, 0.05 r_i.
double length_parameter_lambda(const CfmConfiguration& configuration, double R);

// kappa_i = gamma_i zeta_i K_theta_i/rho_i (thesis eq. 4.51); zeta = R+1 at the ground, 1/R+1 at
// the slider, 2 for a middle s-pivot, R+1 or 1/R+1 for a middle long segment replacing r2 or r3.
std::array<double, 3> pivot_kappa(const CfmConfiguration& configuration, double R);

class CfmModel {
 public:
  explicit CfmModel(CfmOptions options = {});
  // Throws InvalidInput for an unknown configuration, R <= 0 or non-finite, K < 0 or non-finite,
  // a missing K for an existing spring or a nonzero K for a missing one, d outside (0, 100], and
  // d = 100 with R = 1 (the fully folded position, where Phi is 0/0).
  CfmResult evaluate(const CfmParameters& parameters) const;

  const CfmOptions& options() const { return options_; }

 private:
  CfmOptions options_;
};

}  // namespace flexure::cfm
