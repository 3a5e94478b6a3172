#pragma once
// The stability verdict of a point of a continuation path (ShootingSolver::load_path and
// controlled_path, LoadPath::points) under the path's own control at that point
// (docs/stability.md, "Points of a path"): the loads the point carries, with the tip coordinates
// the path holds there as constraints. Under proportional loading those are the end condition's
// (but the first stage of a straight chain with both end coordinates prescribed releases the one
// along its tangent, shooting_solver.h); under displacement control the moving stage holds the
// controlled coordinate too, whose conjugate load is then the support's reaction. So one
// equilibrium can be unstable under load control and stable under displacement control.

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {

// The verdict of `point` of a path of `chain` with the coordinates `held` (the point's own,
// PathPoint::held, unless a caller asks about another control): the chain with a free
// end carrying the point's total tip load (given loads and the support's reaction, all dead) and
// its node loads at the point's load factor (stage 1; full in later stages), its shape from the
// shooting method's Newton iteration started at the point's clamp moment (`options`; it must end
// within 1e-6 of the length at the point's tip), judged with `held` as constraints
// (held_stability.h). A follower force gives not_conservative; an equilibrium that cannot be
// reproduced gives not_checked with the reason.
Stability path_point_stability(const SegmentChain& chain,
                               const PathPoint& point,
                               const PrescribedMask& held,
                               const ShootingSolver::Options& options = {},
                               const StabilityOptions& stability = {});

}  // namespace flexure
