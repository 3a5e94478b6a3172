#include "flexure/mechanisms/design/feasibility.h"

#include <cmath>

#include "flexure/mechanisms/cfm/cfm_model.h"

namespace flexure::design {

double stroke_percent_for(double displacement, double l_tot, double lambda) {
  return 100.0 * displacement * lambda / l_tot;  // eq. 8.6
}

double primary_stress(
    double E, double lambda, double M, double n, double d, double h_p, double l_tot) {
  return E * lambda * M * std::pow(d, n) * h_p / (2.0 * l_tot);  // eq. 8.5
}

double max_primary_thickness(
    double omega, double safety_factor, double lambda, double M, double n, double d, double l_tot) {
  return 2.0 * omega * l_tot / (safety_factor * lambda * M * std::pow(d, n));
}

double length_for_stress(double omega,
                         double safety_factor,
                         double lambda,
                         double M,
                         double n,
                         double h_p,
                         double displacement) {
  const double rhs =
      h_p * safety_factor * lambda * M * std::pow(100.0 * displacement * lambda, n) / (2.0 * omega);
  return std::pow(rhs, 1.0 / (1.0 + n));
}

double stress_screen_M(
    double omega, double safety_factor, double lambda, double n, double h, double d, double l_tot) {
  return 2.0 * omega * l_tot / (safety_factor * lambda * h * std::pow(d, n));  // eq. 8.17
}

ForceCoefficient force_coefficient(const cfm::CfmResult& m) {
  const cfm::CfmConfiguration& c = cfm::find_cfm_configuration(m.config);
  const int p = m.primary_pivot;
  const int ref = c.is_class_1B() ? 2 : 1;
  const double K_prev[3] = {1.0, m.K1, m.K2};  // K_0 = 1 (eq. 4.52); class 1B: K1 = 1
  ForceCoefficient f;
  f.primary_pivot = p;
  f.c = m.lambda * m.lambda * m.kappa[p - 1] * m.beta / (12.0 * m.kappa[ref - 1] * K_prev[p - 1]);
  return f;
}

double design_force(const ForceCoefficient& f, double E, double b_p, double h_p, double l_tot) {
  return f.c * E * b_p * h_p * h_p * h_p / (l_tot * l_tot);
}

double thickness_for_force(
    const ForceCoefficient& f, double F, double E, double b_p, double l_tot) {
  return std::cbrt(F * l_tot * l_tot / (f.c * E * b_p));
}

double width_for_force(const ForceCoefficient& f, double F, double E, double h_p, double l_tot) {
  return F * l_tot * l_tot / (f.c * E * h_p * h_p * h_p);
}

double length_for_force(const ForceCoefficient& f, double F, double E, double b_p, double h_p) {
  return std::sqrt(f.c * E * b_p * h_p * h_p * h_p / F);
}

double second_moment_ratio(const cfm::CfmResult& m, int pivot) {
  const double K_prev[3] = {1.0, m.K1, m.K2};
  const int p = m.primary_pivot;
  if (m.kappa[pivot - 1] <= 0.0) return 0.0;
  return K_prev[pivot - 1] * m.kappa[p - 1] / (K_prev[p - 1] * m.kappa[pivot - 1]);
}

}  // namespace flexure::design
