#pragma once
// Closed-form evaluation of the planar elastica as a pendulum (elastica-general.md).
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
#include "solver/elliptic/elastica_parameters.h"
#include "solver/elliptic/elliptic_functions.h"

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

// Trajectory through the tip state (chi_tip, mu), integrated back to the clamp.
struct BackwardIntegration {
  ElasticaParameters parameters;
  double chi_root = 0.0;  // pendulum angle reached at s = 0
};
BackwardIntegration integrate_from_tip(const PendulumProblem& problem, double tip_from_force);

// Tip-angle residual: chi(0) - chi0 for the trajectory through the tip angle t = theta0 - psi.
double tip_angle_residual(const PendulumProblem& problem, double tip_from_force);

// Position and angle at arc length s in [0, 1] in the normalised (unmirrored) frame. The evaluator
// computes the clamp's amplitude and integrals once for many points.
class ShapeEvaluator {
 public:
  explicit ShapeEvaluator(const ElasticaParameters& parameters);
  ShapePoint at(double s) const;

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

}  // namespace flexure::elliptic
