#include "flexure/beam/beam_auto_ladder.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "flexure/beam/ladder_selector.h"
#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;

// The map describes the PR-3R model with Su's general constants and the CBCM with 6 elements, the
// inextensible beam (BeamProblem's defaults), under dead loads on a free end.
bool map_applies(const BeamProblem& p) {
  return p.is_plain_cantilever() && p.given == BeamProblem::Given::kAlpha2 && !p.stable &&
         p.cbcm_elements == 6 && p.prbm3r_constants == Prbm3rConstantSet::kSu &&
         p.slenderness == 0.0;
}

bool mapped_settings(BeamMethod method, const BeamProblem& p) {
  switch (method) {
    case BeamMethod::kLinear:
    case BeamMethod::kPrbm:
    case BeamMethod::kBcm:
      return true;
    case BeamMethod::kPrbm3r:
      return p.prbm3r_constants == Prbm3rConstantSet::kSu;
    case BeamMethod::kCbcm:
      return p.cbcm_elements == 6;
    default:
      return false;
  }
}

double displacement(const TipPose& tip) { return std::hypot(tip.a_over_l - 1.0, tip.b_over_l); }

std::string rung_name(BeamMethod m) {
  switch (m) {
    case BeamMethod::kLinear:
      return "linear theory";
    case BeamMethod::kPrbm:
      return "the 1R PRBM";
    case BeamMethod::kPrbm3r:
      return "PR-3R (Su)";
    case BeamMethod::kBcm:
      return "the BCM";
    case BeamMethod::kCbcm:
      return "the CBCM (6 elements)";
    default:
      return to_string(m);
  }
}

// A guided end under dead loads with a given load and the map's settings (the guided map's).
bool guided_map_applies(const BeamProblem& p) {
  return !p.chain && p.boundary == EndCondition::kGuided && p.follower == 0.0 &&
         p.given == BeamProblem::Given::kAlpha2 && !p.stable && p.mu == 0.0 &&
         p.cbcm_elements == 6 && p.prbm3r_constants == Prbm3rConstantSet::kSu &&
         p.slenderness == 0.0;
}

// An inverse problem (a given theta0 or b/l) on a free cantilever with the map's settings.
bool inverse_map_applies(const BeamProblem& p) {
  return p.is_plain_cantilever() && p.given != BeamProblem::Given::kAlpha2 && !p.stable &&
         p.cbcm_elements == 6 && p.prbm3r_constants == Prbm3rConstantSet::kSu &&
         p.slenderness == 0.0;
}

