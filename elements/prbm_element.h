#pragma once
// One interface for every pseudo-rigid-body (PRB) element: a flexible segment replaced by rigid
// links, pivots and torsional springs (Howell ch. 5, App. E; virtual work ch. 6).
//
// Frame and units. The segment is clamped (or pinned) at the origin with its undeflected tangent
// along +x. Everything inside the element is nondimensional: lengths are divided by the length l of
// the flexible segment, loads follow EndLoad (force * l^2/EI, moment * l/EI), spring constants are
// K l/EI. Dimensional values enter only at the edges (spring_constant, max_stress).
//
// The force/torque relation is written once, by virtual work (Howell §6.2, eq. 6.53): at PRB angle
// Theta the tip load does work `generalized_load(Theta, load)` per unit dTheta and the springs
// store `spring_moment(Theta)` per unit dTheta; equilibrium is their equality. For a fixed-pinned
// segment this is gamma * F_t = gamma * K_theta * Theta, i.e. (alpha^2)_t = K_theta * Theta
// (eq. 5.59).
#include <algorithm>
#include <cmath>
#include <string>

#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/section.h"
#include "flexure/solver/common/status.h"

namespace flexure {

// The rigid-link layout of the model, nondimensional (divided by l).
struct PrbGeometry {
  double gamma = 1.0;  // characteristic radius factor: tip-side link length along the
                       // undeflected segment is gamma*l, the pivot sits (1-gamma)*l from the clamp
  double link_length =
      1.0;               // length of the moving PRB link (gamma, rho for curved, L/l+1/2 for SLFP)
  double pivot_x = 0.0;  // characteristic pivot, x/l (first pivot when there are two)
  double pivot_y = 0.0;  // characteristic pivot, y/l
  int spring_count = 1;  // torsional springs of constant stiffness_coefficient() each
};

// Range of the PRB angle over which the published (or derived) constants are trusted. The one
// place where a PRB angle is checked against it (the tool, the studies and the mechanisms call
// contains or contains_force).
struct ValidityLimits {
  double theta_max_position = 0.0;  // rad: tip-position error/deflection <= 0.5 % (eq. 5.47)
  double theta_max_force = 0.0;     // rad: Theta_max(K_theta), force relation (eq. 5.63)
  std::string source;  // where the numbers come from (table, eq., "no published limit")

  // Largest |Theta| at which both the tip position and the force relation are trusted.
  double theta_max() const { return std::min(theta_max_position, theta_max_force); }
  // Whether the model is trusted at PRB angle Theta (rad): |Theta| <= theta_max(). NaN is not.
  bool contains(double Theta) const { return std::fabs(Theta) <= theta_max(); }
  // Whether the force-deflection relation alone is trusted at Theta: |Theta| <= theta_max_force
  // (eq. 5.63). A mechanism's force needs only this: its positions are those of its rigid links.
  bool contains_force(double Theta) const { return std::fabs(Theta) <= theta_max_force; }
};

// Normal stress at the most stressed section of the segment (the clamp unless noted by the
// element).
struct SectionStress {
  double bending_moment = 0.0;  // M at that section, dimensional, counter-clockwise positive
  double axial_force = 0.0;     // N along the undeflected axis, dimensional, tension positive
  double sigma_top = 0.0;       // fibre at y = +h/2: -M c/I + N/A (eq. 5.22/5.74)
  double sigma_bottom = 0.0;    // fibre at y = -h/2: +M c/I + N/A (eq. 5.23/5.75)
  double sigma_max = 0.0;       // max(|sigma_top|, |sigma_bottom|)
};

// Equilibrium of the PRB model under a given tip load (nondimensional).
struct PrbEquilibrium : SolveStatus {
  // residual: |spring_moment - generalized_load| at the returned Theta
  double Theta = 0.0;  // PRB angle, rad
  TipPose tip;         // PRB tip at Theta
};

// Virtual work per unit dTheta of a tip force on a rigid link of length r at angle Theta:
// F . dz/dTheta with dz/dTheta = r(-sin Theta, cos Theta) (Howell eqs. 6.99-6.103).
inline double link_force_work(double r, double Theta, const EndLoad& load);

class PrbmElement {
 public:
  virtual ~PrbmElement() = default;

  virtual std::string name() const = 0;
  virtual PrbGeometry geometry() const = 0;

  // K l/EI of each spring (Howell Table 6.1). The dimensional constant is spring_constant().
  virtual double stiffness_coefficient() const = 0;
  double spring_constant(double EI, double length) const;

  // PRB angle of the undeflected segment (Theta_i, nonzero for initially curved segments).
  virtual double initial_angle() const { return 0.0; }

  // Tip (a/l, b/l, theta0) of the model at PRB angle Theta (rad).
  virtual TipPose tip(double Theta) const = 0;

  // Virtual work of the nondimensional tip load per unit dTheta at PRB angle Theta.
  virtual double generalized_load(double Theta, const EndLoad& load) const = 0;
  // Virtual work of the springs per unit dTheta, sum of K_i psi_i dpsi_i/dTheta (nondimensional).
  virtual double spring_moment(double Theta) const = 0;

  // Factor s such that s * unit_load holds the model at Theta (eq. 5.35 solved for the load).
  // Throws InvalidInput when unit_load does no work at Theta (e.g. a force along the link).
  double load_factor_at(double Theta, const EndLoad& unit_load) const;
  // Theta under `load`: the first root of spring_moment - generalized_load (eq. 5.35) met when
  // walking from the unloaded angle in the direction the load pushes (bracket, then regula falsi).
  // Fails (converged = false) if there is none within |Theta - Theta_i| < pi.
  PrbEquilibrium solve(const EndLoad& load) const;

  virtual ValidityLimits limits() const = 0;

  // Bending moment (nondimensional, M l/EI) at the most stressed section and the axial force there
  // (tension positive); default: the clamp, M = mu + a Fy - b Fx (eq. 5.21), N = Fx.
  virtual double max_moment(double Theta, const EndLoad& load) const;
  virtual double axial_force(double Theta, const EndLoad& load) const;
  // Dimensional stress for `load` (nondimensional) on a segment of `length` with `section` in
  // `material` (solver/common/section.h; EI = E I). Both are validated; the section must give its
  // area and thickness (a rectangle: N/A and M c/I with c = h/2), else InvalidInput.
  SectionStress max_stress(double Theta,
                           const EndLoad& load,
                           const Section& section,
                           const Material& material,
                           double length) const;
};

inline double link_force_work(double r, double Theta, const EndLoad& load) {
  return r * (-load.Fx * std::sin(Theta) + load.Fy * std::cos(Theta));
}

}  // namespace flexure
