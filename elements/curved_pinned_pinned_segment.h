#pragma once
// Initially curved pinned-pinned segment (Howell §5.6.1, App. E.7.1): a circular arc of curvature
// kappa0 between two pins, loaded only along the line of the pins (eqs. 5.129-5.134). Modelled by
// two symmetric half-models: pivots gamma*l/2 from each pin, link rho*l/2 at angle Theta, a spring
// K = 2 rho K_theta EI/l at each (eqs. 5.135-5.147). Theta grows as the pins approach.
// Table 5.3 and eqs. 5.137-5.139 disagree (gamma by up to 0.008, rho by up to 0.012;
// docs/prbm.md "Errata followed"): the constants say which one they come from.
#include <string>

#include "flexure/elements/prbm_element.h"

namespace flexure {

struct CurvedPinnedPinnedConstants {
  double kappa0 = 0.5;  // l/R_o, 0.5 <= kappa0 <= 1.5 (range of eqs. 5.138-5.142 and Table 5.3)
  double gamma = 0.793;
  double K_theta = 2.59;
  double delta_theta_max_gamma = 1.677;  // rad, (Delta Theta)_max,gamma of Table 5.3
  double delta_theta_max_K = 0.99;       // rad, (Delta Theta)_max,K_theta of Table 5.3
  std::string source = "Table 5.3, kappa0 = 0.5";

  // gamma from eqs. 5.138-5.139, K_theta from eq. 5.142; the limits interpolated from Table 5.3.
  static CurvedPinnedPinnedConstants from_curve_fits(double kappa0);
  // Table 5.3 interpolated linearly in kappa0 (exact at its rows).
  static CurvedPinnedPinnedConstants from_table(double kappa0);
};

class CurvedPinnedPinnedSegment : public PrbmElement {
 public:
  explicit CurvedPinnedPinnedSegment(CurvedPinnedPinnedConstants constants);

  std::string name() const override { return "initially curved pinned-pinned segment"; }
  PrbGeometry geometry() const override;
  double stiffness_coefficient() const override;  // 2 rho K_theta per spring (eq. 5.143)
  double initial_angle() const override { return Theta_i_; }
  // Pin B at (a/l, 0) (eq. 5.140); theta0 is not modelled (free pins) and reported as 0.
  TipPose tip(double Theta) const override;
  // Only a force along the pins (Fx, compressive when < 0); InvalidInput for Fy or mu.
  double generalized_load(double Theta, const EndLoad& load) const override;
  double spring_moment(double Theta) const override;  // 2 K (Theta - Theta_i)
  ValidityLimits limits() const override;
  // Mid-length moment F b (eq. 5.147), b the rise; the axial force is Fx.
  double max_moment(double Theta, const EndLoad& load) const override;

  double rise(double Theta) const;  // b/l = (rho/2) sin Theta (eq. 5.141)
  double rho() const { return rho_; }
  double a_initial() const { return a_i_; }
  double b_initial() const { return b_i_; }

 private:
  CurvedPinnedPinnedConstants constants_;
  double a_i_ = 1.0;
  double b_i_ = 0.0;
  double Theta_i_ = 0.0;
  double rho_ = 0.0;
};

}  // namespace flexure
