#include "flexure/solver/elliptic/howell_branch.h"

#include <cmath>
#include <limits>

#include "flexure/solver/common/scalar_root.h"
#include "flexure/solver/elliptic/carlson_integrals.h"
#include "flexure/solver/elliptic/elliptic_functions.h"
#include "flexure/solver/elliptic/howell_modulus.h"

namespace flexure::elliptic {
namespace {

// p = c0^2 / (1 + e^-zeta), q = c0^2 / (1 + e^zeta): both keep full relative precision for any
// zeta, and ln(K - F(beta)) is close to linear in zeta at both ends (slope -1/2 for small loads,
// -1/(2 sqrt F) for large), which makes zeta a good unknown for the root finder.
SplitModulus split_from_zeta(double zeta, double c0_sq) {
  const double e = std::exp(-std::fabs(zeta));
  const double big = c0_sq / (1.0 + e);
  const double small = big * e;
  return zeta >= 0.0 ? SplitModulus{big, small} : SplitModulus{small, big};
}

// K(k) - F(beta, k) = u_tip - u_root: the arc length times sqrt(F) on the branch (Howell eq. 2.90).
double branch_length(SplitModulus split, double s0_sq) {
  const ComplementAmplitude c = complement_amplitude(split, s0_sq);
  return std::sqrt(c.sin2) * carlson_rf(c.cos2, c.delta2, 1.0);
}

// G(zeta) = F(beta*|m) and dG/dzeta, for the Newton step from the starting guess. With
// m = k^2 = s0^2 + q, S = sin^2 beta* = q/(q + p s0^2) and dq/dzeta = -p q/c0^2:
//   dS/dzeta = -s0^2 p q/(q + p s0^2)^2,  d beta*/dzeta = (dS/dzeta)/(2 sin beta* cos beta*),
//   dF/dphi = 1/Delta,  dF/dm = [F - (F - E)/m - sin phi cos phi/Delta]/(2 (1 - m))
// (DLMF 19.2.4 and §19.4(i), the k-derivative rewritten for m). F - E comes from the same
// duplication as F (carlson_rf_rd). The bracket of dF/dm loses about -log10(p) digits to
// cancellation as p -> 0, so the caller uses it only for p > 1e-8 (eight digits left, plenty for
// a Newton step).
struct BranchLengthAndSlope {
  double G = 0.0;
  double slope = 0.0;  // dG/dzeta
};
BranchLengthAndSlope branch_length_and_slope(SplitModulus split, double s0_sq, double c0_sq) {
  const ComplementAmplitude c = complement_amplitude(split, s0_sq);
  const CarlsonPair carlson = carlson_rf_rd(c.cos2, c.delta2, 1.0);
  const double sin_b = std::sqrt(c.sin2), cos_b = std::sqrt(c.cos2), delta = std::sqrt(c.delta2);
  const double F = sin_b * carlson.rf;
  const double F_minus_E = c.k2 * c.sin2 * sin_b * carlson.rd / 3.0;
  const double denom = split.q + split.p * s0_sq;
  const double dS = -s0_sq * split.p * split.q / (denom * denom);
  const double dF_dm = (F - F_minus_E / c.k2 - sin_b * cos_b / delta) / (2.0 * split.p);
  const double dm = -split.p * split.q / c0_sq;
  return {F, dS / (2.0 * sin_b * cos_b * delta) + dF_dm * dm};
}

// The tip angle of the branch: sin((chi1 - chi0)/2) sin((chi1 + chi0)/2) = k^2 - s0^2 = q, and
// sin((chi1 + chi0)/2) = k c0 + k' s0 is a sum of positive terms.
double tip_angle_from_split(SplitModulus split, const PendulumProblem& pr) {
  const double k = std::sqrt(pr.s0 * pr.s0 + split.q);
  return 2.0 * std::asin(split.q / (k * pr.c0 + std::sqrt(split.p) * pr.s0));
}

// The tip and the shape parameters of the branch with modulus `split`, load sqrt(F), tip angle
// theta0, given rd = R_D(cos^2 beta*, 1 - k^2 sin^2 beta*, 1).
HowellBranchSolution tip_from_split(
    SplitModulus split, double sqrtF, double theta0, double rd, const PendulumProblem& pr) {
  const double s0_sq = pr.s0 * pr.s0;
  const ComplementAmplitude c = complement_amplitude(split, s0_sq);
  const double k = std::sqrt(c.k2);
  const double sin_beta_star = std::sqrt(c.sin2);
  // int_0^1 sin^2(chi/2) ds = [D(K) - D(beta)]/sqrt(F) with D = F - E; by the complement identity
  // E(beta) + E(beta*) = E + k^2 sin(beta) sin(beta*), D(K) - D(beta) = D(beta*) + k^2 sin(beta)
  // sin(beta*), a sum of positive terms; D(beta*) = k^2 sin^3(beta*) R_D / 3 (DLMF 19.25.9).
  const double d_star = c.k2 * c.sin2 * sin_beta_star * rd / 3.0;
  const double sin2_integral = (d_star + k * pr.s0 * sin_beta_star) / sqrtF;
  // int_0^1 sin(chi) ds = 2k cos(beta)/sqrt(F) = 2 sqrt(q)/sqrt(F).
  const double sin_integral = 2.0 * std::sqrt(split.q) / sqrtF;
  const double cos_integral = 1.0 - 2.0 * sin2_integral;
  // cos(psi) and sin(psi) from the half angles already at hand (s0 = cos(psi/2), c0 = sin(psi/2)).
  const double cp = (pr.s0 - pr.c0) * (pr.s0 + pr.c0);
  const double sp = 2.0 * pr.s0 * pr.c0;

  HowellBranchSolution out;
  out.tip.a_over_l = -cp * cos_integral + sp * sin_integral;
  out.tip.b_over_l = -cp * sin_integral - sp * cos_integral;
  out.tip.theta0 = theta0;
  out.root_moment = 2.0 * sqrtF * std::sqrt(split.q);

  ElasticaParameters& e = out.parameters;
  e.family = ElasticaFamily::kInflectional;
  e.force = sqrtF * sqrtF;
  e.psi = pr.psi;
  e.mu = 0.0;
  e.chi_tip = pr.chi0 + theta0;
  e.modulus2 = c.k2;
  e.complement2 = split.p;
  e.u_tip = complete_K({c.k2, split.p});
  e.u_root = e.u_tip - sqrtF;
  e.winding = 0;
  return out;
}

}  // namespace

HowellBranchSolution solve_howell_branch(double force, double psi, double x_tolerance) {
  const PendulumProblem pr = make_pendulum_problem(force, psi, 0.0);
  const double c0_sq = pr.c0 * pr.c0;
  const double s0_sq = pr.s0 * pr.s0;
  const double sqrtF = std::sqrt(force);
  int evaluations = 0;
  // The equation G(zeta) = sqrt(F), G = K - F(beta) (Howell eq. 2.90), written as
  // rho = (G - sqrt F) + ln(G / sqrt F) = 0. G falls like e^(-zeta/2) for small loads and like
  // -zeta/2 for large ones, so G + ln G is close to linear in zeta over the whole range (slope
  // between -1/2 and -1): the secant iteration below converges from far away in few steps. The
  // logarithm of the ratio keeps full relative precision in G at loads down to 1e-200.
  auto residual = [&](double zeta, double& g) {
    ++evaluations;
    g = branch_length(split_from_zeta(zeta, c0_sq), s0_sq);
    return (g - sqrtF) + std::log(g / sqrtF);
  };

  // Starting guess from the two asymptotes, whichever is deeper inside its range. Small loads:
  // linear beam-column theory gives the tip angle theta0 (Timoshenko & Gere, "Theory of Elastic
  // Stability", §1.11) and q = k^2 - s0^2 ~ s0 c0 theta0. Large loads: k' ~ 4 exp(-sqrt(F) -
  // atanh(s0)), i.e. p/c0^2 ~ 16 e^{-2 sqrt F}/(1 + s0)^2.
  // Compressive axial force (positive in compression) and transverse force, F cos(psi) and
  // F sin(psi) from the half angles.
  const double axial = -force * (pr.s0 - pr.c0) * (pr.s0 + pr.c0);
  const double transverse = 2.0 * force * pr.s0 * pr.c0;
  const double kb = std::sqrt(std::fabs(axial));
  double theta_linear = std::numeric_limits<double>::infinity();
  if (kb < 1e-3) {
    theta_linear = 0.5 * transverse;  // the axial load changes it by 5 kb^2/12 relative
  } else if (axial >= 0.0 && kb < 1.4) {
    // theta0 = Q (sec k - 1)/P, written as 2 Q sin^2(k/2)/(k^2 cos k) to keep small k exact.
    const double h = kb > 0.0 ? std::sin(0.5 * kb) / (0.5 * kb) : 1.0;
    theta_linear = 0.5 * transverse * h * h / std::cos(kb);
  } else if (axial < 0.0) {
    const double h = std::sinh(0.5 * kb) / (0.5 * kb);
    theta_linear = 0.5 * transverse * h * h / std::cosh(kb);
  }
  const double q_linear = pr.s0 * pr.c0 * theta_linear;
  const double p_large = 16.0 * c0_sq * std::exp(-2.0 * sqrtF) / ((1.0 + pr.s0) * (1.0 + pr.s0));
  double z0 = 0.0;
  if (q_linear < p_large && q_linear < c0_sq) {
    z0 = std::log((c0_sq - q_linear) / q_linear);
  } else if (p_large < c0_sq) {
    z0 = std::log(p_large / (c0_sq - p_large));
  }

  // First step: Newton with the exact slope of G where it is accurate (above), otherwise the
  // asymptotic one, d ln G/d zeta ~ -(p + q/G)/(2 c0^2) (-1/2 for small loads, where G ~ sqrt q;
  // -1/(2G) for large, where G ~ -ln(p)/2). Either way d rho/d zeta = (1 + 1/G) dG/d zeta.
  const SplitModulus split0 = split_from_zeta(z0, c0_sq);
  const bool exact_slope = split0.p > 1e-8;
  double g0 = 0.0;
  double slope0 = 0.0;
  ++evaluations;
  if (exact_slope) {
    const BranchLengthAndSlope gs = branch_length_and_slope(split0, s0_sq, c0_sq);
    g0 = gs.G;
    slope0 = gs.slope * (1.0 + 1.0 / g0);
  } else {
    g0 = branch_length(split0, s0_sq);
    slope0 = -(split0.p * g0 + split0.q) * (1.0 + g0) / (2.0 * c0_sq * g0);
  }
  double r0 = (g0 - sqrtF) + std::log(g0 / sqrtF);
  double z1 = z0 - r0 / slope0;
  // Newton's error is C (z1 - z0)^2 with C = rho''/(2 rho') well below 1 here (rho is nearly
  // linear): a step below a tenth of the square root of the tolerance needs no further evaluation.
  if (exact_slope && std::isfinite(z1) &&
      (z1 - z0) * (z1 - z0) <= 0.01 * x_tolerance * std::max(1.0, std::fabs(z1))) {
    HowellBranchSolution out;
    const SplitModulus split = split_from_zeta(z1, c0_sq);
    const ComplementAmplitude c = complement_amplitude(split, s0_sq);
    out = tip_from_split(
        split, sqrtF, tip_angle_from_split(split, pr), carlson_rd(c.cos2, c.delta2, 1.0), pr);
    out.set_converged(true);
    out.residual = r0;
    out.iterations = evaluations;
    return out;
  }
  double g1 = 0.0;
  double r1 = residual(z1, g1);
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  auto update_bracket = [&](double z, double r) {
    if (r > 0.0) lo = std::max(lo, z);  // residual positive: load too small, root at larger zeta
    if (r < 0.0) hi = std::min(hi, z);
  };
  update_bracket(z0, r0);
  update_bracket(z1, r1);
  // The secant step is kept inside the bracket once one is known (bisection otherwise), so it
  // cannot diverge.
  bool converged = r1 == 0.0;
  double zeta = z1;
  // The slope of the pair before (z0, z1), for the error estimate: at first the exact slope at z0
  // (a confluent divided difference), if there is one.
  double z_before = z0;
  double d_before = exact_slope ? slope0 : std::numeric_limits<double>::quiet_NaN();
  constexpr int kMaxIterations = 100;
  for (int iter = 0; iter < kMaxIterations && !converged; ++iter) {
    double z2 = (r1 != r0) ? z1 - r1 * (z1 - z0) / (r1 - r0) : z1;
    if (!(z2 > lo && z2 < hi) || !std::isfinite(z2)) {
      // Outside the bracket: bisect if both ends are known, otherwise step outwards.
      if (std::isfinite(lo) && std::isfinite(hi)) {
        z2 = 0.5 * (lo + hi);
      } else {
        z2 = std::isfinite(lo) ? lo + 2.0 * std::fabs(z1 - z0) + 1.0
                               : hi - 2.0 * std::fabs(z1 - z0) - 1.0;
      }
    }
    const double tolerance = x_tolerance * std::max(1.0, std::fabs(z1));
    // Superlinear convergence: once the step is below the tolerance the error of z2 is far below
    // it, so z2 is accepted without another evaluation.
    if (std::fabs(z2 - z1) <= tolerance) {
      zeta = z2;
      converged = true;
      break;
    }
    // The secant error obeys e2 = C e1 e0 with C = f''/(2 f') near the root; with C estimated from
    // the second divided difference of the last three points, z2 is accepted without another
    // evaluation once its predicted error is a hundredth of the tolerance (and the estimate
    // itself is in the asymptotic regime, C |z2 - z1| < 0.1).
    if (std::isfinite(d_before) && z1 != z0 && z1 != z_before) {
      const double d10 = (r1 - r0) / (z1 - z0);
      const double c = std::fabs((d10 - d_before) / (z1 - z_before) / d10);
      const double step = std::fabs(z2 - z1);
      if (c * step < 0.1 && c * step * std::fabs(z1 - z0) <= 0.01 * tolerance) {
        zeta = z2;
        converged = true;
        break;
      }
    }
    d_before = (z1 != z0) ? (r1 - r0) / (z1 - z0) : std::numeric_limits<double>::quiet_NaN();
    z_before = z0;
    z0 = z1;
    r0 = r1;
    z1 = z2;
    r1 = residual(z1, g1);
    update_bracket(z1, r1);
    zeta = z1;
    if (r1 == 0.0 || (std::isfinite(lo) && std::isfinite(hi) &&
                      hi - lo <= x_tolerance * std::max(1.0, std::fabs(z1)))) {
      converged = true;
    }
  }
  ScalarRootResult root;
  root.set_converged(converged && std::isfinite(r1));
  root.x = zeta;
  root.f = r1;

  HowellBranchSolution out;
  if (root.converged()) {
    const SplitModulus split = split_from_zeta(root.x, c0_sq);
    const ComplementAmplitude c = complement_amplitude(split, s0_sq);
    out = tip_from_split(
        split, sqrtF, tip_angle_from_split(split, pr), carlson_rd(c.cos2, c.delta2, 1.0), pr);
    out.set_converged(true);
  }
  out.residual = root.f;
  out.iterations = evaluations;
  return out;
}

HowellBranchSolution howell_branch_from_tip_angle(double psi, double theta0) {
  PendulumProblem pr = make_pendulum_problem(1.0, psi, 0.0);
  const SplitModulus split = split_from_tip_angle(psi, theta0);
  // sqrt(F) = F(beta*, k) (Howell eq. 2.90) and the R_D of the tip integrals share their
  // arguments: one duplication sequence gives both.
  const ComplementAmplitude c = complement_amplitude(split, pr.s0 * pr.s0);
  const CarlsonPair carlson = carlson_rf_rd(c.cos2, c.delta2, 1.0);
  const double sqrtF = std::sqrt(c.sin2) * carlson.rf;
  pr.force = sqrtF * sqrtF;
  HowellBranchSolution out = tip_from_split(split, sqrtF, theta0, carlson.rd, pr);
  out.set_converged(std::isfinite(sqrtF) && sqrtF > 0.0);
  return out;
}

}  // namespace flexure::elliptic
