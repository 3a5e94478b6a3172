#include "flexure/solver/elliptic/elliptic_functions.h"

#include <fmt/format.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_ellint.h>

#include <cmath>
#include <numbers>

#include "flexure/solver/common/errors.h"
#include "flexure/solver/common/gsl_guard.h"
#include "flexure/solver/common/scalar_root.h"

namespace flexure::elliptic {
namespace {

struct GslHandlerOff {
  GslHandlerOff() { disable_gsl_abort(); }
};
const GslHandlerOff gsl_handler_off;

// Below this complementary parameter the AGM amplitude is refined (jacobi_amplitude): the first
// back-substitution of the AGM takes asin of an argument within about 2 sqrt(mc) of 1 and loses
// up to half the digits (an amplitude error of 2e-9 at mc = 1e-37, u = 43).
constexpr double kAmplitudeRefinement = 1e-4;

// The inverse problem is well conditioned, d phi/du = dn(u) <= 1, and F(phi|m) is increasing in
// phi, so the root of F(phi|m) = u bracketed around the AGM value and refined by Brent's method
// has full precision. (Plain Newton diverges: near phi = pi/2 F grows like ln(1/cos phi).)
double refine_amplitude(double phi, double u, Parameter k) {
  auto miss = [&](double p) { return incomplete_F(p, k) - u; };
  double width = 1e-7 * std::max(1.0, std::fabs(phi));
  double lo = phi - width, hi = phi + width;
  double f_lo = miss(lo), f_hi = miss(hi);
  for (int i = 0; i < 30 && !(f_lo <= 0.0 && f_hi >= 0.0); ++i) {
    width *= 8.0;
    if (f_lo > 0.0) {
      lo -= width;
      f_lo = miss(lo);
    }
    if (f_hi < 0.0) {
      hi += width;
      f_hi = miss(hi);
    }
  }
  if (!(f_lo <= 0.0 && f_hi >= 0.0)) return phi;
  ScalarRootOptions options;
  options.x_tolerance = 0.0;  // Brent's own 2 eps |x| term: the best double
  const ScalarRootResult root = brent_root(miss, lo, hi, f_lo, f_hi, options);
  return root.converged() ? root.x : phi;
}

}  // namespace

double carlson_rf(double x, double y, double z) {
  gsl_sf_result r;
  const int status = gsl_sf_ellint_RF_e(x, y, z, GSL_PREC_DOUBLE, &r);
  if (status != GSL_SUCCESS) {
    throw NoConvergence(
        fmt::format("GSL gsl_sf_ellint_RF({}, {}, {}) failed: {}", x, y, z, gsl_strerror(status)));
  }
  return r.val;
}

double carlson_rd(double x, double y, double z) {
  gsl_sf_result r;
  const int status = gsl_sf_ellint_RD_e(x, y, z, GSL_PREC_DOUBLE, &r);
  if (status != GSL_SUCCESS) {
    throw NoConvergence(
        fmt::format("GSL gsl_sf_ellint_RD({}, {}, {}) failed: {}", x, y, z, gsl_strerror(status)));
  }
  return r.val;
}

double complete_K(Parameter k) { return carlson_rf(0.0, k.mc, 1.0); }

double complete_K_minus_E_over_m(Parameter k) { return carlson_rd(0.0, k.mc, 1.0) / 3.0; }

double delta_amplitude(double phi, Parameter k) {
  const double c = std::cos(phi);
  return std::sqrt(k.mc + k.m * c * c);
}

IncompleteIntegrals incomplete_integrals(double phi, Parameter k) {
  // Reduce to |phi_r| <= pi/2 and add whole half-periods (Howell eqs. F.17-F.18).
  const double j = std::nearbyint(phi / std::numbers::pi);
  const double phi_r = phi - j * std::numbers::pi;
  const double s = std::sin(phi_r);
  const double c = std::cos(phi_r);
  const double delta2 = k.mc + k.m * c * c;
  IncompleteIntegrals out;
  if (s != 0.0) {
    out.F = s * carlson_rf(c * c, delta2, 1.0);
    out.D_over_m = s * s * s * carlson_rd(c * c, delta2, 1.0) / 3.0;
  }
  if (j != 0.0) {
    out.F += 2.0 * j * complete_K(k);
    out.D_over_m += 2.0 * j * complete_K_minus_E_over_m(k);
  }
  return out;
}

double incomplete_F(double phi, Parameter k) {
  const double j = std::nearbyint(phi / std::numbers::pi);
  const double phi_r = phi - j * std::numbers::pi;
  const double s = std::sin(phi_r);
  const double c = std::cos(phi_r);
  double F = (s != 0.0) ? s * carlson_rf(c * c, k.mc + k.m * c * c, 1.0) : 0.0;
  if (j != 0.0) F += 2.0 * j * complete_K(k);
  return F;
}

double incomplete_F(int half_turns, double sin_phi_r, double cos_phi_r, Parameter k) {
  double F =
      (sin_phi_r != 0.0)
          ? sin_phi_r * carlson_rf(cos_phi_r * cos_phi_r, k.mc + k.m * cos_phi_r * cos_phi_r, 1.0)
          : 0.0;
  if (half_turns != 0) F += 2.0 * half_turns * complete_K(k);
  return F;
}

double D_over_m_at(double u, double phi, Parameter k) {
  const IncompleteIntegrals integrals = incomplete_integrals(phi, k);
  if (k.m <= 0.5) return integrals.D_over_m;
  const double E = integrals.F - k.m * integrals.D_over_m;
  return (u - E) / k.m;
}

double jacobi_amplitude(double u, Parameter k) {
  if (k.m <= 0.0) return u;
  if (k.mc <= 0.0) return 2.0 * std::atan(std::tanh(0.5 * u));  // m = 1: gudermannian
  // Descending AGM (A&S 16.4.2-16.4.3): a_{n+1} = (a_n + b_n)/2, b_{n+1} = sqrt(a_n b_n),
  // c_{n+1} = (a_n - b_n)/2; phi_N = 2^N a_N u; phi_{n-1} = (phi_n + asin(c_n/a_n sin phi_n))/2.
  constexpr int kMaxLevels = 40;
  double a[kMaxLevels + 1];
  double c[kMaxLevels + 1];
  a[0] = 1.0;
  c[0] = std::sqrt(k.m);
  double b = std::sqrt(k.mc);
  int n = 0;
  // Stop once c_n is at round-off: the next term, c_n^2 / (4 a_n), is then far below it.
  while (n < kMaxLevels && std::fabs(c[n]) > 1e-15 * a[n]) {
    a[n + 1] = 0.5 * (a[n] + b);
    c[n + 1] = 0.5 * (a[n] - b);
    b = std::sqrt(a[n] * b);
    ++n;
  }
  double phi = std::ldexp(a[n] * u, n);
  for (int i = n; i > 0; --i) phi = 0.5 * (phi + std::asin(c[i] / a[i] * std::sin(phi)));
  if (k.mc < kAmplitudeRefinement) phi = refine_amplitude(phi, u, k);
  return phi;
}

}  // namespace flexure::elliptic
