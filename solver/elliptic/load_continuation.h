#pragma once
// Proportional loading from the unloaded beam, for the general case with an end moment.
//
// With mu != 0 the tip-angle residual g(t, lambda) = chi(0) - chi0 (elastica_closed_form.h) can
// have many roots at full load (many equilibria). The one returned is the one on the equilibrium
// path that starts at the unloaded beam (t = -psi at lambda = 0): the curve g = 0 in the plane of
// the tip angle t and the load factor lambda, followed by pseudo-arclength continuation.
//
// Why the branch cannot be lost silently (docs/theory-elliptic.md, "Branches"):
//  - The path is oriented by the sign of the tangent determinant: the tangent is always
//    (-g_lambda, g_t) / |.|, never "whichever of +-v points forward". Along one smooth branch this
//    vector field is continuous, so consecutive tangents make an acute angle; a corrector that
//    lands on another branch (or on the same curve travelled backwards) shows up as a tangent that
//    turned too far, and the step is rejected and halved.
//  - The first component of the tangent's lambda part, g_t, is positive from the unloaded beam up
//    to the first limit point; a sign change of d lambda / ds between accepted points is a limit
//    point (fold), counted and reported: under load control the beam snaps there.
//  - A step is accepted only when the corrector converges quickly (contracting), stays close to
//    the predictor and the tangent turned by less than max_turn. Below min_step the solve stops
//    and says where, rather than guessing.
#include <string>

#include "flexure/solver/common/status.h"
#include "flexure/solver/elliptic/elastica_closed_form.h"

namespace flexure::elliptic {

struct ContinuationOptions {
  double x_tolerance = 1e-15;  // final relative tolerance on t = theta0 - psi
  // Tolerance of the intermediate corrections (times max(1, |x|)): the path is followed loosely
  // and only the point at full load is polished to x_tolerance. 1e-11 and 1e-7 give the same
  // equilibria (tests/solver/elliptic_branch_grid_test.cpp); the branch is kept by the tangent
  // checks below, not by the corrector's precision.
  double corrector_tolerance = 1e-7;
  double initial_step = 0.05;     // first arclength step in (t, lambda)
  double max_step = 1.0;          // largest arclength step (rad of tip angle, or load factor)
  double predictor_error = 0.05;  // aimed-at predictor error, as a fraction of the step
  double max_step_growth = 3.0;   // largest growth of the step from one step to the next
  // While d lambda/ds falls towards zero (a fold ahead), a step covers at most this fraction of
  // the arclength to zero extrapolated from the last step.
  double level_fraction = 0.5;
  double min_step = 1e-9;               // smaller steps mean the path cannot be followed
  double max_turn = 0.35;               // largest angle between consecutive tangents (rad)
  double max_predictor_distance = 0.3;  // largest corrector move, as a fraction of the step
  int max_corrector_iterations = 8;
  int max_steps = 4000;  // accepted plus rejected steps, plus 10 per expected step: the tip
                         // turns by about |mu| + sqrt(F) rad in steps of max_step
  long max_evaluations = 200000;  // residual evaluations (about 0.3 s) plus 100 per expected step
};

struct ContinuationSolution : SolveStatus {
  // iterations: residual evaluations
  int steps = 0;  // accepted arclength steps
  int rejected_steps = 0;
  int limit_points = 0;                  // folds of lambda passed on the way to lambda = 1
  double first_limit_load_factor = 0.0;  // load factor at the first fold (0 if none)
  double load_factor_reached = 0.0;      // largest load factor on the path
  double tip_from_force = 0.0;           // t = theta0 - psi at the solution
  TipState tip;  // the solution's tip state, with full-precision energy offsets
  // residual: |g| at the solution
  double residual_slope = 0.0;  // d g / d x at the solution, in the final chart
};

ContinuationSolution solve_by_continuation(double force,
                                           double psi,
                                           double mu,
                                           const ContinuationOptions& options);

}  // namespace flexure::elliptic
