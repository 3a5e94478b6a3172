#include "flexure/solver/elliptic/howell_deflection.h"

#include <cmath>
#include <limits>
#include <numbers>

#include "flexure/solver/elliptic/carlson_integrals.h"
#include "flexure/solver/elliptic/howell_modulus.h"

namespace flexure::elliptic {
namespace {

constexpr int kMaxEvaluations = 60;
constexpr double kReliableComplement = 1e-8;  // k'^2 above which the slope keeps 8 digits

}  // namespace

BranchDeflection branch_deflection(double psi, double theta0) {
  const double s0 = std::cos(0.5 * psi), c0 = std::sin(0.5 * psi);
  const double s0_sq = s0 * s0;
  const SplitModulus split = split_from_tip_angle(psi, theta0);
  const ComplementAmplitude c = complement_amplitude(split, s0_sq);
  const CarlsonPair carlson = carlson_rf_rd(c.cos2, c.delta2, 1.0);
  const double sin_b = std::sqrt(c.sin2), cos_b = std::sqrt(c.cos2), delta = std::sqrt(c.delta2);
  const double k = std::sqrt(c.k2);
  // sqrt(F) = G = F(beta*|k^2) (Howell eq. 2.90) and D = F(beta*) - E(beta*) (DLMF 19.25.5,
  // 19.25.9). The tip integrals (as in howell_branch.cpp): int sin chi ds = N1/G with
  // N1 = 2 sqrt(q), int sin^2(chi/2) ds = N2/G with N2 = D + k s0 sin(beta*); then
  // b/l = -cos(psi) N1/G - sin(psi) (1 - 2 N2/G).
  const double G = sin_b * carlson.rf;
  const double D = c.k2 * c.sin2 * sin_b * carlson.rd / 3.0;
  const double root_q = std::sqrt(split.q);
  const double N1 = 2.0 * root_q;
  const double N2 = D + k * s0 * sin_b;
  const double cp = (s0 - c0) * (s0 + c0);
  const double sp = 2.0 * s0 * c0;

  BranchDeflection out;
  out.force = G * G;
  out.b = -cp * N1 / G - sp * (1.0 - 2.0 * N2 / G);
  // Slope, through q (dq/dtheta0 = sin(psi - theta0)/2, m = k^2 = s0^2 + q):
  //   dS/dq = s0^2 c0^2/(q + p s0^2)^2 for S = sin^2 beta*, d beta*/dq = (dS/dq)/(2 sin cos),
  //   dF/dphi = 1/Delta, dF/dm = [F - D/m - sin cos/Delta]/(2 k'^2),
  //   dD/dphi = m sin^2/Delta, dD/dm = dF/dm + D/(2m)
  // (DLMF 19.2.4, 19.2.5 and §19.4(i): dE/dm = (E - F)/(2m)).
  const double denom = split.q + split.p * s0_sq;
  const double dS = s0_sq * c0 * c0 / (denom * denom);
  const double dbeta = dS / (2.0 * sin_b * cos_b);
  const double dF_dm = (G - D / c.k2 - sin_b * cos_b / delta) / (2.0 * split.p);
  const double dG = dbeta / delta + dF_dm;
  const double dD = c.k2 * c.sin2 / delta * dbeta + dF_dm + D / (2.0 * c.k2);
  const double dN1 = 1.0 / root_q;
  const double dN2 = dD + s0 * (0.5 * sin_b / k + k * cos_b * dbeta);
  const double db_dq = (-cp * (dN1 * G - N1 * dG) + 2.0 * sp * (dN2 * G - N2 * dG)) / (G * G);
  out.slope = 0.5 * std::sin(psi - theta0) * db_dq;
  out.slope_reliable = split.p > kReliableComplement && std::isfinite(out.slope);
  return out;
}

DeflectionInverse first_tip_angle_for_deflection(double psi, double target, double max_force) {
  DeflectionInverse out;
  if (!(target > 0.0 && target < 1.0 && psi > 0.0 && psi < std::numbers::pi)) return out;
  // b(theta0) < target on (0, lo] (b rises there); b(hi) >= target once have_hi. Under the one
  // interior maximum of b (howell_deflection.h), a bracket [lo, hi] holds exactly one crossing:
  // the first.
  double lo = 0.0, hi = psi;
  bool have_hi = false;
  // Linear theory: b/l = 2 theta0/3 for small loads.
  double theta = std::min(1.5 * target, 0.5 * psi);
  double previous_theta = std::numeric_limits<double>::quiet_NaN();
  double previous_slope = std::numeric_limits<double>::quiet_NaN();
  while (out.evaluations < kMaxEvaluations) {
    const BranchDeflection d = branch_deflection(psi, theta);
    ++out.evaluations;
    if (!std::isfinite(d.b) || !d.slope_reliable || !(d.force <= max_force)) return out;
    const double miss = d.b - target;
    if (miss == 0.0) {
      out.found = true;
      out.theta0 = theta;
      return out;
    }
    if (miss < 0.0) {
      // Below the target while b falls: past the peak. The first crossing, if any, lies before
      // it; locating it needs the peak, which this search does not look for.
      if (!(d.slope > 0.0)) return out;
      lo = theta;
    } else {
      hi = theta;
      have_hi = true;
    }
    double next = theta - miss / d.slope;
    const double upper = have_hi ? hi : psi;
    const bool newton = d.slope > 0.0 && next > lo && next < upper;
    if (!newton) next = have_hi ? 0.5 * (lo + hi) : theta + 0.5 * (psi - theta);
    const double step = std::fabs(next - theta);
    if (newton) {
      // Newton's error after this step is C step^2, C = |b''/(2 b')| estimated from the slopes at
      // the last two tip angles: accept `next` without another evaluation once that is below
      // round-off (and the estimate is in the asymptotic regime).
      double curvature = std::numeric_limits<double>::infinity();
      if (std::isfinite(previous_slope) && theta != previous_theta) {
        curvature =
            std::fabs((d.slope - previous_slope) / (theta - previous_theta) / (2.0 * d.slope));
      }
      if (step <= 4.0 * std::numeric_limits<double>::epsilon() * theta ||
          (curvature * step < 0.1 && curvature * step * step <= 1e-17 * theta)) {
        out.found = true;
        out.theta0 = next;
        return out;
      }
    }
    previous_theta = theta;
    previous_slope = d.slope;
    theta = next;
  }
  return out;
}

}  // namespace flexure::elliptic
