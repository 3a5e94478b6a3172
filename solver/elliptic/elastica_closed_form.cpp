#include "flexure/solver/elliptic/elastica_closed_form.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "flexure/solver/elliptic/elliptic_functions.h"

namespace flexure {

const char* to_string(ElasticaFamily family) {
  switch (family) {
    case ElasticaFamily::kStraight:
      return "straight";
    case ElasticaFamily::kCircularArc:
      return "circular arc";
    case ElasticaFamily::kInflectional:
      return "inflectional";
    case ElasticaFamily::kNonInflectional:
      return "non-inflectional";
  }
  return "unknown";
}

namespace elliptic {
namespace {

constexpr double kPi = std::numbers::pi;

Parameter parameter_of(const ElasticaParameters& p) { return {p.modulus2, p.complement2}; }

}  // namespace

PendulumProblem make_pendulum_problem(double force, double psi, double mu) {
  PendulumProblem p;
  p.force = force;
  p.psi = psi;
  p.mu = mu;
  p.chi0 = kPi - psi;
  p.s0 = std::cos(0.5 * psi);
  p.c0 = std::sin(0.5 * psi);
  return p;
}

double TipState::t() const { return 2.0 * kPi * winding + tau; }

TipState tip_state_from_angle(const PendulumProblem& problem, double tip_from_force) {
  const double winding = std::nearbyint(tip_from_force / (2.0 * kPi));
  return tip_state_from_reduced_angle(
      problem, static_cast<int>(winding), tip_from_force - 2.0 * kPi * winding);
}

TipState tip_state_from_reduced_angle(const PendulumProblem& problem, int winding, double tau) {
  const double F = problem.force;
  const double mu = problem.mu;
  const double parity = winding % 2 == 0 ? 1.0 : -1.0;
  TipState tip;
  tip.winding = winding;
  tip.tau = tau;
  // sin(chi1/2) = cos(t/2) = (-1)^winding cos(tau/2), cos(chi1/2) = -sin(t/2).
  tip.half_sin = parity * std::cos(0.5 * tau);
  tip.half_cos = -parity * std::sin(0.5 * tau);
  // (H + F)/2 = mu^2/4 + F sin^2(chi1/2) and (F - H)/2 = F cos^2(chi1/2) - mu^2/4: the sign of the
  // second decides the family (docs/theory-elliptic.md).
  tip.h_plus = 0.25 * mu * mu + F * tip.half_sin * tip.half_sin;
  tip.h_minus = F * tip.half_cos * tip.half_cos - 0.25 * mu * mu;
  return tip;
}

bool tip_state_near_separatrix(
    const PendulumProblem& problem, double w, int side, int winding, TipState& tip) {
  const double F = problem.force;
  const double quarter_mu2 = 0.25 * problem.mu * problem.mu;
  // sin^2(tau/2) = (h_minus + mu^2/4)/F.
  const double a = w + quarter_mu2 / F;
  const double b = (F - w * F - quarter_mu2) / F;  // cos^2(tau/2), formed without 1 - a
  if (!(a >= 0.0 && b >= 0.0)) return false;
  const double parity = winding % 2 == 0 ? 1.0 : -1.0;
  tip.winding = winding;
  tip.tau = side * 2.0 * std::asin(std::min(1.0, std::sqrt(a)));
  tip.half_sin = parity * std::sqrt(b);
  tip.half_cos = -parity * side * std::sqrt(a);
  tip.h_minus = w * F;
  tip.h_plus = F - tip.h_minus;
  return true;
}

BackwardIntegration integrate_from_tip(const PendulumProblem& problem, double tip_from_force) {
  return integrate_from_tip(problem, tip_state_from_angle(problem, tip_from_force));
}

BackwardIntegration integrate_from_tip(const PendulumProblem& problem, const TipState& tip) {
  const double F = problem.force;
  const double mu = problem.mu;
  const double chi_tip = tip.t() + kPi;
  // chi_tip = 2 pi winding + pi + tau lies between 2 pi winding and 2 pi (winding + 1): the
  // nearest multiple of 2 pi (family A's centre of oscillation) and the nearest multiple of pi in
  // chi_tip/2 (family B's half-turns) follow from the sign of tau, never from rounding.
  const int upper = tip.winding + (tip.tau > 0.0 ? 1 : 0);
  const double half_sin = tip.half_sin;
  const double half_cos = tip.half_cos;
  const double h_plus = tip.h_plus;
  const double h_minus = tip.h_minus;

  BackwardIntegration out;
  ElasticaParameters& e = out.parameters;
  e.force = F;
  e.psi = problem.psi;
  e.mu = mu;
  e.chi_tip = chi_tip;
  if (h_minus > 0.0 || mu == 0.0) {
    // Family A: sin(chi/2) = k sn(u), chi' = 2 k sqrt(F) cn(u), u = sqrt(F) s + u0.
    e.family = ElasticaFamily::kInflectional;
    e.modulus2 = h_plus / F;
    e.complement2 = std::max(h_minus / F, 0.0);
    const Parameter k{e.modulus2, e.complement2};
    const double kk = std::sqrt(e.modulus2);
    const double sqrtF = std::sqrt(F);
    e.winding = upper;
    // Tip amplitude: sin(phi1) = sin(chi1/2 - pi w)/k, cos(phi1) = mu/(2 k sqrt(F)); reduced to
    // |phi_r| <= pi/2 by whole half-turns so that its cosine is never formed by subtraction.
    const double sin_phi = (e.winding % 2 == 0 ? half_sin : -half_sin) / kk;
    const double cos_phi = 0.5 * mu / (kk * sqrtF);
    const int turns = cos_phi >= 0.0 ? 0 : (sin_phi >= 0.0 ? 1 : -1);
    e.u_tip = turns == 0 ? incomplete_F(0, sin_phi, cos_phi, k)
                         : incomplete_F(turns, -sin_phi, -cos_phi, k);
    e.u_root = e.u_tip - sqrtF;
    const JacobiFunctions root = jacobi_sn_cn_dn(e.u_root, k);
    out.chi_root = 2.0 * kPi * e.winding + 2.0 * std::atan2(kk * root.sn, root.dn);
  } else {
    // Family B: chi = 2 am(v), chi' = 2 sigma q dn(v), v = sigma q s + v0, q^2 = (H + F)/2.
    e.family = ElasticaFamily::kNonInflectional;
    e.modulus2 = F / h_plus;
    // fabs, not negation: on the separatrix itself h_minus = +0 and -0/h_plus is -0, which
    // Carlson's R_F rejects as a second zero argument (the limit m = 1 is regular here).
    e.complement2 = std::fabs(h_minus) / h_plus;
    const Parameter m{e.modulus2, e.complement2};
    const double q = std::sqrt(h_plus);
    const double sigma = mu > 0.0 ? 1.0 : -1.0;
    // Amplitude chi1/2 = j pi + phi_r: sin(phi_r) = (-1)^j cos(t/2), cos(phi_r) = (-1)^(j+1)
    // sin(t/2). The whole half-turns j are kept out of the elliptic argument (am(v + 2jK) =
    // am(v) + j pi): chi = 2 pi j + 2 am(v). K is never needed, which keeps the separatrix itself
    // (m = 1, K infinite) regular and spares the subtraction of large multiples of K.
    const int turns = upper;
    const double parity = turns % 2 == 0 ? 1.0 : -1.0;
    e.winding = turns;
    e.u_tip = incomplete_F(0, parity * half_sin, parity * half_cos, m);
    e.u_root = e.u_tip - sigma * q;
    out.chi_root = 2.0 * kPi * turns + 2.0 * jacobi_amplitude(e.u_root, m);
  }
  return out;
}

double tip_angle_residual(const PendulumProblem& problem, double tip_from_force) {
  return integrate_from_tip(problem, tip_from_force).chi_root - problem.chi0;
}

double tip_angle_residual(const PendulumProblem& problem, const TipState& tip) {
  return integrate_from_tip(problem, tip).chi_root - problem.chi0;
}

double tip_angle_residual_by_addition(const PendulumProblem& problem, const TipState& tip) {
  // Below this denominator the addition formulas are not used (see the header).
  constexpr double kMinDenominator = 1e-3;
  const double F = problem.force;
  const double mu = problem.mu;
  // The same families, windings and tip amplitudes as integrate_from_tip.
  const int upper = tip.winding + (tip.tau > 0.0 ? 1 : 0);
  if (tip.h_minus > 0.0 || mu == 0.0) {
    // Family A: sin(chi/2) = k sn(u), chi' = 2 k sqrt(F) cn(u), u_root = u_tip - sqrt(F).
    const double m = tip.h_plus / F;
    const Parameter k{m, std::max(tip.h_minus / F, 0.0)};
    const double kk = std::sqrt(m);
    const double sqrtF = std::sqrt(F);
    // sn(u_tip) = sin(phi1), cn(u_tip) = cos(phi1) = mu / (2 k sqrt(F)), dn(u_tip) by
    // delta_amplitude's form sqrt(mc + m cn^2).
    const double s1 = (upper % 2 == 0 ? tip.half_sin : -tip.half_sin) / kk;
    const double c1 = 0.5 * mu / (kk * sqrtF);
    const double d1 = std::sqrt(k.mc + m * c1 * c1);
    const JacobiFunctions l = jacobi_sn_cn_dn(sqrtF, k);
    if (c1 * c1 + s1 * s1 * l.dn * l.dn < kMinDenominator) return tip_angle_residual(problem, tip);
    // DLMF 22.8.1 and 22.8.3 with v = -L, both numerators over the same positive denominator:
    // chi_root = 2 pi w + 2 atan2(k sn(u_root), dn(u_root)) as in integrate_from_tip.
    const double sn_root = s1 * l.cn * l.dn - l.sn * c1 * d1;
    const double dn_root = d1 * l.dn + m * s1 * c1 * l.sn * l.cn;
    return 2.0 * kPi * upper + 2.0 * std::atan2(kk * sn_root, dn_root) - problem.chi0;
  }
  // Family B: chi = 2 am(v), v_root = v_tip - sigma q, am(v_tip) = phi_r with |phi_r| <= pi/2.
  const double m = F / tip.h_plus;
  const Parameter k{m, std::fabs(tip.h_minus) / tip.h_plus};
  const double length = (mu > 0.0 ? 1.0 : -1.0) * std::sqrt(tip.h_plus);  // L = sigma q
  const double parity = upper % 2 == 0 ? 1.0 : -1.0;
  const double s1 = parity * tip.half_sin;
  const double c1 = parity * tip.half_cos;
  const double d1 = std::sqrt(k.mc + m * c1 * c1);
  double agm_mean = 0.0;  // pi / (2 K)
  const JacobiFunctions l = jacobi_sn_cn_dn(length, k, agm_mean);
  if (c1 * c1 + s1 * s1 * l.dn * l.dn < kMinDenominator) return tip_angle_residual(problem, tip);
  // sn and cn at the clamp (DLMF 22.8.1, 22.8.2 with v = -L) give am(v_root) modulo 2 pi. The
  // whole turns: with L = 2 K j + r, 0 <= r < 2 K, am(v_tip) - am(v_root) = j pi + (am(v_tip) -
  // am(v_tip - r)), the last in [0, pi) because am rises by pi per 2 K (Howell eq. F.17); at m = 1
  // (K infinite) j = 0 for L >= 0 and -1 for L < 0.
  const double sn_root = s1 * l.cn * l.dn - l.sn * c1 * d1;
  const double cn_root = c1 * l.cn + s1 * l.sn * d1 * l.dn;
  const double j =
      agm_mean > 0.0 ? std::floor(length * agm_mean / kPi) : (length >= 0.0 ? 0.0 : -1.0);
  // am(v_tip) = chi1/2 - pi upper = tau/2 -+ pi/2 (c1 >= 0 puts it in [-pi/2, pi/2]).
  const double phi_tip = 0.5 * tip.tau + (tip.tau > 0.0 ? -0.5 * kPi : 0.5 * kPi);
  // The drop of the amplitude, reduced into [j pi - pi/2, j pi + 3 pi/2).
  const double low = j * kPi - 0.5 * kPi;
  double drop = phi_tip - std::atan2(sn_root, cn_root) - low;
  drop = low + drop - 2.0 * kPi * std::floor(drop / (2.0 * kPi));
  return 2.0 * kPi * upper + 2.0 * (phi_tip - drop) - problem.chi0;
}

ShapeEvaluator::ShapeEvaluator(const ElasticaParameters& parameters)
    : p_(parameters), k_(parameter_of(parameters)) {
  cos_psi_ = std::cos(p_.psi);
  sin_psi_ = std::sin(p_.psi);
  if (p_.family != ElasticaFamily::kInflectional && p_.family != ElasticaFamily::kNonInflectional) {
    return;
  }
  // u_tip - u_root is sqrt(F) in family A and sigma q in family B: ds = du / span.
  span_ = p_.u_tip - p_.u_root;
  phi_root_ = jacobi_amplitude(p_.u_root, k_);
  d_root_ = D_over_m_at(p_.u_root, phi_root_, k_);
  delta_root_ = delta_amplitude(phi_root_, k_);
}

ShapePoint ShapeEvaluator::at(double s) const {
  double amplitude = 0.0;
  return at(s, amplitude);
}

ShapePoint ShapeEvaluator::at(double s, double& amplitude) const {
  amplitude = 0.0;
  ShapePoint point;
  point.s = s;
  if (p_.family == ElasticaFamily::kStraight) {
    point.x = s;
    return point;
  }
  if (p_.family == ElasticaFamily::kCircularArc) {
    // Howell eqs. 2.53, 2.59, 2.64 at arc length s: theta = mu s.
    const double t = p_.mu * s;
    point.theta = t;
    if (p_.mu == 0.0) {
      point.x = s;
    } else {
      point.x = std::sin(t) / p_.mu;
      const double h = std::sin(0.5 * t);
      point.y = 2.0 * h * h / p_.mu;
    }
    return point;
  }
  const double u = p_.u_root + span_ * s;
  const double phi = jacobi_amplitude(u, k_);
  amplitude = phi;
  const double d = D_over_m_at(u, phi, k_);
  const double phi0 = phi_root_;
  double chi = 0.0;
  double sin2_integral = 0.0;  // I(s) = int_0^s sin^2(chi/2) ds
  double sin_integral = 0.0;   // J(s) = int_0^s sin(chi) ds
  if (p_.family == ElasticaFamily::kInflectional) {
    const double kk = std::sqrt(p_.modulus2);
    // int k^2 sn^2 du = u - E(u); int 2k sn dn du = -2k cn(u)  (docs/theory-elliptic.md, family A)
    sin2_integral = p_.modulus2 * (d - d_root_) / span_;
    sin_integral = 4.0 * kk * std::sin(0.5 * (phi + phi0)) * std::sin(0.5 * (phi - phi0)) / span_;
    chi = 2.0 * kPi * p_.winding + 2.0 * std::atan2(kk * std::sin(phi), delta_amplitude(phi, k_));
  } else {
    // int sn^2 dv = (v - E(v))/m; int 2 sn cn dv = -2 dn/m, written without cancellation.
    sin2_integral = (d - d_root_) / span_;
    sin_integral = 2.0 * std::sin(phi - phi0) * std::sin(phi + phi0) /
                   (span_ * (delta_amplitude(phi, k_) + delta_root_));
    chi = 2.0 * kPi * p_.winding + 2.0 * phi;
  }
  // Tangent in the force frame: t.eF = -cos chi, t.ePerp = -sin chi; rotate back by psi.
  const double cos_integral = s - 2.0 * sin2_integral;
  point.x = -cos_psi_ * cos_integral + sin_psi_ * sin_integral;
  point.y = -cos_psi_ * sin_integral - sin_psi_ * cos_integral;
  point.theta = chi + p_.psi - kPi;
  return point;
}

ShapePoint evaluate_normalised(const ElasticaParameters& p, double s) {
  return ShapeEvaluator(p).at(s);
}

double root_curvature(const ElasticaParameters& p) {
  switch (p.family) {
    case ElasticaFamily::kStraight:
      return 0.0;
    case ElasticaFamily::kCircularArc:
      return p.mu;
    case ElasticaFamily::kInflectional: {
      const Parameter k = parameter_of(p);
      const double phi0 = jacobi_amplitude(p.u_root, k);
      return 2.0 * std::sqrt(p.modulus2 * p.force) * std::cos(phi0);
    }
    case ElasticaFamily::kNonInflectional: {
      const Parameter m = parameter_of(p);
      const double phi0 = jacobi_amplitude(p.u_root, m);
      return 2.0 * (p.u_tip - p.u_root) * delta_amplitude(phi0, m);
    }
  }
  return 0.0;
}

namespace {

// Interior zeros of the curvature 2k sqrt(F) cn(u) of family A between the amplitudes at the clamp
// and the tip: where am(u) = pi/2 + j pi, strictly inside the beam.
int inflections_between(double phi0, double phi1) {
  // A zero within 1e-9 rad of an end (e.g. the tip of a beam with mu = 0) is not interior.
  constexpr double kEndSlack = 1e-9;
  const double j_min = std::floor((phi0 - 0.5 * kPi) / kPi + kEndSlack) + 1.0;
  const double j_max = std::ceil((phi1 - 0.5 * kPi) / kPi - kEndSlack) - 1.0;
  return std::max(0, static_cast<int>(j_max - j_min + 1.0));
}

}  // namespace

int count_inflection_points(const ElasticaParameters& p) {
  if (p.family != ElasticaFamily::kInflectional) return 0;
  const Parameter k = parameter_of(p);
  return inflections_between(jacobi_amplitude(p.u_root, k), jacobi_amplitude(p.u_tip, k));
}

EndSummary end_summary(const ElasticaParameters& p) {
  EndSummary out;
  if (p.family != ElasticaFamily::kInflectional && p.family != ElasticaFamily::kNonInflectional) {
    out.tip = evaluate_normalised(p, 1.0);
    out.root_moment = root_curvature(p);
    out.inflection_points = count_inflection_points(p);
    return out;
  }
  // The evaluator's amplitude at the clamp is root_curvature's; the one at s = 1 (u_root + (u_tip -
  // u_root), within an ulp of u_tip) stands in for count_inflection_points' am(u_tip).
  const ShapeEvaluator evaluator(p);
  double phi_tip = 0.0;
  out.tip = evaluator.at(1.0, phi_tip);
  const double phi_root = evaluator.root_amplitude();
  const Parameter k = parameter_of(p);
  if (p.family == ElasticaFamily::kInflectional) {
    out.root_moment = 2.0 * std::sqrt(p.modulus2 * p.force) * std::cos(phi_root);
    out.inflection_points = inflections_between(phi_root, phi_tip);
  } else {
    out.root_moment = 2.0 * (p.u_tip - p.u_root) * delta_amplitude(phi_root, k);
  }
  return out;
}

}  // namespace elliptic
}  // namespace flexure
