#pragma once
// Howell's chain algorithm (Compliant Mechanisms §7.2) with load increments (eqs. 7.24-7.27) and
// the shooting method of §7.2.1 for tip boundary conditions other than a free end.
//
// Theory, accuracy and measured convergence orders: docs/theory-chain.md. In short:
//   * kHowell reproduces the book: one chain pass per load increment with moment arms from the
//     previous increment's geometry, then passes at full load until the geometry stops changing.
//     Without that final iteration the error is first order in 1/increments; with it the answer
//     is the fixed point, whose error is second order in 1/N. With prescribed tip coordinates it
//     uses the same adaptive, converged continuation as kCorrected (with Howell's passes).
//   * kCorrected iterates the moment arms to convergence inside every increment (a converged load
//     path with adaptive steps) and keeps each element's arc length (foreshortening); its error is
//     third order in 1/N, also for curved (kappa0) and tapered (EI profile) segments.
//   Options::accelerate (both variants) converges the passes at a fixed load with Anderson
//   acceleration and the element's own rotation in its moment arms; the fixed point is the same.
//
// Usage: ChainResult r = solve_chain(chain, options);  or
// ChainAlgorithmSolver(options).solve(load).
#include <string>
#include <vector>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/status.h"

namespace flexure {

enum class ChainVariant {
  kHowell,     // Howell §7.2 as printed: eqs. 7.17-7.18, increments, then iterate at full load
  kCorrected,  // converged at every increment; foreshortening, curved and tapered element terms
};
const char* to_string(ChainVariant variant);
// Accepts "howell" and "corrected"; throws InvalidInput naming the allowed values otherwise.
ChainVariant chain_variant_from_string(const std::string& name);

// One point of the load path: the state after a successful load increment.
struct ChainLoadPathPoint {
  double load_factor = 0.0;  // lambda in (0, 1]
  ChainPose tip;
  int iterations = 0;  // chain passes spent on this increment (including shooting evaluations)
};

struct ChainResult : SolveStatus {
  // message: what stopped the solve and how far it got
  // iterations: chain passes in total (all increments, retries and shooting evaluations)
  int increments = 0;         // load increments that succeeded
  int failed_increments = 0;  // increments that failed and were retried with a smaller step
  int newton_iterations = 0;  // corrections of the tip reactions (eqs. 7.38-7.40), summed: one per
                              // constrained iteration (Options::constrained_passes) or Newton step
  double load_factor = 0.0;   // load factor reached (1 when converged)
  // residual: geometry change of the last pass (positions / total length, rad)
  double boundary_residual = 0.0;  // max |tip coordinate - prescribed value| (scaled as above)
  int elements = 0;                // flexible elements used (the requested N)

  ChainPose tip;                  // tip position and tangent angle
  TipPose tip_pose;               // the same as Howell's a/l, b/l, theta0 (l = total length)
  Reaction tip_reaction;          // shooting unknowns: load the tip support exerts (zero if free)
  Reaction root_reaction;         // load the clamp exerts on the chain (moment about the origin)
  double root_moment = 0.0;       // bending moment at the clamp, m(0) = -root_reaction.M
  std::vector<ShapePoint> nodes;  // every element node, s = arc length from the root
  std::vector<ChainLoadPathPoint> load_path;
  // The verdict of the converged nodes (equilibrium_stability with tip_reaction, every end
  // condition; docs/stability.md). An unstable one is refused (converged() false, the verdict
  // kept here): the passes also converge to unstable equilibria the load path never reaches, so
  // the chain algorithm cannot vouch that one is the proportional-loading answer.
  // not_checked when the solve stopped before.
  Stability stability;
};

class ChainAlgorithmSolver {
 public:
  struct Options {
    // Throws InvalidInput naming the first field outside its range.
    void validate() const;

