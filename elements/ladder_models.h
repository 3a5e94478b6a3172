#pragma once
// The cheaper models of the model ladder (docs/models.md), each a solver with Options and a
// SolveStatus result, one section each: the cantilever case they share, linear Euler-Bernoulli
// theory, the beam-constraint model, the chained BCM, the PR-3R model and the derivation of its
// constants. Each is implemented in its own .cpp file.
#include <array>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/status.h"

namespace flexure {

// The problem every model of the ladder solves (docs/models.md): Howell's uniform cantilever
// (length l = 1, EI = 1), clamped at the origin with its tangent along +x, its far end either
//   * free, under the dead tip load EndLoad {Fx, Fy, mu} (Howell eq. 2.67: Fy = alpha2,
//     Fx = -n alpha2), or
//   * guided: the tip angle held at `guided_tip_angle` (0: Howell's fixed-guided beam, §5.3), the
//     tip force given, the tip moment the guide's reaction (so mu must be 0).
// Pinned, slider and fixed ends, rigid links and kinks are chains (segment_chain.h): the chained
// BCM (below) and the exact shooting method solve those.
struct CantileverCase {
  EndLoad load;
  EndCondition end = EndCondition::kFree;  // kFree or kGuided
  double guided_tip_angle = 0.0;           // rad; guided end only

  // Throws InvalidInput naming `model` and what it cannot represent: a non-finite value, an end
  // other than free or guided (naming the models that solve it), an end moment on a guided end.
  void validate(std::string_view model) const;
  // The same problem as a segment chain (one flexible segment; the guided end's angle prescribed).
  SegmentChain to_chain() const;
};

// The statics every model's answer shares: the clamp's bending moment M(0) l/EI of the tip loads
// about the root, for a tip at (a/l, b/l) carrying the force (Fx, Fy) and the moment end_moment
// (mu on a free end, the guide's reaction on a guided one).
inline double root_moment_of(const TipPose& tip, const EndLoad& load, double end_moment) {
  return tip.a_over_l * load.Fy - tip.b_over_l * load.Fx + end_moment;
}

// Linear (small-deflection) Euler-Bernoulli theory of the uniform cantilever: the first rung of
// the model ladder (docs/models.md), the yardstick every student starts from.
//
// Equilibrium is taken in the undeformed configuration, so the bending moment along the beam is
// M(s) = Fy (1 - s) + M_tip and the axial force does nothing (no beam-column effect, a/l = 1):
//   theta(s) = Fy (s - s^2/2) + M_tip s,   y(s) = Fy (s^2/2 - s^3/6) + M_tip s^2/2,   x(s) = s.
// Free end (M_tip = mu): b/l = Fy/3 + mu/2, theta0 = Fy/2 + mu (Gere & Timoshenko, the cantilever
// table). Guided end (tip angle held at phi): M_tip = phi - Fy/2 is the guide's reaction, so
// b/l = Fy/12 + phi/2 (phi = 0: the fixed-guided beam, b = P l^3/(12 EI)).
// Exact in the limit of small loads; every other model of the ladder reduces to it there.
struct LinearBeamResult : SolveStatus {
  // iterations: 0 (closed form); residual: 0
  TipPose tip;
  double root_moment = 0.0;  // M(0) l/EI = Fy + M_tip (equilibrium in the undeformed beam)
  double end_moment = 0.0;   // M_tip l/EI: mu (free) or the guide's reaction (guided)
};

class LinearBeamSolver {
 public:
  struct Options {
    // Nothing to choose: the theory is closed form. validate() exists for the common interface.
    void validate() const {}
  };

  LinearBeamSolver() = default;
  explicit LinearBeamSolver(Options options);

  // Throws InvalidInput for what CantileverCase::validate refuses.
  LinearBeamResult solve(const CantileverCase& problem) const;
  // The deflected shape at `count` >= 2 equally spaced arc lengths.
  std::vector<ShapePoint> shape(const CantileverCase& problem,
                                const LinearBeamResult& result,
                                int count) const;

  const Options& options() const { return options_; }

