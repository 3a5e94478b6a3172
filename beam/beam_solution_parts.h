#pragma once
// Parts of a BeamSolution that every method fills the same way (beam_problem.cpp, beam_ladder.cpp):
// a chain's loads in Howell's parameters, the inflection points of a sampled shape, a shape
// resampled at equal steps of s.
#include <optional>
#include <vector>

#include "flexure/beam/beam_problem.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/end_load.h"

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

}  // namespace flexure
