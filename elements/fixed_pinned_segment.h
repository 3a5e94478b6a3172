#pragma once
// Fixed-pinned segment: a cantilever with a tip force at any angle phi = atan2(1, -n) (Howell §5.2,
// App. E.3). The PRB model is a rigid link of length gamma*l pinned (1-gamma)*l from the clamp with
// a torsional spring K = gamma K_theta EI/l (eq. 5.72); theta0 = c_theta Theta (eq. 5.53).
//
// The constants come from Table 5.1, from the curve fits (eqs. 5.48, 5.60-5.62) or from the
// derivation against the exact solution (prbm_derivation.h, FixedPinnedConstants::from_derivation).
#include <string>

#include "flexure/elements/prbm_element.h"

namespace flexure {

struct FixedPinnedConstants {
  double load_ratio_n = 0.0;     // n: horizontal force nP, compressive for n > 0 (eq. 2.67)
  double gamma = 0.8517;         // characteristic radius factor
  double c_theta = 1.2385;       // parametric angle coefficient (eq. 5.53)
  double K_theta = 2.67617;      // stiffness coefficient (eq. 5.59)
  double theta_max_gamma = 0.0;  // rad, Theta_max(gamma) (position)
  double theta_max_K = 0.0;      // rad, Theta_max(K_theta) (force)
  std::string source = "Table 5.1, n = 0";

  // Table 5.1: the exact row when n is one, else every column interpolated linearly in n.
  static FixedPinnedConstants from_table(double load_ratio_n);
  // Curve fits: gamma eq. 5.48, K_theta eqs. 5.60-5.62; c_theta and Theta_max(gamma) interpolated
  // from Table 5.1 (the book gives no fit for them); Theta_max(K_theta) = 0.7 phi (eq. 5.63) for
  // n < 0, Table 5.1 interpolated for n >= 0 (the rule overestimates it there).
  static FixedPinnedConstants from_curve_fits(double load_ratio_n);
  // Howell's average constants for a segment whose load ratio is not known in advance (§5.2:
  // gamma = 0.85 and K_theta = 2.65, the averages of eqs. 5.51 and 5.64 over -0.5 <= n <= 1;
  // docs/prbm.md "Recommended values"). They are the constants of every long (l) segment of
  // Weight's constant-force mechanisms (Weight 2001 §2.2, App. A.3) and of the modified mechanisms
  // (Ugwuoke & Abolarin eq. 1). c_theta and the two Theta_max are Table 5.1's at n = 0
  // (load_ratio_n = 0); a check at the segment's actual n uses from_table(n).
  static FixedPinnedConstants howell_average();
  // Throws InvalidInput naming the constant unless all are finite and in their physical range.
  void validate() const;
};

class FixedPinnedSegment : public PrbmElement {
 public:
  explicit FixedPinnedSegment(FixedPinnedConstants constants);

  std::string name() const override { return "fixed-pinned segment"; }
  PrbGeometry geometry() const override;
  double stiffness_coefficient() const override;  // gamma K_theta (eq. 5.72)
  TipPose tip(double Theta) const override;       // eqs. 5.49, 5.50, 5.53
  // Only a tip force: a pinned tip carries no moment (InvalidInput if mu != 0).
  double generalized_load(double Theta, const EndLoad& load) const override;
  double spring_moment(double Theta) const override;
  ValidityLimits limits() const override;

  // Howell's load P = alpha2 EI/l^2 that holds the model at Theta for this element's n:
  // alpha2 = K_theta Theta / (eta sin(phi - Theta)) (eqs. 5.56-5.59).
  double alpha2_at(double Theta) const;
  double force_angle() const;  // phi = atan2(1, -n), eq. 5.41
  const FixedPinnedConstants& constants() const { return constants_; }

 private:
  FixedPinnedConstants constants_;
};

// The fixed-pinned segment with FixedPinnedConstants::howell_average(), built once: the PRBM of a
// long (l) segment in mechanisms/ (link gamma l, pivot (1 - gamma) l from the clamp, spring
// K = gamma K_theta EI/l, eq. 5.72).
const FixedPinnedSegment& howell_average_fixed_pinned();

}  // namespace flexure
