// What is checked against what (solver/common/section.h, docs/plate-modulus.md):
//  * the share of the plate stiffening, plate_fraction(beta, nu), against an independent numerical
//    solution of the strip's edge problem: f'''' + 4 f = 0 on [0, t] integrated by classical RK4
//    from the centre line (f'(0) = f'''(0) = 0, two unknown starting values fitted to the free
//    edge f''(t) = -1, f'''(t) = 0), its integral of f^2 by the trapezoid rule; agreement to 1e-7;
//  * the wide-strip asymptote 1 - 3/(4 t) (the two edge layers of docs/plate-modulus.md, derived
//    by hand) to 1e-12 beyond t = 20, and continuity of the two branches at t = 20;
//  * the narrow limit: the fraction vanishes as (8/45) t^4 (series of the closed form) as beta ->
//  0;
//  * auto's threshold: the fraction is 1/2 there, and the threshold's nu dependence is exactly
//    the factor 1/sqrt(1 - nu^2) of t^2 = sqrt(3 (1 - nu^2)) beta/4;
//  * choose_modulus: on gives E/(1 - nu^2) (steel, nu = 0.3: 1/0.91, +9.89 %); off gives E and
//    needs no nu; on or auto without nu, auto without a width, bad names are InvalidInput naming
//    the field; auto picks the plate for a 127 mm x 1.31 mm strip bent to R = 0.1 m (beta = 123)
//    and the beam for a 1.31 mm square bar at the same curvature (beta = 0.013).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <string>

#include "flexure/solver/common/section.h"
#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

using State = std::array<double, 4>;  // f, f', f'', f'''

// f'''' = -4 f from `start` over [0, t] by RK4 with n steps; returns the end state and the
// trapezoid integral of f^2 over [0, t].
std::pair<State, double> integrate(State y, double t, int n) {
  const double h = t / n;
  auto rhs = [](const State& s) { return State{s[1], s[2], s[3], -4.0 * s[0]}; };
  double integral = 0.5 * y[0] * y[0];
  for (int i = 0; i < n; ++i) {
    const State k1 = rhs(y);
    State tmp;
    for (int j = 0; j < 4; ++j) tmp[j] = y[j] + 0.5 * h * k1[j];
    const State k2 = rhs(tmp);
    for (int j = 0; j < 4; ++j) tmp[j] = y[j] + 0.5 * h * k2[j];
    const State k3 = rhs(tmp);
    for (int j = 0; j < 4; ++j) tmp[j] = y[j] + h * k3[j];
    const State k4 = rhs(tmp);
    for (int j = 0; j < 4; ++j) y[j] += h / 6.0 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
    integral += (i + 1 == n ? 0.5 : 1.0) * y[0] * y[0];
  }
  return {y, integral * h};
}

// The share of the plate stiffening by shooting from the centre line: f = p u + q v with u, v the
// solutions starting at (1, 0, 0, 0) and (0, 0, 1, 0); p, q from the edge conditions.
double fraction_by_shooting(double t) {
  const int n = 20000;
  const auto [u, iu] = integrate({1, 0, 0, 0}, t, n);
  const auto [v, iv] = integrate({0, 0, 1, 0}, t, n);
  // [u'' v''; u''' v'''] [p q]^T = [-1 0]^T
  const double det = u[2] * v[3] - v[2] * u[3];
  const double p = (-1.0 * v[3]) / det;
  const double q = (u[3] * 1.0) / det;
  const auto [f, integral] = integrate({p, 0, q, 0}, t, n);
  return 1.0 + f[1] / t + 2.0 / t * (2.0 * integral);  // integral over [-t, t]
}

double beta_of_half_width(double t, double nu) {
  return 4.0 * t * t / std::sqrt(3.0 * (1.0 - nu * nu));
}

TEST(PlateFraction, AgreesWithShootingTheEdgeProblem) {
  for (double nu : {0.3, 0.1, 0.45}) {
    for (double t : {0.3, 0.8, 1.2, 1.6, 2.5, 4.0, 8.0, 15.0}) {
      const double beta = beta_of_half_width(t, nu);
      EXPECT_NEAR(plate_fraction(beta, nu), fraction_by_shooting(t), 1e-7)
          << "nu " << nu << " t " << t;
    }
  }
}