// A chain the ladder's maps describe: one straight, uniform, inextensible and shear-rigid flexible
// segment whose root is placed by rigid links and kinks before it (loads on those pass to the
// clamp; there are none here), nothing after it, dead tip loads only, a free or guided end. Its
// loads turned into the segment's frame (angle phi at the root) and made nondimensional by the
// segment's L and EI are Howell's (n, alpha2, mu): Fy' L^2/EI = alpha2, Fx' L^2/EI = -n alpha2,
// M L/EI = mu. Returns that cantilever, or nothing with `why` saying what the map does not cover.
std::optional<BeamProblem> mapped_chain(const BeamProblem& p, std::string& why) {
  const SegmentChain& c = *p.chain;
  int flexible_index = -1, flexible_count = 0;
  for (int i = 0; i < c.segment_count(); ++i) {
    if (std::holds_alternative<FlexibleSegment>(c.segments[static_cast<std::size_t>(i)])) {
      ++flexible_count;
      flexible_index = i;
    }
  }
  if (flexible_count != 1) {
    why = fmt::format("the chain has {} flexible segments; the ladder's maps are of one",
                      flexible_count);
    return std::nullopt;
  }
  const auto& f = std::get<FlexibleSegment>(c.segments[static_cast<std::size_t>(flexible_index)]);
  if (flexible_index + 1 != c.segment_count()) {
    why =
        "rigid links or kinks after the flexible segment turn with its tip and change the "
        "moment it carries as it deflects; the maps describe loads at the segment's own end";
  } else if (f.kappa0 != 0.0 || !f.EI_profile.empty()) {
    why =
        "the flexible segment is curved or has an EI profile; the maps are of a straight "
        "uniform segment";
  } else if (f.has_distributed_load()) {
    why = "the flexible segment carries a distributed load; the maps are of end loads";
  } else if (f.extensible() || f.shear_flexible()) {
    why =
        "the flexible segment is extensible or shear-flexible (EA or GAs); the maps are of the "
        "inextensible, shear-rigid segment";
  } else if (!c.node_loads.empty()) {
    why = "the chain has joint loads; the maps are of loads at the segment's end";
  } else if (c.tip_load.follower != 0.0) {
    why = "a follower force; the maps are of dead loads";
  } else if (c.end != EndCondition::kFree && c.end != EndCondition::kGuided) {
    why = fmt::format("a {} end; the maps are of the free and the guided end", to_string(c.end));
  } else if (!(p.given == BeamProblem::Given::kAlpha2 && !p.stable && p.cbcm_elements == 6 &&
               p.prbm3r_constants == Prbm3rConstantSet::kSu && p.slenderness == 0.0)) {
    why =
        "the maps are of the default model settings (CBCM 6 elements, Su's PR-3R constants, "
        "no slenderness) and of the proportional-loading answer";
  }
  if (!why.empty()) return std::nullopt;
  const double phi = c.unloaded_nodes()[static_cast<std::size_t>(flexible_index)].theta;
  const double cs = std::cos(phi), sn = std::sin(phi);
  const double force = f.length * f.length / f.EI;
  const double Fx = (c.tip_load.Fx * cs + c.tip_load.Fy * sn) * force;
  const double Fy = (-c.tip_load.Fx * sn + c.tip_load.Fy * cs) * force;
  BeamProblem q = p;
  q.chain.reset();
  q.boundary = c.end;
  q.follower = 0.0;
  q.mu = c.tip_load.M * f.length / f.EI;
  q.prescribed = {};
  if (c.end == EndCondition::kGuided) {
    // The guided end holds the tip angle; in the segment's frame it is the prescribed one less phi.
    q.prescribed.theta = c.prescribed_tip().theta - phi;
  }
  if (Fy != 0.0) {
    q.value = Fy;
    q.load_ratio_n = -Fx / Fy;
  } else if (Fx == 0.0) {
    q.value = 0.0;
    q.load_ratio_n = 0.0;
  } else {
    why =
        "the tip force lies along the segment's axis (alpha2 = 0 with n alpha2 != 0): the maps "
        "are over (n, alpha2)";
    return std::nullopt;
  }
  return q;
}

// Why the ladder is not tried for a problem outside the map (empty where no reason is worth
// giving: a given load with other model settings, a stable equilibrium asked for).
std::string excluded_reason(const BeamProblem& p) {
  if (p.chain) {
    return "the model ladder is not tried for a chain: its maps are of one uniform segment "
           "loaded at its end, and a chain's rigid links, kinks and node loads put loads on its "
           "flexible segments that those maps do not describe";
  }
  if (p.follower != 0.0) {
    return "the model ladder is not tried for a follower force: its models and maps take dead "
           "loads";
  }
  if (p.boundary == EndCondition::kGuided && p.given != BeamProblem::Given::kAlpha2) {
    return "the model ladder is not tried for a guided end with a given tip quantity: the "
           "ladder's models find the load of a free cantilever only";
  }
  if (p.boundary != EndCondition::kFree) {
    return fmt::format("the model ladder is not tried for a {} end: its maps are of the free end",
                       to_string(p.boundary));
  }
  return {};
}

