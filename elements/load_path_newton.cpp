#include "flexure/elements/load_path_newton.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace flexure::detail {
namespace {

// A x = b by LU; where A is (nearly) singular, the minimum-norm least-squares solution (e.g. the
// axial force of an inextensible beam between two fixed ends is indeterminate while it is
// straight).
Eigen::VectorXd solve_linear(const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(A);
  Eigen::VectorXd x = lu.solve(b);
  if (x.allFinite() &&
      (A * x - b).lpNorm<Eigen::Infinity>() <= 1e-9 * (1.0 + b.lpNorm<Eigen::Infinity>())) {
    return x;
  }
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(A);
  cod.setThreshold(1e-12);
  return cod.solve(b);
}

bool forward_difference_jacobian(const ResidualFunction& residual,
                                 const Eigen::VectorXd& z,
                                 double lambda,
                                 const Eigen::VectorXd& r0,
                                 Eigen::MatrixXd& J) {
  J.resize(r0.size(), z.size());
  Eigen::VectorXd zp = z;
  Eigen::VectorXd rp(r0.size());
  for (Eigen::Index j = 0; j < z.size(); ++j) {
    const double h = 1e-8 * std::max(1.0, std::fabs(z[j]));
    zp[j] = z[j] + h;
    if (!residual(zp, lambda, rp)) return false;
    J.col(j) = (rp - r0) / h;
    zp[j] = z[j];
  }
  return true;
}

struct NewtonResult {
  bool converged = false;
  int iterations = 0;
  double residual = 0.0;
};

NewtonResult newton(Eigen::VectorXd& z,
                    double lambda,
                    const ResidualFunction& residual,
                    const JacobianFunction& jacobian,
                    const LoadPathOptions& options) {
  NewtonResult out;
  Eigen::VectorXd r;
  if (!residual(z, lambda, r)) return out;
  double norm = r.lpNorm<Eigen::Infinity>();
  Eigen::MatrixXd J;
  Eigen::VectorXd r_try;
  for (int it = 0; it <= options.max_iterations; ++it) {
    out.residual = norm;
    if (norm <= options.tolerance) {
      out.converged = true;
      return out;
    }
    if (it == options.max_iterations) break;
    const bool have_J =
        jacobian ? jacobian(z, lambda, J) : forward_difference_jacobian(residual, z, lambda, r, J);
    if (!have_J) return out;
    const Eigen::VectorXd step = solve_linear(J, -r);
    if (!step.allFinite()) return out;
    ++out.iterations;
    // Backtracking on the max-norm of the residual: protects against jumping branches.
    double t = 1.0;
    bool accepted = false;
    for (int bt = 0; bt < 12; ++bt, t *= 0.5) {
      const Eigen::VectorXd z_try = z + t * step;
      if (!residual(z_try, lambda, r_try)) continue;
      const double norm_try = r_try.lpNorm<Eigen::Infinity>();
      if (std::isfinite(norm_try) && norm_try < (1.0 - 1e-4 * t) * norm) {
        z = z_try;
        r = r_try;
        norm = norm_try;
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      // At the noise floor of the residual no step decreases it any more.
      out.converged = norm <= 1e3 * options.tolerance;
      out.residual = norm;
      return out;
    }
  }
  return out;
}

}  // namespace

LoadPathOutcome follow_load_path(Eigen::VectorXd& z,
                                 const ResidualFunction& residual,
                                 const JacobianFunction& jacobian,
                                 const MeasureFunction& measure,
                                 const LoadPathOptions& options) {
  LoadPathOutcome out;
  double lambda = 0.0;
  double step = 1.0;
  Eigen::VectorXd previous = z;  // state at the previous accepted load factor (secant predictor)
  double previous_step = 0.0;
  int attempts = 0;
  while (lambda < 1.0) {
    if (++attempts > options.max_load_steps) {
      out.message =
          fmt::format("the load path needed more than {} steps (reached load factor {:.6g})",
                      options.max_load_steps,
                      lambda);
      return out;
    }
    step = std::min(step, 1.0 - lambda);
    const double target = lambda + step;
    Eigen::VectorXd trial = z;
    if (previous_step > 0.0) trial += (z - previous) * (step / previous_step);
    const NewtonResult n = newton(trial, target, residual, jacobian, options);
    out.iterations += n.iterations;
    const double change =
        n.converged ? (measure(trial) - measure(z)).lpNorm<Eigen::Infinity>() : 0.0;
    if (n.converged && (change <= options.max_change || step <= options.min_step)) {
      previous = z;
      previous_step = step;
      z = trial;
      lambda = target == 1.0 || 1.0 - target < 1e-15 ? 1.0 : target;
      out.load_factor = lambda;
      out.residual = n.residual;
      ++out.load_steps;
      // Grow after an easy step, shrink toward the wanted change per step.
      double factor = n.iterations <= 4 ? 2.0 : 1.0;
      if (change > 0.0) factor = std::min(factor, options.max_change / change);
      step = std::max(step * std::clamp(factor, 0.25, 2.0), options.min_step);
      continue;
    }
    if (step <= options.min_step) {
      out.message = fmt::format(
          "the load path could not be followed past load factor {:.6g} (no equilibrium within a "
          "step of {:.1e}: a fold of the load path or a load the model cannot carry)",
          lambda,
          step);
      return out;
    }
    step = std::max(step * 0.5, options.min_step);
  }
  out.converged = true;
  return out;
}

}  // namespace flexure::detail
