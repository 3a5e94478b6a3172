// What is checked against what: the generalized inertia M(theta2) of the slider-crank dynamics
// model (mechanisms/dynamics/slider_crank_dynamics.cpp) against values that do not use it.
//  * Kinetic energy along a stroke: the test writes the kinematics itself from the link lengths
//    (crank end r2 (cos theta2, sin theta2), slider on the x axis at r2 cos theta2 +
//    sqrt(r3^2 - r2^2 sin^2 theta2), coupler from crank end to slider), moves theta2(t) on a
//    prescribed motion, differentiates the positions of the link centres and the link angles in
//    time by a fourth-order central difference, and sums the rigid-body kinetic energies
//    1/2 m |v_C|^2 + 1/2 J_C omega^2 (J_C = m r^2/12 of a uniform bar, computed here) of both
//    halves and 1/2 m_s v_s^2 of the slider. It must equal 1/2 M(theta2) theta2_dot^2 to 1e-8.
//  * A slider-only mechanism (massless links): M = m_s (dDelta x/dtheta2)^2 with the closed-form
//    derivative of the slider position above.
//  * Natural frequencies of linear spring-inertia limits, measured from free oscillations
//    integrated by the forward dynamics: a crank alone on a torsional spring is a uniform rod
//    pivoted at one end, omega = sqrt(3 k / (m r^2)) (W. T. Thomson, Theory of Vibration with
//    Applications, a rod pivoted at its end: J_O = m l^2/3); the whole mechanism about the
//    straight position, where the slider stands still to first order and the coupler turns
//    about the slider pin: J = m2 r2^2/3 + m3 r2^2/3 (each a rod about its end, the coupler at
//    the angular rate r2/r3), K = k1 + k2 (1 + r2/r3)^2 + k3 (r2/r3)^2 per half.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "flexure/mechanisms/dynamics/dynamics.h"