 private:
  Options options_;
};

// The beam-constraint model, BCM (Awtar, Slocum, Sevincer, "Characteristics of beam-based flexure
// modules", J. Mechanical Design 129:625, 2007; docs/models.md): a closed-form relation between
// the end loads of a uniform beam element and its end displacements, correct to second order in
// the displacements, with the axial force as a parameter.
//
// One element of length l, clamped at its root along +x, normalised by EI and l: tip transverse
// displacement y, tip rotation theta (counter-clockwise), axial tip displacement x (positive:
// longer), all per l and in radians; at the tip the transverse force f (EI/l^2, along +y), the
// moment m (EI/l, counter-clockwise: the moment applied at the tip, which holds theta) and the
// axial force p (EI/l^2, tension positive). With u = [y; theta]:
//   [f; m] = (G + p P + p^2 Q) u,  G = [12 -6; -6 4],  P = [6/5 -1/10; -1/10 2/15],
//                                  Q = [-1/700 1/1400; 1/1400 -11/6300]
//   x = p/d - u' P u / 2 - p u' Q u,  d = E A l^2/(EI) = 12 (l/t)^2 for a rectangle of thickness t.
// Signs, checked against limits derived here (tests/elements/beam_constraint_model_test.cpp):
//   * p = 0: G is the inverse of the cantilever's compliance [1/3 1/2; 1/2 1] (b = f/3 + m/2,
//     theta = f/2 + m), so m is the applied tip moment and f the applied tip force;
//   * theta held at 0 (the guided element): f/y = 12 + 6p/5 - p^2/700 vanishes at p = -9.8837,
//     0.14 % from the Euler load -pi^2 of the clamped-guided column;
//   * f = m = 0 (the cantilever): det(G + pP + p^2 Q) vanishes at p = -2.4685, 0.04 % from -pi^2/4;
//     in tension it vanishes again at p = 95.98, where the p^2 Q term overtakes (the expansion's
//     end);
//   * G + pP + p^2 Q is the Taylor expansion to O(p^2) of the exact beam-column stiffness
//     (transcendental in sqrt(|p|));
//   * the kinematic shortening u' P u / 2 is (1/2) int y'^2 ds of the cubic deflection, and
//     -dx/dp = -1/d + u' Q u, i.e. -(1/2) u' (dK/dp) u: the energy-consistent (Maxwell) pairing.
// Valid for |y| up to about 0.1 (Awtar et al.); the BCM is one element of the chained BCM
// (below), which follows larger deflections.
namespace bcm {

// A symmetric 2x2 matrix [a11 a12; a12 a22].
struct Symmetric2 {
  double a11 = 0.0;
  double a12 = 0.0;
  double a22 = 0.0;
  double determinant() const { return a11 * a22 - a12 * a12; }
  bool positive_definite() const { return a11 > 0.0 && determinant() > 0.0; }
  // u' A u for u = [y; theta].
  double quadratic(double y, double theta) const {
    return a11 * y * y + 2.0 * a12 * y * theta + a22 * theta * theta;
  }
};

inline constexpr Symmetric2 kG{12.0, -6.0, 4.0};
inline constexpr Symmetric2 kP{6.0 / 5.0, -1.0 / 10.0, 2.0 / 15.0};
inline constexpr Symmetric2 kQ{-1.0 / 700.0, 1.0 / 1400.0, -11.0 / 6300.0};

// G + p P + p^2 Q.
inline Symmetric2 stiffness(double p) {
  return {kG.a11 + p * kP.a11 + p * p * kQ.a11,
          kG.a12 + p * kP.a12 + p * p * kQ.a12,
          kG.a22 + p * kP.a22 + p * p * kQ.a22};
}

// x = p/d - u' P u / 2 - p u' Q u; inverse_d = 1/d (0: inextensible, d -> infinity).
inline double axial_displacement(double y, double theta, double p, double inverse_d) {
  return p * inverse_d - 0.5 * kP.quadratic(y, theta) - p * kQ.quadratic(y, theta);
}

// The transverse deflection limit of the BCM's validity stated by Awtar et al.: |y| <= 0.1 l.
inline constexpr double kValidDeflection = 0.1;

}  // namespace bcm

struct BcmResult : SolveStatus {
  // iterations: 0 (closed form: one 2x2 solve); residual: max |[f; m] - K u| of that solve
  double y = 0.0, theta = 0.0, x = 0.0;  // the element's tip displacements (per l, rad)
  double p = 0.0, f = 0.0, m = 0.0;      // its tip loads (m: mu, or the guide's reaction)
  TipPose tip;                           // a/l = 1 + x, b/l = y, theta0 = theta
  double root_moment = 0.0;              // M(0) l/EI: the tip loads' moment about the clamp
  double end_moment = 0.0;               // = m
  bool inside_validity = false;          // |y| <= 0.1
};

class BcmSolver {
 public:
  struct Options {
    // Slenderness l/t of a rectangular section: the axial stiffness d = 12 (l/t)^2. 0 (the
    // default): inextensible, d -> infinity, the limit the exact elastica describes.
    double slenderness = 0.0;
    // Throws InvalidInput unless slenderness is 0 or finite and > 0.
    void validate() const;
    // 1/d (0 when inextensible).
    double inverse_axial_stiffness() const;
  };

