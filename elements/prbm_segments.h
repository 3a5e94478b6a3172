#pragma once
// The pseudo-rigid-body segments of Howell's chapter 5 (PrbmElement, prbm_element.h), one section
// each: fixed-pinned (§5.2), fixed-fixed and fixed-guided (§5.5), pinned-pinned, the small-length
// flexural pivot (§5.1), the end-moment segment (§5.4), the initially curved cantilever (§5.8) and
// the initially curved pinned-pinned segment (§5.9). Each is implemented in its own .cpp file.
#include <numbers>
#include <string>

#include "flexure/elements/prbm_element.h"
#include "flexure/elements/prbm_tables.h"
#include "flexure/solver/common/status.h"

namespace flexure {

// Fixed-pinned segment: a cantilever with a tip force at any angle phi = atan2(1, -n) (Howell §5.2,
// App. E.3). The PRB model is a rigid link of length gamma*l pinned (1-gamma)*l from the clamp with
// a torsional spring K = gamma K_theta EI/l (eq. 5.72); theta0 = c_theta Theta (eq. 5.53).
//
// The constants come from Table 5.1, from the curve fits (eqs. 5.48, 5.60-5.62) or from the
// derivation against the exact solution (prbm_derivation.h, FixedPinnedConstants::from_derivation).
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
