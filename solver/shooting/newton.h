#pragma once
// Damped Newton corrector for the shooting residual (Howell eqs. 7.38-7.40, with the Jacobian from
// CVODES sensitivities instead of finite differences).
//
// Two modes: at a fixed load factor lambda (unknowns z), or pseudo-arclength (unknowns z and
// lambda, plus the Keller constraint tangent . (u - u_predicted) = 0 in scaled variables
// u = (z / scale, lambda)), which stays regular at limit points where dg/dz is singular.
#include <Eigen/Dense>
#include <string>

#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/shooting_problem.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {

struct NewtonOutcome : SolveStatus {
  bool damped = false;  // a step shorter than the full Newton step was taken
  // Largest ratio |dz_k| / |dz_(k-1)| of consecutive Newton steps (max norm of the unknowns' part;
  // 0 with fewer than two steps). Near a regular root Newton's steps shrink quadratically, so a
  // ratio near 1 says the start was at the edge of the root's basin (a warm start from a
  // neighbouring load checks it, ShootingSolver::solve_near).
  double contraction = 0.0;
  // residual: max |g_i| at the returned point
  ShootingEvaluation last;  // evaluation at the returned point (with Jacobian)
};

// Watches the integrations of newton_solve's evaluations and learns which one belongs to the point
// Newton ends on, so that what it collects (e.g. the curvature's sign changes,
// inflection_count.h) needs no integration of its own after Newton.
class NewtonRecorder {
 public:
  virtual ~NewtonRecorder() = default;
  virtual StepObserver* observer() = 0;  // set on the integrator during every evaluation
  virtual void begin_evaluation() = 0;   // an evaluation starts (a trial point, say)
  virtual void accept_evaluation() = 0;  // the evaluation just made is Newton's current point
};

// Arclength constraint data; null for the fixed-lambda mode.
struct ArclengthConstraint {
  Eigen::VectorXd tangent;    // unit tangent in scaled variables (z / scale, lambda)
  Eigen::VectorXd predicted;  // predicted point in scaled variables
  Eigen::VectorXd scale;      // z = scale .* z_scaled
};

// Solves g(z, lambda) = 0 for z (lambda fixed) or for (z, lambda) with the constraint. On return z
// and lambda hold the last accepted iterate.
NewtonOutcome newton_solve(const ShootingProblem& problem,
                           ElasticaIntegrator& integrator,
                           const NewtonOptions& options,
                           Eigen::VectorXd& z,
                           double& lambda,
                           const ArclengthConstraint* constraint = nullptr,
                           NewtonRecorder* recorder = nullptr);

// Solves A x = b; falls back to the minimum-norm least-squares solution when A is rank deficient
// (e.g. the axial force of a straight pinned beam is indeterminate at first order).
Eigen::VectorXd robust_solve(const Eigen::MatrixXd& A, const Eigen::VectorXd& b);

}  // namespace flexure
