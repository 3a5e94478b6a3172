// What is checked against what (forward dynamics with CVODES, class 2B-lplm of Table 5):
//  - without friction and force, the total energy 1/2 M theta2'^2 + V is conserved to 1e-8
//    relative over 100 periods of a large release (theta2 = 0.6 rad);
//  - driving the forward model with the inverse-dynamics force history recovers the prescribed
//    sinusoidal slider motion (two different computations of the same equation of motion);
//  - the linearised natural frequency sqrt(K/M) about the straight position (F0 = 0) and about a
//    preloaded equilibrium (F0 = static force at 20 % stroke) against the period of small free
//    oscillations found by CVODES root finding, to 1e-6; the preloaded equilibrium angle against
//    the kinematic theta2 at that displacement;
//  - a driving spring with a fixed actuator holds the slider at rest at the displacement where the
//    spring force equals the static PRBM force (found independently from the static force curve);
//  - with Coulomb friction the energy of a free motion never increases and decays.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/dynamics/dynamics.h"

namespace flexure::dynamics {
namespace {

constexpr double kEnergyTolerance = 1e-8;     // docs/dynamics.md
constexpr double kFrequencyTolerance = 1e-6;  // docs/dynamics.md
// Amplitude of the "small" oscillation: the amplitude-dependent frequency shift is O(eps^2)
// ~ 1e-8 relative, well below kFrequencyTolerance.
constexpr double kSmallAmplitude = 1e-4;
// Tracking the prescribed motion: CVODES at rtol 1e-11 over two periods; the force-driven
// model has near-zero stiffness (constant force) so errors drift rather than decay.
constexpr double kTrackingTolerance = 1e-7;      // relative to the stroke
constexpr double kEquilibriumTolerance = 1e-10;  // bisection to 1e-15 relative

SliderCrankDynamics lplm_model() {
  const CfsmDesign& d = find_cfsm_design("2B-lplm");
  return SliderCrankDynamics(from_bar_links(d.r2, d.r3, d.m2, d.m3, d.m_slider, d.k));
}

std::vector<double> times(double t_end, int count) {
  std::vector<double> t(count);
  for (int i = 0; i < count; ++i) t[i] = t_end * (i + 1) / count;
  return t;
}

TEST(DynamicsForward, FreeMotionConservesEnergyOver100Periods) {
  const SliderCrankDynamics model = lplm_model();
  const double period = 2.0 * std::numbers::pi / linearise(model, 0.0).omega_n;
  ForwardOptions options;
  options.rtol = 1e-13;
  options.atol = 1e-15;
  const ForwardDynamics forward(model, options);
  const ForwardResult r = forward.integrate(0.6, 0.0, times(100 * period, 400), nullptr);
  ASSERT_TRUE(r.converged()) << r.message;
  EXPECT_LT(r.residual, kEnergyTolerance);
  // The release is large: the motion must really swing through the straight position.
  EXPECT_LT(*std::min_element(r.theta2.begin(), r.theta2.end()), -0.5);
}

TEST(DynamicsForward, InverseDynamicsForceReproducesPrescribedMotion) {
  const SliderCrankDynamics model = lplm_model();
  const double r_tot = model.r_tot();
  const SinusoidalMotion motion{0.05 * r_tot, 0.35 * r_tot, 25.0};
  const InverseDynamics inverse(model);
  ForwardOptions options;
  options.rtol = 1e-11;
  options.atol = 1e-14;
  const ForwardDynamics forward(model, options);
  const InputForce force = [&](double t, double, double) { return inverse.at(motion, t).force; };
  const double period = 2.0 * std::numbers::pi / motion.omega;
  const ForwardResult r =
      forward.integrate(model.theta2_at(motion.preload), 0.0, times(2 * period, 50), force);
  ASSERT_TRUE(r.converged()) << r.message;
  for (std::size_t i = 0; i < r.t.size(); ++i) {
    const double expected =
        motion.preload + 0.5 * motion.stroke * (1.0 - std::cos(motion.omega * r.t[i]));
    EXPECT_NEAR(r.delta_x[i], expected, kTrackingTolerance * motion.stroke) << r.t[i];
  }
}

// Mean period of small free oscillations about theta_eq under the constant force F0.
double measured_omega(const SliderCrankDynamics& model,
                      double theta_eq,
                      double F0,
                      double omega_guess) {
  ForwardOptions options;
  options.rtol = 1e-12;
  options.atol = 1e-16;
  options.record_crossings = true;
  options.crossing_level = theta_eq;
  const ForwardDynamics forward(model, options);
  const double period_guess = 2.0 * std::numbers::pi / omega_guess;
  const InputForce force = [F0](double, double, double) { return F0; };
  const ForwardResult r = forward.integrate(
      theta_eq - kSmallAmplitude, 0.0, {10.5 * period_guess}, F0 == 0.0 ? nullptr : force);
  EXPECT_TRUE(r.converged()) << r.message;
  EXPECT_GE(r.upward_crossings.size(), 10u);
  if (r.upward_crossings.size() < 2) return 0.0;
  const double periods = static_cast<double>(r.upward_crossings.size() - 1);
  return 2.0 * std::numbers::pi * periods / (r.upward_crossings.back() - r.upward_crossings[0]);
}

TEST(DynamicsForward, LinearisedFrequencyMatchesFreeOscillationAboutStraightPosition) {
  const SliderCrankDynamics model = lplm_model();
  const Linearisation lin = linearise(model, 0.0);
  ASSERT_TRUE(lin.stable);
  EXPECT_EQ(lin.theta2_eq, 0.0);
  const double omega = measured_omega(model, 0.0, 0.0, lin.omega_n);
  EXPECT_NEAR(omega, lin.omega_n, kFrequencyTolerance * lin.omega_n);
}

TEST(DynamicsForward, LinearisedFrequencyMatchesFreeOscillationUnderPreload) {
  const SliderCrankDynamics model = lplm_model();
  const double theta_expected = model.theta2_at(0.2 * model.r_tot());
  const double F0 = model.static_force(theta_expected);
  const Linearisation lin = linearise(model, F0, theta_expected - 0.05, theta_expected + 0.05);
  EXPECT_NEAR(lin.theta2_eq, theta_expected, kEquilibriumTolerance);
  ASSERT_TRUE(lin.stable) << "stiffness " << lin.stiffness;
  const double omega = measured_omega(model, lin.theta2_eq, F0, lin.omega_n);
  EXPECT_NEAR(omega, lin.omega_n, kFrequencyTolerance * lin.omega_n);
}

TEST(DynamicsForward, DrivingSpringHoldsStaticEquilibrium) {
  constexpr double kRestTolerance = 1e-9;  // rad, rtol 1e-12 over 0.5 s at an equilibrium
  const SliderCrankDynamics model = lplm_model();
  // Choose the equilibrium first: at Delta x* the static force F*, and an actuator position that
  // stretches a 20 kN/m spring by F*/k.
  const double k_drive = 2e4;
  const double theta_star = model.theta2_at(0.25 * model.r_tot());
  const double x_star = model.delta_x_at(theta_star);
  const double x_actuator = x_star + model.static_force(theta_star) / k_drive;
  ForwardOptions options;
  options.rtol = 1e-12;
  options.atol = 1e-15;
  const ForwardDynamics forward(model, options);
  const ForwardResult r = forward.integrate(
      theta_star, 0.0, times(0.5, 20), driving_spring(model, k_drive, [x_actuator](double) {
        return x_actuator;
      }));
  ASSERT_TRUE(r.converged()) << r.message;
  for (double theta : r.theta2) EXPECT_NEAR(theta, theta_star, kRestTolerance);
}

TEST(DynamicsForward, CoulombFrictionDissipatesEnergy) {
  // Energy may rise only by integration error (rtol 1e-10 on states ~1).
  constexpr double kIncreaseAllowance = 1e-8;
  const CfsmDesign& d = find_cfsm_design("2B-lplm");
  DynamicsParameters p = from_bar_links(d.r2, d.r3, d.m2, d.m3, d.m_slider, d.k);
  p.coulomb = {0.02, 0.0, 0.02};
  const SliderCrankDynamics model(p);
  const double period = 2.0 * std::numbers::pi / linearise(model, 0.0).omega_n;
  const ForwardDynamics forward(model);
  const ForwardResult r = forward.integrate(0.6, 0.0, times(5 * period, 200), nullptr);
  ASSERT_TRUE(r.converged()) << r.message;
  const double E0 = model.energy(0.6, 0.0);
  double previous = E0;
  for (double E : r.energy) {
    EXPECT_LE(E, previous + kIncreaseAllowance * E0);
    previous = E;
  }
  EXPECT_LT(r.energy.back(), 0.9 * E0);
}

}  // namespace
}  // namespace flexure::dynamics
