#pragma once
// flexure's public C++ API in one include (docs/architecture.md lists what each header offers).
//
//   #include <flexure/flexure.h>
//   const flexure::EllipticResult r =
//       flexure::EllipticSolver().solve(flexure::EndLoad::howell(0, 3.087, 0));
//   // r.tip.a_over_l, r.tip.b_over_l, r.tip.theta0
//
// Link `flexure::flexure` after `find_package(flexure REQUIRED)`.

// Core: end loads and tip poses, errors.
#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/errors.h"
#include "flexure/solver/common/stability.h"
#include "flexure/solver/common/status.h"
#include "flexure/version.h"

// Beam solvers.
#include "flexure/solver/chain/chain_algorithm_solver.h"
#include "flexure/solver/chain_model/equilibrium_stability.h"
#include "flexure/solver/chain_model/jacobi_stability.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/elliptic/elliptic_solver.h"
#include "flexure/solver/inverse/tip_target.h"
#include "flexure/solver/ode/ode_integrator.h"
#include "flexure/solver/shooting/shooting_shape.h"
#include "flexure/solver/shooting/shooting_solver.h"

// Pseudo-rigid-body model elements and their derivation.
#include "flexure/elements/beam_constraint_model.h"
#include "flexure/elements/cantilever_case.h"
#include "flexure/elements/chained_bcm.h"
#include "flexure/elements/curved_pinned_pinned_segment.h"
#include "flexure/elements/end_moment_segment.h"
#include "flexure/elements/fixed_fixed_segment.h"
#include "flexure/elements/fixed_guided_segment.h"
#include "flexure/elements/fixed_pinned_segment.h"
#include "flexure/elements/initially_curved_cantilever.h"
#include "flexure/elements/linear_beam.h"
#include "flexure/elements/pinned_pinned_segment.h"
#include "flexure/elements/prbm3r.h"
#include "flexure/elements/prbm3r_derivation.h"
#include "flexure/elements/prbm_cantilever.h"
#include "flexure/elements/prbm_derivation.h"
#include "flexure/elements/prbm_element.h"
#include "flexure/elements/prbm_tables.h"
#include "flexure/elements/small_length_flexural_pivot.h"

// Mechanisms: designs, PRBM and exact models, constant-force mechanisms, dynamics.
#include "flexure/mechanisms/cfm/cfm_configuration.h"
#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/cfm/cfm_subclasses.h"
#include "flexure/mechanisms/cfm/constant_force.h"
#include "flexure/mechanisms/cfm_comparison.h"
#include "flexure/mechanisms/cfm_exact.h"
#include "flexure/mechanisms/cfsm_designs.h"
#include "flexure/mechanisms/dynamics/forward_dynamics.h"
#include "flexure/mechanisms/dynamics/inverse_dynamics.h"
#include "flexure/mechanisms/general/general_exact.h"
#include "flexure/mechanisms/general/general_mechanism.h"
#include "flexure/mechanisms/general/general_prbm.h"
#include "flexure/mechanisms/howell_designs.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/mechanisms/mechanism_exact.h"
#include "flexure/mechanisms/mechanism_geometry.h"
#include "flexure/mechanisms/mechanism_prbm.h"
#include "flexure/mechanisms/modified_designs.h"

// Reading chains and mechanisms from TOML files.
#include "flexure/io/chain_toml.h"
#include "flexure/io/general_mechanism_toml.h"
#include "flexure/io/mechanism_drawing.h"
#include "flexure/io/mechanism_toml.h"

// The beam API (<flexure/beam.h>: beam problems by any method, the method choice of `--method
// auto`, physical beams and chains), the PRBM-vs-exact comparison; studies: the mechanisms' method
// choice and the reference problems of `flexure validate`.
#include "flexure/beam.h"
#include "flexure/beam/prbm_comparison.h"
#include "flexure/mechanisms/mechanism_method.h"
#include "flexure/benchmarks/studies/validation_checks.h"
#include "flexure/benchmarks/studies/validation_problems.h"
