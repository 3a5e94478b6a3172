#pragma once
// Closed-form evaluation of the planar elastica as a pendulum (docs/theory-elliptic.md).
//
// Normalised problem: force F >= 0 at angle psi in [0, pi] (the caller mirrors problems with
// Fy < 0), end moment mu. With chi = theta - psi + pi the equilibrium equation theta'' =
// F sin(theta - psi) becomes chi'' = -F sin chi, first integral chi'^2/2 - F cos chi = H.
// The clamp fixes chi(0) = chi0 = pi - psi; the tip fixes chi'(1) = mu.
//
// The forward problem is solved for the tip angle: given it, the tip state (chi1, mu) fixes H and
// the whole trajectory, which is integrated back to s = 0 in closed form; the residual is the root
// angle reached minus chi0. The unknown is t = chi1 - pi = theta0 - psi, the tip angle measured
// from the force direction: in tension the tip aligns with the force (t -> 0) and every quantity
// near the separatrix is formed from sin(t/2) and cos(t/2) without cancellation. Shooting from the
// tip (rather than from the clamp with the root moment) is well conditioned for tension loads,
// where the beam approaches the pendulum's unstable top towards the tip.
#include "flexure/solver/elliptic/elliptic_functions.h"
#include "flexure/solver/elliptic/elliptic_solver.h"

namespace flexure::elliptic {

struct PendulumProblem {
  double force = 0.0;  // F > 0
  double psi = 0.0;    // force angle in [0, pi]
  double mu = 0.0;     // end moment
  double chi0 = 0.0;   // pi - psi: pendulum angle at the clamp
  double s0 = 0.0;     // sin(chi0 / 2) = cos(psi / 2)
  double c0 = 1.0;     // cos(chi0 / 2) = sin(psi / 2)
};
PendulumProblem make_pendulum_problem(double force, double psi, double mu);

// The tip state (chi1 = t + pi, chi1' = mu) in the quantities the closed form needs. The tip
// angle is kept as t = 2 pi winding + tau with |tau| <= pi, so that a tip aligned with the force
// (tau -> 0, tension) keeps tau's relative precision, and the energy offsets are supplied
// directly, because near the separatrix h_minus is exponentially small and cannot be formed from
// t by subtraction (tip_chart.h supplies it from the separatrix chart).
struct TipState {
  int winding = 0;        // t = 2 pi winding + tau
  double tau = 0.0;       // in [-pi, pi]
  double half_sin = 1.0;  // sin(chi1/2) = cos(t/2)
  double half_cos = 0.0;  // cos(chi1/2) = -sin(t/2)
  double h_minus = 0.0;   // (F - H)/2 = F cos^2(chi1/2) - mu^2/4: > 0 inflectional, < 0 not
  double h_plus = 0.0;    // (F + H)/2 = F sin^2(chi1/2) + mu^2/4 = F - h_minus
  double t() const;       // theta0 - psi
};
TipState tip_state_from_angle(const PendulumProblem& problem, double tip_from_force);
// The same from tau and the winding, without forming t.
TipState tip_state_from_reduced_angle(const PendulumProblem& problem, int winding, double tau);

// Tip state from the energy offset w = h_minus / F on one side of a separatrix crossing:
// tau = side * 2 asin(sqrt(w + mu^2/(4F))), side = +-1. Returns false where w is outside the
// side's range (no real tau).
bool tip_state_near_separatrix(
    const PendulumProblem& problem, double w, int side, int winding, TipState& state);

// Trajectory through the tip state (chi_tip, mu), integrated back to the clamp.
struct BackwardIntegration {
  ElasticaParameters parameters;
  double chi_root = 0.0;  // pendulum angle reached at s = 0
};
BackwardIntegration integrate_from_tip(const PendulumProblem& problem, const TipState& tip);
BackwardIntegration integrate_from_tip(const PendulumProblem& problem, double tip_from_force);

// Tip-angle residual: chi(0) - chi0 for the trajectory through the tip angle t = theta0 - psi.
double tip_angle_residual(const PendulumProblem& problem, double tip_from_force);
double tip_angle_residual(const PendulumProblem& problem, const TipState& tip);

// The same residual without the incomplete integral at the tip, by the addition theorem of the
// Jacobi functions (DLMF 22.8.1-22.8.3): sn, cn and dn at the clamp, u_root = u_tip - L, follow
// from those at the tip (the amplitude there is known from the tip state: sn = sin phi1,
// cn = cos phi1) and those of the beam's length L in the elliptic argument (sqrt(F) in family A,
// sigma q in family B), so one Gauss transformation replaces R_F plus the Gauss transformation
// (about a third of a residual's cost). The common denominator D = 1 - m sn^2(u_tip) sn^2(L) =
// cn^2(u_tip) + sn^2(u_tip) dn^2(L) >= 0 cancels in the atan2 of the clamp angle, but the
// numerators' rounding (a few ulps times |L|) is divided by it: where D < 1e-3 the residual above
// is returned instead. The two agree to about 1e-13 (checked in tests/solver/elliptic_solver_test
// .cpp); the continuation follows its path with this one and polishes the final root with the
// residual above (docs/theory-elliptic.md, "How a forward solve works").
double tip_angle_residual_by_addition(const PendulumProblem& problem, const TipState& tip);

// Position and angle at arc length s in [0, 1] in the normalised (unmirrored) frame. The evaluator
// computes the clamp's amplitude and integrals once for many points.
class ShapeEvaluator {
 public:
  explicit ShapeEvaluator(const ElasticaParameters& parameters);
  ShapePoint at(double s) const;
  // The same, and the amplitude am(u) there (families A and B; 0 otherwise).
  ShapePoint at(double s, double& amplitude) const;
  double root_amplitude() const { return phi_root_; }  // am(u_root) (families A and B)

 private:
  ElasticaParameters p_;
  Parameter k_;
  double cos_psi_ = 1.0;
  double sin_psi_ = 0.0;
  double span_ = 0.0;        // u_tip - u_root
  double phi_root_ = 0.0;    // am(u_root)
  double d_root_ = 0.0;      // (F - E)/m at the clamp
  double delta_root_ = 1.0;  // dn(u_root)
};
ShapePoint evaluate_normalised(const ElasticaParameters& parameters, double s);

// Curvature at the clamp (root moment) and number of interior inflection points.
double root_curvature(const ElasticaParameters& parameters);
int count_inflection_points(const ElasticaParameters& parameters);

// The three above at once (the tip, s = 1, as evaluate_normalised gives it), from one amplitude at
// each end instead of five: what every solve reports.
struct EndSummary {
  ShapePoint tip;
  double root_moment = 0.0;
  int inflection_points = 0;
};
EndSummary end_summary(const ElasticaParameters& parameters);

}  // namespace flexure::elliptic
