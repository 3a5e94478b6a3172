#pragma once
// The pseudo-rigid-body elements in one header: the PrbmElement interface, Howell's segments (ch.
// 5) with his Tables 5.1-5.3, and the derivation of their constants from the exact elastica.
//
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
//
// The pseudo-rigid-body segments of Howell's chapter 5 (PrbmElement, above), one section
// each: fixed-pinned (§5.2), fixed-fixed and fixed-guided (§5.5), pinned-pinned, the small-length
// flexural pivot (§5.1), the end-moment segment (§5.4), the initially curved cantilever (§5.8) and
// the initially curved pinned-pinned segment (§5.9). Each is implemented in its own .cpp file.
//
// The published PRB constants, copied exactly as printed (Howell, Compliant Mechanisms, Tables 5.1,
// 5.2, 5.3 = App. E Tables E.1, E.2, E.3: data/howell_table_5_{1,2,3}.csv, compiled into the
// library and read at the first call; eqs. 5.107-5.110 below). Angles in degrees as printed.
// These are data to compare against, not the constants the elements must use: the elements accept
// constants from these tables, from the curve fits (prbm_curve_fits.h) or from the derivation
// (below).
//
// Re-derivation of the PRB constants gamma, Theta_max(gamma), c_theta and K_theta from exact tips,
// by Howell's definitions (§5.2, eqs. 5.42-5.47, 5.53, 5.59; §5.5 for curved beams). The procedure
// (docs/prbm.md):
//
//  1. Sample the exact tip path: uniformly in the tip angle theta0 (step `theta0_step_deg`) from
//     the elliptic solver's inverse problem (fixed-pinned, 0 < theta0 < phi = atan2(1, -n)) or
//     from the circle of a pure end moment (a/l = sin theta0/theta0, b/l = (1 - cos
//     theta0)/theta0); for the initially curved cantilever uniformly in the PRB angle
//     (derive_initially_curved).
//  2. For a trial gamma, Theta = atan2(b, a - (1 - gamma)) (eq. 5.42 / 5.115) and the relative
//     position error error/delta (eq. 5.47), delta measured from the unloaded tip. Theta_max(gamma)
//     is the PRB deflection Theta - Theta_i at which error/delta first exceeds `error_limit`
//     (0.5 %), linearly interpolated between samples. For the force, extra samples at
//     theta0 = phi - step/2^k (k = 1..`tail_samples`) resolve the end of the path, where the load
//     grows without bound; they are used for Theta_max only, never in the fits.
//  3. gamma maximises Theta_max(gamma): a coarse grid, then grids ten times finer (+-2 steps of the
//     previous grid around its best point) down to `gamma_fine_step`, then bisection on the jump
//     where a hump of the error curve touches the limit (Theta_max(gamma) is discontinuous there,
//     so golden-section search is not safe). Finally Theta_max is refined by root finding on the
//     exact error function between the bracketing samples.
//  4. c_theta: least squares through the origin of theta0 - theta0_i against Theta - Theta_i over
//     0 < Theta - Theta_i <= Theta_max(gamma).
//  5. K_theta: least squares through the origin of the tangential load against Theta - Theta_i
//     over 0 < Theta - Theta_i <= Theta_max(K_theta): (alpha2)_t = alpha2 eta sin(phi - Theta) for
//     the force (eqs. 5.57, 5.123), mu/gamma for the end moment (eq. 5.111, K = gamma K_theta; as
//     mu = theta0 on the circle, c_theta = gamma K_theta identically, eq. 5.112).
//     Theta_max(K_theta) is an input (Howell does not state its criterion): Table 5.1's value when
//     n is a row, 0.7 phi (eq. 5.63) for other n < 0, Table 5.1 interpolated in n for other n >= 0
//     (curved beams: that value scaled by (phi - Theta_i)/phi).
#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

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

