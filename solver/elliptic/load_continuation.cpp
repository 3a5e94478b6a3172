#include "flexure/solver/elliptic/load_continuation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "flexure/solver/elliptic/tip_chart.h"

namespace flexure::elliptic {
namespace {

// g(x, lambda): the tip-angle residual of the problem scaled by the load factor, at coordinate x
// of a tip chart (tip_chart.h). NaN outside the chart.
class PathResidual {
 public:
  PathResidual(double force, double psi, double mu)
      : force_(force), mu_(mu), full_(make_pendulum_problem(force, psi, mu)) {}
  // The problem at load factor lambda; the force angle and its half-angle functions do not change
  // along the path.
  PendulumProblem problem(double lambda) const {
    PendulumProblem p = full_;
    p.force = lambda * force_;
    p.mu = lambda * mu_;
    return p;
  }
  // The path is followed with the residual by the addition theorem (tip_angle_residual_by_addition:
  // 0.6 of the cost, within about 1e-13 of the other, far below the corrector tolerance); only the
  // final polish uses the full-precision one, `exact`.
  double operator()(const TipChart& chart, double x, double lambda) {
    return evaluate(chart, x, lambda, false);
  }
  double exact(const TipChart& chart, double x, double lambda) {
    return evaluate(chart, x, lambda, true);
  }
  long evaluations = 0;

