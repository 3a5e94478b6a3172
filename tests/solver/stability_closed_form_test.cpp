// The stability verdict against closed forms (docs/stability.md, "Validation"), by both methods:
// the discrete second variation (segment_chain.h) and the continuous Jacobi count
// (jacobi_stability.h).
//
//  * Straight cantilever under an axial compression P: the critical loads are (2k - 1)^2 pi^2 / 4
//    (theta'' + P theta = 0, theta(0) = theta'(1) = 0), so the index is k for
//    (2k - 1)^2 pi^2 / 4 < P < (2k + 1)^2 pi^2 / 4 and the margin is 1 - 4 P / pi^2.
//  * Straight columns with prescribed tip coordinates, P the compressive support reaction or the
//    given end force; the margin of every straight column is 1 - P / P_cr and its k-th eigenvalue
//    1 - P / P_k (Q - lambda B = (1 - lambda) B - P int eta^2):
//      guided (sway, theta(1) prescribed):              P_1 = pi^2;
//      clamped-pinned (x, y prescribed, moment-free):   P_1 = x1^2, x1 = 4.4934.. the smallest
//                                                       positive root of tan x = x;
//      clamped-clamped (x, y, theta prescribed):        P_1 = 4 pi^2 (symmetric mode),
//                                                       P_2 = x2^2, x2 = 8.9868.. the smallest
//                                                       positive root of tan(x/2) = x/2
//                                                       (antisymmetric mode).
//    The roots are computed here by Brent's method. These three differ from the cantilever only in
//    the constraints and the Dirichlet condition, which the constraint correction must get right:
//    the unconstrained counts are checked to differ.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "flexure/solver/chain_model/jacobi_stability.h"
#include "flexure/solver/chain_model/second_variation.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/scalar_root.h"

