#include "flexure/solver/common/load_search.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "flexure/solver/common/scalar_root.h"

namespace flexure {
namespace {

// quantity - target with a solve count; NaN where the forward solve failed.
class Miss {
 public:
  Miss(const std::function<std::optional<double>(double)>& quantity,
       double target,
       LoadSearchResult& out)
      : quantity_(quantity), target_(target), out_(out) {}
  double operator()(double alpha2) {
    ++out_.solves;
    const std::optional<double> q = quantity_(alpha2);
    if (!q || !std::isfinite(*q)) return std::numeric_limits<double>::quiet_NaN();
    const double miss = *q - target_;
    if (std::fabs(miss) < closest_) {
      closest_ = std::fabs(miss);
      out_.alpha2 = alpha2;
      out_.reached = *q;
      out_.residual = closest_;
    }
    return miss;
  }

 private:
  const std::function<std::optional<double>(double)>& quantity_;
  double target_;
  LoadSearchResult& out_;
  double closest_ = std::numeric_limits<double>::infinity();
};

// Brent on a bracket, then the check that the root reaches the target (not a jump).
bool verified_root(Miss& miss,
                   double a,
                   double b,
                   double fa,
                   double fb,
                   const LoadSearchOptions& options,
                   double& root,
                   double& miss_at_root) {
  ScalarRootOptions opts;
  opts.x_tolerance = options.relative_tolerance * std::max(std::fabs(a), std::fabs(b));
  const ScalarRootResult r = brent_root(miss, a, b, fa, fb, opts);
  if (!r.converged() || !(std::fabs(r.f) <= options.target_tolerance)) return false;
  root = r.x;
  miss_at_root = r.f;
  return true;
}

// Between three grid points whose misses share a sign and whose middle one is the smallest, the
// quantity may touch or cross the target near an extremum that the grid steps over (b/l of a
// compressed beam peaks and falls as the tip curls over). Golden-section search for the point
// closest to the target; a sign change there gives a bracket [a, x] with the extremum's side.
bool bracket_at_extremum(Miss& miss, double a, double fa, double b, double& x, double& fx) {
  const double sign = fa > 0.0 ? 1.0 : -1.0;
  constexpr double kGolden = 0.6180339887498949;
  double lo = a, hi = b;
  double x1 = hi - kGolden * (hi - lo), x2 = lo + kGolden * (hi - lo);
  double f1 = miss(x1), f2 = miss(x2);
  for (int it = 0; it < 60 && std::isfinite(f1) && std::isfinite(f2); ++it) {
    if (sign * f1 <= 0.0 || sign * f2 <= 0.0) {
      x = sign * f1 <= 0.0 ? x1 : x2;
      fx = sign * f1 <= 0.0 ? f1 : f2;
      return true;
    }
    if (std::fabs(hi - lo) <= 1e-13 * std::max(std::fabs(lo), std::fabs(hi))) break;
    if (sign * f1 < sign * f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - kGolden * (hi - lo);
      f1 = miss(x1);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + kGolden * (hi - lo);
      f2 = miss(x2);
    }
  }
  return false;
}

void mark_found(LoadSearchResult& out, double alpha2, double target, double miss) {
  out.status = LoadSearchStatus::kFound;
  out.alpha2 = alpha2;
  out.reached = target + miss;
  out.residual = std::fabs(miss);
}

}  // namespace

LoadSearchResult find_load_for_target(
    const std::function<std::optional<double>(double alpha2)>& quantity,
    double target,
    double at_zero,
    const LoadSearchOptions& options) {
  LoadSearchResult out;
  out.reached = at_zero;
  out.residual = std::fabs(at_zero - target);
  if (at_zero == target) {
    mark_found(out, 0.0, target, 0.0);
    return out;
  }
  Miss miss(quantity, target, out);
  struct Side {
    double sign;
    double last_x = 0.0;
    double last_f = 0.0;
    bool alive = true;
    double before_x = std::numeric_limits<double>::quiet_NaN();  // the grid point before last
    double before_f = std::numeric_limits<double>::quiet_NaN();
  };
  Side sides[2] = {{1.0, 0.0, at_zero - target}, {-1.0, 0.0, at_zero - target}};
  bool missed_bracket = false;
  for (double mag = options.min_alpha2; mag <= options.max_alpha2 * (1.0 + 1e-12);
       mag *= options.growth) {
    double best = std::numeric_limits<double>::quiet_NaN();
    double best_miss = 0.0;
    for (Side& side : sides) {
      if (!side.alive) continue;
      const double x = side.sign * mag;
      const double f = miss(x);
      if (!std::isfinite(f)) {
        side.alive = false;
        out.stopped_early = true;
        continue;
      }
      out.reached_alpha2_max = std::max(out.reached_alpha2_max, mag);
      // A local approach to the target between grid points: look for a hidden crossing.
      double hidden_x = 0.0, hidden_f = 0.0;
      if (std::isfinite(side.before_f) && (f > 0.0) == (side.last_f > 0.0) &&
          (side.last_f > 0.0) == (side.before_f > 0.0) &&
          std::fabs(side.last_f) < std::fabs(side.before_f) &&
          std::fabs(side.last_f) < std::fabs(f) &&
          bracket_at_extremum(miss, side.before_x, side.before_f, x, hidden_x, hidden_f)) {
        double root = hidden_x, miss_at_root = hidden_f;
        if ((hidden_f == 0.0 || verified_root(miss,
                                              std::min(side.before_x, hidden_x),
                                              std::max(side.before_x, hidden_x),
                                              side.before_x < hidden_x ? side.before_f : hidden_f,
                                              side.before_x < hidden_x ? hidden_f : side.before_f,
                                              options,
                                              root,
                                              miss_at_root)) &&
            !(std::fabs(root) >= std::fabs(best))) {
          best = root;
          best_miss = miss_at_root;
        }
      }
      if (mag * options.growth > options.max_alpha2 * (1.0 + 1e-12)) out.scanned_to_max = true;
      if ((f > 0.0) != (side.last_f > 0.0) || f == 0.0) {
        double root = x, miss_at_root = 0.0;
        if (f != 0.0 &&
            !verified_root(miss, side.last_x, x, side.last_f, f, options, root, miss_at_root)) {
          // A jump of the quantity, not a root: remember the first, keep scanning.
          if (!missed_bracket) {
            out.jump_alpha2_from = side.last_x;
            out.jump_alpha2_to = x;
            out.jump_value_from = side.last_f + target;
            out.jump_value_to = f + target;
          }
          missed_bracket = true;
          side.before_x = side.last_x;
          side.before_f = side.last_f;
          side.last_x = x;
          side.last_f = f;
          continue;
        }
        if (!(std::fabs(root) >= std::fabs(best))) {
          best = root;
          best_miss = miss_at_root;
        }
      }
      side.before_x = side.last_x;
      side.before_f = side.last_f;
      side.last_x = x;
      side.last_f = f;
    }
    if (std::isfinite(best)) {
      mark_found(out, best, target, best_miss);
      return out;
    }
    if ((!sides[0].alive && !sides[1].alive) || out.solves >= options.max_solves) break;
  }
  out.status = missed_bracket ? LoadSearchStatus::kMissed : LoadSearchStatus::kUnreachable;
  out.message =
      missed_bracket
          ? fmt::format(
                "the tip quantity jumps across the target {:.6g} (from {:.6g} at alpha2 = {:.6g} "
                "to {:.6g} at alpha2 = {:.6g}: the load path passes a limit point there and the "
                "beam snaps) and no load reaches it within {:.1e}; the closest was {:.9g} at "
                "alpha2 = {:.9g}",
                target,
                out.jump_value_from,
                out.jump_alpha2_from,
                out.jump_value_to,
                out.jump_alpha2_to,
                options.target_tolerance,
                out.reached,
                out.alpha2)
          : fmt::format(
                "the target {:.6g} is not reached by any |alpha2| up to {:.6g} (the forward "
                "solves succeeded up to |alpha2| = {:.6g}; the closest was {:.9g} at alpha2 = "
                "{:.9g})",
                target,
                options.max_alpha2,
                out.reached_alpha2_max,
                out.reached,
                out.alpha2);
  return out;
}

LoadSearchResult refine_load_for_target(
    const std::function<std::optional<double>(double alpha2)>& quantity,
    double target,
    double guess,
    double relative_step,
    const LoadSearchOptions& options) {
  LoadSearchResult out;
  Miss miss(quantity, target, out);
  const double f0 = miss(guess);
  if (!std::isfinite(f0)) {
    out.message = fmt::format("the forward solve failed at the guess alpha2 = {:.9g}", guess);
    return out;
  }
  if (std::fabs(f0) <= options.target_tolerance) {
    mark_found(out, guess, target, f0);
    return out;
  }
  const double scale = std::max(std::fabs(guess), options.min_alpha2);
  for (double step = relative_step * scale; step <= 0.5 * scale; step *= 4.0) {
    for (double direction : {1.0, -1.0}) {
      const double x = guess + direction * step;
      const double f = miss(x);
      if (!std::isfinite(f) || (f > 0.0) == (f0 > 0.0)) continue;
      double root = 0.0, miss_at_root = 0.0;
      if (verified_root(miss,
                        std::min(guess, x),
                        std::max(guess, x),
                        direction > 0.0 ? f0 : f,
                        direction > 0.0 ? f : f0,
                        options,
                        root,
                        miss_at_root)) {
        mark_found(out, root, target, miss_at_root);
        return out;
      }
      out.status = LoadSearchStatus::kMissed;
    }
  }
  out.message = fmt::format(
      "no load within a factor of two of alpha2 = {:.9g} reaches the target {:.6g} within {:.1e}; "
      "the closest was {:.9g} at alpha2 = {:.9g}",
      guess,
      target,
      options.target_tolerance,
      out.reached,
      out.alpha2);
  return out;
}

}  // namespace flexure
