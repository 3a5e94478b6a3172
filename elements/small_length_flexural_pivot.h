#pragma once
// Small-length flexural pivot (Howell §5.1, App. E.1): a short flexible segment of length l
// carrying a long rigid segment of length L (L >> l, (EI)_L >> (EI)_l, eqs. 5.1-5.2). The pivot
// sits at the middle of the flexure, the spring is K = EI/l (eq. 5.14), and Theta = theta0
// (eq. 5.6).
//
// Nondimensional in the flexure length l: the rigid segment is rigid_length_ratio = L/l long.
#include <string>

#include "flexure/elements/prbm_element.h"

namespace flexure {

class SmallLengthFlexuralPivot : public PrbmElement {
 public:
  // rigid_length_ratio = L/l >= 0 (the model assumes L >= 10 l; not enforced, see limits()).
  explicit SmallLengthFlexuralPivot(double rigid_length_ratio);

  // K l/EI of the pivot: K = EI/l (eq. 5.14).
  static constexpr double kStiffnessCoefficient = 1.0;

  std::string name() const override { return "small-length flexural pivot"; }
  PrbGeometry geometry() const override;
  double stiffness_coefficient() const override { return kStiffnessCoefficient; }
  TipPose tip(double Theta) const override;  // eqs. 5.6-5.10
  // Force on the arm L + l/2 (eq. 5.19) plus the tip moment.
  double generalized_load(double Theta, const EndLoad& load) const override;
  double spring_moment(double Theta) const override { return Theta; }  // eq. 5.11
  ValidityLimits limits() const override;

  double arm() const { return rigid_length_ratio_ + 0.5; }  // (L + l/2)/l

 private:
  double rigid_length_ratio_;
};

}  // namespace flexure
