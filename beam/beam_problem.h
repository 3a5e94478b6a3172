#pragma once
// Beam problems in one header: BeamProblem and solve_beam, the methods (BeamMethod), the solver
// object (BeamSolver) and the choice of auto.
//
// A beam problem solved by any method: the cantilever of Howell ch. 2 with an end load (or any
// segment chain and end condition), forward (the load is given) or inverse (the tip angle theta0
// or the deflection b/l is given and the load alpha2 is found), with the method named or chosen by
// `auto`. This is what `flexure beam`, `flexure sweep beam` and `flexure validate` call.
//
// To add a method: a value of BeamMethod (below), a branch in solve_beam()
// (beam_problem.cpp) that fills a BeamSolution from that solver's result, and, if `auto` should
// consider it, a rule in method_selector.cpp (docs/architecture.md, "Adding a beam method").
//
// The methods that solve a beam problem: their names as the
// tool spells them, and the convergence tolerance each one works to.
//
// A beam solver in the library's one calling style (a solver object with validated Options, a
// result that derives from SolveStatus): the method and its numerical settings here, the problem
// (what is loaded and what is given) in BeamProblem.
//
//   flexure::BeamSolver::Options options;
//   options.method = flexure::BeamMethod::kShooting;
//   const flexure::BeamSolver solver(options);  // InvalidInput for a bad setting, naming it
//   flexure::BeamProblem problem;
//   problem.value = 3.0;  // alpha2 = P l^2/EI
//   const flexure::BeamSolution s = solver.solve(problem);
//
// solve_beam(method, problem) stays the shorthand; it reads the same settings from the
// problem's fields (elements, increments, chain_variant, integrator, tolerance, ...), which
// BeamSolver::solve overwrites with the Options.
//
// Method `auto`: the cheapest model whose error for this load is within the tolerance
// ("model no more than a scene needs": the cheapest model that meets the tolerance).
//
// Order of preference (cheapest model first): the PRBM fixed-pinned segment (one pivot, one
// spring), the exact elliptic solution, the shooting solver. The PRBM is taken only when
//   * the load is one Howell's fixed-pinned element models (free cantilever, tip force, mu = 0,
//     -5 <= n <= 10 from Table 5.1),
//   * its PRB angle is inside the validity limits Theta_max(gamma) and Theta_max(K_theta)
//     (Howell eqs. 5.47, 5.63), and
//   * the error measured by `flexure bench` (cantilever_force/prbm, the accuracy map of
//     docs/benchmarks.md) at the neighbouring measured loads is within the tolerance.
// The elliptic solution (error ~1e-14) serves every other free cantilever with dead loads; the
// shooting solver (rtol 1e-12; measured error below 1e-9) every other chain and end condition.
#include <array>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "flexure/elements/ladder_models.h"
#include "flexure/solver/chain/chain_algorithm_solver.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {

enum class BeamMethod {
  kAuto,      // the cheapest method whose error is within the tolerance (choose_beam_method)
  kElliptic,  // exact elliptic-integral elastica (solver/elliptic)
  kShooting,  // shooting method with continuation (solver/shooting)
  kChain,     // Howell's chain algorithm (solver/chain)
  kPrbm,      // pseudo-rigid-body model (elements/prbm_cantilever.h)
  // The cheaper models of the ladder (beam_ladder.h, docs/models.md):
  kLinear,  // linear Euler-Bernoulli theory (elements/ladder_models.h)
  kPrbm3r,  // Su's pseudo-rigid-body 3R model (elements/ladder_models.h)
  kBcm,     // the beam-constraint model, one element (elements/ladder_models.h)
  kCbcm,    // the chained beam-constraint model (elements/ladder_models.h)
};

// "auto", "elliptic", "shooting", "chain", "prbm", "linear", "prbm3r", "bcm", "cbcm", in the order
// of the enum.
inline constexpr std::array<const char*, 9> kBeamMethodNames = {
    "auto", "elliptic", "shooting", "chain", "prbm", "linear", "prbm3r", "bcm", "cbcm"};

const char* to_string(BeamMethod method);
// Throws InvalidInput naming the allowed names.
BeamMethod beam_method_from_string(std::string_view name);