// The inverse problem by the ladder: each closed-form rung (linear theory, then the BCM),
// finds the load that meets the target; at that load its mapped error bound E per length and its
// tip displacement d give E / (d - E), the bound on how far the exact beam under that load has
// its tip from the rung's tip (which meets the target), relative to its displacement. The first
// rung within the tolerance, and cheaper than the elliptic solution at its load, answers.
LadderAutoOutcome solve_inverse_by_ladder(const BeamProblem& problem) {
  LadderAutoOutcome out;
  const double T = problem.tolerance;
  const char* given = problem.given == BeamProblem::Given::kTheta0 ? "theta0" : "b/l";
  std::vector<std::string> passed;
  // The closed forms only: an inverse solve by PR-3R or the CBCM (a load-path Newton iteration per
  // trial load) costs more than the elliptic inverse solve, measured through flexure.beam: at
  // theta0 = 0.5 about 1.4 ms for the four rungs against 0.03 ms elliptic. (The 1R PRBM solves
  // given loads only.)
  for (BeamMethod method : {BeamMethod::kLinear, BeamMethod::kBcm}) {
    const std::string name = rung_name(method);
    BeamSolution s;
    try {
      s = solve_beam(method, problem);
    } catch (const InvalidInput& e) {
      passed.push_back(fmt::format("{} (refused: {})", name, e.what()));
      continue;
    }
    if (!s.converged()) {
      passed.push_back(fmt::format("{} (found no load for the given {})", name, given));
      continue;
    }
    const auto rungs = bench::ladder_estimates(problem.load_ratio_n, s.alpha2, problem.mu);
    if (!rungs) {
      passed.push_back(fmt::format("{} (its load alpha2 = {:.4g} is off the map)", name, s.alpha2));
      continue;
    }
    double E = std::numeric_limits<double>::quiet_NaN(), us = 0.0, exact_us = 0.0;
    for (const bench::LadderEstimate& e : *rungs) {
      if (e.method == method) {
        E = e.error_per_length;
        us = e.microseconds;
      }
      if (e.method == BeamMethod::kElliptic) exact_us = e.microseconds;
    }
    if (std::isnan(E)) {
      passed.push_back(fmt::format("{} (not mapped at its load alpha2 = {:.4g})", name, s.alpha2));
      continue;
    }
    if (us > exact_us) {
      passed.push_back(fmt::format(
          "{} (costs more than the elliptic solution at its load: mapped {:.2g} us against {:.2g})",
          name,
          us,
          exact_us));
      continue;
    }
    const double d = displacement(s.tip);
    const double R = bench::relative_error_bound(E, d);
    if (!(R <= T)) {
      passed.push_back(fmt::format(
          "{} (alpha2 = {:.4g}: mapped error {:.2g} l, up to {:.2g} of its tip displacement)",
          name,
          s.alpha2,
          E,
          R));
      continue;
    }
    std::string cheaper;
    if (!passed.empty()) {
      cheaper = "; cheaper, but not within it: ";
      for (std::size_t i = 0; i < passed.size(); ++i) cheaper += (i ? ", " : "") + passed[i];
    }
    s.method_reason = fmt::format(
        "{}, the cheapest model within the tolerance for this inverse problem: it meets the "
        "given {} at alpha2 = {:.6g}; its mapped tip error there is {:.2g} l ({:g} x the largest "
        "measured at the loads around it, data/ladder_auto_error_map.csv), so under that load the "
        "exact beam's tip lies within {:.2g} of its tip displacement {:.3g} l from this answer's, "
        "within the tolerance {:.2g}{}",
        name,
        given,
        s.alpha2,
        E,
        bench::kBetweenNodesMargin,
        R,
        d,
        T,
        cheaper);
    s.expected_error = R;
    s.expected_error_per_length = E;
    s.methods_tried = {method};
    out.solution = std::move(s);
    return out;
  }
  out.judged = true;
  out.verdict = "no model of the ladder meets the tolerance for this inverse problem: ";
  for (std::size_t i = 0; i < passed.size(); ++i) out.verdict += (i ? ", " : "") + passed[i];
  out.verdict += ", PR-3R and the CBCM (their inverse solves cost more than the elliptic one's)";
  return out;
}

}  // namespace

