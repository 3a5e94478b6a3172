#include "flexure/benchmarks/studies/beam_problem.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "flexure/benchmarks/studies/method_selector.h"
#include "flexure/elements/prbm_cantilever.h"
#include "flexure/solver/common/errors.h"
#include "flexure/solver/elliptic/elliptic_solver.h"
#include "flexure/solver/inverse/tip_target.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {
namespace {

// Inverse problems of the numerical methods reach their target within this (times
// max(1, |target|)): their forward solves converge to about 1e-10 (Newton residual, chain passes).
constexpr double kNumericalInverseTolerance = 1e-8;

// Tip quantity used by the inverse problems.
double given_quantity(const BeamProblem& problem, const TipPose& tip) {
  return problem.given == BeamProblem::Given::kTheta0 ? tip.theta0 : tip.b_over_l;
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
  return solution;
}

// Interior sign changes of the curvature along a sampled shape (numerical methods).
int count_curvature_sign_changes(const std::vector<ShapePoint>& shape) {
  int changes = 0;
  double previous = 0.0;
  for (std::size_t i = 1; i < shape.size(); ++i) {
    const double d = shape[i].theta - shape[i - 1].theta;
    if (std::fabs(d) < 1e-12) continue;
    if (previous != 0.0 && (d > 0.0) != (previous > 0.0)) ++changes;
    previous = d;
  }
  return changes;
}

// Linear interpolation of a shape given at increasing s onto `count` equally spaced points.
std::vector<ShapePoint> resample(const std::vector<ShapePoint>& nodes, int count) {
  std::vector<ShapePoint> out;
  if (nodes.size() < 2 || count < 2) return out;
  const double s0 = nodes.front().s;
  const double s1 = nodes.back().s;
  std::size_t j = 0;
  for (int i = 0; i < count; ++i) {
    const double s = s0 + (s1 - s0) * i / (count - 1);
    while (j + 2 < nodes.size() && nodes[j + 1].s < s) ++j;
    const ShapePoint& a = nodes[j];
    const ShapePoint& b = nodes[j + 1];
    const double t = b.s > a.s ? (s - a.s) / (b.s - a.s) : 0.0;
    out.push_back(
        {s, a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.theta + t * (b.theta - a.theta)});
  }
  return out;
}

// The constant EI of a uniform straight chain of flexible segments, or nullopt.
std::optional<double> uniform_EI(const SegmentChain& chain) {
  std::optional<double> EI;
  for (const Segment& segment : chain.segments) {
    const auto* flexible = std::get_if<FlexibleSegment>(&segment);
    if (flexible == nullptr || !flexible->EI_profile.empty() || flexible->kappa0 != 0.0 ||
        flexible->beyond_elastica()) {
      return std::nullopt;
    }
    if (EI && *EI != flexible->EI) return std::nullopt;
    EI = flexible->EI;
  }
  return EI;
}

// A chain given as a whole: keeps its loads in its own units and states them in Howell's
// parameters where the chain has them (BeamSolution::alpha2).
void describe_chain_loads(const SegmentChain& chain, BeamSolution& s) {
  const TipLoad& tip = chain.tip_load;
  s.chain_tip_load = {tip.Fx, tip.Fy, tip.M};
  s.chain_root_moment = s.root_moment;
  s.chain_reactions = s.reactions;
  const std::optional<double> EI = uniform_EI(chain);
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  if (!EI || tip.follower != 0.0) {
    s.alpha2 = s.load_ratio_n = s.mu = s.root_moment = kNaN;
    s.reactions = {kNaN, kNaN, kNaN};
    return;
  }
  const double L = chain.total_length();
  const double force_scale = L * L / *EI, moment_scale = L / *EI;
  s.alpha2 = tip.Fy * force_scale;
  // + 0.0: no -0. An axial load alone (Fy = 0, Fx != 0) has no Howell's n (eq. 2.67).
  s.load_ratio_n = tip.Fy != 0.0   ? -tip.Fx / tip.Fy + 0.0
                   : tip.Fx == 0.0 ? 0.0
                                   : std::numeric_limits<double>::quiet_NaN();
  s.mu = tip.M * moment_scale;
  s.root_moment *= moment_scale;
  s.reactions = {
      s.reactions.Fx * force_scale, s.reactions.Fy * force_scale, s.reactions.M * moment_scale};
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

BeamSolution beam_solution_from_shooting(const BeamProblem& problem,
                                         double alpha2,
                                         const ShootingResult& r,
                                         int shape_points) {
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
  solution.inflection_points = std::max(r.inflection_points, 0);
  if (shape_points > 0 && r.converged()) {
    solution.shape = static_cast<int>(r.shape.size()) == shape_points
                         ? r.shape
                         : resample(r.shape, shape_points);
  }
  finish_numerical(problem, chain, solution);
  return solution;
}

namespace {

BeamSolution solve_numerical_forward(BeamMethod method,
                                     const BeamProblem& problem,
                                     double alpha2,
                                     int shape_points) {
  if (method == BeamMethod::kShooting) {
    const ShootingSolver::Options options = beam_shooting_options(problem, shape_points);
    const ShootingResult r = solve_shooting(problem.to_chain(alpha2), options);
    return beam_solution_from_shooting(problem, alpha2, r, shape_points);
  }
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
    const BeamSolution s = solve_numerical_forward(method, problem, alpha2, 0);
    if (!s.converged()) return std::nullopt;
    return s.tip;
  };
  const TipTargetSolution found = solve_tip_target(target, forward, kNumericalInverseTolerance);
  if (!found.converged()) {
    // What was reached is in the message; no further (possibly slow) solve at that load.
    BeamSolution missed;
    missed.method = method;
    missed.termination = found.termination;
    missed.alpha2 = found.alpha2;
    missed.iterations = found.forward_solves;
    missed.target_residual = found.residual;
    missed.message = found.message;
    return missed;
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

MethodResolution resolve_beam_method(BeamMethod method, const BeamProblem& problem) {
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
  const bench::AutoMethodChoice choice = bench::choose_beam_method(request);
  return {choice.method, choice.reason, choice.expected_error};
}

BeamMethod resolve_beam_method(BeamMethod method) {
  return method == BeamMethod::kAuto ? BeamMethod::kElliptic : method;
}

BeamSolution solve_beam(BeamMethod method, const BeamProblem& problem) {
  MethodResolution used = resolve_beam_method(method, problem);
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
  solution.methods_tried = std::move(tried);
  if (!problem.chain) {
    solution.load_ratio_n = problem.load_ratio_n;
    solution.mu = problem.mu;
  }
  return solution;
}

}  // namespace flexure