// The convergence tolerance the method works to (recorded in output files); kAuto: elliptic's.
double beam_method_tolerance(BeamMethod method);

}  // namespace flexure

namespace flexure {

// What the user fixed: the load alpha2, the tip angle theta0 or the tip deflection b/l, with
// Howell's load ratio n and end moment mu held fixed (Howell eqs. 2.67, 2.83).
struct BeamProblem {
  enum class Given { kAlpha2, kTheta0, kBOverL };
  Given given = Given::kAlpha2;
  double value = 0.0;         // alpha2, theta0 [rad] or b/l, as selected by `given`
  double load_ratio_n = 0.0;  // n > 0 compressive
  double mu = 0.0;            // end moment M l/EI
  int shape_points = 0;       // 0: no shape; otherwise >= 2 points from s = 0 to s = 1
  // The far end and the numerical methods (shooting, chain).
  EndCondition boundary = EndCondition::kFree;
  TipPrescription prescribed;  // unset = the stress-free tip value (e.g. guided: theta = 0)
  double follower = 0.0;       // follower tip force F l^2/EI along the tip normal
  int elements = 100;          // chain algorithm: N elements
  int increments = 1;          // chain algorithm: load increments to start with (halved on failure)
  ChainVariant chain_variant = ChainVariant::kCorrected;  // chain algorithm
  // Shooting method: the integrator of the flexible segments. GSL's Prince-Dormand 8(7) is the
  // default, 20-35x cheaper per solve than CVODES (the reference) at rtol 1e-9 ... 1e-12 and at
  // least as accurate for these small non-stiff systems (docs/performance.md, "Shooting").
  IntegratorBackend integrator = IntegratorBackend::kRk8pd;
  std::optional<SegmentChain> chain;  // a chain of segments (overrides the loads above)
  // `auto` picks the cheapest method whose relative error is within this (choose_beam_method).
  double tolerance = 1e-6;
  // The cheaper models of the ladder (beam_ladder.h): the chained BCM's number of elements N, the
  // PR-3R model's stored constants (elements/ladder_models.h: Su's general set by default), the
  // slenderness L/t of the BCM and CBCM (d = 12 (L/t)^2; 0: inextensible, the default).
  int cbcm_elements = 6;
  Prbm3rConstantSet prbm3r_constants = Prbm3rConstantSet::kSu;
  double slenderness = 0.0;
  // The stability verdict of the answer (BeamSolution::stability; docs/stability.md): on by
  // default; false leaves it not_checked (a sweep that does not want its cost). Its settings:
  // the defaults judge the margin to 1e-9; a sweep asks for less (margin_accuracy), which only
  // saves the refinements of margins close to 1 (docs/performance.md, "Stability").
  bool judge_stability = true;
  StabilityOptions stability_options;
  // Return a stable equilibrium: when the one reached by proportional loading is not stable
  // (unstable or critical), descend the potential energy from it along its unstable direction and
  // converge by the shooting method's Newton iteration (solver/shooting/stable_equilibrium.h);
  // the answer is then that equilibrium (method shooting) and stable_search says what was done,
  // or it is not converged with the reason. For given loads only (not theta0 or b/l), dead
  // loads only (InvalidInput otherwise).
  bool stable = false;