 private:
  double evaluate(const TipChart& chart, double x, double lambda, bool full_precision) {
    ++evaluations;
    if (!(lambda > 0.0)) return std::nan("");  // a predictor behind the unloaded beam
    const PendulumProblem p = problem(lambda);
    TipState state;
    if (!tip_state_in_chart(p, chart, x, state)) return std::nan("");
    return full_precision ? tip_angle_residual(p, state) : tip_angle_residual_by_addition(p, state);
  }
  double force_, mu_;
  PendulumProblem full_;
};

// A point of the path in chart coordinates (x, lambda) with the residual's partial derivatives.
struct PathPoint {
  TipChart chart;
  double t = 0.0;  // chart coordinate x (named t because the angle chart's x is the tip angle)
  double lambda = 0.0;
  double g = 0.0;
  double g_t = 1.0;       // dg/dx
  double g_lambda = 0.0;  // dg/dlambda
  // Unit tangent sigma (-g_lambda, g_x)/|.|, sigma the chart's orientation: the direction of the
  // path never depends on the step, and dlambda/ds = sigma g_x/|.| has the same meaning in every
  // chart.
  double tangent_t() const { return -chart.orientation() * g_lambda / norm(); }
  double tangent_lambda() const { return chart.orientation() * g_t / norm(); }
  // |(g_x, g_lambda)|; the derivatives are far from overflow, so no hypot (a third of a residual's
  // cost at the rate tangents are taken).
  double norm() const { return std::sqrt(g_t * g_t + g_lambda * g_lambda); }
};

// Forward differences: the residual costs about a microsecond, and the Jacobian only steers the
// corrector (chord method) and orients the tangent, so a relative step of 1e-8 is enough.
bool differentiate(PathResidual& g, PathPoint& p) {
  const double ht = 1e-8 * std::max(1.0, std::fabs(p.t));
  const double hl = 1e-8 * std::max(p.lambda, 1e-3);
  p.g_t = (g(p.chart, p.t + ht, p.lambda) - p.g) / ht;
  p.g_lambda = (g(p.chart, p.t, p.lambda + hl) - p.g) / hl;
  return std::isfinite(p.g_t) && std::isfinite(p.g_lambda) && (p.g_t != 0.0 || p.g_lambda != 0.0);
}

// Keller's pseudo-arclength corrector from the predictor (tp, lp): quasi-Newton on
// g(t, lambda) = 0, tangent . ((t, lambda) - predictor) = 0, or with lambda fixed at the predictor
// when `fixed_lambda`. The Jacobian is the one of the point the step starts from, updated by
// Broyden's rank-one formula after every evaluation (first along the predictor step, then along
// each correction), so no derivative is evaluated before the corrector has converged. It
// converges only if every correction is at most half the previous one, and only while the
// updated Jacobian keeps the path's orientation (the sign of the tangent determinant). A point is
// accepted once the correction it asks for is below the corrector tolerance; its Jacobian is then
// evaluated afresh (forward differences) to orient the new tangent, whose turn the caller checks.
struct Corrected {
  bool ok = false;
  int iterations = 0;
  double first_correction = 0.0;  // the predictor's distance from the path, about
  PathPoint point;
};
Corrected correct(PathResidual& g,
                  const PathPoint& from,
                  double tp,
                  double lp,
                  bool fixed_lambda,
                  const ContinuationOptions& options,
                  double jacobian_drift_t = 0.0,
                  double jacobian_drift_l = 0.0) {
  Corrected out;
  PathPoint p;
  p.chart = from.chart;
  p.t = tp;
  p.lambda = lp;
  p.g = g(p.chart, tp, lp);
  if (!std::isfinite(p.g)) return out;
  // The Jacobian at the predictor: the start point's, moved on by the drift of the last step.
  double j_t = from.g_t + jacobian_drift_t, j_l = from.g_lambda + jacobian_drift_l;
  auto broyden = [&](double dt, double dl, double dg) {
    const double d2 = dt * dt + dl * dl;
    if (!(d2 > 0.0)) return;
    const double r = (dg - (j_t * dt + j_l * dl)) / d2;
    j_t += r * dt;
    j_l += r * dl;
  };
  broyden(tp - from.t, lp - from.lambda, p.g - from.g);
  const double tau_t = from.tangent_t(), tau_l = from.tangent_lambda();
  double previous = HUGE_VAL;
  for (int it = 0; it < options.max_corrector_iterations; ++it) {
    // Orientation at this point must agree with the path's (sign of the tangent determinant).
    const double det = fixed_lambda ? j_t : j_t * tau_l - j_l * tau_t;
    if (!(fixed_lambda ? j_t * from.g_t > 0.0 : det * from.chart.orientation() > 0.0)) return out;
    double dt = 0.0, dl = 0.0;
    if (fixed_lambda) {
      dt = -p.g / j_t;
    } else {
      const double r2 = tau_t * (p.t - tp) + tau_l * (p.lambda - lp);
      dt = (-p.g * tau_l + r2 * j_l) / det;
      dl = (-j_t * r2 + tau_t * p.g) / det;
    }
    const double size = std::sqrt(dt * dt + dl * dl);
    out.iterations = it + 1;
    if (it == 0) out.first_correction = size;
    if (!std::isfinite(size)) return out;
    const double tolerance = options.corrector_tolerance * std::max(1.0, std::fabs(p.t));
    if (size <= tolerance) {
      if (!differentiate(g, p)) return out;
      out.ok = true;
      out.point = p;
      return out;
    }
    if (it > 0 && size > 0.5 * previous) return out;  // not contracting: too far from the path
    // The iteration converges superlinearly, so the correction after this one is smaller than
    // this one by at least the last ratio: once that predicts it below the tolerance, the
    // corrected point is accepted without evaluating it. Its Jacobian is taken at p, a correction
    // away, and its residual is the linear prediction, zero. (At full load the residual is
    // evaluated, as the polish starts from it.)
    if (!fixed_lambda && it > 0 && size * (size / previous) <= tolerance) {
      if (!differentiate(g, p)) return out;
      p.t += dt;
      p.lambda += dl;
      p.g = 0.0;
      if (!(p.lambda > 0.0)) return out;
      out.ok = true;
      out.point = p;
      return out;
    }
    previous = size;
    const double g_before = p.g;
    p.t += dt;
    p.lambda += dl;
    if (!(p.lambda > 0.0)) return out;
    p.g = g(p.chart, p.t, p.lambda);
    if (!std::isfinite(p.g)) return out;
    broyden(dt, dl, p.g - g_before);
  }
  return out;
}

// A point re-expressed in a new chart: it was within the corrector tolerance in the old chart's
// coordinate, which near the separatrix is many times coarser than the new chart's (its scale is
// e^(-sqrt F)/2 or smaller). Secant steps at fixed load factor bring it back within the tolerance
// in the new coordinate, then its Jacobian is evaluated afresh. False if they do not converge.
bool settle(PathResidual& g, PathPoint& p, const ContinuationOptions& options) {
  double slope = p.g_t;
  bool moved = false;
  for (int it = 0; it < options.max_corrector_iterations; ++it) {
    const double dx = -p.g / slope;
    if (!std::isfinite(dx)) return false;
    if (std::fabs(dx) <= options.corrector_tolerance * std::max(1.0, std::fabs(p.t))) {
      return !moved || differentiate(g, p);
    }
    const double g_before = p.g;
    p.t += dx;
    p.g = g(p.chart, p.t, p.lambda);
    if (!std::isfinite(p.g) || p.g == g_before) return false;
    slope = (p.g - g_before) / dx;
    moved = true;
  }
  return false;
}

// Full-precision root at lambda = 1 from a converged path point: secant steps on the
// full-precision residual, which stay on this root because the point is already within the
// corrector tolerance of it.
void polish(PathResidual& g, PathPoint& p, double x_tolerance) {
  double x0 = p.t, g0 = g.exact(p.chart, p.t, 1.0), slope = p.g_t;
  if (!std::isfinite(g0)) return;
  for (int it = 0; it < 30 && g0 != 0.0; ++it) {
    const double x1 = x0 - g0 / slope;
    const double g1 = g.exact(p.chart, x1, 1.0);
    if (!std::isfinite(g1)) break;
    const bool done = std::fabs(x1 - x0) <= x_tolerance * std::max(std::fabs(x1), 1e-200);
    if (std::fabs(g1) <= std::fabs(g0) || done) {
      if (x1 != x0 && g1 != g0) slope = (g1 - g0) / (x1 - x0);
      x0 = x1;
      g0 = g1;
    } else {
      break;  // rounding level reached: keep the best point
    }
    if (done) break;
  }
  p.t = x0;
  p.g = g0;
}

// Load factor at the fold between `from` (d lambda/ds of one sign) and the accepted point one
// arclength step further (the other sign): bisection on the arclength of the predictor, each
// trial corrected onto the path; lambda is stationary there, so its error is quadratic in the
// arclength bracket.
double locate_fold(PathResidual& g,
                   const PathPoint& from,
                   double step,
                   double lambda_end,
                   const ContinuationOptions& options) {
  const bool rising = from.tangent_lambda() > 0.0;
  double lo = 0.0, hi = step;
  double best = rising ? std::max(from.lambda, lambda_end) : std::min(from.lambda, lambda_end);
  // The trials are corrected tightly: `best` is the largest lambda among them, so a trial left at
  // the path's loose corrector_tolerance (1e-7) biased the fold upward by up to that much (9e-8
  // at n = 0, alpha2 = 10, mu = -2 pi against the shooting path's located fold and an
  // independent maximisation of lambda(m0), tests/solver/shooting_bifurcation_test.cpp).
  ContinuationOptions tight = options;
  tight.corrector_tolerance = std::min(options.corrector_tolerance, 1e-13);
  tight.max_corrector_iterations = std::max(options.max_corrector_iterations, 20);
  for (int it = 0; it < 40 && hi - lo > 1e-12 * step; ++it) {
    const double mid = 0.5 * (lo + hi);
    const Corrected c = correct(g,
                                from,
                                from.t + mid * from.tangent_t(),
                                from.lambda + mid * from.tangent_lambda(),
                                false,
                                tight);
    if (!c.ok) break;
    best = rising ? std::max(best, c.point.lambda) : std::min(best, c.point.lambda);
    if ((c.point.tangent_lambda() > 0.0) == rising) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return best;
}

}  // namespace

ContinuationSolution solve_by_continuation(double force,
                                           double psi,
                                           double mu,
                                           const ContinuationOptions& options) {
  ContinuationSolution out;
  PathResidual g(force, psi, mu);
  // Unloaded beam: t = theta0 - psi = -psi. Linear theory gives the path's first direction,
  // d theta0 / d lambda = Fy/2 + mu (axial load has no first-order effect), so the start's
  // tangent is (Fy/2 + mu, 1); as g_t = 1 at zero load, g_lambda = -(Fy/2 + mu).
  PathPoint y;
  y.t = -psi;
  y.lambda = 0.0;
  y.g_t = 1.0;
  y.g_lambda = -(0.5 * force * std::sin(psi) + mu);
  double h = options.initial_step;
  int attempts = 0;
  // The budget grows with the path's expected length: the tip angle turns by about |mu| plus a
  // few radians per buckling mode (about sqrt(F)/pi of them), in steps of at most max_step.
  const double expected_steps = (std::fabs(mu) + std::sqrt(force)) / options.max_step;
  const long max_attempts = options.max_steps + static_cast<long>(10.0 * expected_steps);
  const long max_evaluations = options.max_evaluations + static_cast<long>(100.0 * expected_steps);
  std::string failure;
  double bend_t = 0.0, bend_l = 0.0;
  double drift_t = 0.0, drift_l = 0.0;  // change of the Jacobian per unit arclength
  while (true) {
    if (attempts >= max_attempts || g.evaluations >= max_evaluations) {
      failure = fmt::format("the continuation budget ({} steps, {} residual evaluations) ran out",
                            attempts,
                            g.evaluations);
      break;
    }
    ++attempts;
    const double tau_t = y.tangent_t(), tau_l = y.tangent_lambda();
    // Second-order predictor: the path bends by `bend` per unit arclength (the change of the
    // tangent over the last step), X(h) = y + h tau + h^2 bend / 2.
    const double rise = 1.0 - y.lambda;
    bool crosses = tau_l > 0.0 && tau_l * h + 0.5 * bend_l * h * h >= rise;
    double step = h;
    if (crosses) {
      // Arclength to lambda = 1 on the predicted parabola (its first root, in the stable form).
      const double discriminant = tau_l * tau_l + 2.0 * bend_l * rise;
      step = discriminant >= 0.0 ? 2.0 * rise / (tau_l + std::sqrt(discriminant)) : h;
      crosses = discriminant >= 0.0 && step <= h;
      if (!crosses) step = h;
    }
    const double tp = y.t + step * tau_t + 0.5 * step * step * bend_t;
    const double lp = crosses ? 1.0 : y.lambda + step * tau_l + 0.5 * step * step * bend_l;
    const Corrected c = correct(g, y, tp, lp, crosses, options, drift_t * step, drift_l * step);
    bool accepted = c.ok;
    if (accepted) {
      const PathPoint& p = c.point;
      const double distance =
          std::sqrt((p.t - tp) * (p.t - tp) + (p.lambda - lp) * (p.lambda - lp));
      // The turn is measured from the tangent the bend predicts: the path's own curvature does
      // not count, a jump to another branch or a reversal does.
      double pred_t = tau_t + step * bend_t, pred_l = tau_l + step * bend_l;
      const double pred_norm = std::sqrt(pred_t * pred_t + pred_l * pred_l);
      pred_t /= pred_norm;
      pred_l /= pred_norm;
      const double turn_cos = p.tangent_t() * pred_t + p.tangent_lambda() * pred_l;
      accepted = distance <= options.max_predictor_distance * step + 1e-12 &&
                 turn_cos >= std::cos(options.max_turn);
      if (accepted && !crosses && p.lambda >= 1.0) {
        // The corrected point landed past full load although its predictor did not (the path
        // bends up): a shorter step, until the predictor itself crosses and the corrector is
        // held at lambda = 1. (Going to lambda = 1 along the tangent instead would take a step
        // of (1 - lambda)/tau_lambda, unbounded where the path runs nearly level.)
        h = 0.5 * step;
        continue;
      }
    }
    if (!accepted) {
      ++out.rejected_steps;
      h = 0.5 * step;
      if (h < options.min_step) {
        failure = fmt::format(
            "the arclength step fell below {:.1e} at load factor {:.9g} (tip angle from the force "
            "{:.9g} rad): the path cannot be followed reliably here",
            options.min_step,
            y.lambda,
            y.t);
        break;
      }
      continue;
    }
    const PathPoint& p = c.point;
    if ((p.tangent_lambda() > 0.0) != (tau_l > 0.0)) {
      if (out.limit_points == 0) {
        const PathPoint accepted = c.point;
        out.first_limit_load_factor = locate_fold(g, y, step, accepted.lambda, options);
      }
      ++out.limit_points;
    }
    ++out.steps;
    drift_t = (p.g_t - y.g_t) / step;
    drift_l = (p.g_lambda - y.g_lambda) / step;
    bend_t = (p.tangent_t() - tau_t) / step;
    bend_l = (p.tangent_lambda() - tau_l) / step;
    y = p;
    out.load_factor_reached = std::max(out.load_factor_reached, y.lambda);
    if (crosses) {
      polish(g, y, options.x_tolerance);
      out.set_converged(true);
      break;
    }
    // The first correction is the predictor's error, about (curvature/2) step^2: the next step
    // aims at predictor_error times its length.
    const double ratio = c.first_correction / (options.predictor_error * step);
    const double factor = ratio > 0.0 ? 1.0 / std::sqrt(ratio) : options.max_step_growth;
    h = std::min(step * std::clamp(factor, 0.5, options.max_step_growth), options.max_step);
    // Folds hide where d lambda/ds heads for zero: two of them (an S-shaped path) inside one step
    // would leave its sign unchanged at both ends and go unseen. While it falls towards zero at
    // the rate of the last step, the next step is kept to a fraction of the distance to zero.
    const double level_rate = (y.tangent_lambda() - tau_l) / step;
    if (y.tangent_lambda() * level_rate < 0.0) {
      h = std::min(h,
                   std::max(options.level_fraction * std::fabs(y.tangent_lambda() / level_rate),
                            options.initial_step));
    }
    // Re-express the point in the chart that resolves it best (tip_chart.h); a new chart has its
    // own scale, so the step starts afresh.
    const PendulumProblem problem = g.problem(y.lambda);
    TipState state;
    if (tip_state_in_chart(problem, y.chart, y.t, state)) {
      const ChartPoint best = preferred_chart(problem, y.chart, state);
      if (best.chart.kind != y.chart.kind || best.chart.side != y.chart.side ||
          best.chart.winding != y.chart.winding) {
        PathPoint moved = y;
        moved.chart = best.chart;
        moved.t = best.x;
        moved.g = g(moved.chart, moved.t, moved.lambda);
        if (std::isfinite(moved.g) && differentiate(g, moved) && settle(g, moved, options)) {
          y = moved;
          h = options.initial_step;
          bend_t = bend_l = 0.0;  // the bend is not comparable across charts
          drift_t = drift_l = 0.0;
        }
      }
    }
  }
  out.iterations = static_cast<int>(g.evaluations);
  {
    const PendulumProblem problem = g.problem(y.lambda);
    if (y.lambda > 0.0 && tip_state_in_chart(problem, y.chart, y.t, out.tip)) {
      out.tip_from_force = out.tip.t();
    } else {
      out.tip_from_force = y.t;
    }
  }
  out.residual = std::fabs(y.g);
  out.residual_slope = y.g_t;
  if (out.converged()) {
    out.message = "converged";
  } else {
    out.message =
        fmt::format("elliptic continuation stopped at load factor {:.9g} after {} steps: {}",
                    y.lambda,
                    out.steps,
                    failure);
  }
  return out;
}

}  // namespace flexure::elliptic
