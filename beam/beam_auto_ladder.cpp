#include "flexure/beam/beam_auto_ladder.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "flexure/beam/ladder_selector.h"
#include "flexure/solver/common/errors.h"

namespace flexure {
namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;

// The map describes the PR-3R model with Su's general constants and the CBCM with 6 elements, the
// inextensible beam (BeamProblem's defaults), under dead loads on a free end.
bool map_applies(const BeamProblem& p) {
  return p.is_plain_cantilever() && p.given == BeamProblem::Given::kAlpha2 && !p.stable &&
         p.cbcm_elements == 6 && p.prbm3r_constants == "su" && p.slenderness == 0.0;
}

bool mapped_settings(BeamMethod method, const BeamProblem& p) {
  switch (method) {
    case BeamMethod::kLinear:
    case BeamMethod::kPrbm:
    case BeamMethod::kBcm:
      return true;
    case BeamMethod::kPrbm3r:
      return p.prbm3r_constants == "su";
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
         p.cbcm_elements == 6 && p.prbm3r_constants == "su" && p.slenderness == 0.0;
}

// An inverse problem (a given theta0 or b/l) on a free cantilever with the map's settings.
bool inverse_map_applies(const BeamProblem& p) {
  return p.is_plain_cantilever() && p.given != BeamProblem::Given::kAlpha2 && !p.stable &&
         p.cbcm_elements == 6 && p.prbm3r_constants == "su" && p.slenderness == 0.0;
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

LadderAutoOutcome solve_by_ladder(const BeamProblem& problem) {
  LadderAutoOutcome out;
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
  return choose_rung(problem, *rungs, BeamMethod::kElliptic, "data/ladder_auto_error_map.csv");
}

void attach_mapped_error(const BeamProblem& problem, BeamSolution& s) {
  if (!map_applies(problem) || !mapped_settings(s.method, problem) || !s.converged()) return;
  const double E =
      bench::ladder_mapped_error(s.method, problem.load_ratio_n, problem.value, problem.mu);
  if (!std::isfinite(E)) return;
  s.expected_error_per_length = E;
  s.expected_error = bench::relative_error_bound(E, displacement(s.tip));
}

}  // namespace flexure
