#pragma once
// The equilibrium solver of the ladder's discrete models (PR-3R, the chained BCM; docs/models.md):
// proportional loading from the unloaded structure (load factor lambda from 0 to 1, as the exact
// solvers follow it), natural-parameter continuation with a secant predictor and a damped Newton
// corrector at each load factor. Internal to elements/ (Eigen types; not installed).
//
// The step in lambda starts at 1 (small loads: one step) and adapts: it is halved when Newton
// fails or when any of the model's angles (its measure: every link or element-node angle) turns by
// more than `max_change` in one step, which keeps the path on the branch of proportional loading;
// it grows again after easy steps. Watching every angle, not only the tip's, matters: under a tip
// force and an opposing end moment the tip angle of the path stays small while the interior
// turns, and a long step converged from the unloaded state onto another equilibrium (an S-shape
// of the other sense, measured at n = 1, alpha2 = 4, mu = -2 with a tip-angle watch of 1 rad). A
// step below `min_step` ends the path: a fold of the load path (limit point) or a load the model
// cannot carry.
#include <Eigen/Dense>
#include <functional>
#include <string>

namespace flexure::detail {

struct LoadPathOptions {
  double tolerance = 1e-12;   // converged when max |r_i| <= tolerance (the caller scales r)
  int max_iterations = 30;    // Newton iterations per load step
  int max_load_steps = 2000;  // accepted and rejected steps together
  double min_step = 1e-7;     // smallest step in lambda
  double max_change = 0.25;   // largest change of any of the model's angles in one step, rad
};

struct LoadPathOutcome {
  bool converged = false;
  double load_factor = 0.0;  // the largest lambda reached with a converged state
  int iterations = 0;        // Newton iterations over all steps
  int load_steps = 0;        // accepted steps
  double residual = 0.0;     // max |r_i| at the returned state
  std::string message;       // why it stopped
};

// r(z, lambda): returns false where the model cannot be evaluated (e.g. a singular element).
using ResidualFunction =
    std::function<bool(const Eigen::VectorXd& z, double lambda, Eigen::VectorXd& r)>;
// J = dr/dz; empty: forward differences of the residual.
using JacobianFunction =
    std::function<bool(const Eigen::VectorXd& z, double lambda, Eigen::MatrixXd& J)>;
// The angles the step control watches (e.g. every link's or element node's angle).
using MeasureFunction = std::function<Eigen::VectorXd(const Eigen::VectorXd& z)>;

// z: on entry the state at lambda = 0 (the unloaded structure), on return the state at
// load_factor (1 when converged).
LoadPathOutcome follow_load_path(Eigen::VectorXd& z,
                                 const ResidualFunction& residual,
                                 const JacobianFunction& jacobian,
                                 const MeasureFunction& measure,
                                 const LoadPathOptions& options);

}  // namespace flexure::detail