namespace flexure {
namespace {

constexpr double kPi = std::numbers::pi;
// The discrete margin on the default stations (Richardson-extrapolated) against the closed form.
constexpr double kMarginTolerance = 1e-8;
// The Jacobi count's margin (bisection to 1e-11 on an integration at rtol 1e-12).
constexpr double kJacobiTolerance = 1e-9;

// A root of tan(x) = x, i.e. of sin x - x cos x, in [a, b], by Brent's method.
double root_of_tan_x_equals_x(double a, double b) {
  auto f = [](double x) { return std::sin(x) - x * std::cos(x); };
  const ScalarRootResult r = brent_root(f, a, b, f(a), f(b));
  EXPECT_TRUE(r.converged());
  return r.x;
}

std::vector<ShapePoint> straight(const std::vector<double>& s) {
  std::vector<ShapePoint> shape;
  for (double si : s) shape.push_back(ShapePoint{si, si, 0.0, 0.0});
  return shape;
}

struct Column {
  SegmentChain chain;
  Reaction support;  // the tip support's reaction
  Reaction root;     // the clamp's reaction, -N(0)
};

// A straight uniform column (l = 1, EI = 1) compressed by P along x.
Column column(EndCondition end, double P) {
  Column c;
  c.chain = uniform_cantilever(EndLoad{});
  c.chain.end = end;
  const PrescribedMask mask = prescribed_mask(end);
  if (mask.x) {
    c.support.Fx = -P;  // the support pushes the tip towards the clamp
  } else {
    c.chain.tip_load.Fx = -P;
  }
  c.root.Fx = P;
  return c;
}

Stability discrete_verdict(const Column& c) {
  const std::vector<double> s = stability_stations(c.chain, c.support);
  return equilibrium_stability(c.chain, c.support, straight(s));
}

TEST(StabilityClosedForm, CantileverUnderAxialCompression) {
  for (const double P : {0.0, 0.5, 2.0, 2.6, 3.0, 10.0, 22.0, 23.0, 30.0, 61.0, 62.0, 100.0}) {
    int k = 0;
    while ((2 * k + 1) * (2 * k + 1) * kPi * kPi / 4.0 < P) ++k;
    const double margin = 1.0 - 4.0 * P / (kPi * kPi);
    const Column c = column(EndCondition::kFree, P);
    const Stability d = discrete_verdict(c);
    EXPECT_EQ(d.index, k) << "P = " << P << ": " << d.message;
    EXPECT_NEAR(d.margin, margin, kMarginTolerance * std::max(1.0, std::fabs(margin)))
        << "P = " << P;
    EXPECT_EQ(d.kind, k > 0 ? StabilityKind::kUnstable : StabilityKind::kStable) << P;
    const Stability j = JacobiSecondVariation(c.chain, c.root).verdict();
    EXPECT_EQ(j.index, k) << "P = " << P << ": " << j.message;
    EXPECT_NEAR(j.margin, margin, kJacobiTolerance * std::max(1.0, std::fabs(margin)))
        << "P = " << P;
  }
}

TEST(StabilityClosedForm, TensionOnlyHasMarginOne) {
  // No compressed direction: the eigenvalues accumulate at 1 from above only, margin exactly 1.
  const Column c = column(EndCondition::kFree, -5.0);
  const Stability d = discrete_verdict(c);
  EXPECT_EQ(d.kind, StabilityKind::kStable);
  EXPECT_EQ(d.margin, 1.0);
  EXPECT_EQ(JacobiSecondVariation(c.chain, c.root).verdict().margin, 1.0);
}

TEST(StabilityClosedForm, CriticalLoadIsCriticalWithinTheTolerance) {
  const double P_cr = kPi * kPi / 4.0;
  for (const double factor : {1.0 - 1e-7, 1.0, 1.0 + 1e-7}) {
    const Stability d = discrete_verdict(column(EndCondition::kFree, factor * P_cr));
    EXPECT_EQ(d.kind, StabilityKind::kCritical) << factor << ": " << d.message;
    EXPECT_EQ(d.index, 0);
  }
  // Beyond the tolerance (1e-6 of the critical load) the verdict is decided.
  EXPECT_EQ(discrete_verdict(column(EndCondition::kFree, (1.0 + 1e-5) * P_cr)).kind,
            StabilityKind::kUnstable);
  EXPECT_EQ(discrete_verdict(column(EndCondition::kFree, (1.0 - 1e-5) * P_cr)).kind,
            StabilityKind::kStable);
}

struct ConstrainedCase {
  EndCondition end;
  double P1, P2;  // the first two critical loads
};

std::vector<ConstrainedCase> constrained_cases() {
  // The first two positive roots of tan x = x (4.4934.., 7.7253..).
  const double x1 = root_of_tan_x_equals_x(kPi + 0.1, 1.5 * kPi - 1e-9);
  const double x1b = root_of_tan_x_equals_x(2.0 * kPi + 0.1, 2.5 * kPi - 1e-9);
  const double x2 = 2.0 * x1;  // tan(x/2) = x/2
  // The guided column's second critical load: theta(0) = theta(1) = 0, (2 pi)^2.
  return {{EndCondition::kGuided, kPi * kPi, 4.0 * kPi * kPi},
          {EndCondition::kPinned, x1 * x1, x1b * x1b},
          {EndCondition::kFixed, 4.0 * kPi * kPi, x2 * x2}};
}

TEST(StabilityClosedForm, ClosedFormRootsAreTheBooksValues) {
  const std::vector<ConstrainedCase> cases = constrained_cases();
  EXPECT_NEAR(cases[1].P1, 20.19, 0.005);   // clamped-pinned, 4.4934^2
  EXPECT_NEAR(cases[2].P2, 80.763, 0.001);  // clamped-clamped antisymmetric
}

TEST(StabilityClosedForm, ColumnsWithPrescribedTipCoordinates) {
  for (const ConstrainedCase& k : constrained_cases()) {
    for (const double P : {0.3 * k.P1, 0.9 * k.P1, 0.5 * (k.P1 + k.P2), 1.2 * k.P2}) {
      const int index = P < k.P1 ? 0 : (P < k.P2 ? 1 : 2);
      const Column c = column(k.end, P);
      const std::vector<double> s = stability_stations(c.chain, c.support);
      const Stability d = equilibrium_stability(c.chain, c.support, straight(s));
      const char* name = to_string(k.end);
      EXPECT_EQ(d.index, index) << name << " P = " << P << ": " << d.message;
      const std::vector<double> eig =
          second_variation_eigenvalues(c.chain, c.support, straight(s), 2);
      EXPECT_NEAR(eig[0], 1.0 - P / k.P1, kMarginTolerance * std::max(1.0, P / k.P1))
          << name << " P = " << P;
      EXPECT_NEAR(eig[1], 1.0 - P / k.P2, kMarginTolerance * std::max(1.0, P / k.P2))
          << name << " P = " << P;
      EXPECT_DOUBLE_EQ(d.margin, eig[0]);
      const JacobiSecondVariation j(c.chain, c.root);
      EXPECT_EQ(j.count(0.0), index) << name << " P = " << P;
      EXPECT_NEAR(j.eigenvalue(1), 1.0 - P / k.P1, kJacobiTolerance * std::max(1.0, P / k.P1))
          << name << " P = " << P;
      EXPECT_NEAR(j.eigenvalue(2), 1.0 - P / k.P2, kJacobiTolerance * std::max(1.0, P / k.P2))
          << name << " P = " << P;
    }
  }
}

TEST(StabilityClosedForm, ConstraintsChangeTheCount) {
  // Between the clamped-clamped column's first critical load (4 pi^2) and the clamped-free ones:
  // at P = 30 the cantilever has 2 negative directions, the same column with its tip angle held
  // (eta(1) = 0, guided) 1 (pi^2 < 30 < 4 pi^2), and with y also held (int eta = 0) none. The x
  // constraint of a straight column vanishes (int sin(theta) eta = 0): counted as none.
  const double P = 30.0;
  const Column fixed = column(EndCondition::kFixed, P);
  const JacobiSecondVariation j(fixed.chain, fixed.root);
  EXPECT_EQ(j.constraint_count(), 1);
  EXPECT_EQ(j.unconstrained_count(0.0), 1);
  EXPECT_EQ(j.count(0.0), 0);
  const DiscreteSecondVariation q = discrete_second_variation(
      fixed.chain, fixed.support, straight(stability_stations(fixed.chain, fixed.support)));
  EXPECT_EQ(q.constraints.size(), 1u);
  EXPECT_EQ(constrained_inertia(q, 0.0).negative_A, 1);
  EXPECT_EQ(constrained_inertia(q, 0.0).count, 0);
  const Column free = column(EndCondition::kFree, P);
  EXPECT_EQ(discrete_verdict(free).index, 2);
}

}  // namespace
}  // namespace flexure