namespace flexure {

// One row of Table 5.1: fixed-pinned segment with a tip force at angle phi = atan2(1, -n).
struct FixedPinnedTableRow {
  double load_ratio_n = 0.0;
  double phi_deg = 90.0;             // force angle
  double gamma = 0.0;                // characteristic radius factor
  double theta_max_gamma_deg = 0.0;  // Theta_max(gamma), position error <= 0.5 %
  double c_theta = 0.0;              // parametric angle coefficient, theta0 = c_theta Theta
  double K_theta = 0.0;              // stiffness coefficient, (alpha^2)_t = K_theta Theta
  double theta_max_K_deg = 0.0;      // Theta_max(K_theta)
};
// The 17 rows in the book's order (n = 0 ... 10, then -0.5 ... -5).
const std::vector<FixedPinnedTableRow>& table_5_1();
// The row with exactly this n, or nullptr.
const FixedPinnedTableRow* table_5_1_row(double load_ratio_n);
// All columns linearly interpolated in n between rows (-5 <= n <= 10); throws InvalidInput outside.
FixedPinnedTableRow table_5_1_interpolated(double load_ratio_n);

// One row of Table 5.2: initially curved cantilever.
struct CurvedCantileverTableRow {
  double kappa0 = 0.0;  // l / R_i (eq. 5.114)
  double gamma = 0.0;
  double rho = 0.0;  // PRB link length / l (eq. 5.116)
  double K_theta = 0.0;
};
const std::vector<CurvedCantileverTableRow>& table_5_2();

// One row of Table 5.3: initially curved pinned-pinned segment. Delta Theta in radians.
struct CurvedPinnedPinnedTableRow {
  double kappa0 = 0.0;
  double gamma = 0.0;
  double rho = 0.0;
  double delta_theta_max_gamma = 0.0;
  double K_theta = 0.0;
  double delta_theta_max_K = 0.0;
};
const std::vector<CurvedPinnedPinnedTableRow>& table_5_3();

// End-moment segment (eqs. 5.107-5.110).
struct EndMomentConstants {
  double gamma = 0.7346;          // eq. 5.107
  double theta0_max_deg = 124.4;  // tip angle up to which error < 0.5 % (eq. 5.108)
  double c_theta = 1.5164;        // eq. 5.109
  double K_theta = 2.0643;        // eq. 5.110
};
inline constexpr EndMomentConstants kEndMomentBook{};

}  // namespace flexure

namespace flexure {

// Fixed-pinned segment: a cantilever with a tip force at any angle phi = atan2(1, -n) (Howell §5.2,
// App. E.3). The PRB model is a rigid link of length gamma*l pinned (1-gamma)*l from the clamp with
// a torsional spring K = gamma K_theta EI/l (eq. 5.72); theta0 = c_theta Theta (eq. 5.53).
//
// The constants come from Table 5.1, from the curve fits (eqs. 5.48, 5.60-5.62) or from the
// derivation against the exact solution (derive_fixed_pinned,
// FixedPinnedConstants::from_derivation).
struct FixedPinnedConstants {
  double load_ratio_n = 0.0;     // n: horizontal force nP, compressive for n > 0 (eq. 2.67)
  double gamma = 0.8517;         // characteristic radius factor
  double c_theta = 1.2385;       // parametric angle coefficient (eq. 5.53)
  double K_theta = 2.67617;      // stiffness coefficient (eq. 5.59)
  double theta_max_gamma = 0.0;  // rad, Theta_max(gamma) (position)
  double theta_max_K = 0.0;      // rad, Theta_max(K_theta) (force)
  std::string source = "Table 5.1, n = 0";

  // Table 5.1: the exact row when n is one, else every column interpolated linearly in n.
  static FixedPinnedConstants from_table(double load_ratio_n);
  // Curve fits: gamma eq. 5.48, K_theta eqs. 5.60-5.62; c_theta and Theta_max(gamma) interpolated
  // from Table 5.1 (the book gives no fit for them); Theta_max(K_theta) = 0.7 phi (eq. 5.63) for
  // n < 0, Table 5.1 interpolated for n >= 0 (the rule overestimates it there).
  static FixedPinnedConstants from_curve_fits(double load_ratio_n);
  // Howell's average constants for a segment whose load ratio is not known in advance (§5.2:
  // gamma = 0.85 and K_theta = 2.65, the averages of eqs. 5.51 and 5.64 over -0.5 <= n <= 1;
  // docs/prbm.md "Recommended values"). They are the constants of every long (l) segment of
  // Weight's constant-force mechanisms (Weight 2001 §2.2, App. A.3) and of the modified mechanisms
  // (Ugwuoke & Abolarin eq. 1). c_theta and the two Theta_max are Table 5.1's at n = 0
  // (load_ratio_n = 0); a check at the segment's actual n uses from_table(n).
  static FixedPinnedConstants howell_average();
  // Throws InvalidInput naming the constant unless all are finite and in their physical range.
  void validate() const;
};

class FixedPinnedSegment : public PrbmElement {
 public:
  explicit FixedPinnedSegment(FixedPinnedConstants constants);

