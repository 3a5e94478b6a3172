#include "flexure/beam/beam_problem.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "flexure/beam/beam_auto_ladder.h"
#include "flexure/beam/beam_ladder.h"
#include "flexure/beam/beam_solution_parts.h"
#include "flexure/elements/prbm_cantilever.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/elliptic/elliptic_solver.h"
#include "flexure/solver/inverse/tip_target.h"
#include "flexure/solver/shooting/compressed_cantilever_stability.h"
#include "flexure/solver/shooting/shooting_solver.h"
#include "flexure/solver/shooting/stable_equilibrium.h"
#include "flexure/solver/shooting/tension_stability.h"

namespace flexure {
namespace {

// Inverse problems of the numerical methods reach their target within this (times
// max(1, |target|)): their forward solves converge to about 1e-10 (Newton residual, chain passes).
constexpr double kNumericalInverseTolerance = 1e-8;

// Tip quantity used by the inverse problems.
double given_quantity(const BeamProblem& problem, const TipPose& tip) {
  return problem.given == BeamProblem::Given::kTheta0 ? tip.theta0 : tip.b_over_l;
}

// The verdict from a shape function (docs/stability.md): a shape that cannot be evaluated or a
// chain the verdict refuses leaves it not_checked with the reason (never a failed solve).
Stability judge(const SegmentChain& chain,
                const Reaction& support,
                const ShapeAtStations& shape,
                const StabilityOptions& options) {
  try {
    return equilibrium_stability(chain, support, shape, options);
  } catch (const NoConvergence& e) {
    return not_checked_stability(e.what());
  } catch (const InvalidInput& e) {
    return not_checked_stability(e.what());
  }
}

// The verdict in words, for messages: "unstable (index 1, stability margin -0.216)".
std::string verdict_words(const Stability& s) {
  if (!s.judged()) return std::string(stability_name(s.kind));
  return fmt::format(
      "{} (index {}, stability margin {:.6g})", stability_name(s.kind), s.index, s.margin);
}

// BeamProblem::stable: the answer is not stable, so a stable equilibrium is sought from it
// (solver/shooting/stable_equilibrium.h) and, when found, replaces it (method shooting, whose
// Newton iteration converged it); otherwise the solution is not converged and says why.
void seek_stable(const BeamProblem& problem,
                 const SegmentChain& chain,
                 const ShapeAtStations& start,
                 const Reaction& start_support,
                 int shape_points,
                 BeamSolution& solution) {
  // The chain algorithm cannot vouch that an unstable answer is the path's (its passes also
  // converge off the path), so it is not called that.
  const std::string before = fmt::format("the {} answer{} is {}",
                                         to_string(solution.method),
                                         solution.method == BeamMethod::kChain
                                             ? ""
                                             : ", the equilibrium reached by proportional loading,",
                                         verdict_words(solution.stability));
  StableEquilibriumOptions options;
  options.shooting.shape_points = std::max(shape_points, 401);
  options.shooting.backend = problem.integrator;
  const StableEquilibrium found = find_stable_equilibrium(chain, start, start_support, options);
  if (!found.converged()) {
    solution.set_converged(false);
    solution.stable_search = fmt::format("{}; {}", before, found.message);
    solution.message = fmt::format("no stable equilibrium found: {}", solution.stable_search);
    return;
  }
  const ShootingResult& r = found.equilibrium;
  const double length = chain.total_length();
  solution.method = BeamMethod::kShooting;
  solution.termination = Termination::kConverged;
  solution.iterations += found.iterations + r.iterations;
  solution.residual = r.residual;
  solution.tip = r.tip_pose(length);
  solution.reactions = {r.reaction.Fx, r.reaction.Fy, r.reaction.M};
  solution.root_moment = -r.reaction.M;
  solution.load_factor = 1.0;
  solution.tolerance = options.shooting.rtol;
  solution.family = "numerical";
  solution.elements = 0;
  solution.increments = 0;
  solution.branch = fmt::format(
      "a stable equilibrium off the proportional load path (energy descent from the path's "
      "{} answer, then Newton){}",
      stability_name(solution.stability.kind),
      limit_points_note(solution.limit_points, solution.first_limit_load_factor));
  solution.inflection_points = count_curvature_sign_changes(r.shape);
  // In the chain's units: the numerical methods scale it per unit length afterwards
  // (finish_numerical); the elliptic method's chain has length 1.
  solution.shape.clear();
  if (shape_points > 0) solution.shape = resample(r.shape, shape_points);
  solution.stable_search = fmt::format(
      "{}; {}; the result is {}", before, found.message, verdict_words(found.stability));
  solution.message = fmt::format("a stable equilibrium: {}", found.message);
  solution.stability = found.stability;
  solution.off_path = true;
}

// An answer left unjudged because the verdict is off says so.
void label_unjudged(const BeamProblem& problem, BeamSolution& solution) {
  if (!problem.judge_stability && !problem.stable &&
      solution.stability.kind == StabilityKind::kNotChecked) {
    solution.stability = not_checked_stability("the verdict was switched off (--stability off)");
  }
}

// Whether BeamProblem::stable asks for a search from this answer.
bool wants_stable_search(const BeamProblem& problem, const BeamSolution& solution) {
  return problem.stable && solution.converged() && !solution.stability.stable();
}

BeamSolution solve_elliptic(const BeamProblem& problem) {
  if (!problem.is_plain_cantilever()) {
    throw InvalidInput(
        "the elliptic method solves the uniform cantilever with a free end and dead loads only; "
        "the shooting or chain method solves other end conditions, follower forces and chains");
  }
  const EllipticSolver solver;
  EllipticResult result;
  switch (problem.given) {
    case BeamProblem::Given::kAlpha2:
      result = solver.solve(EndLoad::howell(problem.load_ratio_n, problem.value, problem.mu));
      break;
    case BeamProblem::Given::kTheta0:
      result = solver.solve_for_tip_angle(problem.load_ratio_n, problem.value, problem.mu);
      break;
    case BeamProblem::Given::kBOverL:
      result = solver.solve_for_deflection(problem.load_ratio_n, problem.value, problem.mu);
      break;
  }
  BeamSolution solution;
  solution.method = BeamMethod::kElliptic;
  solution.termination = result.termination;
  solution.message = result.message;
  solution.iterations = result.iterations;
  // Howell's alpha2 is the transverse component P l^2/EI = Fy (eq. 2.83, EndLoad::howell).
  solution.alpha2 = result.load.Fy;
  solution.tip = result.tip;
  solution.branch = result.branch;
  solution.inflection_points = result.inflection_points;
  solution.root_moment = result.root_moment;
  solution.family = to_string(result.parameters.family);
  solution.tolerance = solver.options().tolerance;
  // The clamp holds the tip loads: -F, and the moment -M(0) (statics of the whole beam).
  solution.reactions = {-result.load.Fx, -result.load.Fy, -result.root_moment};
  solution.load_factor = result.converged() ? 1.0 : 0.0;
  solution.limit_points = result.limit_points;
  solution.first_limit_load_factor = result.first_limit_load_factor;
  if (problem.given != BeamProblem::Given::kAlpha2) {
    solution.target_residual = std::fabs(given_quantity(problem, result.tip) - problem.value);
  }
  if (result.converged() && problem.shape_points > 0) {
    solution.shape = solver.shape(result, problem.shape_points);
  }
  if (result.converged() && (problem.judge_stability || problem.stable)) {
    const SegmentChain chain = uniform_cantilever(result.load);
    const ShapeAtStations shape = [&](const std::vector<double>& s) {
      return solver.shape_at(result, s);
    };
    // A shape without inflection nowhere compressed: margin 1 from the tip angle alone, no
    // eigenproblem (tension_stability.h; 15 us of the 18 us of a scalar answer,
    // docs/performance.md); otherwise the discrete second variation.
    const std::optional<Stability> fast = tensioned_cantilever_stability(
        chain, result.tip.theta0, result.inflection_points, problem.stability_options);
    solution.stability = fast ? *fast : judge(chain, Reaction{}, shape, problem.stability_options);
    if (wants_stable_search(problem, solution)) {
      seek_stable(problem, chain, shape, Reaction{}, problem.shape_points, solution);
    }
  }
  return solution;
}

// The PRBM of the cantilever (elements/prbm_cantilever.h): fixed-pinned, end-moment or
// fixed-guided segment, whichever models the end and the load.
BeamSolution solve_prbm(const BeamProblem& problem) {
  if (problem.chain || problem.follower != 0.0 || problem.given != BeamProblem::Given::kAlpha2 ||
      problem.prescribed.x || problem.prescribed.y || problem.prescribed.theta) {
    throw InvalidInput(
        "the PRBM method solves the uniform cantilever for a given load alpha2 (free or guided "
        "end, dead loads, the stress-free tip of the end condition); the elliptic or shooting "
        "method solves the others");
  }
  const PrbmCantileverSolution prbm =
      solve_prbm_cantilever(problem.boundary, problem.load_ratio_n, problem.value, problem.mu);
  const EndLoad load = EndLoad::howell(problem.load_ratio_n, problem.value, problem.mu);
  BeamSolution solution;
  solution.method = BeamMethod::kPrbm;
  solution.termination = prbm.termination;
  solution.message = prbm.message;
  solution.iterations = prbm.iterations;
  solution.residual = prbm.residual;
  solution.alpha2 = problem.value;
  solution.tip = prbm.tip;
  solution.family = "prbm";
  solution.tolerance = beam_method_tolerance(BeamMethod::kPrbm);
  solution.branch = fmt::format("PRBM {} ({}), Theta = {:.4f} rad, {} the validity limits",
                                prbm.element,
                                prbm.constants_source,
                                prbm.Theta,
                                prbm.inside_validity ? "inside" : "OUTSIDE");
  solution.prbm_Theta = prbm.Theta;
  solution.prbm_theta_max = prbm.limits.theta_max();
  solution.prbm_limits_source = prbm.limits.source;
  solution.prbm_inside_validity = prbm.inside_validity;
  solution.root_moment = prbm.root_moment;
  solution.inflection_points = prbm.inflection_points;
  // The clamp holds the tip loads and the root moment (statics of the whole beam); a guided end
  // carries the other end moment, equal and opposite (Howell eq. 5.106).
  solution.reactions = {-load.Fx, -load.Fy, -solution.root_moment};
  solution.load_factor = prbm.converged() ? 1.0 : 0.0;
  if (problem.judge_stability || problem.stable) solution.stability = prbm.stability;
  if (wants_stable_search(problem, solution)) {
    // The PRBM's first root met from the unloaded angle is a minimum of its energy (the energy's
    // slope changes sign from falling to rising there), so this is a critical tangency at most.
    solution.set_converged(false);
    solution.stable_search = fmt::format(
        "the PRBM's equilibrium is {}; the search for a stable equilibrium follows the exact "
        "methods' equilibria only (method elliptic or shooting)",
        verdict_words(solution.stability));
    solution.message = fmt::format("no stable equilibrium found: {}", solution.stable_search);
  }
  return solution;
}

// What every numerical forward solve ends with: a chain's loads in its own units, and the shape
// per unit length of the chain (Howell's a/l, b/l are).
void finish_numerical(const BeamProblem& problem, const SegmentChain& chain, BeamSolution& s) {
  if (problem.chain) describe_chain_loads(chain, s);
  const double length = chain.total_length();
  for (ShapePoint& p : s.shape) {
    p.s /= length;
    p.x /= length;
    p.y /= length;
  }
}

}  // namespace

ShootingSolver::Options beam_shooting_options(const BeamProblem& problem, int shape_points) {
  ShootingSolver::Options options;
  options.shape_points = shape_points;
  // The inflection points from the moment along the integration, not from a sampled shape (a
  // shape of 401 points cost about as much as the solve, docs/performance.md).
  options.count_inflections = true;
  options.backend = problem.integrator;
  return options;
}

namespace {

// beam_solution_from_shooting; `final_answer` false for the forward solves of an inverse
// problem's search, which are not judged (only the answer is); `margin_guess` the sweep's
// prediction of the stability margin (compressed_cantilever_stability.h).
BeamSolution shooting_solution(const BeamProblem& problem,
                               double alpha2,
                               const ShootingResult& r,
                               int shape_points,
                               bool final_answer,
                               std::optional<double> margin_guess = std::nullopt) {
  const SegmentChain chain = problem.to_chain(alpha2);
  BeamSolution solution;
  solution.method = BeamMethod::kShooting;
  solution.alpha2 = alpha2;
  solution.family = "numerical";
  solution.termination = r.termination;
  solution.message = r.message;
  solution.iterations = r.iterations;
  solution.tip = r.tip_pose(chain.total_length());
  solution.reactions = {r.reaction.Fx, r.reaction.Fy, r.reaction.M};
  solution.root_moment = -r.reaction.M;
  solution.load_factor = r.load_factor;
  solution.tolerance = beam_shooting_options(problem, 0).rtol;
  switch (r.path) {
    case ShootingPath::kContinuation:
      solution.branch = fmt::format(
          "proportional loading (pseudo-arclength continuation, {} steps)", r.continuation_steps);
      break;
    case ShootingPath::kTwoStageContinuation:
      solution.branch = fmt::format(
          "proportional loading (two-stage pseudo-arclength continuation, {} steps in the "
          "first stage)",
          r.continuation_steps);
      break;
    case ShootingPath::kDirectNewton:
      solution.branch = "unique equilibrium (direct Newton; contraction bound below 1)";
      break;
    case ShootingPath::kNewtonFromGuess:
      solution.branch = "Newton from a given guess";
      break;
    case ShootingPath::kFromNeighbour:
      // The caller (beam_sweep_solver.cpp) says why this is the proportional-loading branch.
      solution.branch = "Newton from the neighbouring load";
      break;
  }
  solution.limit_points = r.limit_points;
  solution.first_limit_load_factor = r.first_limit_load_factor;
  solution.branch += limit_points_note(r.limit_points, r.first_limit_load_factor);
  // The continuation's located special points (a direct Newton solve of a unique equilibrium has
  // none to pass; a neighbour's start did not trace the path).
  solution.special_points_known = r.path != ShootingPath::kFromNeighbour;
  solution.special_points = r.special_points;
  solution.inflection_points = std::max(r.inflection_points, 0);
  if (shape_points > 0 && r.converged()) {
    solution.shape = static_cast<int>(r.shape.size()) == shape_points
                         ? r.shape
                         : resample(r.shape, shape_points);
  }
  if (r.converged() && final_answer && (problem.judge_stability || problem.stable)) {
    // The shape at the verdict's stations, integrated from the result's unknowns with the
    // options of the solve (the shape_points requested do not matter to it).
    const ShootingSolver::Options options = beam_shooting_options(problem, 0);
    const Reaction support = tip_support_reaction(chain, r.tip_load);
    const ShapeAtStations shape = [&](const std::vector<double>& s) {
      return shooting_shape_at(chain, r, s, options);
    };
    // A uniform cantilever nowhere compressed: margin 1 from the solve's own moment, no
    // eigenproblem (tension_stability.h); compressed, the Jacobi equation along the solution
    // (compressed_cantilever_stability.h); other chains the discrete second variation.
    std::optional<Stability> fast =
        tensioned_cantilever_stability(chain, r, problem.stability_options);
    if (!fast) {
      fast = compressed_cantilever_stability(chain, r, problem.stability_options, margin_guess);
    }
    solution.stability = fast ? *fast : judge(chain, support, shape, problem.stability_options);
    if (wants_stable_search(problem, solution)) {
      seek_stable(problem, chain, shape, support, shape_points, solution);
    }
  }
  finish_numerical(problem, chain, solution);
  label_unjudged(problem, solution);
  return solution;
}

BeamSolution solve_numerical_forward(BeamMethod method,
                                     const BeamProblem& problem,
                                     double alpha2,
                                     int shape_points,
                                     bool final_answer = true) {
  if (method == BeamMethod::kShooting) {
    const ShootingSolver::Options options = beam_shooting_options(problem, shape_points);
    const ShootingResult r = solve_shooting(problem.to_chain(alpha2), options);
    return shooting_solution(problem, alpha2, r, shape_points, final_answer);
  }
  // Only the answer is judged (not the forward solves of an inverse problem's search).
  const bool judge_it = final_answer && (problem.judge_stability || problem.stable);
  const SegmentChain chain = problem.to_chain(alpha2);
  BeamSolution solution;
  solution.method = method;
  solution.alpha2 = alpha2;
  solution.family = "numerical";
  ChainAlgorithmSolver::Options options;
  options.elements = problem.elements;
  options.increments = problem.increments;
  options.variant = problem.chain_variant;
  const ChainResult r = solve_chain(chain, options);
  solution.termination = r.termination;
  solution.message = r.message;
  solution.iterations = r.iterations;
  solution.tip = r.tip_pose;
  solution.reactions = {r.root_reaction.Fx, r.root_reaction.Fy, r.root_reaction.M};
  solution.root_moment = r.root_moment;
  solution.load_factor = r.load_factor;
  solution.tolerance = options.tolerance;
  solution.elements = r.elements;
  solution.increments = r.increments;
  solution.branch = fmt::format("proportional loading ({} load increments, {} variant)",
                                r.increments,
                                to_string(options.variant));
  solution.inflection_points = count_curvature_sign_changes(r.nodes);
  if (shape_points > 0 && r.converged()) solution.shape = resample(r.nodes, shape_points);
  if (judge_it) solution.stability = r.stability;
  // The chain refuses an unstable answer (chain_algorithm_solver.h) but keeps its verdict and
  // nodes: a valid equilibrium to start the search for a stable one from.
  const bool refused_unstable =
      !r.converged() && r.stability.kind == StabilityKind::kUnstable && r.nodes.size() >= 2;
  if (judge_it && problem.stable && (refused_unstable || wants_stable_search(problem, solution))) {
    if (refused_unstable) solution.set_converged(true);  // the search decides
    seek_stable(
        problem, chain, interpolated_shape(r.nodes), r.tip_reaction, shape_points, solution);
  }
  finish_numerical(problem, chain, solution);
  return solution;
}

BeamSolution solve_numerical(BeamMethod method, const BeamProblem& problem) {
  if (problem.given == BeamProblem::Given::kAlpha2 || problem.chain) {
    return solve_numerical_forward(method, problem, problem.value, problem.shape_points);
  }
  if (problem.boundary != EndCondition::kFree) {
    throw InvalidInput(fmt::format(
        "a given tip angle theta0 or deflection b/l finds the load of a free cantilever; with a "
        "{} end give the load alpha2 and prescribe the tip coordinates instead",
        to_string(problem.boundary)));
  }
  TipTarget target;
  target.quantity = problem.given == BeamProblem::Given::kTheta0 ? TipTarget::Quantity::kTheta0
                                                                 : TipTarget::Quantity::kBOverL;
  target.value = problem.value;
  target.load_ratio_n = problem.load_ratio_n;
  target.mu = problem.mu;
  auto forward = [&](double alpha2) -> std::optional<TipPose> {
    const BeamSolution s = solve_numerical_forward(method, problem, alpha2, 0, false);
    if (!s.converged()) return std::nullopt;
    return s.tip;
  };
  const TipTargetSolution found = solve_tip_target(target, forward, kNumericalInverseTolerance);
  if (!found.converged()) {
    // What was reached is in the message; no further (possibly slow) solve at that load.
    return missed_inverse_solution(method, found);  // beam_solution_parts.h
  }
  BeamSolution solution =
      solve_numerical_forward(method, problem, found.alpha2, problem.shape_points);
  solution.iterations += found.forward_solves;
  solution.target_residual = std::fabs(given_quantity(problem, solution.tip) - problem.value);
  if (!found.converged() || !(solution.target_residual <= found.tolerance)) {
    // Never a load that misses its target with exit code 0: report what was reached.
    solution.set_converged(false);
    solution.message = fmt::format("{} (reached {} = {:.9g} at alpha2 = {:.9g}, target {:.9g})",
                                   found.message,
                                   target.name(),
                                   given_quantity(problem, solution.tip),
                                   found.alpha2,
                                   problem.value);
  }
  return solution;
}

}  // namespace

BeamSolution beam_solution_from_shooting(const BeamProblem& problem,
                                         double alpha2,
                                         const ShootingResult& r,
                                         int shape_points,
                                         std::optional<double> margin_guess) {
  return shooting_solution(problem, alpha2, r, shape_points, true, margin_guess);
}

SegmentChain BeamProblem::to_chain(double alpha2) const {
  if (chain) return *chain;
  SegmentChain c = uniform_cantilever(EndLoad::howell(load_ratio_n, alpha2, mu));
  c.tip_load.follower = follower;
  c.end = boundary;
  c.prescribed = prescribed;
  // A prescribed coordinate takes the place of its conjugate load (segment_chain.h).
  const PrescribedMask mask = prescribed_mask(boundary);
  const auto refuse_load = [&](bool prescribed,
                               double load,
                               const char* coordinate,
                               const char* load_name,
                               const char* reaction) {
    if (!prescribed || load == 0.0) return;
    throw InvalidInput(fmt::format(
        "a {} end prescribes the tip {}, so the {} must be 0 (got {:g}); the {} is an output",
        to_string(boundary),
        coordinate,
        load_name,
        load,
        reaction));
  };
  refuse_load(mask.x, c.tip_load.Fx, "x", "horizontal load n alpha2", "horizontal reaction");
  refuse_load(mask.y, c.tip_load.Fy, "y", "transverse load alpha2", "vertical reaction");
  refuse_load(mask.theta, c.tip_load.M, "angle", "end moment mu", "end moment");
  c.validate();
  return c;
}

MethodResolution resolve_beam_method(BeamMethod method,
                                     const BeamProblem& problem,
                                     const std::string& ladder_verdict) {
  const bool inverse = problem.given != BeamProblem::Given::kAlpha2;
  if (method != BeamMethod::kAuto) {
    return {method,
            fmt::format("requested: {}", to_string(method)),
            bench::exact_method_error_bound(method, inverse)};
  }
  bench::AutoMethodRequest request;
  request.load_ratio_n = problem.load_ratio_n;
  request.alpha2 = inverse ? std::numeric_limits<double>::quiet_NaN() : problem.value;
  request.mu = problem.mu;
  request.plain_cantilever = problem.is_plain_cantilever();
  request.tolerance = problem.tolerance;
  request.ladder_verdict = ladder_verdict;
  const bench::AutoMethodChoice choice = bench::choose_beam_method(request);
  return {choice.method, choice.reason, choice.expected_error};
}

BeamMethod resolve_beam_method(BeamMethod method) {
  return method == BeamMethod::kAuto ? BeamMethod::kElliptic : method;
}

BeamSolution solve_beam(BeamMethod method, const BeamProblem& problem) {
  if (problem.stable) {
    if (problem.given != BeamProblem::Given::kAlpha2 && !problem.chain) {
      throw InvalidInput(
          "a stable equilibrium is sought for given loads: with a given tip angle theta0 or "
          "deflection b/l the load is found from the proportional-loading path, and another "
          "equilibrium would miss the target; give the load alpha2 instead");
    }
    const double follower = problem.chain ? problem.chain->tip_load.follower : problem.follower;
    if (follower != 0.0) {
      throw InvalidInput(
          "a stable equilibrium is a minimum of the potential energy, and a follower force has "
          "none (its stability is a dynamic question): the search needs dead loads");
    }
  }
  // auto: the cheap models of the ladder first (beam_auto_ladder.h), then the exact methods.
  std::string ladder_verdict, off_ladder_map;
  if (method == BeamMethod::kAuto) {
    LadderAutoOutcome ladder = solve_by_ladder(problem);
    if (ladder.solution) return std::move(*ladder.solution);
    ladder_verdict = std::move(ladder.verdict);
    if (!ladder.judged && !ladder_verdict.empty()) off_ladder_map = ladder_verdict + "; ";
    if (!ladder.judged) ladder_verdict.clear();
  }
  MethodResolution used = resolve_beam_method(method, problem, ladder_verdict);
  used.reason = off_ladder_map + used.reason;
  const bool inverse = problem.given != BeamProblem::Given::kAlpha2;
  // auto's fallback answers to the tolerance too: refused (exit code 2) when the shooting method
  // cannot meet it, instead of an answer that misses it.
  const auto shooting_fallback = [&](const std::string& reason) {
    bench::require_tolerance_within_reach(problem.tolerance, BeamMethod::kShooting, inverse);
    used = {BeamMethod::kShooting,
            reason,
            bench::exact_method_error_bound(BeamMethod::kShooting, inverse)};
  };
  BeamSolution solution;
  std::vector<BeamMethod> tried{used.method};
  switch (used.method) {
    case BeamMethod::kElliptic:
      try {
        solution = solve_elliptic(problem);
      } catch (const OutsideMethodDomain& e) {
        if (method != BeamMethod::kAuto) throw;
        // auto: the load (or the target's load) lies beyond the elliptic solver's range; the
        // shooting solver has no such fixed limit.
        shooting_fallback(
            fmt::format("{}; the elliptic solver cannot answer ({})", used.reason, e.what()));
        tried.push_back(BeamMethod::kShooting);
        solution = solve_numerical(BeamMethod::kShooting, problem);
      }
      break;
    case BeamMethod::kShooting:
    case BeamMethod::kChain:
      solution = solve_numerical(used.method, problem);
      break;
    case BeamMethod::kPrbm:
      solution = solve_prbm(problem);
      break;
    case BeamMethod::kLinear:
    case BeamMethod::kPrbm3r:
    case BeamMethod::kBcm:
    case BeamMethod::kCbcm:
      solution = solve_ladder_model(used.method, problem);  // beam_ladder.h
      break;
    case BeamMethod::kAuto:
      throw InvalidInput("auto did not resolve to a method");  // resolve_beam_method never does
  }
  if (method == BeamMethod::kAuto && !solution.converged() &&
      used.method != BeamMethod::kShooting) {
    // auto falls back instead of giving up: the shooting method applies to every problem.
    const std::string failed = to_string(used.method);
    const std::string failure = solution.message;
    shooting_fallback(used.reason);
    tried.push_back(BeamMethod::kShooting);
    BeamSolution fallback = solve_numerical(BeamMethod::kShooting, problem);
    used.reason = fmt::format(
        "{}; the {} method did not converge ({}), so the shooting method was tried: "
        "{}",
        used.reason,
        failed,
        failure,
        fallback.converged() ? "it answered" : "it did not converge either");
    solution = std::move(fallback);
  }
  solution.method_reason = used.reason;
  solution.expected_error = used.expected_error;
  if (method != BeamMethod::kAuto) attach_mapped_error(problem, solution);  // beam_auto_ladder.h
  solution.methods_tried = std::move(tried);
  label_unjudged(problem, solution);
  if (problem.stable) {
    if (solution.stable_search.empty() && solution.converged()) {
      solution.stable_search = fmt::format(
          "not needed: the answer, the equilibrium reached by proportional loading, "
          "is {}",
          verdict_words(solution.stability));
    } else if (solution.converged() && solution.off_path) {
      solution.method_reason = fmt::format(
          "{}; its answer was not stable, so a stable equilibrium was sought from it: an energy "
          "descent along its unstable direction, converged by the shooting method's Newton "
          "iteration",
          used.reason);
    }
  }
  if (!problem.chain) {
    solution.load_ratio_n = problem.load_ratio_n;
    solution.mu = problem.mu;
  }
  return solution;
}

}  // namespace flexure
