#pragma once
// Coordinates for the unknown tip state of the elliptic solver with an end moment.
//
// The tip state (chi1 = t + pi, chi1' = mu) is one number. Three charts describe it:
//  - the angle chart, x = t = theta0 - psi: good wherever the tip state is away from the
//    pendulum's saddle and its separatrix;
//  - a saddle chart, x = asinh(tau / epsilon) with t = 2 pi winding + tau: the tip aligned with
//    the force (tension), where tau is exponentially small and only its logarithm matters;
//  - a separatrix chart, x = asinh(w / epsilon) with w = h_minus / F, on one side of one
//    separatrix crossing (tau = side * 2 asin(sqrt(w + mu^2/(4F)))).
// Near the separatrix the backward trajectory lingers at the pendulum's saddle (the beam runs
// along the force in tension, or a loop in compression) and the clamp angle depends on ln|w|:
// equilibria whose tip angles differ by 1e-12 rad differ by O(1) in x, and w is formed without
// the cancellation of F sin^2(t/2) - mu^2/4. The scales are those below which a trajectory
// lingers at the saddle for the whole beam length, so that the residual varies by O(1) per unit
// of x in every chart (docs/theory-elliptic.md, "Charts"): near the saddle H - F factors into the
// two saddle coordinates, (chi' - sqrt(F) xi)(chi' + sqrt(F) xi)/2 with xi = chi - pi, one of which
// must be about sqrt(F) e^(-sqrt F) for the trajectory to linger over the length. A tip at the
// separatrix crossing has the other coordinate about |mu| (it sits |mu|/sqrt(F) from the saddle),
// hence w ~ epsilon d/(1 + d), d = |mu|/sqrt(F), with epsilon = e^(-sqrt F)/2; a tip aligned with
// the force and a negligible moment has tau ~ epsilon.
#include "flexure/solver/elliptic/elastica_closed_form.h"

namespace flexure::elliptic {

struct TipChart {
  enum class Kind { kAngle, kSaddle, kSeparatrix };
  Kind kind = Kind::kAngle;
  int side = 1;     // separatrix chart: sign of tau
  int winding = 0;  // saddle and separatrix charts: t = 2 pi winding + tau

  // Sign of dt/dx: orients the path the same way in every chart.
  int orientation() const { return kind == Kind::kSeparatrix ? side : 1; }
};

// epsilon = e^(-sqrt F)/2 (see above): the scale of the saddle chart's tau.
double separatrix_scale(double force);
// epsilon d/(1 + d), d = |mu|/sqrt(F): the scale of the separatrix chart's w.
double separatrix_chart_scale(const PendulumProblem& problem);

// Tip state at chart coordinate x; false where x is outside the chart.
bool tip_state_in_chart(const PendulumProblem& problem,
                        const TipChart& chart,
                        double x,
                        TipState& state);

// The chart a path point should be expressed in, with hysteresis: the separatrix chart is entered
// when |w| < 0.01 min(a, 1 - a) (a = sin^2(tau/2): the chart is regular away from tau = 0, pi) and
// left when |w| > 0.05 min(a, 1 - a); otherwise the saddle chart is entered when |tau| < 0.01
// and left when |tau| > 0.05. Returns the chart and the point's coordinate in it.
struct ChartPoint {
  TipChart chart;
  double x = 0.0;
};
ChartPoint preferred_chart(const PendulumProblem& problem,
                           const TipChart& current,
                           const TipState& state);

}  // namespace flexure::elliptic
