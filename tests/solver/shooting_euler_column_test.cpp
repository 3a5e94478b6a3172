// What is checked against what: Euler buckling and post-buckling of a pinned-pinned column against
// the classical elastica closed form (Love §263; Timoshenko & Gere §2.7): end slope alpha,
// k = sin(alpha/2), P/Pcr = (2 K(k)/pi)^2, chord/L = 2 E(k)/K(k) - 1, midspan deflection / L =
// k / K(k), with K and E from GSL (gsl_sf_ellint_Kcomp / Ecomp), for alpha up to 170 degrees.
//
// Set-up: by symmetry half the column (length L/2 = 1) is clamped at the midspan (theta = 0) and
// its end is held at the slope alpha (a guided end) under the axial force -P with zero transverse
// force. The shooting solver finds the guide's reaction moment; the closed form says it vanishes
// (the end is a pin) exactly when P = K(k)^2 (Pcr = pi^2/4 for the half length 1).
#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_ellint.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/gsl_guard.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {
namespace {

// Issue requirement: 1e-9. The moment is the difference of O(P) terms, so it is compared with
// P-relative tolerance.
constexpr double kColumnTolerance = 1e-9;

double K_of(double k) {
  gsl_sf_result r;
  EXPECT_EQ(gsl_sf_ellint_Kcomp_e(k, GSL_PREC_DOUBLE, &r), GSL_SUCCESS);
  return r.val;
}
double E_of(double k) {
  gsl_sf_result r;
  EXPECT_EQ(gsl_sf_ellint_Ecomp_e(k, GSL_PREC_DOUBLE, &r), GSL_SUCCESS);
  return r.val;
}

class ShootingEulerColumn : public ::testing::TestWithParam<double> {};

TEST_P(ShootingEulerColumn, PostBuckledLoadMatchesEllipticClosedForm) {
  disable_gsl_abort();
  const double alpha = GetParam() * std::numbers::pi / 180.0;
  const double k = std::sin(0.5 * alpha);
  const double K = K_of(k), E = E_of(k);
  const double P = K * K;  // half length 1: P/Pcr = P / (pi^2/4) = (2K/pi)^2

  SegmentChain half;
  half.segments.push_back(FlexibleSegment{1.0, 1.0, {}, 0.0});
  half.end = EndCondition::kGuided;
  half.prescribed.theta = alpha;
  half.tip_load.Fx = -P;

  const ShootingResult r = ShootingSolver().solve(half);
  ASSERT_TRUE(r.converged()) << r.message;
  // The end is a pin: no moment is needed to hold the slope alpha at this load.
  EXPECT_NEAR(r.tip_load.M, 0.0, kColumnTolerance * P) << "alpha = " << GetParam() << " deg";
  EXPECT_NEAR(r.tip.x, 2.0 * E / K - 1.0, kColumnTolerance);
  EXPECT_NEAR(r.tip.y, 2.0 * k / K, kColumnTolerance);
  // Midspan curvature from the first integral theta'^2 = 2P (cos theta - cos alpha).
  EXPECT_NEAR(-r.reaction.M, 2.0 * k * K, kColumnTolerance * P);
}

INSTANTIATE_TEST_SUITE_P(EndSlopesInDegrees,
                         ShootingEulerColumn,
                         ::testing::Values(1.0, 10.0, 30.0, 60.0, 90.0, 120.0, 150.0, 160.0, 170.0),
                         [](const ::testing::TestParamInfo<double>& info) {
                           return "slope" + std::to_string(static_cast<int>(info.param)) + "deg";
                         });

TEST(ShootingEulerColumn, CriticalLoadIsTheSmallSlopeLimit) {
  // alpha -> 0: P -> pi^2/4 (Euler load of the half length), so the guide moment at the Euler load
  // and a small slope is second order in the slope.
  SegmentChain half;
  half.segments.push_back(FlexibleSegment{1.0, 1.0, {}, 0.0});
  half.end = EndCondition::kGuided;
  half.tip_load.Fx = -std::numbers::pi * std::numbers::pi / 4.0;
  double previous = 0.0;
  for (double alpha : {0.02, 0.01}) {
    half.prescribed.theta = alpha;
    const ShootingResult r = ShootingSolver().solve(half);
    ASSERT_TRUE(r.converged()) << r.message;
    const double moment = std::abs(r.tip_load.M);
    if (previous > 0.0) EXPECT_NEAR(previous / moment, 8.0, 0.1);  // cubic in alpha
    previous = moment;
  }
}

}  // namespace
}  // namespace flexure