namespace {

// The cheapest rung of `rungs` (cheapest first, the reference `exact` among them) within the
// tolerance at the problem's load, as described in the header; `map_file` names the data.
LadderAutoOutcome choose_rung(const BeamProblem& problem,
                              const std::vector<bench::LadderEstimate>& rungs,
                              BeamMethod exact,
                              const char* map_file) {
  LadderAutoOutcome out;
  const double T = problem.tolerance;
  std::vector<std::string> passed;  // why each cheaper rung was not taken
  for (const bench::LadderEstimate& rung : rungs) {
    // A chain's exact method is the shooting method (the elliptic solution solves no chain): the
    // map's elliptic rung is no model for it, and the rungs after it are still tried.
    if (rung.method == BeamMethod::kElliptic && exact != BeamMethod::kElliptic) continue;
    if (rung.method == exact) {
      passed.push_back(
          fmt::format("every other model costs more than the exact {} solution "
                      "here (mapped {:.2g} us)",
                      to_string(exact),
                      rung.microseconds));
      break;
    }
    const double E = rung.error_per_length;
    const std::string name = rung_name(rung.method);
    if (E / 2.0 > T) {
      passed.push_back(fmt::format("{} (mapped error {:.2g} l)", name, E));
      continue;
    }
    BeamSolution s;
    try {
      s = solve_beam(rung.method, problem);
    } catch (const InvalidInput& e) {
      passed.push_back(fmt::format("{} (refused: {})", name, e.what()));
      continue;
    }
    if (!s.converged()) {
      passed.push_back(fmt::format("{} (did not converge)", name));
      continue;
    }
    const double d = displacement(s.tip);
    const double R = bench::relative_error_bound(E, d);
    if (!(R <= T)) {
      passed.push_back(
          fmt::format("{} (mapped error {:.2g} l, up to {:.2g} of its tip displacement {:.3g} l)",
                      name,
                      E,
                      R,
                      d));
      continue;
    }
    std::string validity;
    if (rung.method == BeamMethod::kPrbm) {
      if (!s.prbm_inside_validity) {
        passed.push_back(fmt::format(
            "{} (its PRB angle {:.1f} deg exceeds the validity limit Theta_max = {:.1f} deg, "
            "Howell eqs. 5.47, 5.63)",
            name,
            std::fabs(s.prbm_Theta) * kDeg,
            s.prbm_theta_max * kDeg));
        continue;
      }
      validity = fmt::format("; Theta = {:.1f} deg is inside Theta_max = {:.1f} deg",
                             std::fabs(s.prbm_Theta) * kDeg,
                             s.prbm_theta_max * kDeg);
    }
    std::string cheaper;
    if (!passed.empty()) {
      cheaper = "; cheaper, but not within it: ";
      for (std::size_t i = 0; i < passed.size(); ++i) cheaper += (i ? ", " : "") + passed[i];
    }
    s.method_reason = fmt::format(
        "{}, the cheapest model within the tolerance at this load (mapped {:.2g} us per solve): "
        "its mapped tip error is {:.2g} l ({:g} x the largest measured at the loads around this "
        "one, {}), so at most {:.2g} of its tip displacement {:.3g} "
        "l, within the tolerance {:.2g}{}{}",
        name,
        rung.microseconds,
        E,
        bench::kBetweenNodesMargin,
        map_file,
        R,
        d,
        T,
        validity,
        cheaper);
    s.expected_error = R;
    s.expected_error_per_length = E;
    s.methods_tried = {rung.method};
    out.solution = std::move(s);
    return out;
  }
  out.judged = true;
  out.verdict = "no model of the ladder meets the tolerance at this load more cheaply: ";
  for (std::size_t i = 0; i < passed.size(); ++i) out.verdict += (i ? ", " : "") + passed[i];
  return out;
}

// Why auto did not use the ladder: the load lies outside the map `file` covers. `third` names the
// map's third axis (mu for the free end, the tip angle for the guided end), `unit` its unit.
std::string off_map_verdict(const bench::LadderMapRange& r,
                            const std::string& map,
                            const std::string& third,
                            const std::string& unit,
                            const std::string& file) {
  return fmt::format(
      "the load is off the model ladder's {} ({:g} <= n <= {:g}, {:g} <= alpha2 <= {:g}, {:g} <= "
      "{} <= {:g}{}; {})",
      map,
      r.n_min,
      r.n_max,
      r.alpha2_min,
      r.alpha2_max,
      r.mu_min,
      third,
      r.mu_max,
      unit,
      file);
}

}  // namespace

namespace {
LadderAutoOutcome solve_by_ladder(const BeamProblem& problem, bool for_chain);
}  // namespace

