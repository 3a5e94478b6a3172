#pragma once
// SUNDIALS ARKODE's explicit Runge-Kutta stepper (ERKStep, SUNDIALS 6.4) with its Fehlberg
// 13-7-8 table (ARKODE_FEHLBERG_13_7_8; Fehlberg, NASA TR R-287, 1968), the eighth-order table
// ARKODE 5.4 ships, as a backend of ElasticaIntegrator. Measured against GSL's rk8pd
// (docs/performance.md): its N_Vector operations cost more per step than the stage arithmetic of
// these 4-32-component systems, as in CVODES, so it is not the default.
#include <memory>
#include <string>
#include <vector>

#include "flexure/solver/shooting/elastica_piece.h"

namespace flexure {

class ArkodeErkPiece {
 public:
  explicit ArkodeErkPiece(const ExplicitRkSettings& settings);
  ~ArkodeErkPiece();
  ArkodeErkPiece(const ArkodeErkPiece&) = delete;
  ArkodeErkPiece& operator=(const ArkodeErkPiece&) = delete;

  // As GslRk8pdPiece::integrate (gsl_rk8pd_piece.h).
  bool integrate(const ElasticaPieceData& piece,
                 int Ns,
                 double s_a,
                 double s_b,
                 std::vector<double>& y,
                 ShapeCursor& shape,
                 long& steps,
                 std::string& error);

 private:
  struct Impl;
  ExplicitRkSettings settings_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace flexure
