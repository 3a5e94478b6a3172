#include "flexure/elements/prbm_cantilever.h"

#include <fmt/format.h>

#include "flexure/elements/prbm_element.h"
#include "flexure/elements/prbm_stability.h"
#include "flexure/solver/common/status.h"

namespace flexure {

std::unique_ptr<PrbmElement> prbm_cantilever_element(EndCondition end,
                                                     double load_ratio_n,
                                                     double alpha2,
                                                     double mu) {
  const bool force = alpha2 != 0.0;
  switch (end) {
    case EndCondition::kGuided:
      if (mu != 0.0) {
        throw InvalidInput(fmt::format(
            "a guided end takes the tip moment as a reaction, so the end moment mu must be 0 (got "
            "{:g})",
            mu));
      }
      return std::make_unique<FixedGuidedSegment>(FixedPinnedConstants::from_table(load_ratio_n));
    case EndCondition::kFree:
      if (!force) return std::make_unique<EndMomentSegment>();
      if (mu != 0.0) {
        // Howell's 1R model has one pivot: a force or a moment, not both (§5.2, §5.4).
        throw InvalidInput(fmt::format(
            "the 1R pseudo-rigid-body model (Howell's fixed-pinned segment) carries a tip force or "
            "an end moment, not both (got alpha2 = {:g} with mu = {:g}); the PR-3R model (prbm3r), "
            "the BCM and the chained BCM (bcm, cbcm) and the exact methods carry both",
            alpha2,
            mu));
      }
      return std::make_unique<FixedPinnedSegment>(FixedPinnedConstants::from_table(load_ratio_n));
    default:
      throw InvalidInput(fmt::format(
          "no pseudo-rigid-body element models a cantilever with a {} end (Howell ch. 5 has free "
          "and guided ends); the exact methods solve it",
          to_string(end)));
  }
}

PrbmCantileverSolution solve_prbm_cantilever(EndCondition end,
                                             double load_ratio_n,
                                             double alpha2,
                                             double mu) {
  const std::unique_ptr<PrbmElement> element =
      prbm_cantilever_element(end, load_ratio_n, alpha2, mu);
  const EndLoad load = EndLoad::howell(load_ratio_n, alpha2, mu);
  const PrbEquilibrium eq = element->solve(load);
  PrbmCantileverSolution out;
  out.termination = eq.termination;
  out.message = eq.message;
  out.iterations = eq.iterations;
  out.residual = eq.residual;
  out.element = element->name();
  out.limits = element->limits();
  out.constants_source = out.limits.source;
  if (const auto* pinned = dynamic_cast<const FixedPinnedSegment*>(element.get())) {
    out.constants_source = pinned->constants().source;
  }
  out.Theta = eq.Theta;
  out.tip = eq.tip;
  out.root_moment = element->max_moment(eq.Theta, load);
  out.inside_validity = out.limits.contains(eq.Theta);
  out.inflection_points = end == EndCondition::kGuided && eq.Theta != 0.0 ? 1 : 0;
  out.stability = eq.converged() ? prbm_stability(*element, eq.Theta, load)
                                 : not_checked_stability("the PRBM did not converge");
  return out;
}

}  // namespace flexure
