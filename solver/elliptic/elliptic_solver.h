#pragma once
// Exact large-deflection solution of an initially straight cantilever by elliptic integrals.
//
// Theory: docs/theory-elliptic.md. The elastica theta'' = F sin(theta - psi) (force F at angle psi,
// end moment mu) is a pendulum in chi = theta - psi + pi (docs/theory-elliptic.md). Two families:
// inflectional (|H| < F, modulus k, Jacobi sn/cn) and non-inflectional (H > F, parameter m).
// Howell's eqs. 2.89-2.98 are the special case mu = 0, theta0 below the force angle.
//
// Where several equilibria exist (large compressive loads, large moments) the solver returns the
// one reached by proportional loading from the unloaded beam, found by continuation in the load
// factor (on the goal domain of issue 14, n in [-5, 10], |alpha2| <= 20, |mu| <= 2 pi, mostly by a
// guarded Newton iteration from that continuation's path, tabulated at build time:
// tabulated_predictor.h); the result says which branch it is and how many inflection points the
// shape has.
//
// The parameter set that describes one closed-form elastica, filled by the solver and evaluated by
// the closed form (elastica_closed_form.h, internal).
#include <string>
#include <vector>

#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/status.h"

namespace flexure {

enum class ElasticaFamily {
  kStraight,         // no transverse load and no moment: the beam stays straight
  kCircularArc,      // no force: a circular arc of curvature mu (Howell eqs. 2.53-2.64)
  kInflectional,     // family A, -F < H < F: curvature may change sign
  kNonInflectional,  // family B, H > F: curvature keeps its sign (needs mu != 0)
};
const char* to_string(ElasticaFamily family);

// Everything needed to evaluate the closed-form shape at any arc length. Filled by the solver.
struct ElasticaParameters {
  ElasticaFamily family = ElasticaFamily::kStraight;
  double force = 0.0;        // F = |(Fx, Fy)| l^2/EI (after mirroring so that Fy >= 0)
  double psi = 0.0;          // force angle in [0, pi] (after mirroring)
  bool mirrored = false;     // the problem was mirrored about the x axis because Fy < 0
  double mu = 0.0;           // end moment (after mirroring)
  double chi_tip = 0.0;      // pendulum angle at the tip, chi = theta - psi + pi (after mirroring)
  double modulus2 = 0.0;     // k^2 (family A) or m (family B)
  double complement2 = 1.0;  // 1 - modulus2, kept separately for accuracy near the separatrix
  double u_root = 0.0;       // elliptic argument at the clamp (u in family A, v in family B)
  double u_tip = 0.0;        // elliptic argument at the tip
  int winding = 0;           // family A: chi oscillates about 2 pi winding; family B: chi =
                             // 2 pi winding + 2 am(v), whole half-turns kept out of v
};

}  // namespace flexure

namespace flexure {

// Which equilibrium the solver returned and how it was found (the `branch` text says it in words).
enum class EllipticBranch {
  kPureMoment,          // pure end moment: the unique circular arc (Howell eqs. 2.53-2.64)
  kStraight,            // axial load only: the straight shape (proportional loading)
  kLinearTheory,        // negligible load: linear theory, exact to round-off
  kProportionalUnique,  // mu = 0: the unique proportional-loading solution (Howell eqs. 2.90-2.98)
  kProportionalContinued,  // mu != 0: proportional loading followed by pseudo-arclength
                           // continuation
  kProportionalTabulated,  // mu != 0 on the goal domain of issue 14: the same equilibrium, found by
                           // Newton from the path tabulated by that continuation (tabulated
                           // predictor, docs/theory-elliptic.md)
};

struct EllipticResult : SolveStatus {
  // message: why it stopped; names the offending quantity when it failed
  // iterations: root-finder iterations, summed over continuation steps (with an end moment:
  // residual evaluations, including those of a tabulated prediction the guard refused)
  int continuation_steps = 0;
  // Limit points (folds of the load factor) passed on the path from the unloaded beam; under load
  // control the beam would snap at the first, at first_limit_load_factor.
  int limit_points = 0;
  double first_limit_load_factor = 0.0;

  EndLoad load;  // the load solved for (inverse problems fill in alpha2 here)
  TipPose tip;
  double root_moment = 0.0;  // curvature at the clamp, M(0) l/EI
  int inflection_points = 0;
  // residual: |tip condition| at the returned solution
  EllipticBranch branch_kind = EllipticBranch::kProportionalUnique;  // code branches on this
  std::string branch;  // the same in words, for people ("proportional loading ...")
  ElasticaParameters parameters;
};

class EllipticSolver {
 public:
  // Domain: |F| l^2/EI and |mu| up to these (docs/theory-elliptic.md, "Precision"); beyond, the
  // solver throws OutsideMethodDomain.
  static constexpr double kMaxForce = 1e4;
  static constexpr double kMaxMoment = 1e4;
  // Inverse problems return a load whose tip quantity is within this of the target (times
  // max(1, |target|)), or fail.
  static constexpr double kInverseTolerance = 1e-10;

  struct Options {
    double tolerance = 1e-14;  // relative tolerance on the unknown of each scalar solve
    int max_iterations = 200;  // per scalar solve
    int max_continuation_steps = 4000;
    // With an end moment, on n in [-5, 10], |alpha2| <= 20, |mu| <= 2 pi: start from the tabulated
    // proportional-loading path and settle the equilibrium by a guarded Newton iteration, falling
    // back to the continuation wherever the guard refuses (docs/theory-elliptic.md, "Tabulated
    // predictor"). false: always the continuation (the tests compare the two).
    bool tabulated_predictor = true;

    // Throws InvalidInput naming the first field outside its range.
    void validate() const;
  };

  EllipticSolver() = default;
  // Throws InvalidInput (Options::validate) for bad options.
  explicit EllipticSolver(Options options);

  // Forward problem: tip pose for a given end load. Throws InvalidInput for non-finite loads.
  EllipticResult solve(const EndLoad& load) const;

  // Inverse problems in Howell's parameters (load ratio n fixed, mu fixed): find alpha2 such that
  // the tip angle is theta0, or such that the tip deflection is b/l; the load of smallest |alpha2|
  // that does. The returned tip reaches the target within kInverseTolerance max(1, |target|)
  // (`residual` holds the miss). Throws InvalidInput when the target is outside what the load
  // ratio can reach (e.g. theta0 >= the force angle for mu = 0), OutsideMethodDomain when it may
  // lie beyond the solver's force range, and returns converged = false with what was reached when
  // the tip quantity jumps across the target (a fold between neighbouring loads).
  EllipticResult solve_for_tip_angle(double load_ratio_n, double theta0, double mu = 0.0) const;
  EllipticResult solve_for_deflection(double load_ratio_n, double b_over_l, double mu = 0.0) const;

  // Deflected shape at `count` equally spaced arc lengths from 0 to 1 (count >= 2).
  std::vector<ShapePoint> shape(const EllipticResult& result, int count) const;
  // Shape at given arc lengths in [0, 1].
  std::vector<ShapePoint> shape_at(const EllipticResult& result,
                                   const std::vector<double>& s) const;

  const Options& options() const { return options_; }

 private:
  Options options_;
};

}  // namespace flexure
