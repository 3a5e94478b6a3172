// What is checked against what (initially curved cantilever, Howell §5.5, Table 5.2):
//  * the exact curved-beam tip used by the derivation (elliptic solver, straight beam with end
//    moment mu = kappa0) against an RK4 integration of the curved beam's own law theta' = kappa0 +
//    M/EI with M(1) = 0 (eq. 2.103), started from the solver's root moment;
//  * the unloaded state of the elliptic path with end moment mu = kappa0 against the closed-form
//    circular arc a_i/l = sin kappa0/kappa0, b_i/l = (1 - cos kappa0)/kappa0 (eqs. 5.117-5.118);
//  * kappa0 = 0: the curved-beam derivation (general path, samples uniform in the PRB angle)
//    against the independent fixed-pinned derivation (explicit inverse problem, samples uniform in
//    theta0) for n = -0.5, 0, 1;
//  * the load-ratio averages over -0.5 <= n <= 1 against Table 5.2: gamma and rho within half a
//    unit of the book's last printed digit for kappa0 <= 1; K_theta (per-n fits at the averaged
//    gamma) within the book's rounding plus the Table 5.1 tolerance for kappa0 <= 0.1; for
//    0.25..1, where the derivation misses the table (docs/prbm.md), a REGRESSION check: the gaps
//    +0.0271, +0.0486, +0.0812 measured here, to 5e-4;
//  * CurvedCantileverConstants::from_derivation(0.1) builds an element with Table 5.2's row;
//  * the reason rows kappa0 >= 1.5 are not reproduced: on the tension side of the average the
//    0.5 % range Theta_max(gamma) - Theta_i collapses below 2 deg (docs/prbm.md).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "flexure/elements/prbm_element.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/elliptic/elliptic_solver.h"
#include "tests/support/elastica_reference.h"

