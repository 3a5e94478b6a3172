#pragma once
// The built-in explicit Runge-Kutta backend of ElasticaIntegrator: Dormand-Prince 5(4) (Hairer,
// Norsett & Wanner, Solving ODEs I, Table II.5.2), written here before a library integrator was
// used (solver/shooting/gsl_rk8pd_piece.h); kept as the comparison in benchmarks/perf.
#include <string>
#include <vector>

#include "flexure/solver/shooting/elastica_piece.h"

namespace flexure {

// Integrates the packed state `y` (4 (Ns + 1) components) of one flexible piece from s_a to s_b,
// stopping on every pending shape point of `shape` before s_b. Adds the steps taken to `steps`;
// `observer` (may be null) sees every accepted step. Returns false with `error` on too many steps
// or a non-finite state.
bool dormand_prince_piece(const ElasticaPieceData& piece,
                          int Ns,
                          double s_a,
                          double s_b,
                          std::vector<double>& y,
                          const ExplicitRkSettings& settings,
                          ShapeCursor& shape,
                          StepObserver* observer,
                          long& steps,
                          std::string& error);

}  // namespace flexure
