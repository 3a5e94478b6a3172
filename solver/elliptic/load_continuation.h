#pragma once
// Proportional loading from the unloaded beam, for the general case with an end moment.
//
// With mu != 0 the tip-angle residual can have several roots (several equilibria). The one the
// beam reaches when all loads grow together from zero is found by natural continuation in the load
// factor lambda: predict the tip angle by secant extrapolation, bracket the root nearest the
// prediction, and accept the step only if the prediction was close; otherwise halve the step.
// A step that cannot be made small enough means a limit point: beyond it no equilibrium is
// continuous with proportional loading (the beam would snap), and the solve reports where.
#include <string>

#include "solver/elliptic/elastica_closed_form.h"

namespace flexure::elliptic {

struct ContinuationOptions {
  double x_tolerance = 1e-15;       // final relative tolerance on t = theta0 - psi
  double step_tolerance = 1e-11;    // relative tolerance on t at intermediate load factors
  double max_angle_step = 0.4;      // largest predicted change of tip angle per step (rad)
  double branch_jump_guard = 0.05;  // largest accepted corrector move beyond half the predicted
                                    // change of tip angle (rad)
  double min_load_step = 1e-10;     // smaller steps mean a limit point
  int max_steps = 4000;
};

struct ContinuationSolution {
  bool converged = false;
  std::string message;
  int iterations = 0;  // residual evaluations
  int steps = 0;       // accepted load steps
  double load_factor_reached = 0.0;
  double tip_from_force = 0.0;  // t = theta0 - psi at the solution
  double residual = 0.0;
};

ContinuationSolution solve_by_continuation(double force,
                                           double psi,
                                           double mu,
                                           const ContinuationOptions& options);

}  // namespace flexure::elliptic