namespace flexure {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
// 0.25 deg samples keep the suite fast; against 0.1 deg the averages move by < 0.0004 in gamma and
// < 0.002 in K_theta for kappa0 <= 1 (docs/prbm.md).
constexpr double kStepDeg = 0.25;
// kappa0 = 0, curved path vs fixed-pinned path: gamma and Theta_max(gamma) come from the exact
// error function on both (root-refined), so they agree to the gamma search resolution; c_theta and
// K_theta are least-squares slopes whose weights differ (uniform in Theta vs uniform in theta0,
// theta0/Theta varies by ~5 % over the range), worth a few 1e-3.
constexpr double kSameGammaTolerance = 2e-5;
constexpr double kSameThetaMaxToleranceDeg = 0.05;
constexpr double kSlopeWeightingTolerance = 0.006;
// Table 5.2 prints gamma and K_theta to 2 decimals and rho to 3: half a unit of the last digit.
constexpr double kGammaRowTolerance = 0.005;
constexpr double kRhoRowTolerance = 0.005;  // rho follows gamma (eq. 5.116), so gamma's rounding
// K_theta: the book's rounding plus the Table 5.1 method tolerance of docs/prbm.md (0.01).
constexpr double kKThetaRowTolerance = 0.015;

PrbmDerivationOptions fast_options() {
  PrbmDerivationOptions o;
  o.theta0_step_deg = kStepDeg;
  return o;
}

const CurvedCantileverTableRow& row_at(double kappa0) {
  for (const auto& r : table_5_2()) {
    if (r.kappa0 == kappa0) return r;
  }
  throw std::logic_error("no Table 5.2 row");
}

TEST(CurvedCantileverDerivation, ExactTipMatchesDirectIntegrationOfTheCurvedBeam) {
  // RK4 with 4000 steps: error ~ (1/4000)^4 times derivatives of order alpha2^2 <= 100 -> < 1e-9;
  // the start value m0 is the solver's, so the tolerance also bounds its root-moment error.
  constexpr double kRk4Tolerance = 1e-8;
  const EllipticSolver solver;
  for (double kappa0 : {0.5, 1.0, 2.0}) {
    for (double n : {-0.5, 0.0, 1.0}) {
      const double alpha2 = 3.0;
      const EllipticResult r = solver.solve(EndLoad::howell(n, alpha2, kappa0));
      ASSERT_TRUE(r.converged()) << r.message;
      // The solver's root curvature is kappa0 + the bending moment of the force at the clamp.
      // RK4 of the curved beam itself: theta' = kappa0 + m (tests/support/elastica_reference.h).
      const flexure::testing::ElasticaState c = flexure::testing::integrate_elastica(
          -n * alpha2, alpha2, r.root_moment - kappa0, 4000, kappa0);
      EXPECT_NEAR(c.x, r.tip.a_over_l, kRk4Tolerance) << kappa0 << " " << n;
      EXPECT_NEAR(c.y, r.tip.b_over_l, kRk4Tolerance) << kappa0 << " " << n;
      EXPECT_NEAR(c.theta, r.tip.theta0, kRk4Tolerance) << kappa0 << " " << n;
      EXPECT_NEAR(c.m, 0.0, 1e-7) << "no moment at the free tip; " << kappa0 << " " << n;
    }
  }
}

TEST(CurvedCantileverDerivation, UnloadedEllipticPathIsTheCircularArc) {
  const EllipticSolver solver;
  for (double kappa0 : {0.1, 1.0, 2.0}) {
    const EllipticResult r = solver.solve(EndLoad::howell(0.5, 0.0, kappa0));
    ASSERT_TRUE(r.converged()) << r.message;
    const UnloadedTip arc = UnloadedTip::circular_arc(kappa0);
    EXPECT_NEAR(r.tip.a_over_l, std::sin(kappa0) / kappa0, 1e-12);
    EXPECT_NEAR(r.tip.b_over_l, (1.0 - std::cos(kappa0)) / kappa0, 1e-12);
    EXPECT_NEAR(r.tip.theta0, kappa0, 1e-12);
    EXPECT_NEAR(arc.a, r.tip.a_over_l, 1e-12);
    EXPECT_NEAR(arc.b, r.tip.b_over_l, 1e-12);
  }
}

TEST(CurvedCantileverDerivation, StraightLimitReproducesTheFixedPinnedDerivation) {
  for (double n : {-0.5, 0.0, 1.0}) {
    const PrbmDerivation curved = derive_initially_curved(0.0, n, fast_options());
    const PrbmDerivation straight = derive_fixed_pinned(n, fast_options());
    ASSERT_TRUE(curved.converged()) << curved.message;
    ASSERT_TRUE(straight.converged()) << straight.message;
    EXPECT_EQ(curved.segment, PrbmSegment::kInitiallyCurved);
    EXPECT_EQ(straight.segment, PrbmSegment::kFixedPinned);
    EXPECT_NEAR(curved.gamma, straight.gamma, kSameGammaTolerance) << "n = " << n;
    EXPECT_NEAR(
        curved.theta_max_gamma / kDeg, straight.theta_max_gamma / kDeg, kSameThetaMaxToleranceDeg)
        << "n = " << n;
    EXPECT_NEAR(curved.theta_max_K, straight.theta_max_K, 1e-12) << "n = " << n;
    EXPECT_NEAR(curved.K_theta, straight.K_theta, kSlopeWeightingTolerance) << "n = " << n;
    EXPECT_NEAR(curved.c_theta, straight.c_theta, kSlopeWeightingTolerance) << "n = " << n;
    EXPECT_DOUBLE_EQ(curved.theta_i, 0.0);
    EXPECT_NEAR(curved.rho, curved.gamma, 1e-15);
  }
}

// Regression values (see AveragesReproduceTable52GammaAndRhoUpToKappa0One): derived K_theta minus
// Table 5.2's at kappa0 = 0.25, 0.5, 1, measured with fast_options().
constexpr double kKThetaGap025 = 0.0271;
constexpr double kKThetaGap05 = 0.0486;
constexpr double kKThetaGap1 = 0.0812;
// Half a unit of the fourth decimal: well above rounding differences between builds (the values
// are deterministic), well below any change of the fit range or the averaging (~0.005 and up).
constexpr double kKThetaGapRegressionTolerance = 5e-4;

TEST(CurvedCantileverDerivation, AveragesReproduceTable52GammaAndRhoUpToKappa0One) {
  for (double kappa0 : {0.0, 0.1, 0.25, 0.5, 1.0}) {
    const CurvedCantileverTableRow& row = row_at(kappa0);
    const CurvedCantileverAverage a =
        derive_initially_curved_average(kappa0, -0.5, 1.0, 6, fast_options());
    ASSERT_TRUE(a.converged()) << a.message;
    EXPECT_EQ(a.used, 7) << "kappa0 = " << kappa0 << ": " << a.message;
    EXPECT_EQ(a.used_K, 7) << "kappa0 = " << kappa0 << ": " << a.message;
    EXPECT_NEAR(a.gamma, row.gamma, kGammaRowTolerance) << "kappa0 = " << kappa0;
    EXPECT_NEAR(a.rho, row.rho, kRhoRowTolerance) << "kappa0 = " << kappa0;
    if (kappa0 <= 0.1) {
      EXPECT_NEAR(a.K_theta, row.K_theta, kKThetaRowTolerance) << "kappa0 = " << kappa0;
    } else {
      // REGRESSION, not a table check: for kappa0 = 0.25, 0.5, 1 the derived K_theta misses
      // Table 5.2 (it keeps the book's dip-and-rise shape but sits above it, docs/prbm.md), so
      // no source value exists to assert. Pinned instead to the gaps measured with these options
      // (0.25 deg samples), so that a change of the derivation shows; a change that moves them
      // must re-measure them and say why.
      const double measured_gap = kappa0 == 0.25  ? kKThetaGap025
                                  : kappa0 == 0.5 ? kKThetaGap05
                                                  : kKThetaGap1;
      EXPECT_NEAR(a.K_theta - row.K_theta, measured_gap, kKThetaGapRegressionTolerance)
          << "kappa0 = " << kappa0 << " (regression)";
    }
  }
}

TEST(CurvedCantileverDerivation, StrongCurvatureRowsFailBecauseTheTensionSideRangeCollapses) {
  // kappa0 = 1.5: at n = -0.5 the force angle (63.4 deg) is only ~12 deg beyond Theta_i, and the
  // 0.5 % criterion (relative to a deflection that starts at zero, in a direction that is not
  // normal to the PRB link) holds for less than 2 deg of Theta: the per-n gamma is then set by the
  // initial direction, not by a useful range, and it drags the average away from Table 5.2.
  const PrbmDerivation d = derive_initially_curved(1.5, -0.5, fast_options());
  ASSERT_TRUE(d.converged()) << d.message;
  EXPECT_LT(d.theta_max_gamma / kDeg, 2.0);
  const CurvedCantileverAverage a =
      derive_initially_curved_average(1.5, -0.5, 1.0, 6, fast_options());
  ASSERT_TRUE(a.converged()) << a.message;
  EXPECT_GT(a.gamma - row_at(1.5).gamma, kGammaRowTolerance);
  // kappa0 = 2, n = -0.5: the force does not open the PRB link at all and is left out.
  EXPECT_FALSE(derive_initially_curved(2.0, -0.5, fast_options()).converged());
}

TEST(CurvedCantileverDerivation, ElementFromDerivedConstantsMatchesTable52Row) {
  // kappa0 = 0.1: the element built from the derived averages has Table 5.2's gamma, rho, K_theta
  // within the row tolerances above.
  const CurvedCantileverConstants c = CurvedCantileverConstants::from_derivation(0.1);
  const InitiallyCurvedCantilever element(c);
  const CurvedCantileverTableRow& row = row_at(0.1);
  EXPECT_NEAR(c.gamma, row.gamma, kGammaRowTolerance);
  EXPECT_NEAR(c.K_theta, row.K_theta, kKThetaRowTolerance);
  EXPECT_NEAR(element.rho(), row.rho, kRhoRowTolerance);
  EXPECT_NE(c.source.find("derived"), std::string::npos);
}

TEST(CurvedCantileverDerivation, RejectsInvalidInput) {
  EXPECT_THROW(derive_initially_curved(-0.1, 0.0), InvalidInput);
  EXPECT_THROW(derive_initially_curved(0.5, 20.0), InvalidInput);
  EXPECT_THROW(derive_initially_curved(std::nan(""), 0.0), InvalidInput);
  EXPECT_THROW(derive_initially_curved_average(0.5, 1.0, 0.0), InvalidInput);
  EXPECT_THROW(derive_initially_curved_average(0.5, -0.5, 1.0, 0), InvalidInput);
}

}  // namespace
}  // namespace flexure