  std::string name() const override { return "fixed-pinned segment"; }
  PrbGeometry geometry() const override;
  double stiffness_coefficient() const override;  // gamma K_theta (eq. 5.72)
  TipPose tip(double Theta) const override;       // eqs. 5.49, 5.50, 5.53
  // Only a tip force: a pinned tip carries no moment (InvalidInput if mu != 0).
  double generalized_load(double Theta, const EndLoad& load) const override;
  double spring_moment(double Theta) const override;
  ValidityLimits limits() const override;

  // Howell's load P = alpha2 EI/l^2 that holds the model at Theta for this element's n:
  // alpha2 = K_theta Theta / (eta sin(phi - Theta)) (eqs. 5.56-5.59).
  double alpha2_at(double Theta) const;
  double force_angle() const;  // phi = atan2(1, -n), eq. 5.41
  const FixedPinnedConstants& constants() const { return constants_; }

 private:
  FixedPinnedConstants constants_;
};

// The fixed-pinned segment with FixedPinnedConstants::howell_average(), built once: the PRBM of a
// long (l) segment in mechanisms/ (link gamma l, pivot (1 - gamma) l from the clamp, spring
// K = gamma K_theta EI/l, eq. 5.72).
const FixedPinnedSegment& howell_average_fixed_pinned();

// Fixed-fixed segment under a combined tip force and moment, Howell §5.7 simplified model
// (App. E.8): the fixed-guided layout (pivots (1-gamma)l/2 from each end, middle link gamma*l, a
// spring K = 2 gamma K_theta EI/l at each pivot) but with the end angle theta0 free. It has two
// degrees of freedom (Theta, theta0); as a PrbmElement the end angle is prescribed (theta0 =
// end_angle), which makes it the fixed-guided model for end_angle = 0. solve_free_end() solves both
// coordinates. The book calls the model "less accurate, for initial design"; it has no published
// Theta limit.
struct FixedFixedEquilibrium : SolveStatus {
  // residual: max |generalized force| at the returned point
  double Theta = 0.0;   // middle-link angle, rad
  double theta0 = 0.0;  // end-link angle, rad
  TipPose tip;
};

class FixedFixedSegment : public PrbmElement {
 public:
  explicit FixedFixedSegment(FixedPinnedConstants constants = FixedPinnedConstants::from_table(0.0),
                             double end_angle = 0.0);

  std::string name() const override { return "fixed-fixed segment (simplified model)"; }
  PrbGeometry geometry() const override;
  double stiffness_coefficient() const override;  // 2 gamma K_theta per spring (E.8)
  TipPose tip(double Theta) const override;       // with theta0 = end_angle
  TipPose tip(double Theta, double theta0) const;
  // With the end angle prescribed the tip couple is a reaction and does no work.
  double generalized_load(double Theta, const EndLoad& load) const override;
  double spring_moment(double Theta) const override;  // K Theta + K (Theta - end_angle)
  ValidityLimits limits() const override;
  // Clamp moment including the couple the prescribed end angle needs.
  double max_moment(double Theta, const EndLoad& load) const override;

  // Both coordinates free: Newton on the two generalised forces (virtual work, eq. 6.222).
  FixedFixedEquilibrium solve_free_end(const EndLoad& load) const;

