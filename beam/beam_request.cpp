#include "flexure/beam/beam_request.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "flexure/solver/chain/chain_algorithm_solver.h"
#include "flexure/solver/common/names.h"
#include "flexure/solver/common/section.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/elastica_integrator.h"

namespace flexure {
namespace {

constexpr int kMaxShapePoints = 1'000'000;

void require_finite_value(double value, const std::string& what) {
  if (!std::isfinite(value)) {
    throw InvalidInput(fmt::format(
        "{} = {} is not allowed: it must be a finite number (not NaN or Inf)", what, value));
  }
}

void require_value_in_range(double value, const std::string& what, double lo, double hi) {
  if (!std::isfinite(value) || value < lo || value > hi) {
    throw InvalidInput(
        fmt::format("{} = {} is outside the allowed range [{}, {}]", what, value, lo, hi));
  }
}

// An angle: radians, or with a unit; a plain value above a full turn is probably degrees.
double angle_value(const std::string& text, const std::string& what, BeamInput& input) {
  const Quantity q = parse_quantity(text, Dimension::kAngle, what);
  const std::string warning = io::angle_warning(q, what);
  if (!warning.empty()) input.warnings.push_back({WarningKind::kUnits, warning});
  return q.si;
}

// The settings of the cheaper models (docs/models.md): the chained BCM's elements, the PR-3R
// constants, the slenderness of the BCM and CBCM; each refused with a method that does not use it
// (auto chooses among the models at their defaults, the settings its error map was measured with).
void add_ladder_settings(const BeamRequest& r,
                         const BeamRequestNames& names,
                         BeamProblem& problem) {
  if (r.elements) {
    if (same_name(r.method, "bcm")) {
      throw InvalidInput(fmt::format("{}: the BCM is one element; {} cbcm {} N chains N of them",
                                     names.elements,
                                     names.method,
                                     names.elements));
    }
    if (same_name(r.method, "cbcm")) {
      require_value_in_range(*r.elements, names.elements + " (chained BCM elements N)", 1, 2000);
      problem.cbcm_elements = *r.elements;
    }
  }
  if (r.constants) {
    if (!same_name(r.method, "prbm3r")) {
      throw InvalidInput(
          fmt::format("{} chooses the PR-3R model's constants; {} {} does not use them",
                      names.constants,
                      names.method,
                      r.method));
    }
    problem.prbm3r_constants = prbm3r_constant_set_from_string(*r.constants);
  }
  if (r.slenderness) {
    if (!same_name(r.method, "bcm") && !same_name(r.method, "cbcm")) {
      throw InvalidInput(
          fmt::format("{} sets the axial stiffness of the BCM and CBCM (d = 12 (L/t)^2); {} "
                      "{} does not take it (the exact methods are inextensible; a chain "
                      "segment's EA makes the shooting method extensible, docs/extensible.md)",
                      names.slenderness,
                      names.method,
                      r.method));
    }
    require_finite_value(*r.slenderness, names.slenderness + " (L/t)");
    if (!(*r.slenderness > 0.0)) {
      throw InvalidInput(
          fmt::format("{} L/t must be > 0 (got {:g}); leave it out for the inextensible beam",
                      names.slenderness,
                      *r.slenderness));
    }
    problem.slenderness = *r.slenderness;
  }
}

}  // namespace

BeamRequestNames BeamRequestNames::command_line() {
  BeamRequestNames n;
  n.alpha2 = "--alpha2";
  n.theta0 = "--theta0";
  n.b_over_l = "--b-over-l";
  n.load_ratio_n = "--n";
  n.mu = "--mu";
  n.boundary = "--boundary";
  n.tip_x = "--tip-x";
  n.tip_y = "--tip-y";
  n.tip_angle = "--tip-angle";
  n.follower = "--follower";
  n.method = "--method";
  n.tolerance = "--tol";
  n.elements = "--elements";
  n.increments = "--increments";
  n.integrator = "--integrator";
  n.shape_points = "--shape";
  n.constants = "--constants";
  n.slenderness = "--slenderness";
  n.chain = "--chain";
  n.stable = "--stable";
  n.length = "--length";
  n.E = "--E";
  n.Fx = "--Fx";
  n.Fy = "--Fy";
  n.M = "--M";
  return n;
}

namespace {

BeamInput checked_input(const BeamRequest& r, const BeamRequestNames& names) {
  // The tolerance means one thing: the error auto allows when it chooses a method.
  if (r.tolerance && !same_name(r.method, "auto")) {
    throw InvalidInput(fmt::format(
        "{} is the error {} auto allows when it chooses a method; {} {} works to its own "
        "tolerance, so {} does not apply (drop it, or use {} auto)",
        names.tolerance,
        names.method,
        names.method,
        r.method,
        names.tolerance,
        names.method));
  }
  BeamInput input;
  BeamProblem& problem = input.problem;
  require_finite_value(r.load_ratio_n, names.load_ratio_n + " (load ratio n)");
  require_finite_value(r.mu, names.mu + " (end moment M l/EI)");
  problem.load_ratio_n = r.load_ratio_n;
  problem.mu = r.mu;
  problem.tolerance = r.tolerance.value_or(1e-6);
  problem.boundary = end_condition_from_string(r.boundary);
  const PrescribedMask mask = prescribed_mask(problem.boundary);
  const auto prescribe = [&](const std::optional<double>& value,
                             bool allowed,
                             const std::string& name) -> std::optional<double> {
    if (!value) return std::nullopt;
    require_finite_value(*value, name);
    if (r.chain) {
      // The file's own end condition and [tip] table hold the tip; checking the flag against the
      // default boundary would blame a boundary the user never chose.
      throw InvalidInput(
          fmt::format("{} FILE.toml prescribes the tip itself (its boundary and [tip] table: "
                      "docs/chain-toml.md); do not combine it with {}",
                      names.chain,
                      name));
    }
    if (!allowed) {
      throw InvalidInput(
          fmt::format("{} is not prescribed by {} {} (it prescribes{}{}{})",
                      name,
                      names.boundary,
                      r.boundary,
                      mask.x ? " tip x" : "",
                      mask.y ? " tip y" : "",
                      mask.theta ? " tip angle" : (mask.x || mask.y ? "" : " nothing")));
    }
    return value;
  };
  problem.prescribed.x = prescribe(r.tip_x, mask.x, names.tip_x);
  problem.prescribed.y = prescribe(r.tip_y, mask.y, names.tip_y);
  if (r.tip_angle) {
    problem.prescribed.theta =
        prescribe(angle_value(*r.tip_angle, names.tip_angle, input), mask.theta, names.tip_angle);
  }
  require_finite_value(r.follower, names.follower + " (follower force F l^2/EI)");
  problem.follower = r.follower;
  const int elements = r.elements.value_or(100);
  require_value_in_range(elements, names.elements + " (chain algorithm elements N)", 1, 1'000'000);
  require_value_in_range(r.increments, names.increments + " (load increments)", 1, 1'000'000);
  problem.elements = elements;
  problem.increments = r.increments;
  add_ladder_settings(r, names, problem);
  problem.chain_variant = chain_variant_from_string(r.chain_variant);
  problem.stable = r.stable;
  problem.judge_stability = r.judge_stability;
  if (r.integrator && !same_name(r.method, "shooting") && !same_name(r.method, "auto")) {
    throw InvalidInput(
        fmt::format("{} chooses the shooting method's integrator; {} {} does not use one",
                    names.integrator,
                    names.method,
                    r.method));
  }
  problem.integrator = integrator_backend_from_string(r.integrator.value_or("rk8pd"));
  if (r.shape_points) {
    require_value_in_range(
        *r.shape_points, names.shape_points + " (number of shape points)", 2, kMaxShapePoints);
    problem.shape_points = *r.shape_points;
  }
  const bool any_given = r.alpha2 || r.theta0 || r.b_over_l;
  const bool nondimensional_loads = any_given || r.load_ratio_n != 0.0 || r.mu != 0.0 ||
                                    r.follower != 0.0 || r.boundary != "free";
  if (r.physical) {
    // A physical beam takes any end condition; its prescribed tip x, y are then metres.
    if (any_given || r.load_ratio_n != 0.0 || r.mu != 0.0 || r.follower != 0.0 || r.chain) {
      throw InvalidInput(fmt::format(
          "a physical beam ({}, {}, the section, {}, {}, {}) is loaded in newtons; do not "
          "combine it with the nondimensional {}, {}, {}, {}, {}, {} or with {} (a chain file "
          "can be in SI units itself: docs/chain-toml.md)",
          names.length,
          names.E,
          names.Fx,
          names.Fy,
          names.M,
          names.alpha2,
          names.theta0,
          names.b_over_l,
          names.load_ratio_n,
          names.mu,
          names.follower,
          names.chain));
    }
    return input;
  }
  if (r.chain) {
    if (nondimensional_loads) {
      throw InvalidInput(fmt::format(
          "{} FILE.toml describes the whole problem (segments, loads, boundary); do not "
          "combine it with {}, {}, {}, {}, {}, {} or {}",
          names.chain,
          names.alpha2,
          names.theta0,
          names.b_over_l,
          names.load_ratio_n,
          names.mu,
          names.follower,
          names.boundary));
    }
    return input;
  }
  if (!any_given) {
    throw InvalidInput(fmt::format(
        "one of {}, {} or {} is required (or {} FILE, or a physical beam: {}, {}, the section "
        "and {}, {}, {})",
        names.alpha2,
        names.theta0,
        names.b_over_l,
        names.chain,
        names.length,
        names.E,
        names.Fx,
        names.Fy,
        names.M));
  }
  if ((r.alpha2 ? 1 : 0) + (r.theta0 ? 1 : 0) + (r.b_over_l ? 1 : 0) > 1) {
    std::vector<std::string> given;
    if (r.alpha2) given.push_back(names.alpha2);
    if (r.theta0) given.push_back(names.theta0);
    if (r.b_over_l) given.push_back(names.b_over_l);
    throw InvalidInput(fmt::format("at most one of {}, {} or {} may be given (got {})",
                                   names.alpha2,
                                   names.theta0,
                                   names.b_over_l,
                                   fmt::join(given, " and ")));
  }
  if (r.alpha2) {
    require_finite_value(*r.alpha2, names.alpha2 + " (P l^2/EI)");
    problem.given = BeamProblem::Given::kAlpha2;
    problem.value = *r.alpha2;
  } else if (r.theta0) {
    problem.given = BeamProblem::Given::kTheta0;
    problem.value = angle_value(*r.theta0, names.theta0 + " (tip angle)", input);
  } else {
    require_value_in_range(*r.b_over_l, names.b_over_l + " (tip deflection b/l)", -1.0, 1.0);
    problem.given = BeamProblem::Given::kBOverL;
    problem.value = *r.b_over_l;
  }
  return input;
}

}  // namespace

BeamInput make_beam_input(const BeamRequest& request, const BeamRequestNames& names) {
  BeamInput input = checked_input(request, names);
  input.method = beam_method_from_string(request.method);
  return input;
}

void add_physical_beam(BeamInput& input, PhysicalCantilever beam) {
  // The request's end condition and prescribed tip (metres and radians) belong to the beam.
  beam.end = input.problem.boundary;
  beam.prescribed = input.problem.prescribed;
  input.problem = beam.to_problem(input.problem);
  input.physical = std::move(beam);
}

void add_chain(BeamInput& input, PhysicalChain chain, bool in_si) {
  input.problem.chain = chain.chain;
  input.problem.boundary = chain.chain.end;
  input.chain = std::move(chain);
  input.chain_in_si = in_si;
}

namespace {

void require_finite_answer(double value, const std::string& what) {
  if (!std::isfinite(value)) {
    throw NoConvergence(
        fmt::format("{} came out as {}; no converged solution to report", what, value));
  }
}

}  // namespace

void require_complete_answer(const BeamProblem& problem,
                             const BeamSolution& solution,
                             const PhysicalResults* physical) {
  if (!problem.chain) require_finite_answer(solution.alpha2, "alpha2");
  if (physical) {
    require_finite_answer(physical->max_moment, "max_moment_Nm");
    if (physical->max_stress) require_finite_answer(*physical->max_stress, "max_stress");
  }
  require_finite_answer(solution.tip.a_over_l, "a/l");
  require_finite_answer(solution.tip.b_over_l, "b/l");
  require_finite_answer(solution.tip.theta0, "theta0");
  // A method that converged but returned another number of shape points than asked (a bug to
  // report, never a shorter curve passed on as the answer).
  if (problem.shape_points > 0 && static_cast<int>(solution.shape.size()) != problem.shape_points) {
    throw NoConvergence(fmt::format("method '{}' returned {} shape points instead of {}",
                                    to_string(solution.method),
                                    solution.shape.size(),
                                    problem.shape_points));
  }
}

std::vector<Warning> beam_answer_warnings(const BeamProblem& problem,
                                          const BeamSolution& solution,
                                          const BeamRequestNames& names) {
  std::vector<Warning> out = solution.warnings;
  if (solution.method == BeamMethod::kPrbm && !solution.prbm_inside_validity) {
    // The validity limit: the smaller of Theta_max(gamma) and Theta_max(K_theta) (Howell eqs.
    // 5.47, 5.63). The elliptic solver takes only the free cantilever with dead loads.
    out.push_back(
        {WarningKind::kOutsideValidity,
         fmt::format("the PRB angle Theta = {:.1f} deg is outside the validity limit {:.1f} "
                     "deg ({}); the PRBM tip and force are not trusted here ({} exact)",
                     std::fabs(solution.prbm_Theta) * 180.0 / std::numbers::pi,
                     solution.prbm_theta_max * 180.0 / std::numbers::pi,
                     solution.prbm_limits_source,
                     problem.is_plain_cantilever() ? names.method + " elliptic or shooting is"
                                                   : names.method + " shooting is")});
  }
  const Stability& s = solution.stability;
  if (s.kind == StabilityKind::kUnstable) {
    out.push_back(
        {WarningKind::kOther,
         fmt::format("the returned equilibrium is UNSTABLE (index {}, stability margin {:.6g}): it "
                     "is the equilibrium reached by proportional loading, but the beam cannot stay "
                     "there under these loads and supports (a small disturbance makes it buckle or "
                     "snap away); {} returns a stable equilibrium",
                     s.index,
                     s.margin,
                     names.stable)});
  } else if (s.kind == StabilityKind::kCritical) {
    out.push_back(
        {WarningKind::kOther,
         fmt::format("the returned equilibrium is CRITICAL (stability margin {:.3g}): a buckling "
                     "or limit point, where the slightest further load makes the beam buckle or "
                     "snap",
                     s.margin)});
  }
  return out;
}

}  // namespace flexure
