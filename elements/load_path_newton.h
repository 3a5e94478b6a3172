#pragma once
// The equilibrium solver of the ladder's discrete models (PR-3R, the chained BCM; docs/models.md):
// proportional loading from the unloaded structure (load factor lambda from 0 to 1, as the exact
// solvers follow it), natural-parameter continuation with a secant predictor and a damped Newton
// corrector at each load factor. Internal to elements/ (Eigen types; not installed).
//
// The step in lambda starts at 1 (small loads: one step) and adapts: it is halved when Newton
// fails or when the structure moves more than `max_change` (the model's own measure, e.g. the tip
// angle) in one step, which keeps the path on the branch of proportional loading; it grows again
// after easy steps. A step below `min_step` ends the path: a fold of the load path (limit point)
// or a load the model cannot carry.
#include <Eigen/Dense>
#include <functional>
#include <string>

namespace flexure::detail {

struct LoadPathOptions {
  double tolerance = 1e-12;   // converged when max |r_i| <= tolerance (the caller scales r)
  int max_iterations = 30;    // Newton iterations per load step
  int max_load_steps = 2000;  // accepted and rejected steps together
  double min_step = 1e-7;     // smallest step in lambda
  double max_change = 0.5;    // largest change of the model's measure in one step
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
// The scalar the step control watches (e.g. the tip angle).
using MeasureFunction = std::function<double(const Eigen::VectorXd& z)>;

// z: on entry the state at lambda = 0 (the unloaded structure), on return the state at
// load_factor (1 when converged).
LoadPathOutcome follow_load_path(Eigen::VectorXd& z,
                                 const ResidualFunction& residual,
                                 const JacobianFunction& jacobian,
                                 const MeasureFunction& measure,
                                 const LoadPathOptions& options);

}  // namespace flexure::detail
