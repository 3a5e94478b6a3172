#include "flexure/solver/elliptic/tabulated_predictor.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace flexure::elliptic {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// The addition-theorem residual is followed to this relative step (it agrees with the
// full-precision one to about 1e-13); the full-precision polish takes it from there.
constexpr double kAdditionTolerance = 1e-9;
// Largest correction of the full-precision polish (times max(1, |x|)).
constexpr double kPolishStep = 1e-6;

// Splits a fractional node coordinate into a cell (0 .. nodes - 2) and the position in it.
void split(double f, int nodes, int& cell, double& fraction) {
  cell = std::clamp(static_cast<int>(std::floor(f)), 0, nodes - 2);
  fraction = std::clamp(f - cell, 0.0, 1.0);
}

}  // namespace

PredictorGrid::Load PredictorGrid::load_at(double i, double j, double k) {
  const double sigma = sigma_at(j);
  const double rho = rho_at(k);
  // The point of the boundary of [0, 1] x [-1, 1] at sigma (see the header).
  double a = 1.0, m = sigma - 2.0;
  if (sigma < 1.0) {
    a = sigma;
    m = -1.0;
  } else if (sigma > 3.0) {
    a = 4.0 - sigma;
    m = 1.0;
  }
  return {n_at(i), kMaxAlpha2 * rho * a, kMaxMu * rho * m};
}

bool locate_in_grid(double Fx, double Fy, double mu, GridPoint& at) {
  using G = PredictorGrid;
  if (!(Fy > 0.0 && Fy <= G::kMaxAlpha2) || mu == 0.0 || !(std::fabs(mu) <= G::kMaxMu)) {
    return false;
  }
  const double n = -Fx / Fy;
  if (!(n >= G::kMinN && n <= G::kMaxN)) return false;
  const double a = Fy / G::kMaxAlpha2;
  const double m = mu / G::kMaxMu;
  const double rho = std::max(a, std::fabs(m));
  double sigma = 0.0;
  if (a >= std::fabs(m)) {
    sigma = 2.0 + m / rho;  // the side alpha2 = 20
  } else if (m < 0.0) {
    sigma = a / rho;  // the side mu = -2 pi
  } else {
    sigma = 4.0 - a / rho;  // the side mu = 2 pi
  }
  split((n - G::kMinN) / (G::kMaxN - G::kMinN) * (G::kNodesN - 1), G::kNodesN, at.i, at.ti);
  split(sigma / 4.0 * (G::kNodesSigma - 1), G::kNodesSigma, at.j, at.tj);
  split(rho * (G::kNodesRho - 1), G::kNodesRho, at.k, at.tk);
  return true;
}

double node_coordinate(const PredictorRow& row, const TipChart& chart) {
  switch (chart.kind) {
    case TipChart::Kind::kAngle:
      return row.t;
    case TipChart::Kind::kSaddle:
      return row.winding == chart.winding ? row.x_saddle : kNaN;
    case TipChart::Kind::kSeparatrix:
      return row.winding == chart.winding && row.side == chart.side ? row.x_separatrix : kNaN;
  }
  return kNaN;
}

TipChart cell_chart_of(const PredictorRow& row) {
  TipChart chart;
  chart.kind = static_cast<TipChart::Kind>(row.cell_chart);
  chart.winding = row.winding;
  chart.side = row.side;
  return chart;
}

double interpolate_in_chart(std::span<const PredictorRow> table,
                            const GridPoint& at,
                            const TipChart& chart) {
  double x = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const int di = corner & 1, dj = (corner >> 1) & 1, dk = (corner >> 2) & 1;
    const double weight =
        (di ? at.ti : 1.0 - at.ti) * (dj ? at.tj : 1.0 - at.tj) * (dk ? at.tk : 1.0 - at.tk);
    const PredictorRow& row =
        table[static_cast<std::size_t>(PredictorGrid::index(at.i + di, at.j + dj, at.k + dk))];
    x += weight * node_coordinate(row, chart);  // NaN propagates
  }
  return x;
}

