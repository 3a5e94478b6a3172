#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "flexure/mechanisms/dynamics/dynamics.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/ode/ode_integrator.h"

namespace flexure::dynamics {
namespace {

struct RhsData {
  const SliderCrankDynamics* model = nullptr;
  const InputForce* force = nullptr;
  double sign_velocity = 1e-3;
  double crossing_level = 0.0;
};

// y = (theta2 - crossing_level, theta2'): the offset keeps the event function y0 at full relative
// precision near the crossing (with theta2 itself, theta2 - level is exactly 0 over a short
// interval after a root and CVODES stops with CV_ILL_INPUT, "root found at and very near t").
// Returns 1 (recoverable) past the toggle position so the integrator cuts the step.
int rhs(const RhsData& d, double t, std::span<const double> y, std::span<double> ydot) {
  const double th = y[0] + d.crossing_level, w = y[1];
  ConfigurationTerms c;
  if (!d.model->try_terms(th, c)) return 1;
  const double F = (d.force != nullptr && *d.force) ? (*d.force)(t, th, w) : 0.0;
  if (!std::isfinite(F)) return -1;
  const double Q = -F * c.dr1 + d.model->friction_moment(c, std::tanh(w / d.sign_velocity));
  ydot[0] = w;
  ydot[1] = (Q - 0.5 * c.dM * w * w - c.dV) / c.M;
  return 0;
}

}  // namespace

InputForce driving_spring(const SliderCrankDynamics& model,
                          double k_drive,
                          std::function<double(double t)> actuator) {
  require_finite(k_drive, "driving spring stiffness k_drive");
  if (k_drive <= 0.0) throw InvalidInput(fmt::format("k_drive = {} N/m must be > 0", k_drive));
  if (!actuator) throw InvalidInput("driving_spring: actuator position function is empty");
  // Copies of the model and the function: the returned closure may outlive the arguments.
  return [model, k_drive, actuator = std::move(actuator)](double t, double theta2, double) {
    ConfigurationTerms c;
    if (!model.try_terms(theta2, c)) return std::numeric_limits<double>::quiet_NaN();
    return k_drive * (actuator(t) - (model.r_tot() - c.r1));
  };
}

Linearisation linearise(const SliderCrankDynamics& model,
                        double F0,
                        double theta_lo,
                        double theta_hi) {
  require_finite(F0, "F0");
  if (F0 < 0.0) throw InvalidInput(fmt::format("F0 = {} N must be >= 0", F0));
  Linearisation lin;
  double theta = 0.0;
  if (F0 > 0.0) {
    // Residual V' + F0 r1' = (F_static - F0)(-r1'): its sign is that of F_static - F0 for
    // theta2 > 0. Bisection on the crank angle up to just before the toggle position.
    const DynamicsParameters& p = model.parameters();
    // Stay 1e-6 inside the toggle angle, where cos theta3 -> 0 and r1' has a 1/cos singularity.
    const double theta_max = p.r2 > p.r3 ? std::asin(p.r3 / p.r2) * (1.0 - 1e-6)
                                         : 0.5 * 3.141592653589793 * (1.0 - 1e-6);
    auto residual = [&](double th) {
      const ConfigurationTerms c = model.terms(th);
      return c.dV + F0 * c.dr1;
    };
    double lo = theta_lo > 0.0 ? theta_lo : 1e-9 * theta_max;
    double hi = theta_hi > 0.0 ? std::min(theta_hi, theta_max) : theta_max;
    if (!(lo < hi)) {
      throw InvalidInput(fmt::format("bracket [{}, {}] rad is empty", theta_lo, theta_hi));
    }
    const double f_lo = residual(lo), f_hi = residual(hi);
    if (f_lo * f_hi > 0.0) {
      throw InvalidInput(fmt::format(
          "F0 = {} N: no equilibrium with 0 < theta2 < {} rad (static force does not cross F0)",
          F0,
          theta_max));
    }
    for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
      const double mid = 0.5 * (lo + hi);
      if (residual(mid) * f_lo > 0.0) {
        lo = mid;
      } else {
        hi = mid;
      }
    }
    theta = 0.5 * (lo + hi);
  }
  const ConfigurationTerms c = model.terms(theta);
  lin.theta2_eq = theta;
  lin.stiffness = c.d2V + F0 * c.d2r1;
  lin.inertia = c.M;
  lin.stable = lin.stiffness > 0.0 && c.M > 0.0;
  lin.omega_n = lin.stable ? std::sqrt(lin.stiffness / c.M) : 0.0;
  return lin;
}