 private:
  double end_link() const { return (1.0 - constants_.gamma) / 2.0; }
  FixedPinnedConstants constants_;
  double end_angle_;
};

// Fixed-guided segment (Howell §5.3, App. E.4): both ends clamped, the far end translates without
// rotating. The shape is antisymmetric about an inflection point at mid-length, so each half is a
// fixed-pinned segment of length l/2: two pivots (1-gamma)l/2 from the ends joined by a link
// gamma*l, each with K = 2 gamma K_theta EI/l (eq. 5.105); theta0 = 0 (eq. 5.100).
class FixedGuidedSegment : public PrbmElement {
 public:
  // gamma, K_theta and the limits of a fixed-pinned half (App. E.4 refers to E.3); default n = 0.
  explicit FixedGuidedSegment(
      FixedPinnedConstants constants = FixedPinnedConstants::from_table(0.0));

  std::string name() const override { return "fixed-guided segment"; }
  PrbGeometry geometry() const override;
  double stiffness_coefficient() const override;  // 2 gamma K_theta per spring (eq. 5.105)
  TipPose tip(double Theta) const override;       // App. E.4
  // The tip couple is the guide's reaction and does no work (theta0 is held at 0).
  double generalized_load(double Theta, const EndLoad& load) const override;
  double spring_moment(double Theta) const override;  // two springs, each turned by Theta
  ValidityLimits limits() const override;
  // Equal and opposite end moments: M0 = (P a + nP b)/2 at both ends (eqs. 5.102-5.103, 5.106).
  double max_moment(double Theta, const EndLoad& load) const override;

 private:
  FixedPinnedConstants constants_;
};

// Initially straight pinned-pinned segment (Howell §5.6, App. E.7). Only a force along the line of
// the pins acts (statics, eqs. 5.129-5.134), whatever the segment's shape, so it is a two-force
// member: a rigid link of length l that rotates freely (no bending spring; the axial stiffness EA/l
// is outside this bending theory). The curved segment is CurvedPinnedPinnedSegment (below).
class PinnedPinnedSegment : public PrbmElement {
 public:
  std::string name() const override { return "pinned-pinned segment (straight)"; }
  PrbGeometry geometry() const override { return {1.0, 1.0, 0.0, 0.0, 0}; }
  double stiffness_coefficient() const override { return 0.0; }
  TipPose tip(double Theta) const override;
  double generalized_load(double Theta, const EndLoad& load) const override;
  double spring_moment(double /*Theta*/) const override { return 0.0; }
  ValidityLimits limits() const override;
  double max_moment(double /*Theta*/, const EndLoad& /*load*/) const override { return 0.0; }
};

// Small-length flexural pivot (Howell §5.1, App. E.1): a short flexible segment of length l
// carrying a long rigid segment of length L (L >> l, (EI)_L >> (EI)_l, eqs. 5.1-5.2). The pivot
// sits at the middle of the flexure, the spring is K = EI/l (eq. 5.14), and Theta = theta0
// (eq. 5.6).
//
// Nondimensional in the flexure length l: the rigid segment is rigid_length_ratio = L/l long.
class SmallLengthFlexuralPivot : public PrbmElement {
 public:
  // rigid_length_ratio = L/l >= 0 (the model assumes L >= 10 l; not enforced, see limits()).
  explicit SmallLengthFlexuralPivot(double rigid_length_ratio);

  // K l/EI of the pivot: K = EI/l (eq. 5.14).
  static constexpr double kStiffnessCoefficient = 1.0;

  std::string name() const override { return "small-length flexural pivot"; }
  PrbGeometry geometry() const override;
  double stiffness_coefficient() const override { return kStiffnessCoefficient; }
  TipPose tip(double Theta) const override;  // eqs. 5.6-5.10
  // Force on the arm L + l/2 (eq. 5.19) plus the tip moment.
  double generalized_load(double Theta, const EndLoad& load) const override;
  double spring_moment(double Theta) const override { return Theta; }  // eq. 5.11
  ValidityLimits limits() const override;

  double arm() const { return rigid_length_ratio_ + 0.5; }  // (L + l/2)/l

 private:
  double rigid_length_ratio_;
};

// Cantilever with a pure end moment (Howell §5.4, App. E.5): link gamma*l, theta0 = c_theta Theta,
// K = gamma K_theta EI/l = c_theta EI/l (eqs. 5.107-5.112). The exact tip lies on a circle (eqs.
// 2.59, 2.64), so the constants can be re-derived in closed form (derive_end_moment()).
class EndMomentSegment : public PrbmElement {
 public:
  // theta_max: PRB angle limit (rad) for both position and force; default from eq. 5.108
  // (theta0 < 124.4 deg, i.e. Theta < 124.4/c_theta deg).
  explicit EndMomentSegment(EndMomentConstants constants = kEndMomentBook);

