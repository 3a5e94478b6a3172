#pragma once
// The explicit embedded Runge-Kutta Prince-Dormand 8(7) (RK8(7)13M: Prince & Dormand, J. Comp.
// Appl. Math. 7 (1981) 67-75; Hairer, Norsett & Wanner, Solving ODEs I, §II.5) written out for
// ElasticaIntegrator's packed elastica system: the default backend (kRk8pd). It takes the steps,
// and the step-size control, of GSL's gsl_odeiv2_step_rk8pd with gsl_odeiv2_control_y_new (the
// backend it replaces, GslRk8pdPiece, kept as its reference): the same coefficients, the same
// operations in the same order, the same standard control (the local error of every component
// below atol + rtol |y_i|, the step scaled by 0.9 (tol/err)^(1/8) down to at most 1/5 on a
// rejection, by 0.9 (tol/err)^(1/9) up to at most 5x when the error is below half the
// tolerance), so on a build without contracted multiply-adds it returns GSL's numbers bit for bit
// (tests/solver/prince_dormand87_test.cpp). Why it exists: the right-hand side is inlined and the
// stage sums run over a state of fixed length (the 4, 8, ..., 20 components of 0 to 4 sensitivity
// columns), where GSL calls the right-hand side through a function pointer and sums over a
// run-time length: the shooting sweep of docs/performance.md spends a third of its time in
// these steps ("The edges of issue 27").
#include <vector>

#include "flexure/solver/shooting/elastica_piece.h"

namespace flexure {

class PrinceDormand87Piece final : public ExplicitPieceIntegrator {
 public:
  explicit PrinceDormand87Piece(const ExplicitRkSettings& settings) : settings_(settings) {}
  bool integrate(const PieceRun& run) override;

 private:
  ExplicitRkSettings settings_;
  // Stages, trial state and derivatives: 17 arrays of the packed dimension, kept between runs.
  std::vector<double> work_;
  // First step size per piece (segment and start) from the previous integration of that piece,
  // as GslRk8pdPiece keeps them (docs/theory-shooting.md §4).
  struct FirstStep {
    const FlexibleSegment* segment;
    double s_a;
    double h;
  };
  std::vector<FirstStep> first_step_;
};

}  // namespace flexure
