#pragma once
// Parts of a BeamSolution that every method fills the same way (beam_problem.cpp, beam_ladder.cpp):
// a chain's loads in Howell's parameters, the inflection points of a sampled shape, a shape
// resampled at equal steps of s, the answer of an inverse search that missed its target.
#include <optional>
#include <vector>

#include "flexure/beam/beam_problem.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/end_load.h"
#include "flexure/solver/inverse/tip_target.h"

namespace flexure {

// Interior sign changes of the curvature along a sampled shape (numerical methods).
int count_curvature_sign_changes(const std::vector<ShapePoint>& shape);

// Linear interpolation of a shape given at increasing s onto `count` equally spaced points.
std::vector<ShapePoint> resample(const std::vector<ShapePoint>& nodes, int count);

// The constant EI of a uniform straight chain of flexible segments, or nullopt.
std::optional<double> uniform_EI(const SegmentChain& chain);

// A chain given as a whole: keeps its loads in its own units and states them in Howell's
// parameters where the chain has them (BeamSolution::alpha2).
void describe_chain_loads(const SegmentChain& chain, BeamSolution& s);

// An inverse problem (a given theta0 or b/l) whose search for the load missed its target: the
// load and residual reached, the search's termination and message, its forward solves as the
// iterations; no further solve at that load (beam_problem.cpp, beam_ladder.cpp).
BeamSolution missed_inverse_solution(BeamMethod method, const TipTargetSolution& found);

}  // namespace flexure
