#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "flexure/elements/prbm_element.h"
#include "flexure/solver/common/status.h"

namespace flexure {

TipPose PinnedPinnedSegment::tip(double Theta) const {
  return {std::cos(Theta), std::sin(Theta), Theta};
}

double PinnedPinnedSegment::generalized_load(double Theta, const EndLoad& load) const {
  if (load.mu != 0.0) {
    throw InvalidInput(fmt::format(
        "tip moment mu = {} on a pinned-pinned segment: a pin carries no moment", load.mu));
  }
  return link_force_work(1.0, Theta, load);
}

ValidityLimits PinnedPinnedSegment::limits() const {
  return {std::numbers::pi, std::numbers::pi, "rigid two-force link: no angle limit"};
}

}  // namespace flexure
