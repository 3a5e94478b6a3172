#include "flexure/elements/prbm_curve_fits.h"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

void require_n_range(double n, const char* what) {
  if (!(n >= -5.0 && n <= 10.0)) {
    throw InvalidInput(
        fmt::format("load ratio n = {} is outside the range -5 <= n <= 10 of {}", n, what));
  }
}

void require_kappa_range(double kappa0, const char* what) {
  if (!(kappa0 >= 0.5 && kappa0 <= 1.5)) {
    throw InvalidInput(
        fmt::format("initial curvature kappa0 = {} is outside the range 0.5 <= kappa0 <= 1.5 of {}",
                    kappa0,
                    what));
  }
}

}  // namespace

double gamma_curve_fit(double n) {
  require_n_range(n, "the gamma curve fit (eq. 5.48)");
  if (n > 0.5) return 0.841655 - 0.0067807 * n + 0.000438 * n * n;
  if (n >= -1.8316) return 0.852144 - 0.0182867 * n;
  return 0.912364 + 0.0145928 * n;
}

double K_theta_curve_fit(double n) {
  require_n_range(n, "the K_theta curve fit (eqs. 5.60-5.62)");
  if (n <= -2.5) return 3.024112 + 0.121290 * n + 0.003169 * n * n;  // eq. 5.60
  if (n <= -1.0) {                                                   // eq. 5.61
    return 1.967647 - 2.616021 * n - 3.738166 * n * n - 2.649437 * std::pow(n, 3) -
           0.891906 * std::pow(n, 4) - 0.113063 * std::pow(n, 5);
  }
  return 2.654855 - 0.509896e-1 * n + 0.126749e-1 * n * n - 0.142039e-2 * std::pow(n, 3) +
         0.584525e-4 * std::pow(n, 4);  // eq. 5.62
}

double theta_max_K_rule(double n) {
  require_n_range(n, "the Theta_max(K_theta) rule (eq. 5.63)");
  return 0.7 * std::atan2(1.0, -n);
}

double pinned_pinned_gamma_curve_fit(double kappa0) {
  require_kappa_range(kappa0, "the pinned-pinned gamma fit (eqs. 5.138-5.139)");
  if (kappa0 <= 0.595) return 0.8005 - 0.0173 * kappa0;
  return 0.8063 - 0.0265 * kappa0;
}

double pinned_pinned_K_theta_curve_fit(double kappa0) {
  require_kappa_range(kappa0, "the pinned-pinned K_theta fit (eq. 5.142)");
  return 2.568 - 0.028 * kappa0 + 0.137 * kappa0 * kappa0;
}

}  // namespace flexure
