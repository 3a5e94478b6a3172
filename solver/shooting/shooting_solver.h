#pragma once
// The shooting solver in one header: ShootingSolver and its results, its settings and load paths,
// the shape of a solution at any arc lengths.
//
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
//
// The settings and the load-path types of the shooting solver (ShootingSolver, below):
// the integrator's backend and tolerances, the Newton corrector's and the continuation's options,
// how finely large loads are cut for multiple shooting, and the recorded load path with its
// special points. The machinery they configure (elastica_integrator.h, newton.h, continuation.h,
// shooting_problem.h) is internal: not installed. Theory: docs/theory-shooting.md.
//
// The shape of a shooting solution at any arc lengths, e.g. at the stations the stability verdict
// wants (solver/chain_model/segment_chain.h, docs/stability.md):
//
//   const Reaction support = tip_support_reaction(chain, result.tip_load);
//   const Stability v = equilibrium_stability(chain, support, [&](const std::vector<double>& s) {
//     return shooting_shape_at(chain, result, s, solver.options());
//   });
#include <Eigen/Dense>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/status.h"

namespace flexure {

// Which integrator runs the flexible pieces (docs/theory-shooting.md §4, speed and accuracy in
// docs/performance.md):
//   kRk8pd: the explicit Prince-Dormand 8(7), the default: the fastest at the tolerances the
//     solvers ask for (1e-9 ... 1e-12); GSL's gsl_odeiv2_step_rk8pd and its standard step
//     control, step for step, written out with the right-hand side inlined
//     (prince_dormand87_piece.h; GSL's own stepper is kept as its reference, gsl_rk8pd_piece.h);
//   kCvodes: SUNDIALS CVODES (Adams, forward sensitivities), the reference;
//   kDormandPrince: the explicit Runge-Kutta 5(4) written here, kept for comparison;
//   kArkodeErk: SUNDIALS ARKODE's explicit stepper with the Fehlberg 13-7-8 table, measured
//     against kRk8pd (slower: N_Vector overhead per step).
enum class IntegratorBackend { kRk8pd, kCvodes, kDormandPrince, kArkodeErk };

// Command-line names of the backends: "rk8pd", "cvodes", "dormand-prince", "arkode-erk".
const char* to_string(IntegratorBackend backend);
// Accepts those names (case-insensitive); throws InvalidInput naming the allowed ones otherwise.
IntegratorBackend integrator_backend_from_string(const std::string& name);

struct IntegratorOptions {
  // Which integrator runs the flexible pieces.
  IntegratorBackend backend = IntegratorBackend::kRk8pd;
  double rtol = 1e-12;      // relative tolerance of the local error test (every backend)
  double atol = 1e-14;      // absolute tolerance on every state component
  long max_steps = 200000;  // steps per segment piece before giving up
  bool adams = true;        // Adams-Moulton (non-stiff); false = BDF for very stiff loads
  bool sensitivity_error_control = true;  // include sensitivities in the local error test
  bool fixed_point = true;  // Adams only: fixed-point corrector (no Jacobian, no dense
                            // solve; the elastica is not stiff); false = Newton + dense