  BcmSolver() = default;
  explicit BcmSolver(Options options);

  // The closed form for the cantilever: one element carrying the tip loads in the undeformed frame
  // (p = Fx, f = Fy; m = mu, or on a guided end theta = its prescribed angle and m the reaction).
  // Throws InvalidInput for what CantileverCase::validate refuses, and OutsideMethodDomain where
  // the element's stiffness is not positive definite (past the buckling load, or a tension beyond
  // the range of the expansion in p), naming the models that can answer.
  BcmResult solve(const CantileverCase& problem) const;
  // The element's cubic deflection (Hermite shape of y and theta) at `count` >= 2 points, the
  // axial displacement distributed along it.
  std::vector<ShapePoint> shape(const BcmResult& result, int count) const;

  const Options& options() const { return options_; }

 private:
  Options options_;
};

// The chained beam-constraint model, CBCM (Ma and Chen, "Chained beam-constraint-model (CBCM): a
// powerful tool for modeling large and complicated deflections of flexible beams in compliant
// mechanisms", J. Mechanisms Robotics 8:021018, 2016; docs/models.md).
//
// The flexible segment (length L, EI) is divided into N equal elements of length h = L/N. Element
// j is a BCM (above) in the frame of its own deflected root, the tip of element
// j-1 (angle Phi_j = the root's angle + theta_1 + ... + theta_{j-1}). Its tip loads are those of
// everything distal, in that frame: with F the force the distal part carries (the tip force, the
// node forces beyond the segment and the supports' reactions; no load acts inside the segment),
//   p_j = Fx cos Phi_j + Fy sin Phi_j,  f_j = -Fx sin Phi_j + Fy cos Phi_j,
//   m_j = the moment of the distal loads about the element's tip node,
// normalised by the element: p h^2/EI, f h^2/EI, m h/EI. The element displacements (y_j, theta_j,
// x_j) chain the nodes: node_{j+1} = node_j + h [(1 + x_j) t_j + y_j n_j] (t, n: the element
// frame's axes). Unknowns: y_j, theta_j of every element and the reactions of the prescribed tip
// coordinates; equations: every element's BCM relations and the prescribed coordinates. They are
// solved along proportional loading from the unloaded chain (load_path_newton.h).
//
// N = 1 is the BCM itself in the chain's setting (rigid links, any end). As N grows the CBCM
// converges to the elastica: the tip error falls as h^3, measured on seeded random loads
// (tests/elements/ladder_models_test.cpp; docs/models.md, "Convergence"). Each element's relation
// is correct to second order in its displacements, which are O(h) (theta_j) and O(h^2) (y_j).
//
// Axial stiffness: the segment's d = E A L^2/EI = 12 (L/t)^2 for a rectangle; element j's is
// d h^2/L^2 = d/N^2. It comes from the segment's own EA (FlexibleSegment::EA, set in a chain file
// by `EA` or by `extensible = true` with a section; docs/extensible.md) or, for a segment without
// one, from `slenderness` (L/t); without either it is the inextensible limit d -> infinity, which
// the exact elastica describes. A segment with EA and a slenderness is refused (two values for one
// stiffness). The BCM has no shear deformation: a segment's GAs is not modelled (a warning says
// so).
//
// Chains: one flexible segment (straight, constant EI) with rigid links and kinks before it (they
// only place its root) and after it (they carry the tip), any end condition (segment_chain.h),
// dead node loads on the rigid parts. Not: several flexible segments, an initial curvature, an EI
// profile, a follower force (the shooting method solves those).
struct CbcmResult : SolveStatus {
  // iterations: Newton iterations over all load steps
  // residual: max |BCM relation residual| (in the segment's EI/L^2 and EI/L) and |prescribed
  // coordinate - target| (per L) at the returned state
  int elements = 0;
  int load_steps = 0;
  double load_factor = 0.0;  // the proportional-loading factor reached (1 when converged)
  ChainPose tip;             // the chain's tip, root frame, the chain's units
  Reaction reaction;         // loads the clamp applies to the chain: -N(0), -m(0)
  Reaction tip_load;  // total load on the tip: given + the reaction of a prescribed coordinate
  double root_moment = 0.0;  // bending moment at the clamp, m(0) = -reaction.M
  // The clamp, every joint of the chain and every element node, with the arc length s of the
  // undeformed chain (a kink of length 0 gives two points at one s).
  std::vector<ShapePoint> nodes;
  // The largest element transverse deflection |y_j| (per element length): the BCM's stated range
  // is about 0.1.
  double max_element_deflection = 0.0;
  bool inside_validity = false;
  // The axial stiffness d = EA L^2/EI solved with (infinity: the inextensible segment).
  double axial_stiffness = std::numeric_limits<double>::infinity();
  // The tip of the cantilever as Howell writes it (a/l, b/l per `length`, theta0).
  TipPose tip_pose(double length = 1.0) const {
    return {tip.x / length, tip.y / length, tip.theta};
  }
};

class ChainedBcmSolver {
 public:
  struct Options {
    int elements = 6;  // N equal BCM elements (1: the BCM)
    // Slenderness L/t of the flexible segment (rectangle): d = 12 (L/t)^2. 0 (the default): the
    // segment's own EA when it has one, else the inextensible limit d -> infinity. A chain whose
    // flexible segment has EA refuses a slenderness > 0 (InvalidInput): give one of them.
    double slenderness = 0.0;
    double tolerance = 1e-12;  // max |residual|, relative to max(1, |loads|)
    int max_iterations = 30;   // Newton iterations per load step
    int max_load_steps = 2000;
    // Throws InvalidInput naming the first bad field: elements in [1, 2000], slenderness 0 or
    // finite > 0, tolerance finite > 0, the counts >= 1.
    void validate() const;
  };

