#pragma once
// The shape of a shooting solution at any arc lengths, e.g. at the stations the stability verdict
// wants (solver/chain_model/equilibrium_stability.h, docs/stability.md):
//
//   const Reaction support = tip_support_reaction(chain, result.tip_load);
//   const Stability v = equilibrium_stability(chain, support, [&](const std::vector<double>& s) {
//     return shooting_shape_at(chain, result, s, solver.options());
//   });
#include <vector>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/end_load.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {

// The converged result's equilibrium at arc lengths s (increasing, in [0, total length]),
// integrated with the solver's own integrator and multiple-shooting cuts from its unknowns at full
// load (`options` as the solve used). Throws InvalidInput for an unconverged result or arc lengths
// outside the chain, NoConvergence when the integration fails or does not reproduce the result's
// tip to 1e-8 of the chain's length.
std::vector<ShapePoint> shooting_shape_at(const SegmentChain& chain,
                                          const ShootingResult& result,
                                          const std::vector<double>& s,
                                          const ShootingSolver::Options& options = {});

}  // namespace flexure
