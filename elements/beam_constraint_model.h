#pragma once
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
// (chained_bcm.h), which follows larger deflections.
#include <vector>

#include "flexure/elements/cantilever_case.h"
#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/status.h"

namespace flexure {

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

}  // namespace flexure