  // Throws InvalidInput naming the first field outside its range.
  void validate() const;
};

// State at the end of an integration (the tip for the last stretch of the chain).
struct TipState {
  double x = 0.0;
  double y = 0.0;
  double theta = 0.0;
  double m = 0.0;
  Eigen::Matrix<double, 4, Eigen::Dynamic> sensitivity;  // d(x, y, theta, m)/dp, one column per p
  // Internal force just before the end (on the last segment integrated) and dN/dp.
  Eigen::Vector2d N = Eigen::Vector2d::Zero();
  Eigen::Matrix<double, 2, Eigen::Dynamic> N_sensitivity;
};

struct MultipleShootingOptions {
  double amplification_budget = 2.5;  // max sqrt(|N|/EI) * (part length): growth <= e^budget
  int min_parts_per_segment = 1;      // lower bound on the parts of every flexible segment
  int max_parts_per_segment = 64;     // upper bound (keeps the Newton system small)
};

struct NewtonOptions {
  double residual_tolerance = 1e-10;  // converged when max |g_i| is below this
  double step_tolerance = 1e-13;      // ...or the step is below this (relative) and max |g_i| is
                                      // below 1e3 * residual_tolerance (integration noise floor)
  int max_iterations = 25;            // Newton iterations per solve
  int max_backtracks = 10;            // step halvings in the line search before giving up
  // > 0: a trial point of the line search may cost at most this times the integration steps of
  // the current point (and at least kMinTrialSteps); a costlier one is abandoned as a failed
  // trial, so the step is halved. A trial far from the current point (loads many times its own)
  // costs many steps and is almost never accepted: in the exact mechanism strokes such trials
  // took most of the work (3A-lssm, mechanism_exact.h). 0: no limit.
  double trial_cost_factor = 0.0;
};

struct ContinuationOptions {
  double initial_step = 0.1;   // first arclength step (scaled variables; at most max_step)
  double min_step = 1e-7;      // give up below this step
  double max_step = 0.5;       // cap on the arclength step (`flexure path --max-step`)
  double max_load_step = 0.0;  // > 0: no step changes the load factor by more than this, so the
                               // path has at least 1/max_load_step points per unit of lambda
                               // (`flexure path --min-points`); 0: no such cap
  double growth = 1.6;         // step growth after an easy correction
  // Folds hide where the tangent's lambda-component heads for zero: two of them (an S-shaped
  // path) inside one step leave its sign unchanged at both ends and go unseen. While it falls
  // towards zero at the rate of the last step, the next step covers at most level_fraction of the
  // arclength to zero extrapolated from that rate, but not less than level_min_step.
  double level_fraction = 0.8;
  double level_min_step = 0.05;
  int easy_iterations = 3;  // corrections in at most this many Newton iterations are easy
  int max_steps = 500;      // accepted + rejected steps before giving up (never a hang);
                            // paths in the test grids need at most about 70
  long max_integrator_steps = 500000;   // CVODES steps over the whole path (time budget), times
                                        // max(1, shooting intervals / 16)
  double max_predictor_distance = 0.5;  // reject a correction farther than this * step from the
                                        // predictor (guards against jumping to another branch)
  double max_turn = 0.6;  // reject a step whose tangent turned by more than this (rad); the
                          // tangent's sign comes from the path's orientation (continuation.cpp),
                          // so a corrector that lands on another branch shows up as a large turn
  double bifurcation_step = 1e-3;      // an orientation flip that cannot be located (or is not
                                       // verified as a singular point) is accepted as a crossing
                                       // only at steps this short (continuation.cpp)
  double bifurcation_vicinity = 0.01;  // no ordinary path samples recorded this close to a
                                       // bifurcation (the located point itself is recorded)
  bool record_path = true;             // store every accepted point
  // Special points (docs/theory-shooting.md, "Limit points and bifurcations"): each fold of the
  // load factor and each simple bifurcation (dg/dz singular while lambda keeps its direction) is
  // located on the path by Brent's method on the arclength of the step that passed it: a fold
  // where the tangent's lambda-component vanishes, a bifurcation where det(dg/dz) does. Off: the
  // folds are only counted at the step after them (the point after is marked kLimitPoint).
  bool locate_special_points = true;
  double location_tolerance = 1e-11;  // arclength bracket of a located special point (scaled)
  double singular_tolerance = 1e-6;   // a located bifurcation must have the second-smallest
                                      // singular value of [dg/dz S, dg/dlambda] below this times
                                      // its size over the step (else: a branch jump)
  // Branch switching: at the switch_at_bifurcation-th bifurcation (counted from 1 along the path;
  // 0 = never) the path leaves onto the other branch through it, along that branch's tangent
  // (the algebraic bifurcation equation in the null space of [dg/dz S, dg/dlambda],
  // docs/theory-shooting.md "Branch switching"), by a first step of branch_switch_step;
  // branch_side +1 takes the half-branch on which the tip moves to +y (to +theta when the end holds
  // y, the clamp's moment m(0) grows when it holds both), -1 the other.
  int switch_at_bifurcation = 0;
  int branch_side = 1;
  double branch_switch_step = 0.02;
  int shape_points = 0;  // > 1: the shape (x, y, theta, moment) at this many equally spaced arc
                         // lengths at every recorded point
};

// The kind of a recorded path point. The integer values are the `status` codes of `flexure path`
// files (docs/hdf5-schema.md); keep them.
enum class PathStatus { kStart, kAccepted, kLimitPoint, kEnd, kBifurcation };
const char* to_string(PathStatus status);

struct PathPoint {
  double lambda = 0.0;  // load factor
  ChainPose tip;        // tip x, y, theta
  Reaction reaction;    // loads the clamp applies to the chain
  Reaction tip_load;    // total load on the tip: N(tip), m(tip) (the support's reaction for a
                        // prescribed coordinate)
  double step = 0.0;    // arclength step that reached this point
  int iterations = 0;   // Newton iterations of the corrector
  PathStatus status = PathStatus::kAccepted;
  int stage = 1;   // > 1 in later stages of a staged path (below)
  int branch = 0;  // 0 on the path from zero load; k after switching at the k-th bifurcation
  // The tip coordinates the path holds at this point (its stage's ShootingProblem::mask()): the
  // end condition's under proportional loading, without the one released along the tangent in
  // the first stage of a straight chain with both end coordinates prescribed, with the
  // controlled coordinate in the moving stage of a displacement-controlled path. The stability
  // verdict of the point takes them as constraints (path_point_stability.h).
  PrescribedMask held;
  std::vector<ShapePoint> shape;  // ContinuationOptions::shape_points > 1: the deflected shape
  std::vector<double> moment;     // bending moment at each shape point (statics, same units)
  Eigen::VectorXd z;  // unknowns at the point (of its stage's ShootingProblem); the force points
                      // of a displacement-controlled path are located from them (control_points.h)
};

// A located fold of the load factor (limit point) or simple bifurcation point on the path.
enum class SpecialPointKind { kLimitPoint, kBifurcation };
const char* to_string(SpecialPointKind kind);  // "limit_point", "bifurcation"

struct SpecialPoint {
  SpecialPointKind kind = SpecialPointKind::kLimitPoint;
  double lambda = 0.0;  // load factor at the point (to about 1e-10 when located)
  ChainPose tip;
  Reaction reaction;     // loads the clamp applies to the chain
  Reaction tip_load;     // total load on the tip
  int index = -1;        // position in LoadPath::points (-1 when the path is not recorded)
  int index_after = -1;  // first recorded point after it (-1 when none: the path stopped)
  int stage = 1;
  int branch = 0;         // branch on which it lies (PathPoint::branch)
  bool located = true;    // false: the step could not be refined; lambda is then the nearer end
                          // (a fold: the larger lambda of the step) and index the point after it
  bool switched = false;  // the path left here onto the other branch
  Eigen::VectorXd z;      // unknowns at the point (of the stage's ShootingProblem)
};

// A point of the force-displacement curve of a displacement-controlled path (control_points.h):
// where the support's load conjugate to the moved coordinate (the force on tip-x or tip-y, the
// moment on tip-angle) crosses zero (an equilibrium of the structure with that coordinate free and
// unloaded) or has a local extremum along the path (a limit point under force control: a
// force-controlled experiment snaps there).
enum class ForcePointKind { kZero, kMaximum, kMinimum };
const char* to_string(ForcePointKind kind);  // "force_zero", "force_maximum", "force_minimum"

struct ForcePoint {
  ForcePointKind kind = ForcePointKind::kZero;
  double lambda = 0.0;      // path parameter (fraction moved in the moving stage)
  double coordinate = 0.0;  // the moved coordinate (root frame; rad for tip-angle)
  double force = 0.0;       // the support's load on it (tip load component; 0 at a zero)
  // At a zero: d force / d coordinate along the path (the stiffness the free coordinate sees;
  // > 0 with a stable displacement-controlled state: a stable equilibrium of the free structure);
  // at an extremum: 0 by definition (reported as 0).
  double slope = 0.0;
  ChainPose tip;
  Reaction reaction;      // loads the clamp applies to the chain
  Reaction tip_load;      // total load on the tip
  int index_before = -1;  // the path point before it (LoadPath::points); at a sampled corner
                          // (a bifurcation or fold point that is itself the extremum) that point
  int stage = 1;
  int branch = 0;
  bool located = true;  // false: the refinement failed; the nearest path point is reported
};

struct LoadPath : SolveStatus {
  // converged(): reached lambda = 1
  bool singular_start = false;  // dg/dz singular at lambda = 0: the path starts at a bifurcation
  // message: where and why it stopped
  double lambda_reached = 0.0;               // largest lambda on the path
  int steps = 0;                             // accepted steps
  int rejected_steps = 0;                    // halved steps
  int newton_iterations = 0;                 // summed over all corrections
  int location_corrections = 0;              // corrector solves spent locating special points
  long integrator_steps = 0;                 // integrator steps over the whole path (its cost)
  int limit_points = 0;                      // turning points of lambda passed
  double first_limit_load_factor = 0.0;      // load factor at the first turning point (located)
  int bifurcation_points = 0;                // simple bifurcation points crossed (or switched at)
  std::vector<SpecialPoint> special_points;  // in path order, folds and bifurcations
  // Displacement control only (ShootingSolver::controlled_path): the zero crossings and the
  // extrema of the support's force on the moved coordinate, located (control_points.h).
  std::vector<ForcePoint> force_points;
  bool switched_branch = false;  // the path left onto a bifurcated branch
  std::vector<PathPoint> points;
  Eigen::VectorXd z;    // unknowns at the last accepted point
  double lambda = 0.0;  // load factor at the last accepted point
  // residual: at the last accepted point
  ChainPose tip;       // tip pose at the last accepted point
  TipState tip_state;  // tip state (with the bending moment) at the last accepted point
  // Sign of det dg/dz at the end point when the path converged (0 otherwise): it changes at every
  // limit point and bifurcation point, so a neighbouring load's solution with the same sign and a
  // short, undamped Newton step lies on the same smooth stretch of branch (ShootingSolver::
  // solve_near).
  int jacobian_sign = 0;
};

}  // namespace flexure

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
    // reference, kDormandPrince the former built-in 5(4) (IntegratorBackend, above).
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

namespace flexure {

// The converged result's equilibrium at arc lengths s (increasing, in [0, total length]),
// integrated with the solver's own integrator and multiple-shooting cuts from its unknowns at full
// load (`options` as the solve used). Throws InvalidInput for an unconverged result or arc lengths
// outside the chain, NoConvergence when the integration fails or does not reproduce the result's
// tip to 1e-8 of the chain's length.
std::vector<ShapePoint> shooting_shape_at(const SegmentChain& chain,
                                          const ShootingResult& result,
                                          const std::vector<double>& s,
                                          const ShootingSolver::Options& options = {});

}  // namespace flexure
