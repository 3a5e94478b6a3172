#include "flexure/solver/elliptic/tip_chart.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace flexure::elliptic {
namespace {

// Hysteresis of the chart choice (see preferred_chart).
constexpr double kEnterChart = 0.01;
constexpr double kLeaveChart = 0.05;

}  // namespace

double separatrix_scale(double force) { return 0.5 * std::exp(-std::sqrt(force)); }

double separatrix_chart_scale(const PendulumProblem& problem) {
  // d/(1 + d) rather than min(1, d): the chart must be smooth in the load factor, or the path's
  // tangent jumps where d = 1.
  const double d = std::fabs(problem.mu) / std::sqrt(problem.force);
  // Kept above underflow: for a moment this small the separatrix chart is never preferred.
  return std::max(separatrix_scale(problem.force) * d / (1.0 + d), 1e-290);
}

bool tip_state_in_chart(const PendulumProblem& problem,
                        const TipChart& chart,
                        double x,
                        TipState& state) {
  if (!std::isfinite(x)) return false;
  switch (chart.kind) {
    case TipChart::Kind::kAngle:
      state = tip_state_from_angle(problem, x);
      return true;
    case TipChart::Kind::kSaddle: {
      const double tau = separatrix_scale(problem.force) * std::sinh(x);
      if (!(std::fabs(tau) <= std::numbers::pi)) return false;
      state = tip_state_from_reduced_angle(problem, chart.winding, tau);
      return true;
    }
    case TipChart::Kind::kSeparatrix: {
      const double w = separatrix_chart_scale(problem) * std::sinh(x);
      return std::isfinite(w) &&
             tip_state_near_separatrix(problem, w, chart.side, chart.winding, state);
    }
  }
  return false;
}

ChartPoint preferred_chart(const PendulumProblem& problem,
                           const TipChart& current,
                           const TipState& state) {
  // a = sin^2(tau/2) and 1 - a = cos^2(tau/2), both without cancellation.
  const double a = state.half_cos * state.half_cos;
  const double b = state.half_sin * state.half_sin;
  const double w = state.h_minus / problem.force;
  const double epsilon = separatrix_scale(problem.force);
  auto wanted = [&](TipChart::Kind kind, double measure) {
    return measure < (current.kind == kind ? kLeaveChart : kEnterChart);
  };
  ChartPoint out;
  if (wanted(TipChart::Kind::kSeparatrix, std::fabs(w) / std::min(a, b))) {
    out.chart.kind = TipChart::Kind::kSeparatrix;
    out.chart.side = state.tau >= 0.0 ? 1 : -1;
    out.chart.winding = state.winding;
    out.x = std::asinh(w / separatrix_chart_scale(problem));
  } else if (wanted(TipChart::Kind::kSaddle, std::fabs(state.tau))) {
    out.chart.kind = TipChart::Kind::kSaddle;
    out.chart.winding = state.winding;
    out.x = std::asinh(state.tau / epsilon);
  } else {
    out.x = state.t();
  }
  return out;
}

}  // namespace flexure::elliptic
