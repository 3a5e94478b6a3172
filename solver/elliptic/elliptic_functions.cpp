#include "flexure/solver/elliptic/elliptic_functions.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "flexure/solver/common/status.h"
#include "flexure/solver/elliptic/carlson_integrals.h"

namespace flexure::elliptic {
namespace {

constexpr double kPi = std::numbers::pi;

// The AGM converges quadratically: once |a - b| <= 1e-8 a, the mean (a + b)/2 differs from the
// limit by (a - b)^2/(16 a) <= 1e-17 a.
constexpr double kAgmTolerance = 1e-8;
constexpr int kMaxAgmLevels = 16;  // mc >= 1e-300 needs 12

void require_below_separatrix(Parameter k, const char* what) {
  if (!(k.mc > 0.0)) {
    throw NoConvergence(
        fmt::format("{} is infinite at m = 1 (got m = {}, 1 - m = {})", what, k.m, k.mc));
  }
}

// M(1, k') = pi / (2 K), DLMF 19.8.5.
double agm_of_complement(double mc) {
  double a = 1.0, b = std::sqrt(mc);
  for (int i = 0; i < kMaxAgmLevels && std::fabs(a - b) > kAgmTolerance * a; ++i) {
    const double next = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = next;
  }
  return 0.5 * (a + b);
}

}  // namespace

double complete_K(Parameter k) {
  require_below_separatrix(k, "K(m)");
  return 0.5 * kPi / agm_of_complement(k.mc);
}

double complete_K_minus_E_over_m(Parameter k) {
  require_below_separatrix(k, "K(m) - E(m)");
  // K - E = K sum_{n>=0} 2^(n-1) c_n^2 with c_0^2 = m (DLMF 19.8.2; Howell eq. F.10). Each term is
  // carried divided by m, and c_{n+1} = c_n^2 / (4 a_{n+1}) replaces (a_n - b_n)/2, so nothing
  // cancels and the limit m -> 0 (pi/4) is exact.
  double a = 1.0, b = std::sqrt(k.mc);
  double c2_over_m = 1.0;  // c_n^2 / m
  double sum = 0.5;        // the n = 0 term
  double weight = 0.5;     // 2^(n-1)
  for (int i = 0; i < kMaxAgmLevels; ++i) {
    const double next = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = next;
    c2_over_m *= c2_over_m * k.m / (16.0 * a * a);
    weight *= 2.0;
    const double term = weight * c2_over_m;
    sum += term;
    if (term <= 1e-17 * sum && std::fabs(a - b) <= kAgmTolerance * a) break;
  }
  return sum * 0.5 * kPi / (0.5 * (a + b));
}

double delta_amplitude(double phi, Parameter k) {
  const double c = std::cos(phi);
  return std::sqrt(k.mc + k.m * c * c);
}

IncompleteIntegrals incomplete_integrals(double phi, Parameter k) {
  // Reduce to |phi_r| <= pi/2 and add whole half-periods (Howell eqs. F.17-F.18).
  const double j = std::nearbyint(phi / kPi);
  const double phi_r = phi - j * kPi;
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
  const double j = std::nearbyint(phi / kPi);
  const double phi_r = phi - j * kPi;
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

namespace {

// `agm_mean`, when given, receives M(1, k') = pi / (2 K) (DLMF 19.8.5): 1 at m = 0, 0 at m = 1.
JacobiFunctions gauss_transformation(double u,
                                     Parameter k,
                                     bool with_amplitude,
                                     double* agm_mean = nullptr) {
  JacobiFunctions out;
  if (k.m <= 0.0) {
    if (agm_mean != nullptr) *agm_mean = 1.0;
    out = {std::sin(u), std::cos(u), 1.0, u};
    return out;
  }
  if (k.mc <= 0.0) {
    if (agm_mean != nullptr) *agm_mean = 0.0;
    // m = 1: sn = tanh, cn = dn = sech, am = the Gudermannian (DLMF 22.5.8).
    const double sech = 1.0 / std::cosh(u);
    out = {std::tanh(u), sech, sech, 2.0 * std::atan(std::tanh(0.5 * u))};
    return out;
  }
  // AGM from a_0 = 1, b_0 = k' (DLMF 22.20.1); a[i] and b[i] are kept for the way back.
  double a[kMaxAgmLevels + 1];
  double b[kMaxAgmLevels + 1];
  double inverse_a[kMaxAgmLevels + 1];
  int levels = 0;
  double mean = 1.0;
  {
    double an = 1.0, bn2 = k.mc;  // a_n and b_n^2
    for (int i = 0; i <= kMaxAgmLevels; ++i) {
      levels = i;
      a[i] = an;
      inverse_a[i] = 1.0 / an;  // off the critical path of the recurrence below
      b[i] = std::sqrt(bn2);
      mean = 0.5 * (an + b[i]);
      if (std::fabs(an - b[i]) <= kAgmTolerance * an) break;
      bn2 = an * b[i];
      an = mean;
    }
  }
  // At the top the parameter is 0 and the functions are the circular ones of v = M u = pi u/(2K);
  // the recurrence (Bulirsch 1965, procedure sncndn) carries the ratio cn/sn and dn back down. It
  // depends on v only through cot v, so v is reduced by whole half-turns j (am(u + 2K) = am(u) +
  // pi) and only the sign of sn follows sin v.
  if (agm_mean != nullptr) *agm_mean = mean;
  const double v = mean * u;
  const double turns = std::nearbyint(v / kPi);
  const double w = v - turns * kPi;  // |w| <= pi/2, cos w >= 0
  const double sin_w = std::sin(w);
  const double cos_w = std::cos(w);
  double sn_r = sin_w, cn_r = cos_w, dn = 1.0;
  if (sin_w != 0.0) {
    double ratio = cos_w / sin_w;  // cn/sn at the top
    double c = mean * ratio;
    for (int i = levels; i >= 0; --i) {
      ratio *= c;
      c *= dn;
      dn = (b[i] + ratio) / (a[i] + ratio);
      ratio = c * inverse_a[i];
    }
    const double s = 1.0 / std::sqrt(c * c + 1.0);
    sn_r = sin_w >= 0.0 ? s : -s;
    cn_r = c * sn_r;
  }
  // sn(u) = (-1)^j sn(r), cn(u) = (-1)^j cn(r) for u = r + 2jK; am(r) = atan2(sn(r), cn(r)) lies
  // in [-pi/2, pi/2] because cn(r) >= 0.
  const double parity = std::fmod(turns, 2.0) == 0.0 ? 1.0 : -1.0;
  out.sn = parity * sn_r;
  out.cn = parity * cn_r;
  out.dn = dn;
  out.am = with_amplitude ? turns * kPi + std::atan2(sn_r, cn_r)
                          : std::numeric_limits<double>::quiet_NaN();
  return out;
}

}  // namespace

JacobiFunctions jacobi_functions(double u, Parameter k) { return gauss_transformation(u, k, true); }

JacobiFunctions jacobi_sn_cn_dn(double u, Parameter k) { return gauss_transformation(u, k, false); }

JacobiFunctions jacobi_sn_cn_dn(double u, Parameter k, double& agm_mean) {
  return gauss_transformation(u, k, false, &agm_mean);
}

double jacobi_amplitude(double u, Parameter k) { return jacobi_functions(u, k).am; }

}  // namespace flexure::elliptic
