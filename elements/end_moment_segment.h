#pragma once
// Cantilever with a pure end moment (Howell §5.4, App. E.5): link gamma*l, theta0 = c_theta Theta,
// K = gamma K_theta EI/l = c_theta EI/l (eqs. 5.107-5.112). The exact tip lies on a circle (eqs.
// 2.59, 2.64), so the constants can be re-derived in closed form (derive_end_moment()).
#include <string>

#include "flexure/elements/prbm_element.h"
#include "flexure/elements/prbm_tables.h"

namespace flexure {

class EndMomentSegment : public PrbmElement {
 public:
  // theta_max: PRB angle limit (rad) for both position and force; default from eq. 5.108
  // (theta0 < 124.4 deg, i.e. Theta < 124.4/c_theta deg).
  explicit EndMomentSegment(EndMomentConstants constants = kEndMomentBook);

  std::string name() const override { return "end-moment segment"; }
  PrbGeometry geometry() const override;
  double stiffness_coefficient() const override;  // gamma K_theta (eq. 5.111)
  TipPose tip(double Theta) const override;
  // Only a tip moment (InvalidInput for a force: use the fixed-pinned or fixed-fixed element).
  double generalized_load(double Theta, const EndLoad& load) const override;
  double spring_moment(double Theta) const override;
  ValidityLimits limits() const override;

  const EndMomentConstants& constants() const { return constants_; }

 private:
  EndMomentConstants constants_;
};

}  // namespace flexure
