#include "flexure/beam/beam_ladder.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "flexure/beam/beam_solution_parts.h"
#include "flexure/elements/ladder_models.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/inverse/tip_target.h"

namespace flexure {
namespace {

// Inverse problems end when the tip quantity is within this (times max(1, |target|)) of the
// target: the models' forward solves converge to 1e-12 or better.
constexpr double kInverseTolerance = 1e-10;

// Refuses what the model cannot represent, naming the models that can.
void require_representable(BeamMethod method, const BeamProblem& p) {
  const char* name = to_string(method);
  const double follower = p.chain ? p.chain->tip_load.follower : p.follower;
  if (follower != 0.0) {
    throw InvalidInput(fmt::format(
        "the {} model takes dead loads; the shooting method and the chain algorithm solve a "
        "follower force",
        name));
  }
  const bool chain_capable = method == BeamMethod::kBcm || method == BeamMethod::kCbcm;
  if (!chain_capable && p.chain) {
    throw InvalidInput(fmt::format(
        "the {} model solves Howell's uniform cantilever, not a segment chain; the chained BCM "
        "(cbcm, or bcm for one element) solves a chain of one flexible segment with rigid links "
        "at either end, the shooting method every chain",
        name));
  }
  if (!chain_capable && p.boundary != EndCondition::kFree && p.boundary != EndCondition::kGuided) {
    throw InvalidInput(fmt::format(
        "the {} model solves a cantilever with a free or guided end, not a {} end; the chained "
        "BCM (cbcm, bcm) and the shooting method solve it",
        name,
        to_string(p.boundary)));
  }
  if (p.given != BeamProblem::Given::kAlpha2 && (p.chain || p.boundary != EndCondition::kFree)) {
    throw InvalidInput(fmt::format(
        "a given tip angle theta0 or deflection b/l finds the load of a free cantilever; with a "
        "{} end give the load alpha2 (and prescribe the tip coordinates) instead",
        p.chain ? to_string(p.chain->end) : to_string(p.boundary)));
  }
}

// Howell's cantilever of the problem at load alpha2.
CantileverCase case_of(const BeamProblem& p, double alpha2) {
  CantileverCase c;
  c.load = EndLoad::howell(p.load_ratio_n, alpha2, p.mu);
  c.end = p.boundary;
  if (p.boundary == EndCondition::kGuided) c.guided_tip_angle = p.prescribed.theta.value_or(0.0);
  return c;
}

// A moment varying linearly between the clamp and the tip changes sign inside when they differ
// in sign (linear theory, the BCM's cubic).
int linear_moment_inflections(double root_moment, double end_moment) {
  return root_moment * end_moment < 0.0 ? 1 : 0;
}

void copy_status(const SolveStatus& from, BeamSolution& to) {
  to.termination = from.termination;
  to.message = from.message;
  to.iterations = from.iterations;
  to.residual = from.residual;
  to.warnings = from.warnings;
}

// The closed forms (linear theory, the BCM of the cantilever): equilibrium of the whole beam under
// the full tip loads gives the clamp's reactions, and the moment varies linearly along it.
template <class ClosedFormResult>
BeamSolution closed_form_solution(const CantileverCase& c, const ClosedFormResult& r) {
  BeamSolution s;
  copy_status(r, s);
  s.tip = r.tip;
  s.root_moment = r.root_moment;
  s.reactions = {-c.load.Fx, -c.load.Fy, -r.root_moment};
  s.inflection_points = linear_moment_inflections(r.root_moment, r.end_moment);
  return s;
}

BeamSolution solve_linear(const BeamProblem& p, double alpha2, int shape_points) {
  const CantileverCase c = case_of(p, alpha2);
  const LinearBeamSolver solver;
  const LinearBeamResult r = solver.solve(c);
  BeamSolution s = closed_form_solution(c, r);
  s.branch = "linear theory (equilibrium in the undeformed beam: the axial load does nothing)";
  if (shape_points > 0) s.shape = solver.shape(c, r, shape_points);
  return s;
}

BeamSolution solve_prbm3r(const BeamProblem& p, double alpha2, int shape_points) {
  const CantileverCase c = case_of(p, alpha2);
  Prbm3rSolver::Options options;
  options.constants = Prbm3rConstants::of(p.prbm3r_constants);
  const Prbm3rSolver solver(options);
  const Prbm3rResult r = solver.solve(c);
  BeamSolution s;
  copy_status(r, s);
  s.tip = r.tip;
  s.root_moment = r.root_moment;
  s.reactions = {-r.load_factor * c.load.Fx, -r.load_factor * c.load.Fy, -r.root_moment};
  s.load_factor = r.load_factor;
  s.model_constants = options.constants.name;
  const auto& t = r.joint_angles;
  s.inflection_points = int(t[0] * t[1] < 0.0) + int(t[1] * t[2] < 0.0);
  s.branch = fmt::format(
      "PR-3R model ({} constants): joint angles {:.6f}, {:.6f}, {:.6f} rad{}",
      options.constants.name,
      t[0],
      t[1],
      t[2],
      r.stable ? "" : "; the equilibrium is UNSTABLE (its second variation is not positive)");
  if (r.converged() && shape_points > 0) s.shape = solver.shape(r, shape_points);
  return s;
}

// The closed-form BCM of the free or guided cantilever.
BeamSolution solve_bcm_cantilever(const BeamProblem& p, double alpha2, int shape_points) {
  const CantileverCase c = case_of(p, alpha2);
  BcmSolver::Options options;
  options.slenderness = p.slenderness;
  const BcmSolver solver(options);
  const BcmResult r = solver.solve(c);
  BeamSolution s = closed_form_solution(c, r);
  s.elements = 1;
  s.max_element_deflection = std::fabs(r.y);
  s.model_inside_validity = r.inside_validity;
  s.slenderness = p.slenderness;
  s.axial_stiffness_d = p.slenderness > 0.0 ? 12.0 * p.slenderness * p.slenderness
                                            : std::numeric_limits<double>::infinity();
  s.branch = fmt::format(
      "one BCM element in closed form (axial load p = {:.6g}, |y| = {:.4g} l, {} its stated range "
      "0.1 l)",
      r.p,
      std::fabs(r.y),
      r.inside_validity ? "inside" : "OUTSIDE");
  if (shape_points > 0) s.shape = solver.shape(r, shape_points);
  return s;
}

// The chained BCM (one element for the BCM of a chain) on the problem's chain.
BeamSolution solve_chained(BeamMethod method,
                           const BeamProblem& p,
                           double alpha2,
                           int shape_points) {
  const SegmentChain chain = p.to_chain(alpha2);
  ChainedBcmSolver::Options options;
  options.elements = method == BeamMethod::kBcm ? 1 : p.cbcm_elements;
  options.slenderness = p.slenderness;
  const ChainedBcmSolver solver(options);
  const CbcmResult r = solver.solve(chain);
  const double length = chain.total_length();
  BeamSolution s;
  copy_status(r, s);
  s.tip = r.tip_pose(length);
  s.reactions = r.reaction;
  s.root_moment = r.root_moment;
  s.load_factor = r.load_factor;
  s.elements = r.elements;
  s.max_element_deflection = r.max_element_deflection;
  s.model_inside_validity = r.inside_validity;
  s.slenderness = p.slenderness;
  s.axial_stiffness_d = r.axial_stiffness;
  s.inflection_points = count_curvature_sign_changes(r.nodes);
  // The axial stiffness is named where it is finite: a chain segment's EA sets it without any
  // option, so the answer says which beam was solved.
  const std::string axial =
      std::isfinite(r.axial_stiffness)
          ? fmt::format(", axial stiffness d = EA L^2/EI = {:.6g}{}",
                        r.axial_stiffness,
                        p.slenderness > 0.0 ? " (the slenderness)" : " (the segment's EA)")
          : "";
  s.branch = fmt::format(
      "proportional loading ({} step{}), {} BCM element{} in deflected frames (largest element "
      "|y| = {:.3g} of its length, {} the BCM's stated 0.1){}",
      r.load_steps,
      r.load_steps == 1 ? "" : "s",
      r.elements,
      r.elements == 1 ? "" : "s",
      r.max_element_deflection,
      r.inside_validity ? "inside" : "OUTSIDE",
      axial);
  if (r.converged() && shape_points > 0) {
    s.shape = resample(r.nodes, shape_points);
    for (ShapePoint& q : s.shape) {
      q.s /= length;
      q.x /= length;
      q.y /= length;
    }
  }
  if (p.chain) describe_chain_loads(chain, s);
  return s;
}

BeamSolution solve_forward(BeamMethod method,
                           const BeamProblem& p,
                           double alpha2,
                           int shape_points) {
  BeamSolution s;
  switch (method) {
    case BeamMethod::kLinear:
      s = solve_linear(p, alpha2, shape_points);
      break;
    case BeamMethod::kPrbm3r:
      s = solve_prbm3r(p, alpha2, shape_points);
      break;
    case BeamMethod::kBcm:
      s = !p.chain && (p.boundary == EndCondition::kFree || p.boundary == EndCondition::kGuided)
              ? solve_bcm_cantilever(p, alpha2, shape_points)
              : solve_chained(method, p, alpha2, shape_points);
      break;
    case BeamMethod::kCbcm:
      s = solve_chained(method, p, alpha2, shape_points);
      break;
    default:
      throw InvalidInput(fmt::format("'{}' is not a model of the ladder", to_string(method)));
  }
  s.method = method;
  s.alpha2 = p.chain ? s.alpha2 : alpha2;
  s.family = to_string(method);
  s.tolerance = beam_method_tolerance(method);
  if (!s.converged()) s.load_factor = std::min(s.load_factor, 1.0);
  return s;
}

}  // namespace

bool is_ladder_model(BeamMethod method) {
  return method == BeamMethod::kLinear || method == BeamMethod::kPrbm3r ||
         method == BeamMethod::kBcm || method == BeamMethod::kCbcm;
}

BeamSolution solve_ladder_model(BeamMethod method, const BeamProblem& problem) {
  require_representable(method, problem);
  if (problem.given == BeamProblem::Given::kAlpha2 || problem.chain) {
    return solve_forward(method, problem, problem.value, problem.shape_points);
  }
  TipTarget target;
  target.quantity = problem.given == BeamProblem::Given::kTheta0 ? TipTarget::Quantity::kTheta0
                                                                 : TipTarget::Quantity::kBOverL;
  target.value = problem.value;
  target.load_ratio_n = problem.load_ratio_n;
  target.mu = problem.mu;
  const auto forward = [&](double alpha2) -> std::optional<TipPose> {
    try {
      const BeamSolution s = solve_forward(method, problem, alpha2, 0);
      if (!s.converged()) return std::nullopt;
      return s.tip;
    } catch (const OutsideMethodDomain&) {
      return std::nullopt;  // the BCM past buckling: no tip at this load
    }
  };
  const TipTargetSolution found = solve_tip_target(target, forward, kInverseTolerance);
  if (!found.converged()) {
    BeamSolution missed = missed_inverse_solution(method, found);  // beam_solution_parts.h
    missed.family = to_string(method);
    return missed;
  }
  BeamSolution s = solve_forward(method, problem, found.alpha2, problem.shape_points);
  s.iterations += found.forward_solves;
  s.target_residual = std::fabs(target.of(s.tip) - problem.value);
  if (!(s.target_residual <= found.tolerance)) {
    s.set_converged(false);
    s.message = fmt::format("{} (reached {} = {:.9g} at alpha2 = {:.9g}, target {:.9g})",
                            found.message,
                            target.name(),
                            target.of(s.tip),
                            found.alpha2,
                            problem.value);
  }
  return s;
}

}  // namespace flexure