void ForwardOptions::validate() const {
  if (!(rtol > 0.0) || !(atol > 0.0)) {
    throw InvalidInput("ForwardOptions: rtol and atol must be > 0");
  }
  if (!(friction_sign_velocity > 0.0)) {
    throw InvalidInput("ForwardOptions: friction_sign_velocity must be > 0");
  }
  if (max_steps < 1) throw InvalidInput("ForwardOptions: max_steps must be >= 1");
  if (!std::isfinite(crossing_level)) {
    throw InvalidInput("ForwardOptions: crossing_level must be a finite angle (rad)");
  }
}

ForwardDynamics::ForwardDynamics(SliderCrankDynamics model, ForwardOptions options)
    : model_(std::move(model)), options_(options) {
  options_.validate();
}

ForwardResult ForwardDynamics::integrate(double theta2_0,
                                         double theta2_dot_0,
                                         const std::vector<double>& output_times,
                                         const InputForce& force) const {
  require_finite(theta2_0, "theta2_0");
  require_finite(theta2_dot_0, "theta2_dot_0");
  model_.terms(theta2_0);  // throws past the toggle position
  double previous = 0.0;
  for (double t : output_times) {
    if (!std::isfinite(t) || t <= previous) {
      throw InvalidInput("output_times must be finite, > 0 and increasing");
    }
    previous = t;
  }
  if (model_.terms(theta2_0).M <= 0.0) {
    throw InvalidInput("generalized inertia M is zero (all masses zero): no forward dynamics");
  }

  RhsData data;
  data.model = &model_;
  data.force = &force;
  data.sign_velocity = options_.friction_sign_velocity;
  data.crossing_level = options_.crossing_level;

  OdeIntegrator::Options ode_options;
  ode_options.rtol = options_.rtol;
  ode_options.atol = options_.atol;
  ode_options.max_steps = options_.max_steps;
  ode_options.method = options_.adams ? OdeIntegrator::Method::kAdams : OdeIntegrator::Method::kBdf;
  const OdeIntegrator integrator(ode_options);
  OdeIntegrator::Event upward_crossing;
  upward_crossing.g = [](double, std::span<const double> y) { return y[0]; };
  upward_crossing.direction = OdeIntegrator::Direction::kUpward;
  const double y0[2] = {theta2_0 - data.crossing_level, theta2_dot_0};
  const OdeIntegrator::Solution solution = integrator.integrate(
      [&data](double t, std::span<const double> y, std::span<double> ydot) {
        return rhs(data, t, y, ydot);
      },
      0.0,
      y0,
      output_times,
      options_.record_crossings ? &upward_crossing : nullptr);

  ForwardResult result;
  result.upward_crossings = solution.event_times;
  const double E0 = model_.energy(theta2_0, theta2_dot_0);
  const bool conservative = !force;
  for (std::size_t i = 0; i < solution.t.size(); ++i) {
    const double th = solution.y[i][0] + data.crossing_level, w = solution.y[i][1];
    result.t.push_back(solution.t[i]);
    result.theta2.push_back(th);
    result.theta2_dot.push_back(w);
    result.delta_x.push_back(model_.delta_x_at(th));
    const double E = model_.energy(th, w);
    result.energy.push_back(E);
    if (conservative && E0 != 0.0) {
      result.residual = std::max(result.residual, std::abs(E - E0) / std::abs(E0));
    }
  }
  result.iterations = solution.steps;
  if (!solution.status.ok) {
    result.message = fmt::format("{} at t = {} s (target {} s, {} outputs done)",
                                 solution.status.message,
                                 solution.status.t_reached,
                                 solution.status.t_target,
                                 result.t.size());
    return result;
  }
  result.set_converged(true);
  result.message = "integrated to the last output time";
  return result;
}

}  // namespace flexure::dynamics
