#pragma once
// Fixed-guided segment (Howell §5.3, App. E.4): both ends clamped, the far end translates without
// rotating. The shape is antisymmetric about an inflection point at mid-length, so each half is a
// fixed-pinned segment of length l/2: two pivots (1-gamma)l/2 from the ends joined by a link
// gamma*l, each with K = 2 gamma K_theta EI/l (eq. 5.105); theta0 = 0 (eq. 5.100).
#include <string>

#include "flexure/elements/fixed_pinned_segment.h"
#include "flexure/elements/prbm_element.h"

namespace flexure {

class FixedGuidedSegment : public PrbmElement {
 public:
  // gamma, K_theta and the limits of a fixed-pinned half (App. E.4 refers to E.3); default n = 0.
  explicit FixedGuidedSegment(
      FixedPinnedConstants constants = FixedPinnedConstants::from_table(0.0));

  std::string name() const override { return "fixed-guided segment"; }
  PrbGeometry geometry() const override;
  double stiffness_coefficient() const override;  // 2 gamma K_theta per spring (eq. 5.105)
  TipPose tip(double Theta) const override;       // App. E.4
  // The tip couple is the guide's reaction and does no work (theta0 is held at 0).
  double generalized_load(double Theta, const EndLoad& load) const override;
  double spring_moment(double Theta) const override;  // two springs, each turned by Theta
  ValidityLimits limits() const override;
  // Equal and opposite end moments: M0 = (P a + nP b)/2 at both ends (eqs. 5.102-5.103, 5.106).
  double max_moment(double Theta, const EndLoad& load) const override;

 private:
  FixedPinnedConstants constants_;
};

}  // namespace flexure
