#include "flexure/solver/elliptic/load_continuation.h"

#include <fmt/format.h>

#include <cmath>

#include "flexure/solver/elliptic/tip_chart.h"

namespace flexure::elliptic {
namespace {

// g(x, lambda): the tip-angle residual of the problem scaled by the load factor, at coordinate x
// of a tip chart (tip_chart.h). NaN outside the chart.
class PathResidual {
 public:
  PathResidual(double force, double psi, double mu) : force_(force), psi_(psi), mu_(mu) {}
  PendulumProblem problem(double lambda) const {
    return make_pendulum_problem(lambda * force_, psi_, lambda * mu_);
  }
  double operator()(const TipChart& chart, double x, double lambda) {
    ++evaluations;
    const PendulumProblem p = problem(lambda);
    TipState state;
    if (!tip_state_in_chart(p, chart, x, state)) return std::nan("");
    return tip_angle_residual(p, state);
  }
  long evaluations = 0;

 private:
  double force_, psi_, mu_;
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
  double tangent_t() const { return -chart.orientation() * g_lambda / std::hypot(g_t, g_lambda); }
  double tangent_lambda() const { return chart.orientation() * g_t / std::hypot(g_t, g_lambda); }
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

// Keller's pseudo-arclength corrector from the predictor (tp, lp): Newton (chord) on
// g(t, lambda) = 0, tangent . ((t, lambda) - predictor) = 0, or with lambda fixed at the predictor
// when `fixed_lambda`. Converges only if every correction is at most half the previous one.
struct Corrected {
  bool ok = false;
  int iterations = 0;
  PathPoint point;
};
Corrected correct(PathResidual& g,
                  const PathPoint& from,
                  double tp,
                  double lp,
                  bool fixed_lambda,
                  const ContinuationOptions& options) {
  Corrected out;
  PathPoint p;
  p.chart = from.chart;
  p.t = tp;
  p.lambda = lp;
  p.g = g(p.chart, tp, lp);
  if (!std::isfinite(p.g) || !differentiate(g, p)) return out;
  const double g_t = p.g_t, g_l = p.g_lambda;
  const double tau_t = from.tangent_t(), tau_l = from.tangent_lambda();
  // Orientation at the predictor must agree with the path's (sign of the tangent determinant).
  const double det = fixed_lambda ? g_t : g_t * tau_l - g_l * tau_t;
  if (!(fixed_lambda ? g_t * from.g_t > 0.0 : det * from.chart.orientation() > 0.0)) return out;
  double previous = HUGE_VAL;
  for (int it = 0; it < options.max_corrector_iterations; ++it) {
    if (it > 0) p.g = g(p.chart, p.t, p.lambda);
    if (!std::isfinite(p.g)) return out;
    double dt = 0.0, dl = 0.0;
    if (fixed_lambda) {
      dt = -p.g / g_t;
    } else {
      const double r2 = tau_t * (p.t - tp) + tau_l * (p.lambda - lp);
      dt = (-p.g * tau_l + r2 * g_l) / det;
      dl = (-g_t * r2 + tau_t * p.g) / det;
    }
    p.t += dt;
    p.lambda += dl;
    out.iterations = it + 1;
    const double size = std::hypot(dt, dl);
    if (!std::isfinite(size) || !(p.lambda > 0.0)) return out;
    if (size <= options.corrector_tolerance * std::max(1.0, std::fabs(p.t))) {
      p.g = g(p.chart, p.t, p.lambda);
      if (!std::isfinite(p.g) || !differentiate(g, p)) return out;
      out.ok = true;
      out.point = p;
      return out;
    }
    if (it > 0 && size > 0.5 * previous) return out;  // not contracting: too far from the path
    previous = size;
  }
  return out;
}

// Full-precision root at lambda = 1 from a converged path point: secant steps, which stay on this
// root because the point is already within 1e-11 of it.
void polish(PathResidual& g, PathPoint& p, double x_tolerance) {
  double x0 = p.t, g0 = p.g, slope = p.g_t;
  for (int it = 0; it < 30 && g0 != 0.0; ++it) {
    const double x1 = x0 - g0 / slope;
    const double g1 = g(p.chart, x1, 1.0);
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
  for (int it = 0; it < 40 && hi - lo > 1e-12 * step; ++it) {
    const double mid = 0.5 * (lo + hi);
    const Corrected c = correct(g,
                                from,
                                from.t + mid * from.tangent_t(),
                                from.lambda + mid * from.tangent_lambda(),
                                false,
                                options);
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
  bool overshot = false;
  std::string failure;
  while (true) {
    if (attempts >= max_attempts || g.evaluations >= max_evaluations) {
      failure = fmt::format("the continuation budget ({} steps, {} residual evaluations) ran out",
                            attempts,
                            g.evaluations);
      break;
    }
    ++attempts;
    const double tau_t = y.tangent_t(), tau_l = y.tangent_lambda();
    // A corrected point may land just past full load although its predictor did not: then the
    // next attempt goes to lambda = 1 directly.
    const bool crosses = tau_l > 0.0 && (overshot || y.lambda + h * tau_l >= 1.0);
    overshot = false;
    const double step = crosses ? (1.0 - y.lambda) / tau_l : h;
    const Corrected c = correct(
        g, y, y.t + step * tau_t, crosses ? 1.0 : y.lambda + step * tau_l, crosses, options);
    bool accepted = c.ok;
    if (accepted) {
      const PathPoint& p = c.point;
      const double distance = std::hypot(p.t - (y.t + step * tau_t),
                                         p.lambda - (crosses ? 1.0 : y.lambda + step * tau_l));
      const double turn_cos = p.tangent_t() * tau_t + p.tangent_lambda() * tau_l;
      accepted = distance <= options.max_predictor_distance * step + 1e-12 &&
                 turn_cos >= std::cos(options.max_turn);
      if (accepted && !crosses && p.lambda >= 1.0) {
        overshot = true;
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
    y = p;
    out.load_factor_reached = std::max(out.load_factor_reached, y.lambda);
    if (crosses) {
      polish(g, y, options.x_tolerance);
      out.set_converged(true);
      break;
    }
    const bool easy = c.iterations <= 3;
    h = easy ? std::min(1.6 * step, options.max_step) : step;
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
        if (std::isfinite(moved.g) && differentiate(g, moved)) {
          y = moved;
          h = options.initial_step;
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