  std::string name() const override { return "end-moment segment"; }
  PrbGeometry geometry() const override;
  double stiffness_coefficient() const override;  // gamma K_theta (eq. 5.111)
  TipPose tip(double Theta) const override;
  // Only a tip moment (InvalidInput for a force: use the fixed-pinned or fixed-fixed element).
  double generalized_load(double Theta, const EndLoad& load) const override;
  double spring_moment(double Theta) const override;
  ValidityLimits limits() const override;

  const EndMomentConstants& constants() const { return constants_; }

 private:
  EndMomentConstants constants_;
};

// Initially curved cantilever with a tip force (Howell §5.5, App. E.6): a circular arc of curvature
// kappa0 = l/R_i (eq. 5.114). gamma is measured along the arc as if it were straight; the PRB link
// joins that point to the tip, length rho*l at angle Theta_i when unloaded (eqs. 5.115-5.118), and
// K = rho K_theta EI/l acts on Theta - Theta_i (eqs. 5.124-5.127).
//
// The book gives no c_theta and no Theta limits for curved beams; tip() uses
// theta0 = kappa0 + c_theta (Theta - Theta_i) with the straight-beam c_theta of the constants, and
// limits() are the straight-beam (Table 5.1, n = 0) limits applied to Theta - Theta_i. Both are
// flagged as such.
struct CurvedCantileverConstants {
  double kappa0 = 0.0;      // l / R_i, 0 <= kappa0 <= 2 (Table 5.2's range)
  double gamma = 0.85;      // Table 5.2
  double K_theta = 2.65;    // Table 5.2
  double c_theta = 1.2385;  // not published for curved beams: straight-beam Table 5.1, n = 0
  std::string source = "Table 5.2, kappa0 = 0";

  // Table 5.2's gamma and K_theta interpolated linearly in kappa0 (exact at its rows).
  static CurvedCantileverConstants from_table(double kappa0);
  // gamma, K_theta and c_theta re-derived from the exact curved-beam path and averaged over
  // n_min <= n <= n_max (derive_initially_curved_average, docs/prbm.md); 0 <= kappa0 <= 3. Throws
  // NoConvergence when no load ratio in the range gives a derivation.
  static CurvedCantileverConstants from_derivation(double kappa0,
                                                   double n_min = -0.5,
                                                   double n_max = 1.0);
};

class InitiallyCurvedCantilever : public PrbmElement {
 public:
  explicit InitiallyCurvedCantilever(CurvedCantileverConstants constants);

  std::string name() const override { return "initially curved cantilever"; }
  PrbGeometry geometry() const override;
  double stiffness_coefficient() const override;  // rho K_theta (eq. 5.127)
  double initial_angle() const override { return Theta_i_; }
  TipPose tip(double Theta) const override;  // eqs. 5.119-5.120
  // Only a tip force (a moment in the same sense is a change of kappa0, §5.7 case I).
  double generalized_load(double Theta, const EndLoad& load) const override;
  double spring_moment(double Theta) const override;  // K (Theta - Theta_i), eq. 5.126
  ValidityLimits limits() const override;

  double rho() const { return rho_; }
  // Unloaded tip a_i/l, b_i/l (eqs. 5.117-5.118).
  double a_initial() const { return a_i_; }
  double b_initial() const { return b_i_; }
  const CurvedCantileverConstants& constants() const { return constants_; }

