#pragma once
// Exact large-deflection solution of an initially straight cantilever by elliptic integrals.
//
// Theory: docs/theory-elliptic.md. The elastica theta'' = F sin(theta - psi) (force F at angle psi,
// end moment mu) is a pendulum in chi = theta - psi + pi (elastica-general.md). Two families:
// inflectional (|H| < F, modulus k, Jacobi sn/cn) and non-inflectional (H > F, parameter m).
// Howell's eqs. 2.89-2.98 are the special case mu = 0, theta0 below the force angle.
//
// Where several equilibria exist (large compressive loads, large moments) the solver returns the one
// reached by proportional loading from the unloaded beam, found by continuation in the load factor;
// the result says which branch it is and how many inflection points the shape has.
#include <string>
#include <vector>

#include "solver/common/end_load.h"

namespace flexure {

enum class ElasticaFamily {
  kStraight,          // no transverse load and no moment: the beam stays straight
  kCircularArc,       // no force: a circular arc of curvature mu (eqs. 2.53-2.64)
  kInflectional,      // family A, -F < H < F: curvature may change sign
  kNonInflectional,   // family B, H > F: curvature keeps its sign (needs mu != 0)
};
const char* to_string(ElasticaFamily family);

// Everything needed to evaluate the closed-form shape at any arc length. Filled by the solver.
struct ElasticaParameters {
  ElasticaFamily family = ElasticaFamily::kStraight;
  double force = 0.0;       // F = |(Fx, Fy)| (after reflection so that Fy >= 0)
  double psi = 0.0;         // force angle in [0, pi] (after reflection)
  bool reflected = false;   // true when the problem was mirrored about the x axis (Fy < 0)
  double mu = 0.0;          // end moment (after reflection)
  double chi_tip = 0.0;     // pendulum angle at the tip, chi = theta - psi + pi (after reflection)
  double modulus2 = 0.0;    // k^2 (family A) or m (family B)
  double complement2 = 1.0; // 1 - modulus2, kept separately for accuracy near the separatrix
  double u_root = 0.0;      // elliptic argument at the clamp
  double u_tip = 0.0;       // elliptic argument at the tip
  int winding = 0;          // family A: chi oscillates about 2*pi*winding
};

struct EllipticResult {
  bool converged = false;
  std::string message;      // why it stopped; names the offending quantity when it failed
  int iterations = 0;       // root-finder iterations, summed over continuation steps
  int continuation_steps = 0;

  EndLoad load;             // the load solved for (inverse problems fill in alpha2 here)
  TipPose tip;
  double root_moment = 0.0; // curvature at the clamp, M(0) l/EI
  int inflection_points = 0;
  double residual = 0.0;    // |tip condition| at the returned solution
  std::string branch;       // "proportional loading" or a note on how the branch was chosen
  ElasticaParameters parameters;
};

class EllipticSolver {
 public:
  struct Options {
    double tolerance = 1e-14;       // relative tolerance on the unknown of each scalar solve
    int max_iterations = 200;       // per scalar solve
    int max_continuation_steps = 4000;
  };

  EllipticSolver() = default;
  explicit EllipticSolver(Options options) : options_(options) {}

  // Forward problem: tip pose for a given end load. Throws InvalidInput for non-finite loads.
  EllipticResult solve(const EndLoad& load) const;

  // Inverse problems in Howell's parameters (load ratio n fixed, mu fixed): find alpha2 such that
  // the tip angle is theta0, or such that the tip deflection is b/l. Throws InvalidInput when the
  // target is outside what the load ratio can reach (e.g. theta0 >= the force angle for mu = 0).
  EllipticResult solve_for_tip_angle(double load_ratio_n, double theta0, double mu = 0.0) const;
  EllipticResult solve_for_deflection(double load_ratio_n, double b_over_l, double mu = 0.0) const;

  // Deflected shape at `count` equally spaced arc lengths from 0 to 1 (count >= 2).
  std::vector<ShapePoint> shape(const EllipticResult& result, int count) const;
  // Shape at given arc lengths in [0, 1].
  std::vector<ShapePoint> shape_at(const EllipticResult& result, const std::vector<double>& s) const;

  const Options& options() const { return options_; }

 private:
  Options options_;
};

}  // namespace flexure
