#include "flexure/solver/shooting/newton.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace flexure {

Eigen::VectorXd robust_solve(const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  // One decomposition object per thread, its buffers kept between calls (a sweep point's Newton
  // solve takes one or two of these small systems, and their allocations showed in the profile of
  // the shooting sweep, docs/performance.md); compute() does what the constructor did.
  thread_local Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr;
  qr.setThreshold(1e-13);
  qr.compute(A);
  if (qr.rank() == A.cols()) return qr.solve(b);
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(A);
  cod.setThreshold(1e-13);
  return cod.solve(b);
}

namespace {

struct Augmented {
  Eigen::VectorXd g;  // residual (and constraint)
  Eigen::MatrixXd J;  // Jacobian in the solver's unknowns
};

// Residual and Jacobian of the system Newton works on: g(z) or [g(z, lambda); constraint].
bool assemble(const ShootingProblem& problem,
              ElasticaIntegrator& integrator,
              const Eigen::VectorXd& z,
              double lambda,
              const ArclengthConstraint* c,
              ShootingEvaluation& eval,
              Augmented& out) {
  if (!problem.evaluate(z, lambda, true, c != nullptr, integrator, eval)) return false;
  const int nz = problem.size();
  if (c == nullptr) {
    out.g = eval.residual;
    out.J = eval.jacobian;
    return true;
  }
  out.g.resize(nz + 1);
  out.J.resize(nz + 1, nz + 1);
  out.g.head(nz) = eval.residual;
  out.J.topLeftCorner(nz, nz) = eval.jacobian;
  out.J.topRightCorner(nz, 1) = eval.d_lambda;
  Eigen::VectorXd u(nz + 1);
  u.head(nz) = z.cwiseQuotient(c->scale);
  u[nz] = lambda;
  out.g[nz] = c->tangent.dot(u - c->predicted);
  out.J.bottomLeftCorner(1, nz) = c->tangent.head(nz).cwiseQuotient(c->scale).transpose();
  out.J(nz, nz) = c->tangent[nz];
  return true;
}

}  // namespace

namespace {
// Fewest integration steps a trial may take under NewtonOptions::trial_cost_factor.
constexpr long kMinTrialSteps = 200;
}  // namespace

NewtonOutcome newton_solve(const ShootingProblem& problem,
                           ElasticaIntegrator& integrator,
                           const NewtonOptions& options,
                           Eigen::VectorXd& z,
                           double& lambda,
                           const ArclengthConstraint* constraint,
                           NewtonRecorder* recorder) {
  NewtonOutcome out;
  // The recorder watches every evaluation and is told which one is the current point.
  struct Watch {
    ElasticaIntegrator& integrator;
    NewtonRecorder* recorder;
    explicit Watch(ElasticaIntegrator& i, NewtonRecorder* r) : integrator(i), recorder(r) {
      if (recorder != nullptr) integrator.set_step_observer(recorder->observer());
    }
    ~Watch() {
      if (recorder != nullptr) integrator.set_step_observer(nullptr);
    }
    void begin() {
      if (recorder != nullptr) recorder->begin_evaluation();
    }
    void accept() {
      if (recorder != nullptr) recorder->accept_evaluation();
    }
  } watch(integrator, recorder);
  const int nz = problem.size();
  Augmented sys;
  long cost = integrator.steps_taken();
  watch.begin();
  if (!assemble(problem, integrator, z, lambda, constraint, out.last, sys)) {
    out.message = "integration failed at the starting guess: " + out.last.error;
    return out;
  }
  watch.accept();
  cost = integrator.steps_taken() - cost;  // of an evaluation at the current point
  double norm = sys.g.lpNorm<Eigen::Infinity>();
  double previous_step = 0.0;
  for (int it = 0; it < options.max_iterations; ++it) {
    out.residual = norm;
    if (norm <= options.residual_tolerance) {
      out.set_converged(true);
      out.message = fmt::format(
          "converged: max residual {:.3e} after {} Newton iterations", norm, out.iterations);
      return out;
    }
    const Eigen::VectorXd step = robust_solve(sys.J, -sys.g);
    if (!step.allFinite()) {
      out.message =
          fmt::format("Newton step is not finite (singular Jacobian) at max residual {:.3e}", norm);
      return out;
    }
    ++out.iterations;
    // Backtracking on the max-norm of the residual: the sensitivity Jacobian is exact, so a
    // full step is accepted near the solution; halving protects against jumping branches.
    double t = 1.0;
    bool accepted = false;
    for (int bt = 0; bt <= options.max_backtracks; ++bt, t *= 0.5) {
      Eigen::VectorXd z_try = z + t * step.head(nz);
      double lambda_try = constraint != nullptr ? lambda + t * step[nz] : lambda;
      ShootingEvaluation eval;
      Augmented trial;
      const long before = integrator.steps_taken();
      if (options.trial_cost_factor > 0.0) {
        integrator.set_step_limit(
            before + std::max(kMinTrialSteps, static_cast<long>(options.trial_cost_factor * cost)));
      }
      watch.begin();
      const bool evaluated =
          assemble(problem, integrator, z_try, lambda_try, constraint, eval, trial);
      integrator.set_step_limit(0);
      if (evaluated) {
        const double trial_norm = trial.g.lpNorm<Eigen::Infinity>();
        if (trial_norm < (1.0 - 1e-4 * t) * norm || trial_norm <= options.residual_tolerance) {
          watch.accept();
          z = z_try;
          lambda = lambda_try;
          cost = integrator.steps_taken() - before;
          sys = std::move(trial);
          out.last = std::move(eval);
          norm = trial_norm;
          accepted = true;
          if (bt > 0) out.damped = true;
          break;
        }
      }
    }
    const double step_norm = step.head(nz).lpNorm<Eigen::Infinity>();
    // Steps at the integration's noise level say nothing about the basin.
    if (previous_step > 1e-8 * (1.0 + z.lpNorm<Eigen::Infinity>())) {
      out.contraction = std::max(out.contraction, step_norm / previous_step);
    }
    previous_step = step_norm;
    if (!accepted) {
      // At the integration noise floor no step reduces the residual any more.
      if (step_norm <= options.step_tolerance * (1.0 + z.lpNorm<Eigen::Infinity>()) &&
          norm <= 1e3 * options.residual_tolerance) {
        out.set_converged(true);
        out.residual = norm;
        out.message =
            fmt::format("converged at the integration noise floor: max residual {:.3e}", norm);
        return out;
      }
      out.residual = norm;
      out.message =
          fmt::format("line search failed after {} Newton iterations at max residual {:.3e}",
                      out.iterations,
                      norm);
      return out;
    }
  }
  out.residual = norm;
  if (norm <= options.residual_tolerance) {
    out.set_converged(true);
    out.message = fmt::format("converged: max residual {:.3e}", norm);
  } else {
    out.message = fmt::format("no convergence in {} Newton iterations (max residual {:.3e})",
                              options.max_iterations,
                              norm);
  }
  return out;
}

}  // namespace flexure