  // The segment chain this problem describes (the given chain, or Howell's uniform cantilever with
  // Fx = -n alpha2, Fy = alpha2, M = mu, the follower force and the end condition). Throws
  // InvalidInput when a prescribed tip coordinate has a load on it.
  SegmentChain to_chain(double alpha2) const;
  bool is_plain_cantilever() const {
    return !chain && boundary == EndCondition::kFree && follower == 0.0;
  }
};

// A method-independent summary of one solve (the keys of `flexure beam --json`).
struct BeamSolution : SolveStatus {
  BeamMethod method = BeamMethod::kElliptic;  // the method actually used (what auto resolved to)
  std::string method_reason;                  // why that method: requested, or auto's reasoning
  // The relative tip error the method that answered is known to stay within (MethodResolution);
  // NaN where none is known (chain, PRBM off its measured map).
  double expected_error = std::numeric_limits<double>::quiet_NaN();
  // The ladder's models (linear, prbm, prbm3r, bcm, cbcm) on a free cantilever the model ladder's
  // map covers: the mapped bound on |tip - exact tip| per length (beam_auto_ladder.h); NaN
  // otherwise. expected_error is then the relative bound it gives with the answer's displacement.
  double expected_error_per_length = std::numeric_limits<double>::quiet_NaN();
  // Every method tried, in order (auto tries a second when the first fails); the last is `method`.
  std::vector<BeamMethod> methods_tried;
  // Howell's load parameters (eqs. 2.67, 2.83). For a chain given as a whole they exist only when
  // it is uniform (flexible segments of one constant EI, straight, total length L): alpha2 = Fy
  // L^2/EI, n = -Fx/Fy, mu = M L/EI; otherwise NaN (no single alpha2), and root_moment and
  // reactions are NaN too: chain_root_moment and chain_reactions hold them in the chain's own
  // units.
  double alpha2 = 0.0;
  double load_ratio_n = 0.0;
  double mu = 0.0;
  TipPose tip;
  std::string branch;  // the equilibrium returned, in words (for people; code reads the counts)
  int inflection_points = 0;
  double root_moment = 0.0;
  std::string family;
  double tolerance = 0.0;  // the method's convergence tolerance (recorded in output files)
  std::vector<ShapePoint> shape;
  Reaction reactions;        // at the root
  int elements = 0;          // chain algorithm only (0 otherwise)
  int increments = 0;        // chain algorithm only: increments taken
  double load_factor = 1.0;  // load factor reached (1 when converged)
  // Inverse problems: |tip quantity - target| at the returned load; NaN for a forward problem. A
  // converged inverse always has it within the method's stated tolerance.
  double target_residual = std::numeric_limits<double>::quiet_NaN();
  // Folds of the load factor on the path from the unloaded beam (snap-through under load
  // control at the first); elliptic and shooting only.
  int limit_points = 0;
  double first_limit_load_factor = 0.0;
  // Shooting only: the limit points and bifurcation points its continuation passed, located on the
  // path (solver/shooting/continuation.h), in Howell's units (the chain's for a chain file) with
  // the tip per unit length; `special_points_known` false for the other methods and for answers
  // whose path is not the shooting method's own (a direct Newton solve of a provably unique
  // equilibrium passes none, a sweep's neighbour start does not trace it).
  bool special_points_known = false;
  std::vector<SpecialPoint> special_points;
  // Chains given as a whole: the tip load, root moment and clamp reactions in the chain's units.
  Reaction chain_tip_load;
  double chain_root_moment = 0.0;
  Reaction chain_reactions;
  // PRBM only: the PRB angle (rad), the validity limit it is checked against (rad, the smaller of
  // Theta_max(gamma) and Theta_max(K_theta), Howell eqs. 5.47 and 5.63), where that limit comes
  // from, and whether |Theta| is within it.
  double prbm_Theta = 0.0;
  double prbm_theta_max = 0.0;
  std::string prbm_limits_source;
  bool prbm_inside_validity = false;
  // The cheaper models of the ladder (beam_ladder.h): the PR-3R constants used; the BCM's and
  // CBCM's largest element deflection |y|/element length (NaN for the others), whether it is within
  // the BCM's stated 0.1, the slenderness L/t given (0: none) and the axial stiffness
  // d = EA L^2/EI solved with (from the slenderness or a chain segment's EA; infinity: the
  // inextensible beam, NaN: not a BCM).
  std::string model_constants;
  double max_element_deflection = std::numeric_limits<double>::quiet_NaN();
  bool model_inside_validity = true;
  double slenderness = 0.0;
  double axial_stiffness_d = std::numeric_limits<double>::quiet_NaN();
  // The stability verdict of the returned equilibrium under the problem's loads and supports
  // (docs/stability.md): the discrete second variation for elliptic, shooting and the chain
  // algorithm, d^2V/dTheta^2 of the PRBM's energy for the PRBM; not_conservative for a follower
  // force, not_checked when the solve failed or judge_stability is off. An unstable answer is
  // still the documented proportional-loading answer, now labelled.
  Stability stability;
  // BeamProblem::stable: what the search for a stable equilibrium did (empty when not asked), and
  // whether its result replaced the proportional-loading answer (the answer is then off the path).
  std::string stable_search;
  bool off_path = false;
};

// The method `auto` resolves to for this problem: the cheapest whose error is within
// problem.tolerance (PRBM inside its validity limits and measured accuracy, else elliptic for
// Howell's free cantilever, else shooting), with the reason (choose_beam_method). A named method
// resolves to itself.
struct MethodResolution {
  BeamMethod method = BeamMethod::kElliptic;
  std::string reason;
  // The relative tip error the method is known to stay within (choose_beam_method); NaN where it
  // depends on the discretisation (chain) or is not measured (PRBM off the map).
  double expected_error = std::numeric_limits<double>::quiet_NaN();
};
// `ladder_verdict`: why auto's pass over the model ladder (beam_auto_ladder.h) took no cheap
// model; when given, the 1R PRBM has been judged there and is not considered again.
MethodResolution resolve_beam_method(BeamMethod method,
                                     const BeamProblem& problem,
                                     const std::string& ladder_verdict = {});
// Without a problem (sweeps over alpha2): auto = elliptic.
BeamMethod resolve_beam_method(BeamMethod method);

// Solves `problem` with `method`. Throws InvalidInput for bad input or a problem the method does
// not solve (OutsideMethodDomain for a load beyond its range); a failed solve returns converged()
// false and a message. The answer carries its stability verdict; with problem.stable an answer
// that is not stable is replaced by a stable equilibrium (or not converged when none is found).
// With kAuto, a load beyond the elliptic solver's range, or a solve of the chosen method that does
// not converge, goes to the shooting method (it follows the load path past limit points);
// method_reason then says which method answered and why.
BeamSolution solve_beam(BeamMethod method, const BeamProblem& problem);

// The shooting method's part of solve_beam for a forward problem, split so that a sweep can start
// each point from its neighbour (beam_sweep_solver.h): the solver's options for `problem` (the
// shape at `shape_points` points, 0 for none; the inflection points counted without a shape),
// and a result at load alpha2 as the BeamSolution solve_beam returns (with its stability verdict
// per problem.judge_stability, and with problem.stable a stable equilibrium searched from it).
// `margin_guess`: the sweep's prediction of the stability margin from its neighbours', where the
// compressed cantilever's Jacobi verdict starts its search (compressed_cantilever_stability.h;
// the same verdict, fewer integrations).
ShootingSolver::Options beam_shooting_options(const BeamProblem& problem, int shape_points);
BeamSolution beam_solution_from_shooting(const BeamProblem& problem,
                                         double alpha2,
                                         const ShootingResult& r,
                                         int shape_points,
                                         std::optional<double> margin_guess = std::nullopt);

}  // namespace flexure

