#pragma once
// The force points of a displacement-controlled path (ShootingSolver::controlled_path): where the
// support's load conjugate to the moved tip coordinate crosses zero, and where it has a local
// extremum along the path (docs/paths.md).
//
// Both are located on the path itself, not on its samples: between two recorded points the path
// is reached by Newton with Keller's constraint on the chord between them (the hyperplane through
// a point of the chord, normal to it: regular through folds of the path parameter), a zero by
// Brent's method on the chord parameter, an extremum by golden-section search on each of the two
// chords around the sampled extremum. At a bifurcation where the path switched branch the force
// has a corner; a sampled extremum there is that point itself.
#include <vector>

#include "flexure/solver/shooting/continuation.h"
#include "flexure/solver/shooting/newton.h"
#include "flexure/solver/shooting/shooting_problem.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {

// The support's load conjugate to `coordinate` (Fx, Fy or M of `load`).
double conjugate_load(const Reaction& load, TipCoordinate coordinate);
// The coordinate's value at `tip`.
double coordinate_value(const ChainPose& tip, TipCoordinate coordinate);

// The force points of `path`, whose recorded points (with their unknowns PathPoint::z) all lie
// on the moving stage `problem` (the controlled coordinate moved from its start to its target as
// lambda goes from 0 to 1). In path order; `corrections` counts the Newton solves spent.
std::vector<ForcePoint> locate_force_points(const ShootingProblem& problem,
                                            ElasticaIntegrator& integrator,
                                            const NewtonOptions& newton,
                                            const LoadPath& path,
                                            TipCoordinate coordinate,
                                            int& corrections);

}  // namespace flexure
