#include <fmt/format.h>

#include "flexure/elements/ladder_models.h"
#include "flexure/solver/common/status.h"

namespace flexure {

void CantileverCase::validate(std::string_view model) const {
  require_finite(load.Fx, fmt::format("the {} model's tip force Fx", model));
  require_finite(load.Fy, fmt::format("the {} model's tip force Fy", model));
  require_finite(load.mu, fmt::format("the {} model's end moment mu", model));
  require_finite(guided_tip_angle, fmt::format("the {} model's guided tip angle", model));
  if (end != EndCondition::kFree && end != EndCondition::kGuided) {
    throw InvalidInput(fmt::format(
        "the {} model solves a cantilever with a free or guided end, not a {} end; the chained "
        "BCM (cbcm, bcm) solves {} ends as a chain, and the shooting method solves every end",
        model,
        to_string(end),
        to_string(end)));
  }
  if (end == EndCondition::kGuided && load.mu != 0.0) {
    throw InvalidInput(fmt::format(
        "a guided end takes the tip moment as a reaction, so the end moment mu must be 0 (got "
        "{:g})",
        load.mu));
  }
  if (end == EndCondition::kFree && guided_tip_angle != 0.0) {
    throw InvalidInput(fmt::format(
        "the {} model: a tip angle is prescribed only on a guided end (got {:g} rad on a free end)",
        model,
        guided_tip_angle));
  }
}

SegmentChain CantileverCase::to_chain() const {
  SegmentChain chain = uniform_cantilever(load);
  chain.end = end;
  if (end == EndCondition::kGuided) {
    chain.tip_load.M = 0.0;
    chain.prescribed.theta = guided_tip_angle;
  }
  return chain;
}

}  // namespace flexure
