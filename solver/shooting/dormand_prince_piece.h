#pragma once
// The built-in explicit Runge-Kutta backend of ElasticaIntegrator: Dormand-Prince 5(4) (Hairer,
// Norsett & Wanner, Solving ODEs I, Table II.5.2), written here before a library integrator was
// used (solver/shooting/gsl_rk8pd_piece.h); kept as the comparison in benchmarks/perf.
#include "flexure/solver/shooting/elastica_piece.h"

namespace flexure {

class DormandPrincePiece final : public ExplicitPieceIntegrator {
 public:
  explicit DormandPrincePiece(const ExplicitRkSettings& settings) : settings_(settings) {}
  bool integrate(const PieceRun& run) override;

 private:
  ExplicitRkSettings settings_;
};

}  // namespace flexure