    int elements = 100;  // N, elements over the flexible segments (rigid links add one each)
    // Load increments n_inc (eq. 7.27) to start with: the first step is 1/n_inc of the load and no
    // step is longer; a step whose passes fail (no convergence, a buckled element, shooting
    // failure, a node turned by more than max_angle_step) is halved, so increments are added only
    // where the path needs them. Howell's variant with a free end takes exactly n_inc book
    // increments (one pass each) before its iteration at full load, whose convergence does not
    // depend on n_inc (docs/theory-chain.md §4).
    int increments = 1;
    ChainVariant variant = ChainVariant::kCorrected;  // see the header comment
    double tolerance = 1e-12;  // passes stop when positions/total length and angles change less
    // Adaptive steps before the last: pass tolerance (and 100x that for the tip conditions).
    double path_tolerance = 1e-9;
    int max_iterations = 2000;  // passes per converged evaluation (an increment, or full load)
    bool iterate_at_full_load = true;  // kHowell: false returns the last increment unconverged
    // Adaptive steps: a failed step is halved down to this, then the solve stops.
    double min_load_step = 1e-5;
    // Adaptive steps: a step that turns any node by more than this (rad) counts as failed, because
    // a large jump may land on another equilibrium branch (near buckling, 1.5 rad let the passes
    // settle on the mirror image: n = 13.48, alpha2 = 2.42 gave theta0 = -3.19 for 3.04).
    double max_angle_step = 0.25;
    double shooting_tolerance = 1e-10;  // |tip coordinate - prescribed| (scaled as residual)
    // Prescribed tip coordinates: the passes meet them as they go, the reactions corrected by
    // every pass (chain_constrained.h; the same discrete equilibrium). false: the shooting method
    // of §7.2.1 as printed, Newton on the reactions around fully converged passes of the chain
    // with a free end, which needed over a million passes for a guided end under compression
    // (docs/theory-chain.md §5).
    bool constrained_passes = true;
    int max_newton_iterations = 30;  // per increment (constrained_passes = false only)
    // Converge the passes at a fixed load with Anderson acceleration and the implicit own
    // rotation of each element (chain_pass.h). The fixed point is the same; false gives Howell's
    // plain passes, whose convergence slows down badly as the load grows (57 passes at
    // alpha2 = 10, > 5000 at alpha2 = 200 for N = 100; docs/theory-chain.md §4).
    bool accelerate = true;
    int anderson_depth = 5;        // history length of the Anderson acceleration
    bool record_load_path = true;  // fill ChainResult::load_path
    // Adaptive path (corrected variant; Howell's with tip conditions): follow the load path on a
    // coarse chain (elements/8, at least 4 per flexible segment) and solve the requested chain in
    // one increment from its answer; if that increment fails (or turns a node by more than
    // max_angle_step) the path is followed on the requested chain. Same discrete equilibrium,
    // about 7x fewer element passes at alpha2 = 10 (docs/theory-chain.md §4). false: the path on
    // the requested chain only.
    bool coarse_path = true;
    // Self-checks of the converged shape (docs/theory-chain.md, "Self-checks"): no flexible
    // element may turn by more than this (rad) beyond its stress-free curvature, and no chord may
    // exceed its element's length. A failed check doubles the elements (up to max_elements) when
    // refine_elements is set, and is reported as not converged otherwise.
    double max_element_rotation = 0.2;
    bool refine_elements = true;
    // With refine_elements and the coarse path: the doublings the load needs are predicted from
    // the coarse chain's answer before the requested chain is solved, so that it is solved once
    // (docs/theory-chain.md, "Self-checks"). false: solve, check, double and solve again.
    bool predict_elements = true;
    int max_elements = 6400;
  };

  ChainAlgorithmSolver() = default;
  explicit ChainAlgorithmSolver(Options options) : options_(options) {}

  // Throws InvalidInput for an invalid chain or invalid options.
  ChainResult solve(const SegmentChain& chain) const;
  // Howell's nondimensional cantilever (l = 1, EI = 1) with a dead end load.
  ChainResult solve(const EndLoad& load) const;

  const Options& options() const { return options_; }

 private:
  ChainResult solve_once(const SegmentChain& chain, const Options& requested) const;
  Options options_;
};

// One-call entry point.
ChainResult solve_chain(const SegmentChain& chain,
                        const ChainAlgorithmSolver::Options& options = {});

}  // namespace flexure
