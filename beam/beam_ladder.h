#pragma once
// Beam problems (beam_problem.h) solved by the cheaper models of the ladder (docs/models.md):
// linear Euler-Bernoulli theory, Su's PR-3R model, the beam-constraint model (BCM) and the chained
// BCM (CBCM), each filling the method-independent BeamSolution that `flexure beam` prints.
//
// What each represents:
//   * linear, prbm3r: Howell's uniform cantilever with a free or guided end and dead loads;
//   * bcm, cbcm: the same, and any segment chain of one straight uniform flexible segment with
//     rigid links or kinks at either end, under any end condition (free, guided, pinned, slider,
//     fixed); bcm is one element, in closed form for the free and guided cantilever;
//   * none of them: a follower force, several flexible segments, an initial curvature, an EI
//     profile (the shooting method and the chain algorithm solve those).
// A given tip angle or deflection (the inverse problems) is solved for the free cantilever by the
// model's own forward solves (solver/inverse/tip_target.h).
#include "flexure/beam/beam_problem.h"

namespace flexure {

// kLinear, kPrbm3r, kBcm, kCbcm.
bool is_ladder_model(BeamMethod method);

// Throws InvalidInput for a problem the model cannot represent, with the reason and the models
// that can, and OutsideMethodDomain for the BCM past its element's buckling load; a solve that
// does not converge returns converged() false with the message.
BeamSolution solve_ladder_model(BeamMethod method, const BeamProblem& problem);

}  // namespace flexure
