#pragma once
// Pseudo-arclength continuation of the shooting problem in the load factor lambda.
//
// Proportional loading (segment_chain.h): lambda = 0 is the stress-free chain, lambda = 1 the
// requested load. The path (z(s), lambda(s)) is parameterised by arc length in scaled variables
// (z / scale, lambda), so it passes limit points (snap-through, where lambda turns back) that
// stepping in lambda alone cannot. Predictor: the unit tangent (null vector of [dg/dz dg/dlambda]);
// corrector: Newton with the Keller constraint (newton.h). Steps grow after easy corrections and
// are halved after a failed one; below min_step the path stops and reports the lambda reached.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/newton.h"
#include "flexure/solver/shooting/shooting_problem.h"

namespace flexure {

struct ContinuationOptions {
  double initial_step = 0.1;  // first arclength step (scaled variables)
  double min_step = 1e-7;     // give up below this step
  double max_step = 0.5;      // cap on the arclength step
  double growth = 1.6;        // step growth after an easy correction
  int easy_iterations = 3;    // corrections in at most this many Newton iterations are easy
  int max_steps = 500;        // accepted + rejected steps before giving up (never a hang);
                              // paths in the test grids need at most about 70
  long max_integrator_steps = 500000;   // CVODES steps over the whole path (time budget), times
                                        // max(1, shooting intervals / 16)
  double max_predictor_distance = 0.5;  // reject a correction farther than this * step from the
                                        // predictor (guards against jumping to another branch)
  double max_turn = 0.6;  // reject a step whose tangent turned by more than this (rad); the
                          // tangent's sign comes from the path's orientation (continuation.cpp),
                          // so a corrector that lands on another branch shows up as a large turn
  double bifurcation_step = 1e-3;      // an orientation flip that persists at steps this short is a
                                       // bifurcation point crossed on the branch (continuation.cpp)
  double bifurcation_vicinity = 0.01;  // no path samples recorded this close to a crossing
  bool record_path = true;             // store every accepted point
};

enum class PathStatus { kStart, kAccepted, kLimitPoint, kEnd };
const char* to_string(PathStatus status);

struct PathPoint {
  double lambda = 0.0;  // load factor
  ChainPose tip;        // tip x, y, theta
  Reaction reaction;    // loads the clamp applies to the chain
  double step = 0.0;    // arclength step that reached this point
  int iterations = 0;   // Newton iterations of the corrector
  PathStatus status = PathStatus::kAccepted;
  int stage = 1;  // 2 only in the second stage of a two-stage path (shooting_solver.h)
};

struct LoadPath : SolveStatus {
  // converged(): reached lambda = 1
  bool singular_start = false;  // dg/dz singular at lambda = 0: the path starts at a bifurcation
  // message: where and why it stopped
  double lambda_reached = 0.0;           // largest lambda on the path
  int steps = 0;                         // accepted steps
  int rejected_steps = 0;                // halved steps
  int newton_iterations = 0;             // summed over all corrections
  int limit_points = 0;                  // turning points of lambda passed
  double first_limit_load_factor = 0.0;  // largest lambda before the first turning point
  int bifurcation_points = 0;  // simple bifurcation points crossed (the path stays on its branch)
  std::vector<PathPoint> points;
  Eigen::VectorXd z;    // unknowns at the last accepted point
  double lambda = 0.0;  // load factor at the last accepted point
  // residual: at the last accepted point
  ChainPose tip;       // tip pose at the last accepted point
  TipState tip_state;  // tip state (with the bending moment) at the last accepted point
  // Sign of det dg/dz at the end point when the path converged (0 otherwise): it changes at every
  // limit point and bifurcation point, so a neighbouring load's solution with the same sign and a
  // short, undamped Newton step lies on the same smooth stretch of branch (ShootingSolver::
  // solve_near).
  int jacobian_sign = 0;
};

// Sign of det dg/dz of an evaluation with its Jacobian (0 when it is exactly singular).
int jacobian_sign(const ShootingEvaluation& eval);

// Follows the path from lambda = 0 to lambda = 1 (or until it stops), starting from `start`
// (which must solve g(start, 0) = 0; default: problem.unloaded_unknowns()). Stops at once, with
// a message, when dg/dz is singular at the start (a bifurcation, e.g. shortening a straight
// inextensible chain).
LoadPath continue_load_path(const ShootingProblem& problem,
                            ElasticaIntegrator& integrator,
                            const ContinuationOptions& options,
                            const NewtonOptions& newton,
                            const Eigen::VectorXd* start = nullptr);

// True when dg/dz is rank deficient at (z, lambda) (relative threshold 1e-10).
bool singular_jacobian(const ShootingEvaluation& eval);

}  // namespace flexure