TEST(PlateFraction, WideStripAsymptote) {
  for (double t : {20.0, 40.0, 1e3, 1e6}) {
    EXPECT_NEAR(plate_fraction(beta_of_half_width(t, 0.3), 0.3), 1.0 - 0.75 / t, 1e-12);
  }
  // Both branches agree where they meet (the closed form at 19.999, the asymptote at 20).
  EXPECT_NEAR(plate_fraction(beta_of_half_width(19.999999, 0.3), 0.3), 1.0 - 0.75 / 20.0, 1e-8);
}

TEST(PlateFraction, NarrowStripIsABeam) {
  EXPECT_EQ(plate_fraction(0.0, 0.3), 0.0);
  // (8/45) t^4 at small t (docs/plate-modulus.md): 3.03e-4 at beta = 0.1, nu = 0.3.
  for (double t : {0.02, 0.06, 0.2}) {
    EXPECT_NEAR(plate_fraction(beta_of_half_width(t, 0.3), 0.3) / (8.0 / 45.0 * std::pow(t, 4)),
                1.0,
                0.01 + 0.1 * t * t * t * t)
        << t;
  }
  EXPECT_GT(plate_fraction(1e6, 0.3), 0.99);
}

TEST(PlateFraction, ThresholdIsTheHalfWayPoint) {
  const double beta = searle_threshold(0.3);
  EXPECT_NEAR(plate_fraction(beta, 0.3), 0.5, 1e-10);
  EXPECT_NEAR(beta, 6.297, 5e-3);  // docs/plate-modulus.md
  // t* is universal, so beta* scales as 1/sqrt(1 - nu^2).
  EXPECT_NEAR(
      searle_threshold(0.45) / searle_threshold(0.0), 1.0 / std::sqrt(1.0 - 0.45 * 0.45), 1e-12);
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InvalidInput& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InvalidInput thrown";
  return {};
}

TEST(ChooseModulus, OnOffAndErrors) {
  const double E = 200e9;
  const ModulusChoice off = choose_modulus(PlateRule::kOff, E, std::nullopt, {}, {}, {}, "beam");
  EXPECT_FALSE(off.plate);
  EXPECT_EQ(off.effective_E, E);
  const ModulusChoice on = choose_modulus(PlateRule::kOn, E, 0.3, {}, {}, {}, "beam");
  EXPECT_TRUE(on.plate);
  EXPECT_NEAR(on.effective_E / E, 1.0 / 0.91, 1e-15);
  EXPECT_NEAR(on.effective_E / E - 1.0, 0.0989, 1e-4);  // "about 9.9 % more force"
  EXPECT_NE(message_of([&] {
              choose_modulus(PlateRule::kOn, E, {}, {}, {}, {}, "segment 2");
            }).find("segment 2: plate = on needs Poisson's ratio nu"),
            std::string::npos);
  EXPECT_NE(message_of([&] {
              choose_modulus(PlateRule::kAuto, E, 0.3, {}, {}, 1.0, "beam");
            }).find("needs the strip's width and thickness"),
            std::string::npos);
  EXPECT_NE(message_of([&] { plate_rule_from_string("yes", "--plate"); }).find("--plate must be"),
            std::string::npos);
  EXPECT_EQ(plate_rule_from_string("AUTO", "x"), PlateRule::kAuto);
  EXPECT_NE(message_of([&] { choose_modulus(PlateRule::kOn, E, 0.5, {}, {}, {}, "m"); }).find("nu"),
            std::string::npos);
}

TEST(ChooseModulus, AutoPicksThePlateForAWideStripAndTheBeamForASquareBar) {
  const double E = 200e9, R = 0.1;
  const ModulusChoice strip = choose_modulus(PlateRule::kAuto, E, 0.3, 0.127, 1.31e-3, 1 / R, "s");
  EXPECT_NEAR(*strip.beta, 0.127 * 0.127 / (R * 1.31e-3), 1e-9);
  EXPECT_TRUE(strip.plate);
  EXPECT_NEAR(strip.effective_E, E / 0.91, 1e-3);
  EXPECT_GT(*strip.fraction, 0.85);
  const ModulusChoice bar = choose_modulus(PlateRule::kAuto, E, 0.3, 1.31e-3, 1.31e-3, 1 / R, "s");
  EXPECT_FALSE(bar.plate);
  EXPECT_EQ(bar.effective_E, E);
  EXPECT_LT(*bar.fraction, 1e-5);  // (8/45) t^4 = 5.2e-6
}

}  // namespace
}  // namespace flexure
