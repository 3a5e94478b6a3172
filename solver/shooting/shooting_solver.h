#pragma once
// Reference solver for planar segment chains: shooting on the root loads (integrated at rtol 1e-12
// by GSL's Prince-Dormand 8(7), or CVODES, elastica_integrator.h) and a Newton method whose
// Jacobian comes from forward sensitivities.
//
// Theory and conventions: docs/theory-shooting.md. Problem description:
// solver/chain_model/segment_chain.h.
//
// Strategy of solve() (Options::strategy):
//   kContinuation: pseudo-arclength continuation in the load factor from zero (continuation.h);
//     passes limit points and returns the proportional-loading branch, like EllipticSolver.
//   kDirect: Newton at full load from the linear-theory guess (the load-path tangent at zero).
//     Fast, but for large or compressive loads it may converge to another equilibrium.
//   kAuto (default): kDirect when the equilibrium is provably unique (the elastica operator is a
//     contraction, see unique_equilibrium_bound()), otherwise kContinuation; a failed direct
//     attempt falls back to continuation.
// A problem that cannot be completed returns converged == false with the load factor reached.
//
// CLI entry points: solve_shooting(chain, options) and trace_load_path(chain, options).
#include <Eigen/Dense>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/shooting_options.h"

namespace flexure {

// The machinery behind the solver (internal headers, not installed): the residual and the
// integrator (shooting_problem.h, elastica_integrator.h) and how the load factor enters.
class ShootingProblem;
class ElasticaIntegrator;
struct Homotopy;

// How solve() reached its answer (the `method` text says the same for people).
enum class ShootingPath {
  kDirectNewton,          // Newton at full load from the linear guess (unique equilibrium)
  kContinuation,          // pseudo-arclength continuation from the unloaded chain
  kTwoStageContinuation,  // a straight chain with both tip coordinates prescribed
  kNewtonFromGuess,       // solve_from(): Newton from a caller's guess
  kFromNeighbour,         // solve_near(): Newton from a neighbouring load's solution, checked
};

struct ShootingResult : SolveStatus {
  // message: how it converged, or where and why it stopped
  ShootingPath path = ShootingPath::kDirectNewton;
  std::string method;  // the path in words: "direct Newton", "continuation", ...
  // iterations: Newton iterations, summed over continuation steps
  int continuation_steps = 0;  // accepted continuation steps (0 for a direct solve)
  int limit_points = 0;        // folds of the load factor passed on the path (snap-through)
  double first_limit_load_factor = 0.0;      // load factor at the first of them (located)
  int bifurcation_points = 0;                // simple bifurcation points passed on the path
  std::vector<SpecialPoint> special_points;  // the folds and bifurcations, located
  int shooting_intervals = 1;  // 1 = single shooting; more = multiple shooting cuts + 1
  long integrator_steps = 0;   // integrator steps taken in all integrations of this solve
  // residual: max |g_i| of the far-end conditions at the returned point
  double load_factor = 0.0;  // load factor reached (1 when converged)

  ChainPose tip;      // tip x, y, theta (root frame)
  Reaction reaction;  // loads the clamp applies to the chain: -N(0), -m(0)
  Reaction tip_load;  // total load on the tip, given + reaction: N(tip), m(tip); for a
                      // prescribed coordinate this is the support's reaction
  std::vector<std::string> unknown_names;
  std::vector<double> unknowns;   // m(0), shot force components, then the states at the cuts
  std::vector<ShapePoint> shape;  // on request (Options::shape_points), s from 0 to total length
  // On request (Options::count_inflections): interior sign changes of the curvature m/EI + kappa0
  // (inflection_count.h); -1 when not counted.
  int inflection_points = -1;
  // With the inflection points, from the same samples: the largest |m/EI + kappa0| along the
  // chain (the step ends and the moment's interior extrema; inflection_count.h). NaN when not
  // recorded (not counted, or a backend that shows no steps). The fast stability verdict of a
  // tensioned cantilever uses it (solver/shooting/tension_stability.h).
  double largest_curvature = std::numeric_limits<double>::quiet_NaN();
  // Sign of det dg/dz at the returned point (0: not known, e.g. a two-stage path); it changes at
  // every limit point and bifurcation point of a branch (solve_near checks it).
  int jacobian_sign = 0;

