#include "flexure/solver/common/scalar_root.h"

#include <cmath>
#include <limits>
#include <utility>

namespace flexure {
namespace {

ScalarRootResult finish(bool converged, double x, double f, int iterations) {
  ScalarRootResult r;
  r.set_converged(converged);
  r.x = x;
  r.f = f;
  r.iterations = iterations;
  r.residual = std::fabs(f);
  if (!converged) r.message = "no root within the iteration limit, or a non-finite function value";
  return r;
}

}  // namespace

// Brent, "Algorithms for Minimization without Derivatives" (1973), ch. 4 (zeroin).
ScalarRootResult brent_root(const std::function<double(double)>& f,
                            double a,
                            double b,
                            double fa,
                            double fb,
                            const ScalarRootOptions& options) {
  ScalarRootResult result;
  if (fa == 0.0) return finish(true, a, 0.0, 0);
  if (fb == 0.0) return finish(true, b, 0.0, 0);
  if (!(std::isfinite(fa) && std::isfinite(fb)) || (fa > 0.0) == (fb > 0.0)) {
    result.x = b;
    result.f = fb;
    result.residual = std::fabs(fb);
    result.message = "the values at the ends do not bracket a root";
    return result;
  }
  constexpr double eps = std::numeric_limits<double>::epsilon();
  double c = a, fc = fa, d = b - a, e = d;
  for (int iter = 1; iter <= options.max_iterations; ++iter) {
    if ((fb > 0.0) == (fc > 0.0)) {
      c = a;
      fc = fa;
      d = e = b - a;
    }
    if (std::fabs(fc) < std::fabs(fb)) {
      a = b;
      b = c;
      c = a;
      fa = fb;
      fb = fc;
      fc = fa;
    }
    const double tol = 2.0 * eps * std::fabs(b) + 0.5 * options.x_tolerance;
    const double m = 0.5 * (c - b);
    if (std::fabs(m) <= tol || fb == 0.0) return finish(true, b, fb, iter - 1);
    if (std::fabs(e) >= tol && std::fabs(fa) > std::fabs(fb)) {
      double p, q, r;
      const double s = fb / fa;
      if (a == c) {
        p = 2.0 * m * s;
        q = 1.0 - s;
      } else {
        q = fa / fc;
        r = fb / fc;
        p = s * (2.0 * m * q * (q - r) - (b - a) * (r - 1.0));
        q = (q - 1.0) * (r - 1.0) * (s - 1.0);
      }
      if (p > 0.0)
        q = -q;
      else
        p = -p;
      if (2.0 * p < std::min(3.0 * m * q - std::fabs(tol * q), std::fabs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = m;
        e = m;
      }
    } else {
      d = m;
      e = m;
    }
    a = b;
    fa = fb;
    b += (std::fabs(d) > tol) ? d : (m > 0.0 ? tol : -tol);
    fb = f(b);
    if (!std::isfinite(fb)) return finish(false, b, fb, iter);
  }
  return finish(false, b, fb, options.max_iterations);
}

}  // namespace flexure
