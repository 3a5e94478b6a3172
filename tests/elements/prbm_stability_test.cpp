// The PRBM's own stability verdict (elements/prbm_stability.h): d^2V/dTheta^2 of the PRB model's
// potential energy, Howell §11.1. Checked against
//   * a finite difference of the energy itself: V(Theta) = int_0^Theta (spring_moment -
//     generalized_load) dt, the integrals by 5-point Gauss-Legendre over each step (exact to
//     rounding for these smooth integrands), second difference with h = 1e-3 (error about
//     h^2 V'''' / 12 < 1e-7 of V'' here): the fixed-pinned segment at Table 5.1 rows n = -2, 0, 1,
//     4 and 10, the fixed-guided and the end-moment segment, at random angles and loads;
//   * closed forms: under an axial compression P at Theta = 0 the margin is 1 - P / K_Theta
//     (fixed-pinned: V'' = gamma K_Theta - gamma P) and 1 - P / (4 K_Theta) (fixed-guided: two
//     springs of 2 gamma K_Theta, V'' = 4 gamma K_Theta - gamma P); 1 for a moment alone;
//   * the classification: 2 K_Theta unstable (index 1), K_Theta (1 + 1e-8) critical;
//   * the cantilever's PRBM answers (solve_prbm_cantilever) inside Table 5.1's validity limits:
//     stable, as the exact beam is under those loads (the first root of the virtual-work
//     equation met from the unloaded angle is where the energy's slope turns from falling to
//     rising).
#include "flexure/elements/prbm_stability.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <random>

#include "flexure/elements/prbm_cantilever.h"
#include "flexure/elements/prbm_element.h"

namespace flexure {
namespace {

// int_a^b (spring_moment - generalized_load) dt by 5-point Gauss-Legendre.
double energy_change(const PrbmElement& e, const EndLoad& load, double a, double b) {
  static const std::array<double, 5> x = {
      0.0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640, 0.9061798459386640};
  static const std::array<double, 5> w = {0.5688888888888889,
                                          0.4786286704993665,
                                          0.4786286704993665,
                                          0.2369268850561891,
                                          0.2369268850561891};
  double sum = 0.0;
  for (int i = 0; i < 5; ++i) {
    const double t = 0.5 * (a + b) + 0.5 * (b - a) * x[i];
    sum += w[i] * (e.spring_moment(t) - e.generalized_load(t, load));
  }
  return 0.5 * (b - a) * sum;
}

// (V(Theta + h) - 2 V(Theta) + V(Theta - h)) / h^2.
double energy_second_difference(const PrbmElement& e, const EndLoad& load, double Theta) {
  const double h = 1e-3;
  return (energy_change(e, load, Theta, Theta + h) - energy_change(e, load, Theta - h, Theta)) /
         (h * h);
}

TEST(PrbmStability, SecondDerivativeMatchesTheEnergysFiniteDifference) {
  std::mt19937_64 rng(27201u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int checked = 0;
  for (const double n : {-2.0, 0.0, 1.0, 4.0, 10.0}) {
    const FixedPinnedSegment pinned(FixedPinnedConstants::from_table(n));
    const FixedGuidedSegment guided(FixedPinnedConstants::from_table(n));
    for (int i = 0; i < 20; ++i) {
      const double Theta = (2.0 * unit(rng) - 1.0) * 1.5;
      const EndLoad load = EndLoad::howell(n, (2.0 * unit(rng) - 1.0) * 10.0, 0.0);
      for (const PrbmElement* e :
           {static_cast<const PrbmElement*>(&pinned), static_cast<const PrbmElement*>(&guided)}) {
        const double exact = prbm_energy_curvature(*e, Theta, load).second_derivative;
        const double fd = energy_second_difference(*e, load, Theta);
        EXPECT_NEAR(exact, fd, 1e-6 * std::max(1.0, std::fabs(fd)))
            << e->name() << ", n = " << n << ", Theta = " << Theta;
        ++checked;
      }
    }
  }
  const EndMomentSegment moment;
  for (int i = 0; i < 10; ++i) {
    const double Theta = (2.0 * unit(rng) - 1.0) * 1.5;
    const EndLoad load{0.0, 0.0, (2.0 * unit(rng) - 1.0) * 3.0};
    EXPECT_NEAR(prbm_energy_curvature(moment, Theta, load).second_derivative,
                energy_second_difference(moment, load, Theta),
                1e-6);
    EXPECT_NEAR(prbm_stability(moment, Theta, load).margin, 1.0, 1e-12);
    ++checked;
  }
  EXPECT_EQ(checked, 210);
}

TEST(PrbmStability, AxialCompressionClosedForms) {
  for (const double n : {0.0, 1.0, 5.0}) {
    const FixedPinnedConstants c = FixedPinnedConstants::from_table(n);
    const FixedPinnedSegment pinned(c);
    const FixedGuidedSegment guided(c);
    for (const double P : {0.5, 1.0, 2.0, 5.0, 20.0}) {
      const EndLoad axial{-P, 0.0, 0.0};
      EXPECT_NEAR(prbm_stability(pinned, 0.0, axial).margin, 1.0 - P / c.K_theta, 1e-12);
      EXPECT_NEAR(prbm_stability(guided, 0.0, axial).margin, 1.0 - P / (4.0 * c.K_theta), 1e-12);
      // Tension stiffens: 1 + P / K_Theta.
      EXPECT_NEAR(
          prbm_stability(pinned, 0.0, EndLoad{P, 0.0, 0.0}).margin, 1.0 + P / c.K_theta, 1e-12);
    }
    const Stability beyond = prbm_stability(pinned, 0.0, EndLoad{-2.0 * c.K_theta, 0.0, 0.0});
    EXPECT_EQ(beyond.kind, StabilityKind::kUnstable);
    EXPECT_EQ(beyond.index, 1);
    EXPECT_NEAR(beyond.margin, -1.0, 1e-12);
    const Stability at = prbm_stability(pinned, 0.0, EndLoad{-c.K_theta * (1.0 + 1e-8), 0.0, 0.0});
    EXPECT_EQ(at.kind, StabilityKind::kCritical) << at.message;
    EXPECT_EQ(at.index, 0);
  }
}

TEST(PrbmStability, CantileverAnswersInsideTheLimitsAreStable) {
  std::mt19937_64 rng(27202u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int inside = 0;
  for (int i = 0; i < 200; ++i) {
    const double n = -4.0 + 14.0 * unit(rng), alpha2 = 10.0 * unit(rng);
    const EndCondition end = i % 3 == 0 ? EndCondition::kGuided : EndCondition::kFree;
    const PrbmCantileverSolution s = solve_prbm_cantilever(end, n, alpha2, 0.0);
    ASSERT_TRUE(s.converged()) << s.message;
    ASSERT_TRUE(s.stability.judged()) << s.stability.message;
    if (!s.inside_validity) continue;
    ++inside;
    EXPECT_EQ(s.stability.kind, StabilityKind::kStable)
        << to_string(end) << ", n = " << n << ", alpha2 = " << alpha2 << ": "
        << s.stability.message;
    // The verdict is that of the element at the returned angle (the energy's finite difference).
    const std::unique_ptr<PrbmElement> e = prbm_cantilever_element(end, n, alpha2, 0.0);
    const EndLoad load = EndLoad::howell(n, alpha2, 0.0);
    const double k = prbm_energy_curvature(*e, s.Theta, load).spring_stiffness;
    EXPECT_NEAR(s.stability.margin * k, energy_second_difference(*e, load, s.Theta), 1e-6 * k);
  }
  EXPECT_GE(inside, 50);
}

}  // namespace
}  // namespace flexure
