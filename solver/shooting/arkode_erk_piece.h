#pragma once
// SUNDIALS ARKODE's explicit Runge-Kutta stepper (ERKStep, SUNDIALS 6.4) with its Fehlberg
// 13-7-8 table (ARKODE_FEHLBERG_13_7_8; Fehlberg, NASA TR R-287, 1968), the eighth-order table
// ARKODE 5.4 ships, as a backend of ElasticaIntegrator. Measured against GSL's rk8pd
// (docs/performance.md): its N_Vector operations cost more per step than the stage arithmetic of
// these 4-32-component systems, as in CVODES, so it is not the default. ARKODE's steps are its
// own: no step observer, and the step limit is ExplicitRkSettings::max_steps.
#include <memory>

#include "flexure/solver/shooting/elastica_piece.h"

namespace flexure {

class ArkodeErkPiece final : public ExplicitPieceIntegrator {
 public:
  explicit ArkodeErkPiece(const ExplicitRkSettings& settings);
  ~ArkodeErkPiece() override;
  bool integrate(const PieceRun& run) override;

 private:
  struct Impl;
  ExplicitRkSettings settings_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace flexure
