#pragma once
// GSL's explicit embedded Runge-Kutta Prince-Dormand 8(7) (gsl_odeiv2_step_rk8pd; Prince &
// Dormand, J. Comp. Appl. Math. 7 (1981) 67-75; Hairer, Norsett & Wanner, Solving ODEs I,
// §II.5) as a backend of ElasticaIntegrator: the default. An eighth-order step needs fewer
// right-hand sides than Dormand-Prince 5(4) at the tolerances the shooting method asks for
// (docs/theory-shooting.md §4, docs/performance.md), and GSL's stepper works on plain arrays, so
// its overhead per step is small for these 4-32-component systems (unlike the N_Vector
// operations of SUNDIALS, which dominate CVODES and ARKODE here).
#include <memory>

#include "flexure/solver/shooting/elastica_piece.h"

namespace flexure {

class GslRk8pdPiece final : public ExplicitPieceIntegrator {
 public:
  explicit GslRk8pdPiece(const ExplicitRkSettings& settings);
  ~GslRk8pdPiece() override;
  bool integrate(const PieceRun& run) override;

 private:
  struct Impl;
  ExplicitRkSettings settings_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace flexure