  ChainedBcmSolver();
  explicit ChainedBcmSolver(Options options);

  // Howell's cantilever (free or guided end). Throws InvalidInput for what
  // CantileverCase::validate refuses.
  CbcmResult solve(const CantileverCase& problem) const;
  // A chain of one flexible segment with rigid links at either end (see above). Throws
  // InvalidInput for a chain outside that class (several flexible segments, a curved or tapered
  // one, a distributed or follower load), naming the method that solves it, and for a segment with
  // EA given a slenderness too.
  CbcmResult solve(const SegmentChain& chain) const;

  // "bcm" for one element, else "cbcm": the name messages use.
  std::string model_name() const;
  const Options& options() const { return options_; }

 private:
  Options options_;
};

// The pseudo-rigid-body 3R model of a cantilever (Su, "A pseudorigid-body 3R model for determining
// large deflection of cantilever beams subject to tip loads", J. Mechanisms Robotics 1:021008,
// 2009; docs/models.md): four rigid links of lengths gamma0..gamma3 (times l, from the clamp)
// joined by three revolute joints with torsion springs k1..k3 (times EI/l). Unlike Howell's 1R
// model (one pivot, elements/prbm_element.h) it carries a tip force at any angle together
// with an end moment.
//
// Kinematics (nondimensional, clamp at the origin along +x): joint i (i = 1..3) sits at the end of
// link i-1; theta_i is the rotation of joint i, link j's angle is theta_1 + ... + theta_j, the tip
// angle theta0 = theta_1 + theta_2 + theta_3.
// Statics under dead tip loads (Fx, Fy, M), the stationarity of
//   V = sum k_i theta_i^2/2 - Fx x_tip - Fy y_tip - M theta0:
//   k_i theta_i = (x_tip - x_i) Fy - (y_tip - y_i) Fx + M      (i = 1, 2, 3),
// the moment of the tip loads about joint i. A guided end holds theta0 at its prescribed angle and
// M becomes the guide's reaction (a Lagrange multiplier of that constraint; derived here, not in
// Su's paper).
//
// Small loads (linear in the load, every x_tip - x_i = 1 - s_i with s_i the joint's arc length):
//   b/l = Fy sum (1 - s_i)^2/k_i + M sum (1 - s_i)/k_i,  theta0 = Fy sum (1 - s_i)/k_i + M sum
//   1/k_i.
// With Su's general constants b/l = 0.34066 Fy: 2.2 % softer than the exact Fy/3 (the constants
// trade small-load accuracy for large deflections); theta0 = 0.4985 Fy + 1.0069 M.
// The stored sets of PR-3R constants (below): Su's general set, Su's sets fitted to an end moment
// and to a transverse force, and flexure's own (derived against the exact elastica).
enum class Prbm3rConstantSet { kSu, kSuMoment, kSuForce, kFlexure };
// "su", "su-moment", "su-force", "flexure" (the `--constants` choices and the JSON/HDF5 names).
const char* to_string(Prbm3rConstantSet set);
// The set of that name (case-insensitive); throws InvalidInput "PR-3R constants 'NAME' are unknown
// (allowed: su, su-moment, su-force, flexure)".
Prbm3rConstantSet prbm3r_constant_set_from_string(std::string_view name);

struct Prbm3rConstants {
  std::array<double, 4> gamma{};  // link lengths / l, clamp to tip; sum 1
  std::array<double, 3> k{};      // spring stiffnesses / (EI/l), clamp to tip
  std::string name;               // "su", "su-moment", "su-force", "flexure"
  std::string source;             // where the numbers come from, for people

