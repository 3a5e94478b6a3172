#pragma once
// Initially curved cantilever with a tip force (Howell §5.5, App. E.6): a circular arc of curvature
// kappa0 = l/R_i (eq. 5.114). gamma is measured along the arc as if it were straight; the PRB link
// joins that point to the tip, length rho*l at angle Theta_i when unloaded (eqs. 5.115-5.118), and
// K = rho K_theta EI/l acts on Theta - Theta_i (eqs. 5.124-5.127).
//
// The book gives no c_theta and no Theta limits for curved beams; tip() uses
// theta0 = kappa0 + c_theta (Theta - Theta_i) with the straight-beam c_theta of the constants, and
// limits() are the straight-beam (Table 5.1, n = 0) limits applied to Theta - Theta_i. Both are
// flagged as such.
#include <string>

#include "flexure/elements/prbm_element.h"

namespace flexure {

struct CurvedCantileverConstants {
  double kappa0 = 0.0;      // l / R_i, 0 <= kappa0 <= 2 (Table 5.2's range)
  double gamma = 0.85;      // Table 5.2
  double K_theta = 2.65;    // Table 5.2
  double c_theta = 1.2385;  // not published for curved beams: straight-beam Table 5.1, n = 0
  std::string source = "Table 5.2, kappa0 = 0";

  // Table 5.2's gamma and K_theta interpolated linearly in kappa0 (exact at its rows).
  static CurvedCantileverConstants from_table(double kappa0);
  // gamma, K_theta and c_theta re-derived from the exact curved-beam path and averaged over
  // n_min <= n <= n_max (derive_initially_curved_average, docs/prbm.md); 0 <= kappa0 <= 3. Throws
  // NoConvergence when no load ratio in the range gives a derivation.
  static CurvedCantileverConstants from_derivation(double kappa0,
                                                   double n_min = -0.5,
                                                   double n_max = 1.0);
};

class InitiallyCurvedCantilever : public PrbmElement {
 public:
  explicit InitiallyCurvedCantilever(CurvedCantileverConstants constants);

  std::string name() const override { return "initially curved cantilever"; }
  PrbGeometry geometry() const override;
  double stiffness_coefficient() const override;  // rho K_theta (eq. 5.127)
  double initial_angle() const override { return Theta_i_; }
  TipPose tip(double Theta) const override;  // eqs. 5.119-5.120
  // Only a tip force (a moment in the same sense is a change of kappa0, §5.7 case I).
  double generalized_load(double Theta, const EndLoad& load) const override;
  double spring_moment(double Theta) const override;  // K (Theta - Theta_i), eq. 5.126
  ValidityLimits limits() const override;

  double rho() const { return rho_; }
  // Unloaded tip a_i/l, b_i/l (eqs. 5.117-5.118).
  double a_initial() const { return a_i_; }
  double b_initial() const { return b_i_; }
  const CurvedCantileverConstants& constants() const { return constants_; }

 private:
  CurvedCantileverConstants constants_;
  double a_i_ = 1.0;
  double b_i_ = 0.0;
  double Theta_i_ = 0.0;
  double rho_ = 0.0;
};

}  // namespace flexure
