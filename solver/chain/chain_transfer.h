#pragma once
// Carries a chain geometry from one discretisation of a SegmentChain to another of the same chain
// (different element counts): the coarse load path's answer as the start of the passes on the
// fine chain (chain_algorithm_solver.cpp, docs/theory-chain.md §4).
#include "flexure/solver/chain/chain_discretisation.h"
#include "flexure/solver/chain/chain_pass.h"

namespace flexure {

// Every node of `to` gets x, y and theta interpolated linearly in arc length between the nodes of
// `from` on the same segment of the chain; the nodes of a segment's ends (SegmentChain nodes,
// including both ends of a zero-length kink) map onto each other. A start for the passes, not an
// equilibrium. Throws std::logic_error when the two do not discretise the same chain.
ChainGeometry transfer_geometry(const ChainDiscretisation& from,
                                const ChainGeometry& from_geometry,
                                const ChainDiscretisation& to);

}  // namespace flexure
