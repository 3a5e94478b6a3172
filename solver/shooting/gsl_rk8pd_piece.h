#pragma once
// GSL's explicit embedded Runge-Kutta Prince-Dormand 8(7) (gsl_odeiv2_step_rk8pd; Prince &
// Dormand, J. Comp. Appl. Math. 7 (1981) 67-75; Hairer, Norsett & Wanner, Solving ODEs I,
// §II.5) as a backend of ElasticaIntegrator: the default. An eighth-order step needs fewer
// right-hand sides than Dormand-Prince 5(4) at the tolerances the shooting method asks for
// (docs/theory-shooting.md §4, docs/performance.md), and GSL's stepper works on plain arrays, so
// its overhead per step is small for these 4-32-component systems (unlike the N_Vector
// operations of SUNDIALS, which dominate CVODES and ARKODE here).
#include <memory>
#include <string>
#include <vector>

#include "flexure/solver/shooting/elastica_piece.h"

namespace flexure {

class GslRk8pdPiece {
 public:
  explicit GslRk8pdPiece(const ExplicitRkSettings& settings);
  ~GslRk8pdPiece();
  GslRk8pdPiece(const GslRk8pdPiece&) = delete;
  GslRk8pdPiece& operator=(const GslRk8pdPiece&) = delete;

  // Integrates the packed state `y` (4 (Ns + 1) components) of one flexible piece from s_a to
  // s_b, stopping on every pending shape point of `shape` before s_b. Adds the steps taken to
  // `steps`; `observer` (may be null) sees every accepted step. Returns false with `error` when
  // GSL fails, more than `max_steps` steps are needed or the state is not finite.
  bool integrate(const ElasticaPieceData& piece,
                 int Ns,
                 double s_a,
                 double s_b,
                 std::vector<double>& y,
                 ShapeCursor& shape,
                 StepObserver* observer,
                 long max_steps,
                 long& steps,
                 std::string& error);

 private:
  struct Impl;
  ExplicitRkSettings settings_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace flexure
