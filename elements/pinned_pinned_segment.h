#pragma once
// Initially straight pinned-pinned segment (Howell §5.6, App. E.7). Only a force along the line of
// the pins acts (statics, eqs. 5.129-5.134), whatever the segment's shape, so it is a two-force
// member: a rigid link of length l that rotates freely (no bending spring; the axial stiffness EA/l
// is outside this bending theory). The curved segment is in curved_pinned_pinned_segment.h.
#include <numbers>
#include <string>

#include "flexure/elements/prbm_element.h"

namespace flexure {

class PinnedPinnedSegment : public PrbmElement {
 public:
  std::string name() const override { return "pinned-pinned segment (straight)"; }
  PrbGeometry geometry() const override { return {1.0, 1.0, 0.0, 0.0, 0}; }
  double stiffness_coefficient() const override { return 0.0; }
  TipPose tip(double Theta) const override;
  double generalized_load(double Theta, const EndLoad& load) const override;
  double spring_moment(double /*Theta*/) const override { return 0.0; }
  ValidityLimits limits() const override;
  double max_moment(double /*Theta*/, const EndLoad& /*load*/) const override { return 0.0; }
};

}  // namespace flexure