GuardedNewton guarded_newton(const PendulumProblem& problem,
                             const TipChart& chart,
                             double x0,
                             double radius,
                             double x_tolerance) {
  GuardedNewton out;
  if (!std::isfinite(x0) || !(radius > 0.0)) return out;
  auto residual = [&](double x) {
    ++out.evaluations;
    TipState state;
    if (!tip_state_in_chart(problem, chart, x, state)) return kNaN;
    return tip_angle_residual_by_addition(problem, state);
  };
  const double orientation = chart.orientation();
  double x = x0;
  double g = residual(x);
  const double h = 1e-7 * std::max(1.0, std::fabs(x));
  double slope = (residual(x + h) - g) / h;
  if (!std::isfinite(g) || !std::isfinite(slope)) return out;
  double previous_step = HUGE_VAL;
  for (int step = 0;; ++step) {
    // A root of the other orientation, or the iteration heading across a fold.
    if (!(orientation * slope > 0.0)) return out;
    const double dx = -g / slope;
    if (!std::isfinite(dx) || std::fabs(dx) > 0.5 * previous_step) return out;
    const double next = x + dx;
    if (!(std::fabs(next - x0) <= radius)) return out;
    if (std::fabs(dx) <= kAdditionTolerance * std::max(1.0, std::fabs(next))) {
      x = next;
      break;
    }
    if (step + 1 >= kMaxNewtonSteps) return out;
    const double g_next = residual(next);
    if (!std::isfinite(g_next)) return out;
    if (g_next != g) slope = (g_next - g) / dx;
    x = next;
    g = g_next;
    previous_step = std::fabs(dx);
  }
  // Full-precision root: steps with the Newton iteration's last slope (a secant over its last
  // step, good to about 1e-7) on the integral form of the residual, from a point already within
  // about 1e-13 of the root, until the correction asked for is below x_tolerance (relative), or the
  // residual stops falling (rounding level: the best point is kept). Secants at this level would be
  // differences of rounding errors, so the slope is kept; and a correction that is not small is not
  // a polish: the root is refused.
  out.slope = slope;
  TipState tip;
  if (!tip_state_in_chart(problem, chart, x, tip)) return out;
  ++out.evaluations;
  BackwardIntegration at_x = integrate_from_tip(problem, tip);
  g = at_x.chi_root - problem.chi0;
  if (!std::isfinite(g)) return out;
  for (int it = 0; it < 30 && g != 0.0; ++it) {
    const double dx = -g / slope;
    if (!(std::fabs(dx) > x_tolerance * std::max(std::fabs(x), 1e-200))) break;
    if (!(std::fabs(dx) <= kPolishStep * std::max(1.0, std::fabs(x)))) return out;
    TipState next_tip;
    if (!tip_state_in_chart(problem, chart, x + dx, next_tip)) break;
    ++out.evaluations;
    BackwardIntegration at_next = integrate_from_tip(problem, next_tip);
    const double g_next = at_next.chi_root - problem.chi0;
    if (!(std::fabs(g_next) < std::fabs(g))) break;  // rounding level: keep the best
    x += dx;
    g = g_next;
    tip = next_tip;
    at_x = at_next;
  }
  if (!(std::fabs(x - x0) <= radius)) return out;
  out.accepted = true;
  out.x = x;
  out.tip = tip;
  out.parameters = at_x.parameters;
  out.residual = std::fabs(g);
  return out;
}

GuardedNewton solve_with_predictor(std::span<const PredictorRow> table,
                                   double Fx,
                                   double Fy,
                                   double mu,
                                   const PendulumProblem& problem,
                                   double x_tolerance) {
  GridPoint at;
  if (table.size() != static_cast<std::size_t>(PredictorGrid::kNodes) ||
      !locate_in_grid(Fx, Fy, mu, at)) {
    return {};
  }
  const PredictorRow& row = table[static_cast<std::size_t>(PredictorGrid::index(at.i, at.j, at.k))];
  if (row.cell_chart == kCellContinuation) return {};
  const TipChart chart = cell_chart_of(row);
  return guarded_newton(
      problem, chart, interpolate_in_chart(table, at, chart), row.cell_radius, x_tolerance);
}

}  // namespace flexure::elliptic
