#include "flexure/solver/elliptic/howell_branch.h"

#include <cmath>
#include <limits>

#include "flexure/solver/common/scalar_root.h"
#include "flexure/solver/elliptic/carlson_integrals.h"
#include "flexure/solver/elliptic/elliptic_functions.h"

namespace flexure::elliptic {
namespace {

// The modulus of the branch, held as p = k'^2 and q = k^2 - s0^2 with p + q = c0^2.
struct SplitModulus {
  double p = 0.0;
  double q = 0.0;
};

// p = c0^2 / (1 + e^-zeta), q = c0^2 / (1 + e^zeta): both keep full relative precision for any
// zeta, and ln(K - F(beta)) is close to linear in zeta at both ends (slope -1/2 for small loads,
// -1/(2 sqrt F) for large), which makes zeta a good unknown for the root finder.
SplitModulus split_from_zeta(double zeta, double c0_sq) {
  const double e = std::exp(-std::fabs(zeta));
  const double big = c0_sq / (1.0 + e);
  const double small = c0_sq * e / (1.0 + e);
  return zeta >= 0.0 ? SplitModulus{big, small} : SplitModulus{small, big};
}

// Amplitude beta* with K - F(beta, k) = F(beta*, k), from tan(beta) tan(beta*) = 1/k'.
struct ComplementAmplitude {
  double sin2 = 0.0;    // sin^2 beta*
  double cos2 = 0.0;    // cos^2 beta*
  double delta2 = 0.0;  // 1 - k^2 sin^2 beta*
  double k2 = 0.0;      // k^2
};

ComplementAmplitude complement_amplitude(SplitModulus split, double s0_sq) {
  ComplementAmplitude c;
  const double denom = split.q + split.p * s0_sq;
  c.k2 = s0_sq + split.q;
  c.sin2 = split.q / denom;
  c.cos2 = split.p * s0_sq / denom;
  c.delta2 = split.p * c.k2 / denom;
  return c;
}

// K(k) - F(beta, k) = u_tip - u_root: the arc length times sqrt(F) on the branch (Howell eq. 2.90).
double branch_length(SplitModulus split, double s0_sq) {
  const ComplementAmplitude c = complement_amplitude(split, s0_sq);
  return std::sqrt(c.sin2) * carlson_rf(c.cos2, c.delta2, 1.0);
}

HowellBranchSolution tip_from_split(SplitModulus split, double sqrtF, const PendulumProblem& pr) {
  const double s0_sq = pr.s0 * pr.s0;
  const ComplementAmplitude c = complement_amplitude(split, s0_sq);
  const double k = std::sqrt(c.k2);
  const double sin_beta_star = std::sqrt(c.sin2);
  // int_0^1 sin^2(chi/2) ds = [D(K) - D(beta)]/sqrt(F) with D = F - E; by the complement identity
  // E(beta) + E(beta*) = E + k^2 sin(beta) sin(beta*), D(K) - D(beta) = D(beta*) + k^2 sin(beta)
  // sin(beta*), a sum of positive terms.
  const double d_star = c.k2 * c.sin2 * sin_beta_star * carlson_rd(c.cos2, c.delta2, 1.0) / 3.0;
  const double sin2_integral = (d_star + k * pr.s0 * sin_beta_star) / sqrtF;
  // int_0^1 sin(chi) ds = 2k cos(beta)/sqrt(F) = 2 sqrt(q)/sqrt(F).
  const double sin_integral = 2.0 * std::sqrt(split.q) / sqrtF;
  const double cos_integral = 1.0 - 2.0 * sin2_integral;
  const double cp = std::cos(pr.psi);
  const double sp = std::sin(pr.psi);

  HowellBranchSolution out;
  out.tip.a_over_l = -cp * cos_integral + sp * sin_integral;
  out.tip.b_over_l = -cp * sin_integral - sp * cos_integral;
  // sin((chi1 - chi0)/2) sin((chi1 + chi0)/2) = k^2 - s0^2 = q, and sin((chi1 + chi0)/2) =
  // k c0 + k' s0 is a sum of positive terms.
  out.tip.theta0 = 2.0 * std::asin(split.q / (k * pr.c0 + std::sqrt(split.p) * pr.s0));
  out.root_moment = 2.0 * sqrtF * std::sqrt(split.q);

  ElasticaParameters& e = out.parameters;
  e.family = ElasticaFamily::kInflectional;
  e.force = sqrtF * sqrtF;
  e.psi = pr.psi;
  e.mu = 0.0;
  e.chi_tip = pr.chi0 + out.tip.theta0;
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
  const double log_target = std::log(sqrtF);
  int evaluations = 0;
  auto residual = [&](double zeta) {
    ++evaluations;
    return std::log(branch_length(split_from_zeta(zeta, c0_sq), s0_sq)) - log_target;
  };

  // Starting guess from the two asymptotes. Small loads: linear beam-column theory gives the tip
  // angle theta0 (Timoshenko & Gere, "Theory of Elastic Stability", §1.11) and
  // q = k^2 - s0^2 ~ s0 c0 theta0. Large loads: k' ~ 4 exp(-sqrt(F) - atanh(s0)), i.e.
  // p/c0^2 ~ 16 e^{-2 sqrt F}/(1 + s0)^2.
  double zeta0 = 0.0;
  const double axial = -force * std::cos(psi);  // compressive axial force, positive in compression
  const double transverse = force * std::sin(psi);
  const double kb = std::sqrt(std::fabs(axial));
  double theta_linear = std::numeric_limits<double>::infinity();
  if (axial >= 0.0 && kb < 1.4) {
    // theta0 = Q (sec k - 1)/P, written as 2 Q sin^2(k/2)/(k^2 cos k) to keep small k exact.
    const double h = kb > 0.0 ? std::sin(0.5 * kb) / (0.5 * kb) : 1.0;
    theta_linear = 0.5 * transverse * h * h / std::cos(kb);
  } else if (axial < 0.0) {
    const double h = std::sinh(0.5 * kb) / (0.5 * kb);
    theta_linear = 0.5 * transverse * h * h / std::cosh(kb);
  }
  const double q_linear = pr.s0 * pr.c0 * theta_linear;
  const double p_large = 16.0 * c0_sq * std::exp(-2.0 * sqrtF) / ((1.0 + pr.s0) * (1.0 + pr.s0));
  if (q_linear < 0.25 * c0_sq) {
    zeta0 = std::log((c0_sq - q_linear) / q_linear);
  } else if (p_large < 0.25 * c0_sq) {
    zeta0 = std::log(p_large / (c0_sq - p_large));
  }
  // ln(K - F(beta)) decreases in zeta with slope about -1/(2 max(sqrt F, 1)) and is nearly linear
  // at both ends, so a secant iteration from the asymptotic guess converges in a few steps. The
  // secant step is kept inside the bracket once one is known (bisection otherwise), so it cannot
  // diverge.
  double z0 = zeta0;
  double r0 = residual(z0);
  // First step with the asymptotic slope d ln G/d zeta ~ -(p + q/G)/(2 c0^2), G = K - F(beta):
  // -1/2 for small loads (G ~ sqrt q), -1/(2G) for large (G ~ -ln(p)/2).
  const SplitModulus split0 = split_from_zeta(z0, c0_sq);
  const double g0 = sqrtF * std::exp(r0);
  const double slope0 = -0.5 * (split0.p + split0.q / g0) / c0_sq;
  double z1 = z0 - r0 / slope0;
  double r1 = residual(z1);
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  auto update_bracket = [&](double z, double r) {
    if (r > 0.0) lo = std::max(lo, z);  // residual positive: load too small, root at larger zeta
    if (r < 0.0) hi = std::min(hi, z);
  };
  update_bracket(z0, r0);
  update_bracket(z1, r1);
  bool converged = r1 == 0.0;
  double zeta = z1;
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
    // Superlinear convergence: once the step is below the tolerance the error of z2 is far below
    // it, so z2 is accepted without another evaluation.
    if (std::fabs(z2 - z1) <= x_tolerance * std::max(1.0, std::fabs(z1))) {
      zeta = z2;
      converged = true;
      break;
    }
    z0 = z1;
    r0 = r1;
    z1 = z2;
    r1 = residual(z1);
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
    out = tip_from_split(split_from_zeta(root.x, c0_sq), sqrtF, pr);
    out.set_converged(true);
  }
  out.residual = root.f;
  out.iterations = evaluations;
  return out;
}

HowellBranchSolution howell_branch_from_tip_angle(double psi, double theta0) {
  PendulumProblem pr = make_pendulum_problem(1.0, psi, 0.0);
  // k = sin(chi1/2) with chi1 = chi0 + theta0; p = cos^2(chi1/2) = sin^2((psi - theta0)/2) and
  // q = sin(theta0/2) sin(psi - theta0/2), both without cancellation.
  const double half_gap = std::sin(0.5 * (psi - theta0));
  SplitModulus split;
  split.p = half_gap * half_gap;
  split.q = std::sin(0.5 * theta0) * std::sin(psi - 0.5 * theta0);
  const double sqrtF = branch_length(split, pr.s0 * pr.s0);
  pr.force = sqrtF * sqrtF;
  HowellBranchSolution out = tip_from_split(split, sqrtF, pr);
  out.set_converged(std::isfinite(sqrtF) && sqrtF > 0.0);
  out.tip.theta0 = theta0;  // exact by construction
  out.parameters.chi_tip = pr.chi0 + theta0;
  return out;
}

}  // namespace flexure::elliptic
