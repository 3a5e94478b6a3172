#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "flexure/mechanisms/dynamics/dynamics.h"
#include "flexure/solver/common/status.h"

namespace flexure::dynamics {

void InverseDynamicsOptions::validate() const {
  if (samples_per_period < 8 || samples_per_period % 2 != 0) {
    throw InvalidInput(
        fmt::format("samples_per_period = {} must be even and >= 8", samples_per_period));
  }
  require_finite(friction_sign_velocity, "friction_sign_velocity");
  if (friction_sign_velocity < 0.0) {
    throw InvalidInput("friction_sign_velocity must be >= 0");
  }
}

InverseDynamics::InverseDynamics(SliderCrankDynamics model, InverseDynamicsOptions options)
    : model_(std::move(model)), options_(options) {
  options_.validate();
}

void InverseDynamics::check(const SinusoidalMotion& m) const {
  require_finite(m.preload, "preload");
  require_finite(m.stroke, "stroke");
  require_finite(m.omega, "omega");
  if (m.preload <= 0.0) {
    // At Delta x = 0 the mechanism is straight, dr1/dtheta2 = 0 and F = Q/0.
    throw InvalidInput(fmt::format("preload = {} m must be > 0", m.preload));
  }
  if (m.stroke <= 0.0) throw InvalidInput(fmt::format("stroke = {} m must be > 0", m.stroke));
  if (m.omega < 0.0) throw InvalidInput(fmt::format("omega = {} rad/s must be >= 0", m.omega));
  model_.theta2_at(m.preload + m.stroke);  // throws past the toggle position
}

ForceSample InverseDynamics::evaluate(double t, double delta_x, double x_dot, double x_ddot) const {
  ForceSample s;
  s.t = t;
  s.delta_x = delta_x;
  s.theta2 = model_.theta2_at(delta_x);
  const ConfigurationTerms c = model_.terms(s.theta2);
  // r1 = r_tot - Delta x: r1' theta2' = -x', r1' theta2'' + r1'' theta2'^2 = -x''.
  s.theta2_dot = -x_dot / c.dr1;
  s.theta2_ddot = (-x_ddot - c.d2r1 * s.theta2_dot * s.theta2_dot) / c.dr1;
  double sign_value = 0.0;
  if (options_.friction_sign_velocity > 0.0) {
    sign_value = std::tanh(s.theta2_dot / options_.friction_sign_velocity);
  } else {
    sign_value = (s.theta2_dot > 0.0) - (s.theta2_dot < 0.0);
  }
  const double Q_CF = model_.friction_moment(c, sign_value);
  // Eq. 29 keeps tau_AF on the side of the input moment: tau_F = LHS - tau_CF - tau_AF.
  const double tau_AF = model_.axial_moment(c);
  const double lhs = c.M * s.theta2_ddot + 0.5 * c.dM * s.theta2_dot * s.theta2_dot + c.dV;
  s.force = (lhs - Q_CF - tau_AF) / (-c.dr1);
  s.static_force = c.dV / (-c.dr1);
  return s;
}

ForceSample InverseDynamics::at(const SinusoidalMotion& m, double t) const {
  check(m);
  const double a = 0.5 * m.stroke, w = m.omega;
  const double x = m.preload + a * (1.0 - std::cos(w * t));
  return evaluate(t, x, a * w * std::sin(w * t), a * w * w * std::cos(w * t));
}

std::vector<ForceSample> InverseDynamics::history(const SinusoidalMotion& m) const {
  check(m);
  const int N = options_.samples_per_period;
  std::vector<ForceSample> out;
  out.reserve(N);
  const double a = 0.5 * m.stroke, w = m.omega;
  const double period = w > 0.0 ? 2.0 * std::numbers::pi / w : 0.0;
  for (int k = 0; k < N; ++k) {
    const double phase = 2.0 * std::numbers::pi * k / N;
    const double x = m.preload + a * (1.0 - std::cos(phase));
    out.push_back(
        evaluate(period * k / N, x, a * w * std::sin(phase), a * w * w * std::cos(phase)));
  }
  return out;
}

ForceStatistics InverseDynamics::statistics(const SinusoidalMotion& m) const {
  const std::vector<ForceSample> h = history(m);
  std::vector<double> f(h.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    f[i] = h[i].force;
    sum += f[i];
  }
  ForceStatistics s;
  s.omega = m.omega;
  // Uniform samples of a periodic function: the rectangle rule is the trapezoid rule.
  s.mean = sum / static_cast<double>(f.size());
  const auto [lo, hi] = std::minmax_element(f.begin(), f.end());
  s.min = *lo;
  s.max = *hi;
  s.peak_to_peak = s.max - s.min;
  s.percent_constant_force = 100.0 * s.min / s.max;
  const std::size_t n = f.size();  // even
  std::nth_element(f.begin(), f.begin() + n / 2, f.end());
  const double upper = f[n / 2];
  const double lower = *std::max_element(f.begin(), f.begin() + n / 2);
  s.median = 0.5 * (lower + upper);
  return s;
}

std::vector<ForceStatistics> InverseDynamics::sweep(
    SinusoidalMotion motion,
    const std::vector<double>& omegas,
    const std::function<void(std::size_t, std::size_t)>& progress) const {
  std::vector<ForceStatistics> rows;
  rows.reserve(omegas.size());
  for (double w : omegas) {
    motion.omega = w;
    rows.push_back(statistics(motion));
    if (progress) progress(rows.size(), omegas.size());
  }
  return rows;
}

double static_nominal_force(const SliderCrankDynamics& model, double stroke, int points) {
  require_finite(stroke, "stroke");
  if (stroke <= 0.0) throw InvalidInput("stroke must be > 0");
  if (points < 1) throw InvalidInput("points must be >= 1");
  double sum = 0.0;
  for (int i = 1; i <= points; ++i) {
    sum += model.static_force(model.theta2_at(stroke * i / points));
  }
  return sum / points;
}

}  // namespace flexure::dynamics
