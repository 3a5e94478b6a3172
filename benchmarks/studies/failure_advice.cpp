#include "flexure/benchmarks/studies/failure_advice.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace flexure {
namespace {

enum class Regime {
  kPlainDeadLoad,  // Howell's free uniform cantilever with dead loads: every method applies
  kDeadLoad,       // other dead-load problems (guided end, a chain from a file)
  kPrescribedTip,  // pinned, slider or fixed end: tip coordinates prescribed
  kFollower,       // a follower force (not conservative)
};

Regime regime_of(const BeamProblem& p) {
  const double follower = p.chain ? p.chain->tip_load.follower : p.follower;
  const EndCondition end = p.chain ? p.chain->end : p.boundary;
  if (follower != 0.0) return Regime::kFollower;
  if (end == EndCondition::kPinned || end == EndCondition::kSlider || end == EndCondition::kFixed) {
    return Regime::kPrescribedTip;
  }
  return p.is_plain_cantilever() ? Regime::kPlainDeadLoad : Regime::kDeadLoad;
}

// How far each method reaches within a regime: a higher rank is suggested after a lower one fails.
int rank(Regime r, BeamMethod m) {
  switch (m) {
    case BeamMethod::kChain:
      return r == Regime::kFollower ? 2 : 1;
    case BeamMethod::kShooting:
      return r == Regime::kFollower ? 1 : 2;
    case BeamMethod::kElliptic:
      return r == Regime::kPlainDeadLoad ? 3 : -1;
    default:
      return 0;  // the PRBM (an approximation) and auto are never suggested
  }
}

struct Loads {
  double force = std::numeric_limits<double>::quiet_NaN();  // |F| l^2/EI, NaN when not known
  double mu = 0.0;
  double follower = 0.0;
};

Loads loads_of(const BeamProblem& p, const BeamSolution& failed) {
  Loads l;
  l.follower = std::fabs(p.chain ? p.chain->tip_load.follower : p.follower);
  if (p.chain) return l;  // a chain in its own units: no Howell load to compare with the reaches
  // An inverse problem: the load its search had reached when it stopped.
  const double alpha2 = p.given == BeamProblem::Given::kAlpha2 ? p.value : failed.alpha2;
  if (std::isfinite(alpha2)) l.force = std::fabs(alpha2) * std::hypot(1.0, p.load_ratio_n);
  l.mu = std::fabs(p.mu);
  return l;
}

bool within(double value, double reach) { return !std::isfinite(value) || value <= reach; }

bool in_reach(Regime r, BeamMethod m, const Loads& l) {
  if (rank(r, m) <= 0) return false;
  switch (m) {
    case BeamMethod::kElliptic:
      return within(l.force, kEllipticForceRange) && l.mu <= kEllipticForceRange;
    case BeamMethod::kShooting:
      return within(l.force, kShootingForceReach) && l.follower <= kShootingFollowerReach;
    case BeamMethod::kChain:
      return within(l.force, kChainForceReach) && l.follower <= kChainFollowerReach;
    default:
      return false;
  }
}

const char* method_words(BeamMethod m) {
  switch (m) {
    case BeamMethod::kElliptic:
      return "the elliptic solver";
    case BeamMethod::kShooting:
      return "the shooting method";
    case BeamMethod::kChain:
      return "the chain algorithm";
    default:
      return "the PRBM";
  }
}

std::string why(Regime r, BeamMethod m) {
  switch (m) {
    case BeamMethod::kElliptic:
      return fmt::format(
          "it solves the free cantilever with dead loads in closed form up to |F| l^2/EI = {}, "
          "including the large end moments at which the continuation methods lose their path",
          load_text(kEllipticForceRange));
    case BeamMethod::kShooting:
      return fmt::format(
          "it solves the same equations without discretisation (the chain algorithm's reference) "
          "and is measured to converge up to |F| l^2/EI of about {}",
          load_text(kShootingForceReach));
    case BeamMethod::kChain:
      return r == Regime::kFollower
                 ? fmt::format(
                       "it follows a follower force in its own load increments: measured to "
                       "converge up to a follower force of {:g}, where the shooting continuation "
                       "stops between {:g} and 150",
                       kChainFollowerReach,
                       kShootingFollowerReach)
                 : fmt::format("it is measured to converge up to |F| l^2/EI of about {}",
                               load_text(kChainForceReach));
    default:
      return "";
  }
}

// What to change when no method is known to reach further.
std::string what_to_change(Regime r, const Loads& l) {
  if (r != Regime::kFollower && std::isfinite(l.force) && l.force > kShootingForceReach) {
    return fmt::format(
        "No method of flexure is measured to solve |F| l^2/EI = {}: the shooting method "
        "converged up to about {} (a tip force across the beam; more with an axial component), "
        "the chain algorithm up to about {}{}. Try a smaller load.",
        load_text(l.force),
        load_text(kShootingForceReach),
        load_text(kChainForceReach),
        r == Regime::kPlainDeadLoad ? fmt::format(", and the elliptic solver's range ends at {}",
                                                  load_text(kEllipticForceRange))
                                    : std::string());
  }
  switch (r) {
    case Regime::kFollower:
      return fmt::format(
          "No other method is known to follow a follower force of {:g}: the shooting "
          "continuation is measured to follow one up to about {:g}, the chain algorithm up to "
          "about {:g}. Try a smaller follower force.",
          l.follower,
          kShootingFollowerReach,
          kChainFollowerReach);
    case Regime::kPrescribedTip:
      return "No other method is known to reach further with a prescribed tip. Try a tip nearer "
             "the unloaded one (a smaller displacement), or, where a straight beam is pushed "
             "together between its ends, a tip offset across the beam (tip y) or a tip angle "
             "large enough to select the buckled shape.";
    default:
      return "No other method is known to reach further here. Try a smaller load or end moment; "
             "the load path from zero, followed up to where it stops, shows how far it gets.";
  }
}

}  // namespace