LadderAutoOutcome solve_by_ladder(const BeamProblem& problem) {
  return solve_by_ladder(problem, false);
}

namespace {

LadderAutoOutcome solve_by_ladder(const BeamProblem& problem, bool for_chain) {
  LadderAutoOutcome out;
  if (problem.chain) {
    // A chain that is one segment loaded at its end: the map of that cantilever chooses the
    // model, which then solves the chain itself (its answer in the chain's units and frame).
    std::string why;
    const std::optional<BeamProblem> cantilever = mapped_chain(problem, why);
    if (!cantilever) {
      out.verdict = "the model ladder's maps do not cover this chain (" + why + ")";
      return out;
    }
    LadderAutoOutcome mapped = solve_by_ladder(*cantilever, true);
    const std::string equivalent = fmt::format(
        "the chain is one uniform segment loaded at its end: in the segment's frame Howell's "
        "cantilever with n = {:.6g}, alpha2 = {:.6g}, mu = {:.6g}{}",
        cantilever->load_ratio_n,
        cantilever->value,
        cantilever->mu,
        cantilever->boundary == EndCondition::kGuided
            ? fmt::format(" and a guided tip angle {:.6g} rad", *cantilever->prescribed.theta)
            : std::string());
    if (!mapped.solution) {
      // (judged false: the verdict leads the exact method's reason.)
      out.verdict = equivalent + "; " +
                    (mapped.verdict.empty() ? std::string("the ladder's maps do not apply to it")
                                            : mapped.verdict);
      return out;
    }
    const BeamMethod method = mapped.solution->method;
    BeamSolution s;
    try {
      s = solve_beam(method, problem);
    } catch (const InvalidInput& e) {
      out.verdict = fmt::format("{}; {} was chosen by the map but refused the chain: {}",
                                equivalent,
                                rung_name(method),
                                e.what());
      return out;
    }
    if (!s.converged()) {
      out.verdict = fmt::format("{}; {} was chosen by the map but did not converge on the chain",
                                equivalent,
                                rung_name(method));
      return out;
    }
    s.method_reason = equivalent + "; " + mapped.solution->method_reason;
    s.expected_error = mapped.solution->expected_error;
    s.expected_error_per_length = mapped.solution->expected_error_per_length;
    s.methods_tried = {method};
    out.solution = std::move(s);
    return out;
  }
  if (inverse_map_applies(problem)) return solve_inverse_by_ladder(problem);
  if (guided_map_applies(problem)) {
    const double tip_angle = problem.prescribed.theta.value_or(0.0);
    const auto rungs =
        bench::ladder_estimates_guided(problem.load_ratio_n, problem.value, tip_angle);
    if (!rungs) {
      out.verdict = off_map_verdict(bench::ladder_guided_map_range(),
                                    "map of the guided end",
                                    "tip angle",
                                    " rad",
                                    "data/ladder_auto_error_map_guided.csv");
      return out;
    }
    return choose_rung(
        problem, *rungs, BeamMethod::kShooting, "data/ladder_auto_error_map_guided.csv");
  }
  if (!map_applies(problem)) {
    out.verdict = excluded_reason(problem);
    return out;
  }
  const auto rungs = bench::ladder_estimates(problem.load_ratio_n, problem.value, problem.mu);
  if (!rungs) {
    out.verdict = off_map_verdict(
        bench::ladder_map_range(), "map", "mu", "", "data/ladder_auto_error_map.csv");
    return out;
  }
  return choose_rung(problem,
                     *rungs,
                     for_chain ? BeamMethod::kShooting : BeamMethod::kElliptic,
                     "data/ladder_auto_error_map.csv");
}

}  // namespace

void attach_mapped_error(const BeamProblem& problem, BeamSolution& s) {
  if (!map_applies(problem) || !mapped_settings(s.method, problem) || !s.converged()) return;
  const double E =
      bench::ladder_mapped_error(s.method, problem.load_ratio_n, problem.value, problem.mu);
  if (!std::isfinite(E)) return;
  s.expected_error_per_length = E;
  s.expected_error = bench::relative_error_bound(E, displacement(s.tip));
}

}  // namespace flexure