  // Su's general set (0.10, 0.35, 0.40, 0.15; 3.51, 2.99, 2.58), data/su_prbm3r_constants.csv.
  static Prbm3rConstants su();
  // Su's sets fitted to one load alone (same gamma): a pure end moment, a transverse tip force.
  static Prbm3rConstants su_moment();
  static Prbm3rConstants su_force();
  // The set flexure derives itself against the exact elastica (below),
  // stored in data/prbm3r_flexure_constants.csv with its objective and load domain.
  static Prbm3rConstants flexure();
  // The stored set `set`.
  static Prbm3rConstants of(Prbm3rConstantSet set);
  // By name (case-insensitive): su, su-moment, su-force, flexure. Throws InvalidInput listing them.
  static Prbm3rConstants by_name(std::string_view name);
  // The names by_name takes, in that order.
  static const std::vector<std::string>& names();

  // Arc length of joint i (1..3) from the clamp: gamma0 + ... + gamma_{i-1}.
  double joint_arc_length(int i) const;
  // Small-load compliances (the linear limit above): b/Fy, theta0/Fy (= b/M), theta0/M.
  double small_load_b_per_force() const;
  double small_load_theta_per_force() const;
  double small_load_theta_per_moment() const;

  // Throws InvalidInput naming the field unless every gamma_i > 0, their sum is 1 (within 1e-6)
  // and every k_i > 0, all finite.
  void validate() const;
};

struct Prbm3rResult : SolveStatus {
  // iterations: Newton iterations over all load steps
  // residual: max |k_i theta_i - moment about joint i| at the returned angles (and |theta0 - its
  // prescribed value| on a guided end)
  std::array<double, 3> joint_angles{};  // theta_1..theta_3, rad
  TipPose tip;
  double root_moment = 0.0;  // M(0) l/EI: the tip loads' moment about the clamp
  double end_moment = 0.0;   // mu (free) or the guide's reaction (guided)
  int load_steps = 0;        // proportional-loading steps taken
  double load_factor = 0.0;  // reached (1 when converged)
  // Whether the equilibrium is stable: the second variation of V (restricted to theta0 fixed on a
  // guided end) is positive definite.
  bool stable = false;
};

class Prbm3rSolver {
 public:
  struct Options {
    Prbm3rConstants constants = Prbm3rConstants::su();
    double tolerance = 1e-13;  // max |residual| (moments, EI/l)
    int max_iterations = 30;   // Newton iterations per load step
    int max_load_steps = 2000;
    // Throws InvalidInput naming the first bad field (the constants' validate() included).
    void validate() const;
  };