std::string load_text(double value) {
  if (!std::isfinite(value) || std::fabs(value) < 1e4) return fmt::format("{:.4g}", value);
  const int exponent = static_cast<int>(std::floor(std::log10(std::fabs(value))));
  return fmt::format("{:.4g}e{}", value / std::pow(10.0, exponent), exponent);
}

BeamFailureAdvice advise_after_failure(const BeamProblem& problem,
                                       const BeamSolution& failed,
                                       const std::vector<BeamMethod>& tried) {
  const Regime r = regime_of(problem);
  const Loads l = loads_of(problem, failed);
  std::vector<BeamMethod> all_tried = tried;
  if (std::find(all_tried.begin(), all_tried.end(), failed.method) == all_tried.end()) {
    all_tried.push_back(failed.method);
  }
  BeamFailureAdvice advice;
  for (BeamMethod y : {BeamMethod::kElliptic, BeamMethod::kShooting, BeamMethod::kChain}) {
    if (std::find(all_tried.begin(), all_tried.end(), y) != all_tried.end()) continue;
    if (!in_reach(r, y, l)) continue;
    // Above every tried method that was within its own reach (see failure_advice.h).
    const bool above = std::all_of(all_tried.begin(), all_tried.end(), [&](BeamMethod x) {
      return !in_reach(r, x, l) || rank(r, y) > rank(r, x);
    });
    if (above) advice.methods.push_back(y);
  }
  std::sort(advice.methods.begin(), advice.methods.end(), [&](BeamMethod a, BeamMethod b) {
    return rank(r, a) > rank(r, b);
  });
  // The two most capable (after the PRBM every exact method qualifies).
  if (advice.methods.size() > 2) advice.methods.resize(2);
  if (advice.methods.empty()) {
    advice.text = what_to_change(r, l);
    advice.load_path_helps = advice.text.find("load path") != std::string::npos;
    return advice;
  }
  std::string text = "Try ";
  for (std::size_t i = 0; i < advice.methods.size(); ++i) {
    advice.names.push_back(method_words(advice.methods[i]));
    advice.reasons.push_back(why(r, advice.methods[i]));
    if (i > 0) text += "; or ";
    text += advice.names.back() + ": " + advice.reasons.back();
  }
  advice.text = text + ".";
  return advice;
}

}  // namespace flexure
