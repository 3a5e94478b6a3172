#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "flexure/elements/prbm_element.h"
#include "flexure/solver/common/status.h"

namespace flexure {

SmallLengthFlexuralPivot::SmallLengthFlexuralPivot(double rigid_length_ratio)
    : rigid_length_ratio_(rigid_length_ratio) {
  if (!std::isfinite(rigid_length_ratio) || rigid_length_ratio < 0.0) {
    throw InvalidInput(
        fmt::format("rigid-to-flexible length ratio L/l = {} must be a finite number >= 0",
                    rigid_length_ratio));
  }
}

PrbGeometry SmallLengthFlexuralPivot::geometry() const {
  // gamma is not defined for the SLFP; the pivot at mid-flexure means a moving link of L + l/2.
  return {0.5, arm(), 0.5, 0.0, 1};
}

TipPose SmallLengthFlexuralPivot::tip(double Theta) const {
  return {0.5 + arm() * std::cos(Theta), arm() * std::sin(Theta), Theta};
}

double SmallLengthFlexuralPivot::generalized_load(double Theta, const EndLoad& load) const {
  return link_force_work(arm(), Theta, load) + load.mu;
}

ValidityLimits SmallLengthFlexuralPivot::limits() const {
  // Howell gives no angle limit for the SLFP; its accuracy rests on L >= 10 l (eqs. 5.1-5.2).
  return {std::numbers::pi / 2.0,
          std::numbers::pi / 2.0,
          "no published angle limit; pi/2 reported, accuracy requires L >= 10 l (eqs. 5.1-5.2)"};
}

}  // namespace flexure
