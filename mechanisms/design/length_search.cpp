#include "flexure/mechanisms/design/length_search.h"

#include <algorithm>
#include <cmath>

namespace flexure::design {
namespace {

// Bisection in log l of a bracket with pred(bad) false and pred(good) true, good > bad.
double bisect(const std::function<bool(double)>& pred, double bad, double good, double tol) {
  while (good / bad - 1.0 > tol) {
    const double m = std::sqrt(bad * good);
    (pred(m) ? good : bad) = m;
  }
  return good;
}

}  // namespace

std::optional<double> first_feasible_length(const std::function<bool(double)>& cheap,
                                            const std::function<LengthProbe(double)>& full,
                                            double lower,
                                            double upper,
                                            const LengthSearchOptions& o) {
  if (!(lower > 0.0) || upper < lower) return std::nullopt;
  // The cheap condition: scan up from lower, then bisect the first bracket.
  double candidate = 0.0;
  if (cheap(lower)) {
    candidate = lower;
  } else {
    double bad = lower;
    for (;;) {
      if (bad >= upper) return std::nullopt;
      const double next = std::min(upper, bad * o.scan_factor);
      if (cheap(next)) {
        candidate = bisect(cheap, bad, next, o.cheap_tolerance);
        break;
      }
      bad = next;
    }
  }
  // The full condition holds at or above the cheap one's answer.
  LengthProbe p = full(candidate);
  if (p.feasible) return candidate;
  double bad = candidate;
  std::optional<double> r_bad = p.stress_ratio;
  // Find a feasible length: where the stress binds, the stress of the least stressed section
  // falls about like 1/l (eqs. 8.2, 8.5: h ~ l^(2/3) at fixed width, sigma ~ h d^n/l), so a
  // step to l r lands near the answer; else doubling steps.
  double good = 0.0, step = 0.01;
  std::optional<double> r_good;
  for (int it = 0; it < 60; ++it) {
    if (bad >= upper) return std::nullopt;
    const double next = std::min(
        upper,
        r_bad && *r_bad > 1.0 ? bad * std::min(2.0, *r_bad * (1.0 + 1e-3)) : bad * (1.0 + step));
    step *= 2.0;
    const LengthProbe q = full(next);
    if (q.feasible) {
      good = next;
      r_good = q.stress_ratio;
      break;
    }
    bad = next;
    r_bad = q.stress_ratio;
  }
  if (good == 0.0) return std::nullopt;
  // Shrink [bad, good] to full_tolerance: interpolate log(ratio) linearly in log l where both
  // ends have a ratio and probe just either side of the estimate; else bisect.
  bool below = true;  // probe below the estimate after a feasible probe, above after another
  for (int it = 0; it < 60 && good / bad - 1.0 > o.full_tolerance; ++it) {
    double x = std::sqrt(bad * good);
    if (r_bad && r_good && *r_bad > 1.0 && *r_good <= 1.0 && *r_good > 0.0) {
      const double yb = std::log(*r_bad), yg = std::log(*r_good);
      const double xb = std::log(bad), xg = std::log(good);
      const double root = xb + (0.0 - yb) * (xg - xb) / (yg - yb);
      // Probe a third of the tolerance below the estimate (then above it), inside the bracket.
      const double lo = xb + 1e-3 * (xg - xb), hi = xg - 1e-3 * (xg - xb);
      x = std::exp(std::clamp(root + (below ? -1.0 : 1.0) * o.full_tolerance / 3.0, lo, hi));
    }
    const LengthProbe q = full(x);
    below = q.feasible;
    if (q.feasible) {
      good = x;
      r_good = q.stress_ratio;
    } else {
      bad = x;
      r_bad = q.stress_ratio;
    }
  }
  if (good / bad - 1.0 > o.full_tolerance) {
    return bisect([&](double l) { return full(l).feasible; }, bad, good, o.full_tolerance);
  }
  return good;
}

}  // namespace flexure::design