 private:
  CurvedCantileverConstants constants_;
  double a_i_ = 1.0;
  double b_i_ = 0.0;
  double Theta_i_ = 0.0;
  double rho_ = 0.0;
};

// Initially curved pinned-pinned segment (Howell §5.6.1, App. E.7.1): a circular arc of curvature
// kappa0 between two pins, loaded only along the line of the pins (eqs. 5.129-5.134). Modelled by
// two symmetric half-models: pivots gamma*l/2 from each pin, link rho*l/2 at angle Theta, a spring
// K = 2 rho K_theta EI/l at each (eqs. 5.135-5.147). Theta grows as the pins approach.
// Table 5.3 and eqs. 5.137-5.139 disagree (gamma by up to 0.008, rho by up to 0.012;
// docs/prbm.md "Errata followed"): the constants say which one they come from.
struct CurvedPinnedPinnedConstants {
  double kappa0 = 0.5;  // l/R_o, 0.5 <= kappa0 <= 1.5 (range of eqs. 5.138-5.142 and Table 5.3)
  double gamma = 0.793;
  double K_theta = 2.59;
  double delta_theta_max_gamma = 1.677;  // rad, (Delta Theta)_max,gamma of Table 5.3
  double delta_theta_max_K = 0.99;       // rad, (Delta Theta)_max,K_theta of Table 5.3
  std::string source = "Table 5.3, kappa0 = 0.5";

  // gamma from eqs. 5.138-5.139, K_theta from eq. 5.142; the limits interpolated from Table 5.3.
  static CurvedPinnedPinnedConstants from_curve_fits(double kappa0);
  // Table 5.3 interpolated linearly in kappa0 (exact at its rows).
  static CurvedPinnedPinnedConstants from_table(double kappa0);
};

class CurvedPinnedPinnedSegment : public PrbmElement {
 public:
  explicit CurvedPinnedPinnedSegment(CurvedPinnedPinnedConstants constants);

  std::string name() const override { return "initially curved pinned-pinned segment"; }
  PrbGeometry geometry() const override;
  double stiffness_coefficient() const override;  // 2 rho K_theta per spring (eq. 5.143)
  double initial_angle() const override { return Theta_i_; }
  // Pin B at (a/l, 0) (eq. 5.140); theta0 is not modelled (free pins) and reported as 0.
  TipPose tip(double Theta) const override;
  // Only a force along the pins (Fx, compressive when < 0); InvalidInput for Fy or mu.
  double generalized_load(double Theta, const EndLoad& load) const override;
  double spring_moment(double Theta) const override;  // 2 K (Theta - Theta_i)
  ValidityLimits limits() const override;
  // Mid-length moment F b (eq. 5.147), b the rise; the axial force is Fx.
  double max_moment(double Theta, const EndLoad& load) const override;

  double rise(double Theta) const;  // b/l = (rho/2) sin Theta (eq. 5.141)
  double rho() const { return rho_; }
  double a_initial() const { return a_i_; }
  double b_initial() const { return b_i_; }

 private:
  CurvedPinnedPinnedConstants constants_;
  double a_i_ = 1.0;
  double b_i_ = 0.0;
  double Theta_i_ = 0.0;
  double rho_ = 0.0;
};

}  // namespace flexure

