#pragma once
// flexure's beam API in one include: beam problems solved by any method (solve_beam, the method
// choice of auto), the exact solvers with their Options and results, segment chains, sections and
// materials, beams and chains in SI units. Link `flexure::beam` after
// `find_package(flexure REQUIRED)`; the beam layer links no HDF5 and no toml++.
//
//   #include <flexure/beam.h>
//   flexure::BeamProblem problem;
//   problem.value = 3.0;  // alpha2 = P l^2/EI
//   const flexure::BeamSolution s = flexure::solve_beam(flexure::BeamMethod::kAuto, problem);
//   // s.tip.a_over_l, s.tip.b_over_l, s.tip.theta0, s.method, s.converged()

// Core: errors, results' status and warnings, end loads, sections and materials, stability.
#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/section.h"
#include "flexure/solver/common/status.h"
#include "flexure/version.h"

// The solvers: elliptic integrals, shooting (with its options and load paths, the shape at any arc
// length, rigid contact), Howell's chain algorithm, the stability verdict, tip targets.
#include "flexure/solver/chain/chain_algorithm_solver.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/elliptic/elliptic_solver.h"
#include "flexure/solver/inverse/tip_target.h"
#include "flexure/solver/shooting/rigid_contact.h"
#include "flexure/solver/shooting/shooting_solver.h"

// The beam layer: problems by any method, the method choice, physical beams and chains.
#include "flexure/beam/beam_problem.h"
#include "flexure/beam/physical_beam.h"