namespace flexure {

class BeamSolver {
 public:
  struct Options {
    BeamMethod method = BeamMethod::kAuto;
    // auto: the relative tip error allowed when it chooses a method (choose_beam_method).
    double auto_tolerance = 1e-6;
    // Shooting: the integrator of the flexible segments (GSL's Prince-Dormand 8(7) by default).
    IntegratorBackend integrator = IntegratorBackend::kRk8pd;
    int elements = 100;  // chain algorithm: N elements (Howell sec. 5.11)
    int increments = 1;  // chain algorithm: load increments to start with (halved on failure)
    ChainVariant chain_variant = ChainVariant::kCorrected;
    int shape_points = 0;  // 0: no shape; otherwise >= 2 points from s = 0 to s = 1
    // The model ladder (beam_ladder.h): the chained BCM's elements, the PR-3R constants, the
    // slenderness L/t of the BCM and CBCM (0: inextensible).
    int cbcm_elements = 6;
    Prbm3rConstantSet prbm3r_constants = Prbm3rConstantSet::kSu;
    double slenderness = 0.0;
    bool judge_stability = true;  // the stability verdict of the answer (docs/stability.md)
    bool stable = false;          // return a stable equilibrium (BeamProblem::stable)
    // Throws InvalidInput naming the setting and its allowed range.
    void validate() const;
  };

  BeamSolver() : BeamSolver(Options{}) {}
  explicit BeamSolver(Options options);

  const Options& options() const { return options_; }
  // solve_beam(options.method, problem) with the problem's settings replaced by the Options.
  BeamSolution solve(const BeamProblem& problem) const;

