#include "flexure/solver/inverse/tip_target.h"

#include <fmt/format.h>

#include <cmath>
#include <vector>

#include "flexure/solver/common/load_search.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/elliptic/elliptic_solver.h"

namespace flexure {
namespace {

// Forward solves allowed for the method's own search: a failure must come fast, and a shooting
// solve under strong tension costs seconds.
constexpr int kMaxMethodSolves = 24;

enum class ExactOutcome { kFound, kJumps, kBeyondRange };

// The exact load, or why there is none. Unreachable targets throw InvalidInput.
ExactOutcome exact_load(const TipTarget& target, double& alpha2, std::string& note) {
  const EllipticSolver elliptic;
  try {
    const EllipticResult r =
        target.quantity == TipTarget::Quantity::kTheta0
            ? elliptic.solve_for_tip_angle(target.load_ratio_n, target.value, target.mu)
            : elliptic.solve_for_deflection(target.load_ratio_n, target.value, target.mu);
    note = r.message;
    alpha2 = r.load.Fy;
    return r.converged() ? ExactOutcome::kFound : ExactOutcome::kJumps;
  } catch (const OutsideMethodDomain& e) {
    note = e.what();
    return ExactOutcome::kBeyondRange;
  }
}

// Loads just past the elliptic range where the target may lie: on each side of alpha2, the exact
// quantity at the last two loads of the range, extrapolated in ln|alpha2|, must reach the target
// within ten times the range's end. A target approached only asymptotically is not searched.
std::vector<double> loads_past_the_range(const TipTarget& target) {
  const EllipticSolver elliptic;
  const double end = 0.999999 * EllipticSolver::kMaxForce / std::hypot(1.0, target.load_ratio_n);
  std::vector<double> out;
  for (double sign : {1.0, -1.0}) {
    try {
      const EllipticResult far =
          elliptic.solve(EndLoad::howell(target.load_ratio_n, sign * end, target.mu));
      const EllipticResult near =
          elliptic.solve(EndLoad::howell(target.load_ratio_n, sign * end / 1.5, target.mu));
      if (!far.converged() || !near.converged()) continue;
      const double slope = (target.of(far.tip) - target.of(near.tip)) / std::log(1.5);
      const double log_steps = (target.value - target.of(far.tip)) / slope;
      if (std::isfinite(log_steps) && log_steps > 0.0 && log_steps < std::log(10.0)) {
        out.push_back(sign * end * std::exp(log_steps));
      }
    } catch (const InvalidInput&) {
    }
  }
  return out;
}

}  // namespace

TipTargetSolution solve_tip_target(
    const TipTarget& target,
    const std::function<std::optional<TipPose>(double alpha2)>& forward,
    double tolerance) {
  require_finite(target.value, target.name());
  require_finite(target.load_ratio_n, "load ratio n");
  require_finite(target.mu, "end moment mu");
  TipTargetSolution out;
  out.tolerance = tolerance * std::max(1.0, std::fabs(target.value));
  auto quantity = [&](double alpha2) -> std::optional<double> {
    const std::optional<TipPose> tip = forward(alpha2);
    if (!tip) return std::nullopt;
    return target.of(*tip);
  };
  LoadSearchOptions options;
  options.target_tolerance = out.tolerance;
  options.relative_tolerance = 1e-12;
  options.max_solves = kMaxMethodSolves;
  // The method's own scan may go past the exact solver's range |F| l^2/EI <= 1e4.
  options.max_alpha2 = 1e5;
  std::string note;
  double guess = 0.0;
  const ExactOutcome exact = exact_load(target, guess, note);  // throws if unreachable
  LoadSearchResult found;
  if (exact == ExactOutcome::kJumps) {
    // The exact tip quantity jumps across the target at a fold of the load path: the method's
    // model of the same beam does too, and a scan of its own would only spend its budget.
    out.message = fmt::format("{} (exact elliptic solution)", note);
    out.termination = Termination::kLimitPoint;
    out.alpha2 = guess;
    return out;
  }
  if (exact == ExactOutcome::kFound) {
    // The method's model differs from the exact one by its discretisation error: refine locally.
    found = refine_load_for_target(quantity, target.value, guess, 1e-4, options);
    out.message = found.found()
                      ? fmt::format(
                            "load from the exact elliptic inverse (alpha2 = {:.12g}), refined "
                            "with the method",
                            guess)
                      : fmt::format("{} not reached near the exact load alpha2 = {:.12g}: {}",
                                    target.name(),
                                    guess,
                                    found.message);
  } else {
    // Beyond the exact solver's range: search with the method only where the exact trend at the
    // range's end points to a load just past it.
    const std::vector<double> candidates = loads_past_the_range(target);
    if (candidates.empty()) {
      throw InvalidInput(fmt::format(
          "{}; but the exact tip quantity at the end of the range approaches the target too "
          "slowly for any load within ten times the range to reach it",
          note));
    }
    for (double candidate : candidates) {
      found = refine_load_for_target(quantity, target.value, candidate, 0.05, options);
      if (found.found()) break;
    }
    out.message =
        found.found()
            ? "the exact load lies past the elliptic solver's range; found with the method"
            : fmt::format("{}; the method did not reach it near the extrapolated load either",
                          note);
  }
  out.set_converged(found.found());
  // Brackets without a root: the quantity jumps across the target at a fold of the load path.
  if (found.status == LoadSearchStatus::kMissed) out.termination = Termination::kLimitPoint;
  out.alpha2 = found.alpha2;
  out.reached = found.reached;
  out.residual = found.residual;
  out.forward_solves = found.solves;
  return out;
}

}  // namespace flexure
