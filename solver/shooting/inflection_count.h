#pragma once
// Inflection points of a solved shooting problem from one integration of its unknowns, without a
// sampled shape: the interior sign changes of the curvature theta' = m/EI + kappa0 along the
// flexible segments (Howell eq. 2.67; an inflection point is where the curvature changes sign).
//
// On every accepted step of the explicit integrator the moment is the quintic Hermite interpolant
// of moment_interpolant.h (as accurate as the integrated state); the curvature is taken at both
// ends of the step and at the interpolant's interior extrema, so that two sign changes inside one
// step are seen too. Values within 1e-9 of the largest |curvature| count as zero (a free tip
// without an end moment has m = 0 there, which is not an inflection). Backends without steps to
// show (CVODES, ARKODE) fall back to the sign changes of theta along a shape of 401 points.
#include <Eigen/Dense>
#include <limits>
#include <string>
#include <vector>

#include "flexure/solver/shooting/elastica_integrator.h"
#include "flexure/solver/shooting/elastica_piece.h"
#include "flexure/solver/shooting/newton.h"
#include "flexure/solver/shooting/shooting_problem.h"

namespace flexure {

struct InflectionCount {
  int inflection_points = 0;
  // The largest |m/EI + kappa0| over the same samples (ShootingResult::largest_curvature); NaN
  // when the backend shows no steps.
  double largest_curvature = std::numeric_limits<double>::quiet_NaN();
  TipState tip;  // the tip state of the same integration (no sensitivities)
};

// Collects the curvature samples of the integrations it watches. As the recorder of newton_solve
// it keeps those of the evaluation at Newton's current point, so that the count of the converged
// point needs no integration of its own (explicit backends only; others show no steps).
class CurvatureRecorder : public StepObserver, public NewtonRecorder {
 public:
  void accepted_step(const ElasticaPieceData& piece,
                     double s0,
                     const double* y0,
                     const double* f0,
                     double s1,
                     const double* y1,
                     const double* f1) override;
  StepObserver* observer() override { return this; }
  void begin_evaluation() override { current_.clear(); }
  void accept_evaluation() override {
    accepted_.swap(current_);
    have_accepted_ = true;
  }
  bool has_accepted() const { return have_accepted_; }
  // The inflection points of the accepted evaluation.
  int inflection_points() const;
  // The largest |m/EI + kappa0| of the accepted evaluation: at the step ends and the moment's
  // interior extrema, so the maximum over the chain to the interpolant's accuracy.
  double largest_curvature() const;

 private:
  std::vector<double> current_, accepted_;
  bool have_accepted_ = false;
};

// `z` holds all unknowns of `problem` at load factor `lambda`. Returns false with `error` when the
// integration fails.
bool count_inflections(const ShootingProblem& problem,
                       const Eigen::VectorXd& z,
                       double lambda,
                       ElasticaIntegrator& integrator,
                       InflectionCount& out,
                       std::string& error);

// The sign changes of a sequence of values, ignoring those within `zero` of 0.
int sign_changes(const std::vector<double>& values, double zero);

}  // namespace flexure