 private:
  Options options_;
};

// The Options a problem's own settings amount to (for a caller of solve_beam moving to
// BeamSolver).
BeamSolver::Options beam_solver_options(BeamMethod method, const BeamProblem& problem);

}  // namespace flexure

namespace flexure {

struct AutoMethodRequest {
  double load_ratio_n = 0.0;
  double alpha2 = 0.0;  // NaN when the load is not given (inverse problems)
  double mu = 0.0;
  bool plain_cantilever = true;  // free end, dead loads, uniform straight beam
  double tolerance = 1e-6;       // relative error allowed (tip position error / deflection)
  // Set when auto's pass over the model ladder (beam_auto_ladder.h) has judged the cheap models,
  // the 1R PRBM among them, at this load and taken none: why, for the reason; the PRBM is then not
  // considered again.
  std::string ladder_verdict;
};

struct AutoMethodChoice {
  BeamMethod method = BeamMethod::kElliptic;  // kPrbm, kElliptic or kShooting
  std::string reason;                         // one sentence: why this method and not a cheaper one
  double expected_error = 0.0;  // the error bound the choice rests on (relative tip error)
};

// The relative tip errors (|tip - exact tip| / tip displacement, the measure of the tolerance) the
// exact methods are known to stay within (docs/benchmarks.md). Forward problems: the elliptic
// solver's scalar solves converge to 1e-14 relative (bound 1e-13); the shooting method at rtol
// 1e-12 is measured below 1e-9 on the benchmark set. Inverse problems end when the tip quantity
// is within 1e-10 (elliptic) or 1e-8 (shooting) of its target (solve_beam), which bounds them.
inline constexpr double kEllipticErrorBound = 1e-13;
inline constexpr double kEllipticInverseErrorBound = 1e-10;
inline constexpr double kShootingErrorBound = 1e-9;
inline constexpr double kShootingInverseErrorBound = 1e-8;
// The bound of an exact method (kElliptic or kShooting; NaN for the others, whose error depends on
// the load and the discretisation).
double exact_method_error_bound(BeamMethod method, bool inverse);

// A tolerance below what every method that can answer reaches: the answer would miss it, so the
// problem is refused before any solve (exit code 2). Names the smallest tolerance that can be met.
class ToleranceBelowReach : public InvalidInput {
 public:
  ToleranceBelowReach(const std::string& message, double best_tolerance, std::string best_method)
      : InvalidInput(message),
        best_tolerance_(best_tolerance),
        best_method_(std::move(best_method)) {}
  double best_tolerance() const { return best_tolerance_; }
  const std::string& best_method() const { return best_method_; }  // "elliptic", "exact", ...

 private:
  double best_tolerance_;
  std::string best_method_;
};

// Throws ToleranceBelowReach when `tolerance` is below the bound of `method` (an exact method that
// auto falls back to).
void require_tolerance_within_reach(double tolerance, BeamMethod method, bool inverse);

// Throws InvalidInput unless the tolerance is finite and > 0, and ToleranceBelowReach when it is
// below the error bound of the most accurate method for this problem.
AutoMethodChoice choose_beam_method(const AutoMethodRequest& request);

// The PRBM's relative tip-position error measured by `flexure bench` for the fixed-pinned segment
// at (n, alpha2): 1.5 times the largest value at the measured loads around it
// (data/method_auto_error_map.csv, compiled into the library). NaN outside the measured range
// (-2 <= n <= 3, 0.5 <= alpha2 <= 20).
double prbm_measured_error(double load_ratio_n, double alpha2);

}  // namespace flexure

// Compatibility: the method choice was in namespace flexure::bench while it lived in the studies
// layer (issue 28 moved it to the beam layer). Existing code that names bench:: keeps compiling.
namespace flexure::bench {
using flexure::AutoMethodChoice;
using flexure::AutoMethodRequest;
using flexure::choose_beam_method;
using flexure::exact_method_error_bound;
using flexure::kEllipticErrorBound;
using flexure::kEllipticInverseErrorBound;
using flexure::kShootingErrorBound;
using flexure::kShootingInverseErrorBound;
using flexure::prbm_measured_error;
using flexure::require_tolerance_within_reach;
using flexure::ToleranceBelowReach;
}  // namespace flexure::bench
