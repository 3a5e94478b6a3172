#include "solver/common/load_search.h"

#include <fmt/format.h>

#include <cmath>

#include "solver/common/scalar_root.h"

namespace flexure {

LoadSearchResult find_load_for_target(
    const std::function<std::optional<double>(double alpha2)>& quantity,
    double target,
    double at_zero,
    const LoadSearchOptions& options) {
  LoadSearchResult out;
  if (at_zero == target) {
    out.found = true;
    return out;
  }
  auto residual = [&](double alpha2) {
    ++out.solves;
    const std::optional<double> q = quantity(alpha2);
    return q ? *q - target : std::nan("");
  };
  double reached = 0.0;
  for (double sign : {1.0, -1.0}) {
    double a = 0.0;
    double fa = at_zero - target;
    for (double mag = options.min_alpha2; mag <= options.max_alpha2 * (1.0 + 1e-12);
         mag *= options.growth) {
      const double b = sign * mag;
      const double fb = residual(b);
      if (!std::isfinite(fb)) break;
      reached = std::max(reached, mag);
      if ((fa > 0.0) != (fb > 0.0) || fb == 0.0) {
        ScalarRootOptions opts;
        opts.x_tolerance = options.relative_tolerance * std::fabs(b);
        const ScalarRootResult root = brent_root(residual, a, b, fa, fb, opts);
        if (root.converged) {
          out.found = true;
          out.alpha2 = root.x;
          return out;
        }
        break;
      }
      a = b;
      fa = fb;
    }
  }
  out.message = fmt::format(
      "the target {:.6g} is not reached by any |alpha2| up to {:.6g} (the forward solves succeeded "
      "up to |alpha2| = {:.6g})",
      target,
      options.max_alpha2,
      reached);
  return out;
}

}  // namespace flexure
