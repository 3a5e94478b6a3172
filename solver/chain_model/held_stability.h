#pragma once
// The stability verdict with the tip coordinates held given explicitly (segment_chain.h
// takes them from the chain's end condition): a path under displacement control holds the
// controlled coordinate too, and the first stage of a staged path releases one, so the equilibrium
// is judged under the constraints it is actually held by (docs/stability.md, "Points of a path").
// A free end with its x held, say, is no end condition of segment_chain.h, but it is a constraint
// of the second variation: int sin(theta) eta ds = 0.
#include "flexure/solver/chain_model/segment_chain.h"

namespace flexure {

// equilibrium_stability(chain, support_reaction, shape_at, options) with `held` in place of
// prescribed_mask(chain.end); the support reaction may have components conjugate to held
// coordinates only.
Stability equilibrium_stability_held(const SegmentChain& chain,
                                     const Reaction& support_reaction,
                                     const ShapeAtStations& shape_at,
                                     const PrescribedMask& held,
                                     const StabilityOptions& options = {});

}  // namespace flexure