namespace flexure::dynamics {
namespace {

// The finite-difference kinetic energy: fourth-order differences at h = 1e-3 s on a motion of
// unit time scale, truncation ~h^4 = 1e-12 and rounding ~1e-16/h = 1e-13, relative.
constexpr double kEnergyTolerance = 1e-8;
// Closed forms in double precision, different algebra: rounding only.
constexpr double kClosedForm = 1e-12;
// A free oscillation of amplitude 1e-4 rad: the amplitude shifts the frequency by O(1e-8), CVODES
// at rtol 1e-12 keeps the crossings to ~1e-10 of a period.
constexpr double kFrequencyTolerance = 1e-6;
constexpr double kSmallAmplitude = 1e-4;

// Link lengths and masses of a small mechanism (SI units; not a built-in design, so that nothing
// here is shared with the data the library ships).
constexpr double kR2 = 0.031, kR3 = 0.047;                      // m
constexpr double kM2 = 0.012, kM3 = 0.018;                      // kg per half
constexpr double kMSlider = 0.025;                              // kg
constexpr std::array<double, 3> kSprings = {0.21, 0.13, 0.08};  // N m per half
constexpr double kHalves = 2.0;

struct Pose {
  double bx, by;    // crank end (pin 2)
  double sx;        // slider (pin 3) on the x axis
  double theta3;    // coupler angle, from pin 2 to the slider
  double c2x, c2y;  // centre of the crank
  double c3x, c3y;  // centre of the coupler
};

// The kinematics of the test, from the link lengths alone.
Pose pose(double theta2) {
  Pose p;
  p.bx = kR2 * std::cos(theta2);
  p.by = kR2 * std::sin(theta2);
  p.sx = p.bx + std::sqrt(kR3 * kR3 - p.by * p.by);
  p.theta3 = std::atan2(-p.by, p.sx - p.bx);
  p.c2x = 0.5 * p.bx;
  p.c2y = 0.5 * p.by;
  p.c3x = 0.5 * (p.bx + p.sx);
  p.c3y = 0.5 * p.by;
  return p;
}

// A stroke: theta2 swings from -0.2 through the straight position out to 1.1 rad (r3 > r2: the
// coupler reaches the slider axis at every crank angle, there is no toggle position).
double motion(double t) { return 0.45 + 0.65 * std::sin(1.3 * t); }
double motion_rate(double t) { return 0.65 * 1.3 * std::cos(1.3 * t); }

// Fourth-order central difference of f at t.
template <typename F>
double rate(F f, double t, double h) {
  return (f(t - 2 * h) - 8 * f(t - h) + 8 * f(t + h) - f(t + 2 * h)) / (12 * h);
}

double kinetic_energy_by_differences(
    double t, double m2, double m3, double j2, double j3, double m_slider) {
  constexpr double h = 1e-3;
  const auto at = [](double tt) { return pose(motion(tt)); };
  const double v2x = rate([&](double tt) { return at(tt).c2x; }, t, h);
  const double v2y = rate([&](double tt) { return at(tt).c2y; }, t, h);
  const double v3x = rate([&](double tt) { return at(tt).c3x; }, t, h);
  const double v3y = rate([&](double tt) { return at(tt).c3y; }, t, h);
  const double w2 = rate([&](double tt) { return motion(tt); }, t, h);
  const double w3 = rate([&](double tt) { return at(tt).theta3; }, t, h);
  const double vs = rate([&](double tt) { return at(tt).sx; }, t, h);
  const double half = 0.5 * m2 * (v2x * v2x + v2y * v2y) + 0.5 * j2 * w2 * w2 +
                      0.5 * m3 * (v3x * v3x + v3y * v3y) + 0.5 * j3 * w3 * w3;
  return kHalves * half + 0.5 * m_slider * vs * vs;
}

TEST(DynamicsInertia, KineticEnergyOfUniformBarsEqualsHalfMThetaDotSquared) {
  const SliderCrankDynamics model(from_bar_links(kR2, kR3, kM2, kM3, kMSlider, kSprings, kHalves));
  const double j2 = kM2 * kR2 * kR2 / 12.0, j3 = kM3 * kR3 * kR3 / 12.0;  // uniform bars
  int checked = 0;
  for (double t = 0.0; t < 5.0; t += 0.05) {
    const double theta2 = motion(t), theta2_dot = motion_rate(t);
    if (std::abs(theta2_dot) < 0.05) continue;  // the turning points carry no kinetic energy
    const double expected = kinetic_energy_by_differences(t, kM2, kM3, j2, j3, kMSlider);
    const double model_energy = 0.5 * model.terms(theta2).M * theta2_dot * theta2_dot;
    EXPECT_NEAR(model_energy, expected, kEnergyTolerance * expected)
        << "theta2 = " << theta2 << ", theta2_dot = " << theta2_dot;
    ++checked;
  }
  EXPECT_GE(checked, 80);
}

TEST(DynamicsInertia, KineticEnergyWithInertiasThatAreNotUniformBars) {
  // Each term on its own: links with their own J_C (a crank with a hub, a coupler with end
  // masses), and each mass alone.
  const std::array<std::array<double, 5>, 5> cases = {{
      {kM2, kM3, 3.1e-6, 7.7e-6, kMSlider},
      {kM2, 0.0, 0.0, 0.0, 0.0},
      {0.0, kM3, 0.0, 0.0, 0.0},
      {0.0, 0.0, 3.1e-6, 0.0, 0.0},
      {0.0, 0.0, 0.0, 7.7e-6, 0.0},
  }};
  for (const auto& c : cases) {
    DynamicsParameters p;
    p.r2 = kR2;
    p.r3 = kR3;
    p.m2 = c[0];
    p.m3 = c[1];
    p.J_C2 = c[2];
    p.J_C3 = c[3];
    p.m_slider = c[4];
    p.k = kSprings;
    p.halves = kHalves;
    const SliderCrankDynamics model(p);
    for (double t = 0.1; t < 5.0; t += 0.25) {
      const double theta2_dot = motion_rate(t);
      if (std::abs(theta2_dot) < 0.05) continue;
      const double expected = kinetic_energy_by_differences(t, c[0], c[1], c[2], c[3], c[4]);
      const double model_energy = 0.5 * model.terms(motion(t)).M * theta2_dot * theta2_dot;
      EXPECT_NEAR(model_energy, expected, kEnergyTolerance * expected)
          << "m2 " << c[0] << " m3 " << c[1] << " J_C2 " << c[2] << " J_C3 " << c[3] << " m_s "
          << c[4] << " at theta2 = " << motion(t);
    }
  }
}

TEST(DynamicsInertia, SliderOnlyMechanismHasTheSliderMassTimesTheSquaredTransmission) {
  DynamicsParameters p;
  p.r2 = kR2;
  p.r3 = kR3;
  p.m_slider = kMSlider;
  const SliderCrankDynamics model(p);
  for (double theta2 = -1.2; theta2 <= 1.2; theta2 += 0.1) {
    // Delta x = r2 + r3 - r2 cos theta2 - sqrt(r3^2 - r2^2 sin^2 theta2), differentiated.
    const double s = std::sin(theta2), c = std::cos(theta2);
    const double dx = kR2 * s + kR2 * kR2 * s * c / std::sqrt(kR3 * kR3 - kR2 * kR2 * s * s);
    const double expected = kMSlider * dx * dx;
    EXPECT_NEAR(model.terms(theta2).M, expected, kClosedForm * kMSlider * kR2 * kR2)
        << "theta2 = " << theta2;
  }
}

// Angular frequency of free oscillations about the straight position, from the mean period
// between upward crossings of theta2 = 0 in a CVODES integration of the model.
double measured_omega(const SliderCrankDynamics& model, double omega_guess) {
  ForwardOptions options;
  options.rtol = 1e-12;
  options.atol = 1e-16;
  options.record_crossings = true;
  options.crossing_level = 0.0;
  const ForwardDynamics forward(model, options);
  const double period_guess = 2.0 * std::numbers::pi / omega_guess;
  const ForwardResult r = forward.integrate(-kSmallAmplitude, 0.0, {10.5 * period_guess}, nullptr);
  EXPECT_TRUE(r.converged()) << r.message;
  EXPECT_GE(r.upward_crossings.size(), 10u);
  if (r.upward_crossings.size() < 2) return 0.0;
  const double periods = static_cast<double>(r.upward_crossings.size() - 1);
  return 2.0 * std::numbers::pi * periods / (r.upward_crossings.back() - r.upward_crossings[0]);
}

TEST(DynamicsInertia, CrankOnATorsionalSpringIsARodPivotedAtItsEnd) {
  constexpr double k1 = 0.21;
  const SliderCrankDynamics model(from_bar_links(kR2, kR3, kM2, 0.0, 0.0, {k1, 0.0, 0.0}, kHalves));
  const double textbook = std::sqrt(3.0 * k1 / (kM2 * kR2 * kR2));
  EXPECT_NEAR(measured_omega(model, textbook), textbook, kFrequencyTolerance * textbook);
  EXPECT_NEAR(linearise(model, 0.0).omega_n, textbook, kClosedForm * textbook);
}

TEST(DynamicsInertia, WholeMechanismAboutTheStraightPositionIsTwoRodsOnSprings) {
  const SliderCrankDynamics model(from_bar_links(kR2, kR3, kM2, kM3, kMSlider, kSprings, kHalves));
  const double ratio = kR2 / kR3;
  const double stiffness =
      kSprings[0] + kSprings[1] * (1.0 + ratio) * (1.0 + ratio) + kSprings[2] * ratio * ratio;
  const double inertia = (kM2 + kM3) * kR2 * kR2 / 3.0;  // the slider does not move to first order
  const double expected = std::sqrt(stiffness / inertia);
  EXPECT_NEAR(measured_omega(model, expected), expected, kFrequencyTolerance * expected);
}

}  // namespace
}  // namespace flexure::dynamics
