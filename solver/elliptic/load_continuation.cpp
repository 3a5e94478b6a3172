#include "solver/elliptic/load_continuation.h"

#include <fmt/format.h>

#include <cmath>

#include "solver/common/scalar_root.h"

namespace flexure::elliptic {
namespace {

struct Corrected {
  bool found = false;
  double chi = 0.0;
  double residual = 0.0;
};

// Root of the tip-angle residual near `predicted`: secant iteration from the prediction (a few
// evaluations when the prediction is good), falling back to a bracket search in windows growing
// from `window` and Brent's method when the secant leaves the window.
Corrected correct(const PendulumProblem& problem,
                  double predicted,
                  double window,
                  double x_tolerance,
                  int& evaluations) {
  auto residual = [&](double chi) {
    ++evaluations;
    return tip_angle_residual(problem, chi);
  };
  const double r_center = residual(predicted);
  if (!std::isfinite(r_center)) return {};
  if (r_center == 0.0) return {true, predicted, 0.0};

  // Secant phase. The residual's slope d chi(0)/d chi1 is 1 for an unloaded beam; start there.
  {
    // First secant pair from a small finite-difference step: the residual's slope ranges from
    // near 0 to large (tension), so no fixed slope guess is good.
    double x0 = predicted, r0 = r_center;
    double x1 = predicted + 1e-7 * std::max(1.0, std::fabs(predicted));
    if (std::fabs(x1 - predicted) <= 4.0 * window) {
      double r1 = residual(x1);
      for (int iter = 0; iter < 12 && std::isfinite(r1); ++iter) {
        if (r1 == r0) break;
        const double x2 = x1 - r1 * (x1 - x0) / (r1 - r0);
        if (!std::isfinite(x2) || std::fabs(x2 - predicted) > 4.0 * window) break;
        // Relative to |t|: near the separatrix k'^2 ~ sin^2(t/2), so t needs relative precision.
        if (std::fabs(x2 - x1) <= x_tolerance * std::max(std::fabs(x1), 1e-200)) {
          return {true, x2, r1};
        }
        x0 = x1;
        r0 = r1;
        x1 = x2;
        r1 = residual(x1);
        if (r1 == 0.0) return {true, x1, 0.0};
      }
    }
  }

  // Bracket phase: sample outwards from the prediction, nearest side first.
  double left = predicted, r_left = r_center;
  double right = predicted, r_right = r_center;
  ScalarRootOptions opts;
  opts.x_tolerance = x_tolerance * std::max(std::fabs(predicted), 1e-200);
  for (int level = 0; level < 6; ++level) {
    const double reach = window * std::ldexp(1.0, level);
    for (int side = 0; side < 2; ++side) {
      // The residual usually increases with chi1, so a negative residual puts the root right.
      const bool go_right = (side == 0) == (r_center < 0.0);
      const double x = predicted + (go_right ? reach : -reach);
      const double r = residual(x);
      if (!std::isfinite(r)) continue;
      double& edge = go_right ? right : left;
      double& r_edge = go_right ? r_right : r_left;
      if ((r > 0.0) != (r_edge > 0.0) || r == 0.0) {
        const ScalarRootResult root = brent_root(residual, edge, x, r_edge, r, opts);
        if (root.converged) return {true, root.x, root.f};
        return {};
      }
      edge = x;
      r_edge = r;
    }
  }
  return {};
}

}  // namespace

ContinuationSolution solve_by_continuation(double force,
                                           double psi,
                                           double mu,
                                           const ContinuationOptions& options) {
  ContinuationSolution out;
  // Unknown: t = theta0 - psi (elastica_closed_form.h); unloaded, theta0 = 0.
  // Linear theory at lambda -> 0: theta0 = Fy/2 + mu (axial load neglected), the first slope.
  double slope = 0.5 * force * std::sin(psi) + mu;
  double lambda = 0.0;
  double chi = -psi;
  double step = std::min(1.0, options.max_angle_step / std::max(std::fabs(slope), 1e-12));
  int evaluations = 0;
  while (lambda < 1.0) {
    if (out.steps >= options.max_steps) {
      out.message =
          fmt::format("elliptic continuation stopped after {} load steps at load factor {:.6g}",
                      out.steps,
                      lambda);
      break;
    }
    const double next = std::min(1.0, lambda + step);
    const double h = next - lambda;
    const double predicted = chi + h * slope;
    const PendulumProblem problem = make_pendulum_problem(next * force, psi, next * mu);
    const double window = std::max(0.25 * std::fabs(predicted - chi), 1e-6);
    const double tol = next == 1.0 ? options.x_tolerance : options.step_tolerance;
    const Corrected c = correct(problem, predicted, window, tol, evaluations);
    const double change = c.chi - chi;
    // A secant predictor is first order, so its error grows like h^2; the check only guards
    // against the corrector landing on another equilibrium, which differs by a finite angle.
    const bool close = c.found && std::fabs(c.chi - predicted) <=
                                      0.5 * std::fabs(predicted - chi) + options.branch_jump_guard;
    if (!close) {
      step *= 0.5;
      if (step < options.min_load_step) {
        out.message = fmt::format(
            "no equilibrium continuous with proportional loading beyond load factor {:.9g}: a "
            "limit "
            "point (the beam snaps through); the shooting method with arc-length continuation can "
            "follow the path past it",
            lambda);
        break;
      }
      continue;
    }
    slope = change / h;
    lambda = next;
    chi = c.chi;
    out.residual = c.residual;
    ++out.steps;
    // Grow the step, but keep the predicted change of tip angle moderate.
    step = std::min(2.0 * step, options.max_angle_step / std::max(std::fabs(slope), 1e-12));
  }
  out.iterations = evaluations;
  out.load_factor_reached = lambda;
  out.tip_from_force = chi;
  out.converged = lambda >= 1.0;
  if (out.converged) out.message = "converged";
  return out;
}

}  // namespace flexure::elliptic
