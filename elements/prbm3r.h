#pragma once
// The pseudo-rigid-body 3R model of a cantilever (Su, "A pseudorigid-body 3R model for determining
// large deflection of cantilever beams subject to tip loads", J. Mechanisms Robotics 1:021008,
// 2009; docs/models.md): four rigid links of lengths gamma0..gamma3 (times l, from the clamp)
// joined by three revolute joints with torsion springs k1..k3 (times EI/l). Unlike Howell's 1R
// model (one pivot, elements/fixed_pinned_segment.h) it carries a tip force at any angle together
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
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "flexure/elements/cantilever_case.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/status.h"

namespace flexure {

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
  // The set flexure derives itself against the exact elastica (elements/prbm3r_derivation.h),
  // stored in data/prbm3r_flexure_constants.csv with its objective and load domain.
  static Prbm3rConstants flexure();
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

}  // namespace flexure