  Prbm3rSolver();
  explicit Prbm3rSolver(Options options);

  // Proportional loading from the unloaded beam (elements/load_path_newton.h). Throws
  // InvalidInput for what CantileverCase::validate refuses.
  Prbm3rResult solve(const CantileverCase& problem) const;
  // The links as a polyline at `count` >= 2 equally spaced arc lengths (theta: the link angle).
  std::vector<ShapePoint> shape(const Prbm3rResult& result, int count) const;
  // Clamp, joints 1-3 and tip of the links at the given joint angles.
  std::array<ChainPose, 5> joints(const std::array<double, 3>& joint_angles) const;

  const Options& options() const { return options_; }

 private:
  Options options_;
};

// PR-3R constants derived by flexure itself (docs/models.md, "PR-3R constants"), the way
// prbm_element.h re-derives Howell's 1R constants: the link lengths gamma0..gamma3 and spring
// stiffnesses k1..k3 (above) that minimise the PR-3R model's error against the exact
// elliptic elastica over a stated domain of tip loads.
//
// Objective: the root mean square over the domain's loads of
//   e^2 = (|tip - exact tip| / |exact tip displacement|)^2
//       + (|theta0 - exact theta0| / max(|exact theta0|, |exact tip displacement|))^2,
// the relative tip position error (the measure of --tol) and a relative tip angle error. A load
// the model cannot follow (no converged proportional loading) counts as e = 1.
// Parameters: gamma1, gamma2, gamma3 (gamma0 = 1 - their sum, every gamma >= 0.02) and ln k1..k3;
// Nelder-Mead from Su's general set, restarted from its best point until a restart gains less
// than 1e-6 (or `restarts` are spent).
struct Prbm3rDerivationOptions {
  // The load domain: the free cantilever at every (n, alpha2, mu) of these axes whose exact
  // solution (proportional loading) has |theta0| <= max_tip_angle.
  std::vector<double> load_ratio_n{-2.0, -1.0, 0.0, 1.0};
  std::vector<double> alpha2{0.5, 1.0, 2.0, 3.0, 5.0, 7.5, 10.0};
  std::vector<double> mu{-2.0, -1.0, 0.0, 1.0, 2.0};
  double max_tip_angle = 2.0;  // rad
  int max_evaluations = 4000;  // objective evaluations per Nelder-Mead run
  int restarts = 4;
  // Throws InvalidInput naming the field: empty or non-finite axes, alpha2 <= 0 with mu = 0 only
  // (no load), max_tip_angle outside (0, pi], counts < 1.
  void validate() const;
  // The domain in words (for the data file and the report).
  std::string describe() const;
};

struct Prbm3rDerivation : SolveStatus {
  // iterations: objective evaluations; residual: the objective at the derived constants
  Prbm3rConstants constants;           // name "flexure"
  double objective = 0.0;              // RMS of e over the domain (above)
  double objective_su = 0.0;           // the same for Su's general set
  double max_position_error = 0.0;     // largest relative tip position error over the domain
  double max_position_error_su = 0.0;  // the same for Su's general set
  int loads = 0;                       // loads in the domain (exact solutions kept)
  std::string domain;                  // Prbm3rDerivationOptions::describe()
};

Prbm3rDerivation derive_prbm3r_constants(const Prbm3rDerivationOptions& options = {});

// The data file data/prbm3r_flexure_constants.csv for a derivation: a comment block with the
// provenance (`provenance`: tool version, commit, command), the objective and the domain, then one
// row "flexure" with the columns of data/su_prbm3r_constants.csv and the objective.
std::string prbm3r_constants_csv(const Prbm3rDerivation& derivation, const std::string& provenance);

}  // namespace flexure
