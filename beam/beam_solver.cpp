#include <fmt/format.h>

#include <cmath>
#include <utility>

#include "flexure/beam/beam_problem.h"
#include "flexure/elements/ladder_models.h"
#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

void require_in(double value, const char* name, double lo, double hi) {
  if (!std::isfinite(value) || value < lo || value > hi) {
    throw InvalidInput(fmt::format(
        "BeamSolver::Options::{} = {} is outside the allowed range [{}, {}]", name, value, lo, hi));
  }
}

}  // namespace

void BeamSolver::Options::validate() const {
  if (!(std::isfinite(auto_tolerance) && auto_tolerance > 0.0)) {
    throw InvalidInput(fmt::format(
        "BeamSolver::Options::auto_tolerance = {} must be a finite number > 0", auto_tolerance));
  }
  require_in(elements, "elements", 1, 1'000'000);
  require_in(increments, "increments", 1, 1'000'000);
  if (shape_points != 0) require_in(shape_points, "shape_points", 2, 1'000'000);
  require_in(cbcm_elements, "cbcm_elements", 1, 2000);
  if (!(std::isfinite(slenderness) && slenderness >= 0.0)) {
    throw InvalidInput(
        fmt::format("BeamSolver::Options::slenderness = {} must be a finite L/t > 0, or 0 for the "
                    "inextensible beam",
                    slenderness));
  }
  Prbm3rConstants::of(prbm3r_constants);  // InvalidInput for a value outside the enum
}

BeamSolver::BeamSolver(Options options) : options_(std::move(options)) { options_.validate(); }

BeamSolution BeamSolver::solve(const BeamProblem& problem) const {
  BeamProblem p = problem;
  p.tolerance = options_.auto_tolerance;
  p.integrator = options_.integrator;
  p.elements = options_.elements;
  p.increments = options_.increments;
  p.chain_variant = options_.chain_variant;
  p.shape_points = options_.shape_points;
  p.cbcm_elements = options_.cbcm_elements;
  p.prbm3r_constants = options_.prbm3r_constants;
  p.slenderness = options_.slenderness;
  p.judge_stability = options_.judge_stability;
  p.stable = options_.stable;
  return solve_beam(options_.method, p);
}

BeamSolver::Options beam_solver_options(BeamMethod method, const BeamProblem& problem) {
  BeamSolver::Options o;
  o.method = method;
  o.auto_tolerance = problem.tolerance;
  o.integrator = problem.integrator;
  o.elements = problem.elements;
  o.increments = problem.increments;
  o.chain_variant = problem.chain_variant;
  o.shape_points = problem.shape_points;
  o.cbcm_elements = problem.cbcm_elements;
  o.prbm3r_constants = problem.prbm3r_constants;
  o.slenderness = problem.slenderness;
  o.judge_stability = problem.judge_stability;
  o.stable = problem.stable;
  return o;
}

}  // namespace flexure