  // Howell's tip description for a cantilever of length l: (x/l, y/l, theta).
  TipPose tip_pose(double length = 1.0) const {
    return TipPose{tip.x / length, tip.y / length, tip.theta};
  }
};

enum class ShootingStrategy { kAuto, kContinuation, kDirect };

// Displacement control of a path (ShootingSolver::controlled_path): a tip coordinate is moved
// and is the path parameter, instead of the loads growing in proportion.
enum class TipCoordinate { kX, kY, kTheta };
const char* to_string(TipCoordinate coordinate);  // "tip-x", "tip-y", "tip-angle"
struct DisplacementControl {
  TipCoordinate coordinate = TipCoordinate::kY;
  double target = 0.0;  // the coordinate's value at the end of the path (root frame; rad)
  // One way, as an experiment moves it: where the path folds back (a limit point of the moved
  // coordinate) and an equilibrium lies next to the fold just beyond it (a buckled branch
  // rejoining the unbuckled one), go on from there to the target instead of following the fold
  // back (docs/paths.md). `flexure path --one-way`.
  bool one_way = false;
};

// A solution at a neighbouring load to start from (ShootingSolver::solve_near): the next point of
// a sweep, say.
struct ShootingNeighbour {
  std::vector<double> unknowns;   // all unknowns of the neighbour's ShootingResult
  int jacobian_sign = 0;          // the neighbour's ShootingResult::jacobian_sign (must be +-1)
  std::vector<double> predicted;  // optional: the unknowns predicted for this load (same size),
                                  // e.g. extrapolated from two neighbours; empty: `unknowns`
  ChainPose tip;                  // the neighbour's tip, for the jump check
};

// Contraction constant of the elastica map theta -> integral of m/EI for a chain with a free end
// and dead loads only; below 1 the equilibrium is unique for any end moment. Returns +infinity when
// the bound does not apply (prescribed tip coordinates, follower force). Uniform single segment:
// 4 |F| L^2 / (pi^2 EI) (Green's operator of theta'' with theta(0) = theta'(L) = 0 has norm
// 4 L^2 / pi^2); general chain: max|N| * integral over the flexible arc of (L_total - s)/EI(s) ds
// (a short flexure at the root of a long rigid link counts with its lever L_total, not L/2).
double unique_equilibrium_bound(const SegmentChain& chain);

class ShootingSolver {
 public:
  struct Options {
    ShootingStrategy strategy = ShootingStrategy::kAuto;  // see the comment at the top
    double rtol = 1e-12;  // integrator relative tolerance (reference: <= 1e-12)
    double atol = 1e-14;  // integrator absolute tolerance
    bool adams = true;    // CVODES only: Adams-Moulton; false = BDF
    // GSL's Prince-Dormand 8(7) by default, the fastest at these tolerances; kCvodes is the
    // reference, kDormandPrince the former built-in 5(4) (shooting_options.h).
    IntegratorBackend backend = IntegratorBackend::kRk8pd;
    NewtonOptions newton;                       // Newton corrector tolerances and iteration limits
    ContinuationOptions continuation;           // used when the direct attempt fails or is disabled
    MultipleShootingOptions multiple_shooting;  // how finely large loads are cut (see
                                                // shooting_problem.h)
    int shape_points = 0;  // > 1: return the shape at this many equally spaced s
    // Count the inflection points (ShootingResult::inflection_points) from the integration of the
    // solution, without a sampled shape (inflection_count.h).
    bool count_inflections = false;
    // solve_near: the largest change of the tip angle (rad) and of the tip position (in total
    // lengths) from the neighbour that is accepted; a larger one is a jump (a snap-through, or
    // another branch).
    double max_neighbour_jump = 0.2;

    // Throws InvalidInput naming the first field outside its range (checked by every solve).
    void validate() const;

    // The integrator settings these options imply (tolerances, method, backend).
    IntegratorOptions integrator_options() const {
      IntegratorOptions io;
      io.rtol = rtol;
      io.atol = atol;
      io.adams = adams;
      io.backend = backend;
      return io;
    }
  };