namespace flexure {

// One exact tip on the load path: tip angle, tip position and the load that produces it.
struct PathSample {
  double theta0 = 0.0;  // rad
  double a = 1.0;       // a/l
  double b = 0.0;       // b/l
  double load = 0.0;    // alpha2 = P l^2/EI (force) or mu = M l/EI (end moment)
  bool in_fit = true;   // false for the extra tail samples approaching theta0 -> phi, which locate
                        // Theta_max(gamma) but stay out of the uniformly weighted fits
  double path_parameter = 0.0;  // the argument of the path's `exact` function that gives this tip
                                // (theta0 for the straight paths, alpha2 for the curved beam)
};

// The unloaded tip the deflection is measured from: (1, 0, 0) for an initially straight beam, the
// circular arc a_i/l = sin kappa0/kappa0, b_i/l = (1 - cos kappa0)/kappa0, theta0 = kappa0 for an
// initially curved one (Howell eqs. 5.117-5.118).
struct UnloadedTip {
  double a = 1.0;
  double b = 0.0;
  double theta0 = 0.0;
  static UnloadedTip circular_arc(double kappa0);
};

// PRB angle of an exact tip for characteristic radius factor gamma (Howell eq. 5.42 / 5.115): the
// pivot sits at ((1 - gamma) l, 0) whether or not the beam is initially curved.
double prb_angle(const PathSample& sample, double gamma);
// PRB link length rho l (eq. 5.116; rho = gamma for a straight beam) and its unloaded angle
// Theta_i (eq. 5.115; 0 for a straight beam).
double prb_link_length(double gamma, const UnloadedTip& unloaded);
double prb_initial_angle(double gamma, const UnloadedTip& unloaded);
// Position error of the PRB tip (eqs. 5.119-5.120, or 5.49-5.50 when straight) relative to the tip
// deflection from the unloaded tip, error/delta (eqs. 5.44-5.47).
double relative_position_error(const PathSample& sample,
                               double gamma,
                               const UnloadedTip& unloaded = {});

struct PrbmDerivationOptions {
  double theta0_step_deg = 0.1;  // sampling step of the exact tip angle, degrees (> 0, <= 5)
  double error_limit = 0.005;    // error/delta defining Theta_max(gamma) (eq. 5.43), 0.5 %
  double gamma_min = 0.60;       // search interval for gamma
  double gamma_max = 0.99;
  double gamma_coarse_step = 0.002;  // first grid in gamma
  double gamma_fine_step = 1e-5;     // finest grid (each grid is 10x finer than the previous)
  double theta_max_K_deg = 0.0;      // Theta_max(K_theta) in degrees; <= 0 selects the rule above
  double end_moment_theta0_max_deg = 350.0;  // sampled tip-angle range for the end moment
  int tail_samples = 0;  // extra samples approaching phi (0..60); 0 = uniform only
  // Initially curved cantilever only (derive_initially_curved):
  double curved_reference_gamma = 0.85;    // pivot ((1 - this) l, 0) about which the samples are
                                           // spaced uniformly in Theta (theta0 is not monotone)
  double curved_alpha2_max = 200.0;        // the sampled path ends at this load
  bool curved_K_range_from_gamma = false;  // fit K_theta over Theta_max(gamma) of the curved beam
                                           // instead of the straight-beam Theta_max(K_theta) of n
  // Throws InvalidInput naming the field unless every option is finite and in its range.
  void validate() const;
};

// The segment a derivation is for: fixed-pinned under a tip force (Howell §5.2), the end moment
// (§5.4), the initially curved cantilever (§5.5).
enum class PrbmSegment { kFixedPinned, kEndMoment, kInitiallyCurved };
// "fixed-pinned", "end-moment", "initially-curved": the names of `flexure prbm --segment` and of
// the JSON key "segment".
std::string_view to_string(PrbmSegment segment);
// The segment of that name; throws InvalidInput quoting the name and listing the allowed ones.
PrbmSegment prbm_segment_from_string(std::string_view name);

struct PrbmDerivation : SolveStatus {
  // message: what limited the result, or why it failed
  // iterations: exact tip evaluations (samples + root-finding refinements)
  // residual: |error/delta - error_limit| at the refined Theta_max(gamma)

