#pragma once
// Whether a prescribed tip position can be reached by an inextensible chain clamped at the root.
//
// A chain of total length L reaches no point farther than L from the root, and a point at exactly
// that distance only fully straightened along the clamp's tangent: any other point on that circle
// needs an infinite reaction (the pinned target (0.6, 0.8) of a unit beam ran 730 iterations before
// it failed). Points strictly inside the circle are reachable. Checked before any solve, so that an
// unreachable target is bad input (exit code 2), reported at once with the load factor at which the
// prescribed path of the tip leaves the reachable set.
#include <string>

#include "flexure/solver/chain_model/segment_chain.h"

namespace flexure {

// Largest load factor at which the prescribed tip position is still strictly reachable (1 when
// the full target is); the prescribed coordinates move linearly from the stress-free tip.
double reachable_load_factor(const SegmentChain& chain);

// Throws InvalidInput naming the target, its distance from the root and the chain length when
// the prescribed tip position (pinned, slider, fixed) cannot be reached.
void require_reachable_tip(const SegmentChain& chain);

}  // namespace flexure