  ShootingSolver() = default;
  explicit ShootingSolver(Options options) : options_(options) {}

  // Throws InvalidInput for an invalid chain; never throws for non-convergence.
  ShootingResult solve(const SegmentChain& chain) const;
  // Convenience: Howell's nondimensional cantilever (length 1, EI 1) with an end load.
  ShootingResult solve(const EndLoad& load) const { return solve(uniform_cantilever(load)); }
  // Newton at full load from given unknowns (e.g. a neighbouring solution); no continuation. The
  // guess holds either the root unknowns (m0, then any shot force components) or all unknowns.
  ShootingResult solve_from(const SegmentChain& chain, const std::vector<double>& guess) const;

  // Newton at full load from a neighbouring load's solution, kept only when it provably stays on
  // the neighbour's smooth stretch of branch: Newton converges with full steps that shrink at
  // least 4x per iteration (the start lies well inside the root's basin), the sign of det dg/dz is
  // the neighbour's (no limit point or bifurcation point between them), Newton moves less from a
  // prediction than half the predicted move, and the tip moves by at most max_neighbour_jump.
  // Otherwise the result is not converged and says which check failed;
  // the caller then solves from zero load (solve()). Neighbours with other multiple-shooting cuts
  // lend their root unknowns. Whether that stretch of branch is the proportional-loading answer at
  // this load is the caller's to know (for a load on the same ray from zero, farther out, it is:
  // beam/beam_sweep_solver.h); limit_points is 0 (the caller knows the path).
  ShootingResult solve_near(const SegmentChain& chain, const ShootingNeighbour& neighbour) const;

  // Load path by pseudo-arclength continuation from zero load (all points recorded). A straight
  // chain with both end coordinates prescribed is recorded in the two stages solve() uses: stage 1
  // points have PathPoint::stage = 1 (lambda = load factor), stage 2 points stage = 2 (lambda =
  // fraction of the released coordinate's travel, loads at full value).
  LoadPath load_path(const SegmentChain& chain) const;

  // Path under displacement control: stage 1 applies the given loads by proportional loading
  // (load_path(), recorded; skipped when the chain carries no load and prescribes no motion) with
  // the controlled coordinate held at its unloaded value when the end condition prescribes it,
  // free otherwise; the last stage moves the controlled coordinate linearly from where stage 1
  // left it to `control.target` with the loads at full value (lambda = fraction moved), so the
  // support's reaction (PathPoint::tip_load) traced against the coordinate is the
  // force-displacement curve. The end condition's other prescribed coordinates stay at their
  // targets; the load conjugate to the controlled coordinate must be zero (it is the reaction).
  // Throws InvalidInput for a target the chain cannot reach.
  LoadPath controlled_path(const SegmentChain& chain, const DisplacementControl& control) const;

  const Options& options() const { return options_; }

 private:
  ShootingResult finish(const ShootingProblem& problem,
                        ElasticaIntegrator& integrator,
                        const Eigen::VectorXd& z,
                        double lambda,
                        ShootingResult result,
                        const TipState* known_tip = nullptr) const;
  struct TwoStageRun;  // shooting_solver.cpp
  TwoStageRun run_two_stages(const SegmentChain& chain,
                             ElasticaIntegrator& integrator,
                             bool record_path) const;
  void go_on_past_folds(const SegmentChain& chain,
                        const Homotopy& moving,
                        const ShootingProblem& problem,
                        ElasticaIntegrator& integrator,
                        const ContinuationOptions& copt,
                        TipCoordinate coordinate,
                        LoadPath& moved) const;
  ShootingResult solve_in_two_stages(const SegmentChain& chain,
                                     ElasticaIntegrator& integrator,
                                     ShootingResult result) const;
  Options options_;
};

// CLI entry points.
ShootingResult solve_shooting(const SegmentChain& chain, const ShootingSolver::Options& options);
LoadPath trace_load_path(const SegmentChain& chain, const ShootingSolver::Options& options);
LoadPath trace_controlled_path(const SegmentChain& chain,
                               const DisplacementControl& control,
                               const ShootingSolver::Options& options);

}  // namespace flexure
