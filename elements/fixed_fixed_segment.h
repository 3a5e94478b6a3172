#pragma once
// Fixed-fixed segment under a combined tip force and moment, Howell §5.7 simplified model
// (App. E.8): the fixed-guided layout (pivots (1-gamma)l/2 from each end, middle link gamma*l, a
// spring K = 2 gamma K_theta EI/l at each pivot) but with the end angle theta0 free. It has two
// degrees of freedom (Theta, theta0); as a PrbmElement the end angle is prescribed (theta0 =
// end_angle), which makes it the fixed-guided model for end_angle = 0. solve_free_end() solves both
// coordinates. The book calls the model "less accurate, for initial design"; it has no published
// Theta limit.
#include <string>

#include "flexure/elements/fixed_pinned_segment.h"
#include "flexure/elements/prbm_element.h"
#include "flexure/solver/common/status.h"

namespace flexure {

struct FixedFixedEquilibrium : SolveStatus {
  // residual: max |generalized force| at the returned point
  double Theta = 0.0;   // middle-link angle, rad
  double theta0 = 0.0;  // end-link angle, rad
  TipPose tip;
};

class FixedFixedSegment : public PrbmElement {
 public:
  explicit FixedFixedSegment(FixedPinnedConstants constants = FixedPinnedConstants::from_table(0.0),
                             double end_angle = 0.0);

  std::string name() const override { return "fixed-fixed segment (simplified model)"; }
  PrbGeometry geometry() const override;
  double stiffness_coefficient() const override;  // 2 gamma K_theta per spring (E.8)
  TipPose tip(double Theta) const override;       // with theta0 = end_angle
  TipPose tip(double Theta, double theta0) const;
  // With the end angle prescribed the tip couple is a reaction and does no work.
  double generalized_load(double Theta, const EndLoad& load) const override;
  double spring_moment(double Theta) const override;  // K Theta + K (Theta - end_angle)
  ValidityLimits limits() const override;
  // Clamp moment including the couple the prescribed end angle needs.
  double max_moment(double Theta, const EndLoad& load) const override;

  // Both coordinates free: Newton on the two generalised forces (virtual work, eq. 6.222).
  FixedFixedEquilibrium solve_free_end(const EndLoad& load) const;

 private:
  double end_link() const { return (1.0 - constants_.gamma) / 2.0; }
  FixedPinnedConstants constants_;
  double end_angle_;
};

}  // namespace flexure