  PrbmSegment segment = PrbmSegment::kFixedPinned;
  double load_ratio_n = 0.0;
  double kappa0 = 0.0;   // initial curvature l/R_i (0 unless initially curved)
  double rho = 0.0;      // PRB link length / l at the derived gamma (eq. 5.116; gamma if straight)
  double theta_i = 0.0;  // unloaded PRB angle Theta_i, rad (eq. 5.115; 0 if straight)
  double phi = 0.0;      // force angle atan2(1, -n), rad (pi for the end moment: unused)
  double gamma = 0.0;
  double theta_max_gamma = 0.0;        // rad, measured from Theta_i (the PRB deflection)
  double theta0_at_theta_max = 0.0;    // rad, tip angle where the error reaches the limit
  bool theta_max_at_path_end = false;  // error never reached the limit before theta0 -> phi
  double c_theta = 0.0;                // (theta0 - theta0_i) = c_theta (Theta - Theta_i)
  double K_theta = 0.0;                // (alpha2)_t = K_theta (Theta - Theta_i)
  double theta_max_K = 0.0;            // rad, the range of Theta - Theta_i used for the K_theta fit
  std::string theta_max_K_source;
  int samples = 0;  // exact tips on the sampled path
  int samples_c_theta_fit = 0;
  int samples_K_theta_fit = 0;
};

// Howell's Table 5.1 constants for load ratio n (-20 <= n <= 20) from the exact elliptic solution.
PrbmDerivation derive_fixed_pinned(double load_ratio_n, const PrbmDerivationOptions& options = {});

// End-moment constants (Howell §5.4) from the closed-form circular tip path.
PrbmDerivation derive_end_moment(const PrbmDerivationOptions& options = {});

// Initially curved cantilever (Howell §5.5) with a tip force at load ratio n: the same procedure on
// the exact path of a circular arc of curvature kappa0 = l/R_i (0 <= kappa0 <= 3). Its theta(s) is
// that of a straight beam with end moment mu = kappa0 (EI(theta' - kappa0/l) = M(s), eq. 2.103), so
// the tips come from EllipticSolver::solve(EndLoad::howell(n, alpha2, kappa0)). The samples are
// spaced uniformly in the PRB angle about the pivot of `curved_reference_gamma` (theta0 is not
// monotone in the load), deflections and angles are measured from the unloaded arc (eqs.
// 5.115-5.120), and K_theta fits (alpha2)_t = alpha2 eta sin(phi - Theta) against Theta - Theta_i
// (eqs. 5.121-5.124) over the straight-beam Theta_max(K_theta) of n (the rule of
// derive_fixed_pinned) or, with `curved_K_range_from_gamma`, over Theta_max(gamma). Not converged
// (with the reason) when the force does not open the PRB link (phi <= Theta_i + 1 deg).
PrbmDerivation derive_initially_curved(double kappa0,
                                       double load_ratio_n,
                                       const PrbmDerivationOptions& options = {});

// Table 5.2's "recommended values": the constants of derive_initially_curved averaged over the
// load ratio, (int f dn)/(int dn) as in Howell eqs. 5.51 and 5.64, by the trapezoid rule on
// n_intervals equal steps of [n_min, n_max]. Two passes on the same exact samples: (1) gamma (and
// c_theta) per n, averaged; rho and Theta_i follow from the averaged gamma (eqs. 5.115-5.118);
// (2) K_theta per n with gamma fixed at that average -- the link the model uses for every n
// ("a constant value of gamma for various values of n", §5.5.1) -- averaged. Load ratios whose
// derivation fails (the force does not open the link, or the path ends first) are left out and
// named in `message`; the average is then over the remaining ones.
struct CurvedCantileverAverage : SolveStatus {
  // iterations: elliptic solves over all load ratios
  // residual: largest per-n residual of pass 1
  double kappa0 = 0.0;
  double n_min = -0.5;
  double n_max = 1.0;
  double gamma = 0.0;
  double rho = 0.0;                   // eq. 5.116 with the averaged gamma
  double theta_i = 0.0;               // eq. 5.115 with the averaged gamma, rad
  double K_theta = 0.0;               // pass 2: per-n fits at the averaged gamma, averaged
  double K_theta_per_n_gamma = 0.0;   // pass 1: per-n fits at each n's own gamma, averaged
  double c_theta = 0.0;               // pass 1
  double theta_max_gamma_min = 0.0;   // smallest per-n Theta_max(gamma) - Theta_i of pass 1, rad
  std::vector<PrbmDerivation> per_n;  // pass 1, every load ratio
  std::vector<PrbmDerivation> per_n_at_average_gamma;  // pass 2, every load ratio
  int used = 0;                                        // load ratios in the gamma average
  int used_K = 0;                                      // load ratios in the K_theta average
};
CurvedCantileverAverage derive_initially_curved_average(double kappa0,
                                                        double n_min = -0.5,
                                                        double n_max = 1.0,
                                                        int n_intervals = 6,
                                                        const PrbmDerivationOptions& options = {});

// The generic procedure on a sampled path (Theta increasing along it). `exact` evaluates a tip at
// any path parameter between two samples' `path_parameter` (used to refine Theta_max);
// `tangential_load(sample, Theta, gamma)` gives the quantity fitted by K_theta (Theta - Theta_i);
// `unloaded` is the tip the deflections and Theta_i are measured from.
PrbmDerivation derive_from_path(
    const std::vector<PathSample>& samples,
    const std::function<PathSample(double)>& exact,
    const std::function<double(const PathSample&, double, double)>& tangential_load,
    double theta_max_K,
    const PrbmDerivationOptions& options,
    const UnloadedTip& unloaded = {});

}  // namespace flexure
