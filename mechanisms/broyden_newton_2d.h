#pragma once
// Damped Newton iteration on two unknowns with Broyden updates of the Jacobian, used by the exact
// mechanism models that close a loop by shooting (mechanism_exact_pin.cpp): each evaluation is a
// full shooting solve, so the Jacobian is formed by finite differences only when none is known or
// a step with the old one fails to halve the mismatch, and is otherwise updated from the steps.
#include <Eigen/Dense>
#include <algorithm>
#include <functional>

namespace flexure::mechanism {

struct BroydenNewtonOptions {
  double tolerance = 1e-10;    // stop when |r| is below this
  double noise_floor = 1e-12;  // |r| below this is round-off: no line search, no failure
  int max_iterations = 50;
};

struct BroydenNewtonOutcome {
  int iterations = 0;
  bool stalled = false;  // no decrease of |r| above the noise floor (the caller names it)
};

// `evaluate(x)` returns an Eval with members `bool ok` and `Eigen::Vector2d r` (the mismatch).
// `x` and `e` (the evaluation at x) are updated in place; `J` is used as the starting Jacobian
// when `have_jacobian`. `fd_steps(x)` gives the finite-difference steps; `before_step(e)` runs at
// the start of every iteration (e.g. to keep warm starts of the inner solves current).
template <typename Eval>
BroydenNewtonOutcome broyden_newton_2d(
    const std::function<Eval(const Eigen::Vector2d&)>& evaluate,
    Eigen::Vector2d& x,
    Eval& e,
    Eigen::Matrix2d& J,
    bool have_jacobian,
    const std::function<Eigen::Vector2d(const Eigen::Vector2d&)>& fd_steps,
    const std::function<void(const Eval&)>& before_step,
    const BroydenNewtonOptions& options) {
  BroydenNewtonOutcome out;
  bool fresh = false;
  for (; e.ok && e.r.norm() > options.tolerance && out.iterations < options.max_iterations;
       ++out.iterations) {
    before_step(e);
    if (!have_jacobian) {
      const Eigen::Vector2d h = fd_steps(x);
      const Eval ex = evaluate(x + Eigen::Vector2d(h(0), 0.0));
      const Eval ey = evaluate(x + Eigen::Vector2d(0.0, h(1)));
      if (!ex.ok || !ey.ok) {
        e = ex.ok ? ey : ex;
        break;
      }
      J.col(0) = (ex.r - e.r) / h(0);
      J.col(1) = (ey.r - e.r) / h(1);
      have_jacobian = fresh = true;
    }
    const Eigen::Vector2d step = J.fullPivLu().solve(-e.r);
    Eval trial = evaluate(x + step);
    if (!fresh && !(trial.ok && trial.r.norm() < 0.5 * e.r.norm())) {
      have_jacobian = false;  // stale Jacobian: refresh it and retry from the same point
      continue;
    }
    const bool at_floor = e.r.norm() <= options.noise_floor;
    double t = 1.0;
    for (int k = 0; k < 12 && !at_floor && !(trial.ok && trial.r.norm() < e.r.norm()); ++k) {
      t *= 0.5;
      trial = evaluate(x + t * step);
    }
    if (!trial.ok || trial.r.norm() >= e.r.norm()) {
      out.stalled = e.r.norm() > options.noise_floor;
      break;
    }
    const Eigen::Vector2d dx = t * step;
    J += ((trial.r - e.r) - J * dx) * dx.transpose() / dx.squaredNorm();  // Broyden
    fresh = false;
    x += dx;
    e = trial;
  }
  return out;
}

}  // namespace flexure::mechanism
