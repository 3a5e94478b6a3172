#include <fmt/format.h>

#include <cmath>

#include "flexure/mechanisms/cfm/slider_crank.h"
#include "flexure/mechanisms/dynamics/dynamics.h"
#include "flexure/solver/common/status.h"

namespace flexure::dynamics {
namespace {

void require_nonnegative(double value, const std::string& what) {
  require_finite(value, what);
  if (value < 0.0) throw InvalidInput(fmt::format("{} = {} must be >= 0", what, value));
}
void require_positive(double value, const std::string& what) {
  require_finite(value, what);
  if (value <= 0.0) throw InvalidInput(fmt::format("{} = {} must be > 0", what, value));
}

}  // namespace

DynamicsParameters from_bar_links(double r2,
                                  double r3,
                                  double m2,
                                  double m3,
                                  double m_slider,
                                  std::array<double, 3> k,
                                  double halves) {
  require_positive(r2, "r2");
  require_positive(r3, "r3");
  require_nonnegative(m2, "m2");
  require_nonnegative(m3, "m3");
  DynamicsParameters p;
  p.r2 = r2;
  p.r3 = r3;
  p.m2 = m2;
  p.m3 = m3;
  p.m_slider = m_slider;
  // Uniform slender bar about its centre.
  p.J_C2 = m2 * r2 * r2 / 12.0;
  p.J_C3 = m3 * r3 * r3 / 12.0;
  p.k = k;
  p.halves = halves;
  return p;
}

SliderCrankDynamics::SliderCrankDynamics(DynamicsParameters parameters) : p_(parameters) {
  require_positive(p_.r2, "r2");
  require_positive(p_.r3, "r3");
  require_nonnegative(p_.m2, "m2");
  require_nonnegative(p_.m3, "m3");
  require_nonnegative(p_.m_slider, "m_slider");
  require_nonnegative(p_.J_C2, "J_C2");
  require_nonnegative(p_.J_C3, "J_C3");
  require_positive(p_.halves, "halves");
  require_finite(p_.axial_alpha, "axial_alpha");
  for (int i = 0; i < 3; ++i) {
    require_nonnegative(p_.k[i], fmt::format("k{}", i + 1));
    require_nonnegative(p_.coulomb[i], fmt::format("Coulomb friction C{}", i + 1));
  }
  if (std::abs(p_.axial_alpha) * p_.r2 >= p_.r3) {
    throw InvalidInput(
        fmt::format("axial_alpha = {} must satisfy r2 |alpha| < r3 (eq. 28)", p_.axial_alpha));
  }
}

bool SliderCrankDynamics::try_terms(double theta2, ConfigurationTerms& t) const {
  const double r2 = p_.r2, r3 = p_.r3;
  const double s2 = std::sin(theta2), c2 = std::cos(theta2);
  const double s3 = -(r2 / r3) * s2;  // loop closure in y: r2 sin theta2 + r3 sin theta3 = 0
  const double c3_sq = 1.0 - s3 * s3;
  if (!std::isfinite(theta2) || c3_sq <= 0.0) return false;
  const double c3 = std::sqrt(c3_sq);
  t.theta2 = theta2;
  t.theta3 = std::asin(s3);
  // Differentiating the y loop closure: r2 c2 + r3 c3 g = 0, then once more for dg.
  t.g = -r2 * c2 / (r3 * c3);
  t.dg = r2 * (s2 * c3 - c2 * s3 * t.g) / (r3 * c3 * c3);
  t.r1 = r2 * c2 + r3 * c3;
  t.dr1 = -r2 * s2 - r3 * s3 * t.g;
  t.d2r1 = -r2 * c2 - r3 * c3 * t.g * t.g - r3 * s3 * t.dg;

  // Velocity of the centre of link 3 per unit dtheta2/dt, and its theta2 derivative.
  const double J3x = -r2 * s2 - 0.5 * r3 * s3 * t.g;
  const double J3y = r2 * c2 + 0.5 * r3 * c3 * t.g;
  const double dJ3x = -r2 * c2 - 0.5 * r3 * (c3 * t.g * t.g + s3 * t.dg);
  const double dJ3y = -r2 * s2 + 0.5 * r3 * (-s3 * t.g * t.g + c3 * t.dg);
  // Link 2 turns about the ground pivot: J_O2 = J_C2 + m2 (r2/2)^2 (parallel axes).
  const double J_O2 = p_.J_C2 + 0.25 * p_.m2 * r2 * r2;
  const double M_half = J_O2 + p_.m3 * (J3x * J3x + J3y * J3y) + p_.J_C3 * t.g * t.g;
  const double dM_half = 2.0 * p_.m3 * (J3x * dJ3x + J3y * dJ3y) + 2.0 * p_.J_C3 * t.g * t.dg;
  t.M = p_.halves * M_half + p_.m_slider * t.dr1 * t.dr1;
  t.dM = p_.halves * dM_half + 2.0 * p_.m_slider * t.dr1 * t.d2r1;

  const double psi1 = theta2, psi2 = theta2 - t.theta3, psi3 = -t.theta3;
  t.dpsi = {1.0, 1.0 - t.g, -t.g};
  const double h = p_.halves;
  const auto& k = p_.k;
  t.V = 0.5 * h * (k[0] * psi1 * psi1 + k[1] * psi2 * psi2 + k[2] * psi3 * psi3);
  t.dV = h * (k[0] * psi1 * t.dpsi[0] + k[1] * psi2 * t.dpsi[1] + k[2] * psi3 * t.dpsi[2]);
  // d(dpsi2)/dtheta2 = -dg, d(dpsi3)/dtheta2 = -dg.
  t.d2V = h * (k[0] + k[1] * (t.dpsi[1] * t.dpsi[1] - psi2 * t.dg) +
               k[2] * (t.dpsi[2] * t.dpsi[2] - psi3 * t.dg));
  return true;
}

ConfigurationTerms SliderCrankDynamics::terms(double theta2) const {
  ConfigurationTerms t;
  if (!try_terms(theta2, t)) {
    throw InvalidInput(fmt::format(
        "theta2 = {} rad is past the toggle position: (r2/r3)|sin theta2| must be < 1", theta2));
  }
  return t;
}

double SliderCrankDynamics::theta2_at(double delta_x) const {
  const double R = p_.r3 / p_.r2;
  const double u = delta_x / r_tot();
  const double u_max = cfm::toggle_stroke_percent(R) / 100.0;
  if (!std::isfinite(u) || u < 0.0 || u > u_max) {
    throw InvalidInput(fmt::format(
        "slider displacement Delta x = {} m must be in [0, {}] m (up to the toggle position)",
        delta_x,
        u_max * r_tot()));
  }
  return cfm::slider_crank_pose(R, u).theta2;
}

double SliderCrankDynamics::delta_x_at(double theta2) const { return r_tot() - terms(theta2).r1; }

double SliderCrankDynamics::static_force(double theta2) const {
  const ConfigurationTerms t = terms(theta2);
  if (t.dr1 == 0.0) {
    throw InvalidInput("static_force: theta2 = 0 is the straight position, where F = 0/0");
  }
  return t.dV / (-t.dr1);
}

double SliderCrankDynamics::friction_moment(const ConfigurationTerms& t, double sign_value) const {
  // A pin's Coulomb moment C_i opposes its relative rotation psi_i; its virtual work
  // -C_i sign(dpsi_i/dt) dpsi_i = -C_i sign(dtheta2/dt) |dpsi_i/dtheta2| dtheta2 gives eq. 27's
  // factors 1, 1 + r2 c2/sqrt(r3^2 - r2^2 s2^2), r2 c2/sqrt(...) (dpsi_i >= 0 on the branch).
  double sum = 0.0;
  for (int i = 0; i < 3; ++i) sum += p_.coulomb[i] * std::abs(t.dpsi[i]);
  return -sign_value * p_.halves * sum;
}

double SliderCrankDynamics::axial_moment(const ConfigurationTerms& t) const {
  if (p_.axial_alpha == 0.0) return 0.0;
  if (t.dr1 == 0.0) {
    throw InvalidInput("axial-force term (eq. 28) needs theta2 != 0 (a preload > 0)");
  }
  const double F_static = t.dV / (-t.dr1);
  const double a = p_.axial_alpha, r2 = p_.r2, r3 = p_.r3;
  return F_static * r2 * a * (1.0 + r2 / std::sqrt(r3 * r3 - r2 * r2 * a * a));
}

double SliderCrankDynamics::energy(double theta2, double theta2_dot) const {
  const ConfigurationTerms t = terms(theta2);
  return 0.5 * t.M * theta2_dot * theta2_dot + t.V;
}

}  // namespace flexure::dynamics
