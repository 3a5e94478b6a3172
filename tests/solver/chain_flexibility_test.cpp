// What is checked against what: the chain-algorithm element flexibility (Howell eq. 7.30, factored
// form of docs/theory-chain.md) against (a) the numerical inverse of the reduced stiffness block of
// eq. 7.29, (b) the linear cantilever compliances L^3/3EI, L^2/2EI, L/EI at zero axial load, and
// (c) the exact cantilever Euler load pi^2 EI/(4 L^2), which the consistent geometric stiffness
// approximates from above (D = 0 at L^2 P/EI = -2.4857).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "flexure/solver/chain/element_flexibility.h"

namespace flexure {
namespace {

// Inverting a 2x2 matrix in double precision: relative rounding of a few ulps times its condition
// number (below 1e4 for the cases here).
constexpr double kInverseTolerance = 1e-11;

TEST(ChainFlexibility, IsTheInverseOfTheEq729StiffnessBlock) {
  for (double L : {0.01, 0.1, 1.0, 3.0}) {
    for (double EI : {0.5, 1.0, 200.0}) {
      for (double p : {-2.0, -1.0, -0.3, 0.0, 0.7, 5.0, 40.0}) {  // p = L^2 P_ax / EI
        const double P = p * EI / (L * L);
        const ElementFlexibility f = element_flexibility(L, EI, P);
        ASSERT_TRUE(f.valid) << "L=" << L << " p=" << p;
        const ElementStiffness k = element_stiffness(L, EI, P);
        // K * F must be the identity.
        const double i11 = k.k22 * f.f22 + k.k23 * f.f23;
        const double i12 = k.k22 * f.f23 + k.k23 * f.f33;
        const double i21 = k.k23 * f.f22 + k.k33 * f.f23;
        const double i22 = k.k23 * f.f23 + k.k33 * f.f33;
        EXPECT_NEAR(i11, 1.0, kInverseTolerance) << "L=" << L << " EI=" << EI << " p=" << p;
        EXPECT_NEAR(i22, 1.0, kInverseTolerance) << "L=" << L << " EI=" << EI << " p=" << p;
        // Off-diagonal entries carry units 1/length and length: compare them made dimensionless.
        EXPECT_NEAR(i12 * L, 0.0, kInverseTolerance) << "L=" << L << " p=" << p;
        EXPECT_NEAR(i21 / L, 0.0, kInverseTolerance) << "L=" << L << " p=" << p;
      }
    }
  }
}

TEST(ChainFlexibility, ReducesToLinearCantileverCompliancesWithoutAxialLoad) {
  const double L = 0.37;
  const double EI = 2.5;
  const ElementFlexibility f = element_flexibility(L, EI, 0.0);
  ASSERT_TRUE(f.valid);
  EXPECT_NEAR(f.f22, L * L * L / (3.0 * EI), 1e-15);
  EXPECT_NEAR(f.f23, L * L / (2.0 * EI), 1e-15);
  EXPECT_NEAR(f.f33, L / EI, 1e-15);
}

TEST(ChainFlexibility, TensionStiffensAndCompressionSoftens) {
  const ElementFlexibility free = element_flexibility(1.0, 1.0, 0.0);
  const ElementFlexibility tension = element_flexibility(1.0, 1.0, 1.0);
  const ElementFlexibility compression = element_flexibility(1.0, 1.0, -1.0);
  EXPECT_LT(tension.f22, free.f22);
  EXPECT_LT(tension.f33, free.f33);
  EXPECT_GT(compression.f22, free.f22);
  EXPECT_GT(compression.f33, free.f33);
}

TEST(ChainFlexibility, BucklesJustAboveTheCantileverEulerLoad) {
  // Root of D = 240 + 104 p + 3 p^2 nearest zero: p = (-104 + sqrt(104^2 - 2880)) / 6.
  const double p_root = (-104.0 + std::sqrt(104.0 * 104.0 - 2880.0)) / 6.0;
  const double p_euler = -std::numbers::pi * std::numbers::pi / 4.0;
  // The two-node cubic element overestimates the buckling load by 0.74 % (Rayleigh-Ritz bound).
  EXPECT_LT(p_root, p_euler);
  EXPECT_NEAR(p_root / p_euler, 1.0, 0.01);
  EXPECT_TRUE(element_flexibility(1.0, 1.0, 0.999 * p_root).valid);
  EXPECT_FALSE(element_flexibility(1.0, 1.0, 1.001 * p_root).valid);
  // Near the root the compliance grows without bound.
  EXPECT_GT(element_flexibility(1.0, 1.0, 0.999 * p_root).f33, 100.0);
}

}  // namespace
}  // namespace flexure
