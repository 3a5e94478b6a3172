// What is checked against what: the shooting solver (CVODES + sensitivity Newton) on a uniform
// cantilever against closed forms -- the pure end moment circle (Howell eqs. 2.59, 2.64), the
// small-load linear limit b = alpha^2/3 (Howell eq. 2.13 nondimensional) and its convergence rate,
// and the exact n = 0 table of Howell's elliptic integrals (eqs. 2.90-2.98, values computed with
// mpmath to 8 digits). Also a stress-free curved beam (kappa0) against its circular arc.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {
namespace {

// CVODES runs at rtol 1e-12; the tip residual is driven below 1e-10; closed forms are exact.
constexpr double kClosedFormTolerance = 1e-10;
// The n = 0 table has 8 significant digits: half a unit in the last place.
constexpr double kTableTolerance = 6e-8;

TEST(ShootingClosedForm, PureEndMomentIsACircularArc) {
  const ShootingSolver solver;
  for (double mu : {0.3,
                    1.0,
                    std::numbers::pi,
                    1.5 * std::numbers::pi,
                    2.0 * std::numbers::pi,
                    -2.0 * std::numbers::pi,
                    3.0 * std::numbers::pi}) {
    const ShootingResult r = solver.solve(EndLoad{0.0, 0.0, mu});
    ASSERT_TRUE(r.converged()) << "mu = " << mu << ": " << r.message;
    EXPECT_NEAR(r.tip.x, std::sin(mu) / mu, kClosedFormTolerance) << "mu = " << mu;
    EXPECT_NEAR(r.tip.y, (1.0 - std::cos(mu)) / mu, kClosedFormTolerance) << "mu = " << mu;
    EXPECT_NEAR(r.tip.theta, mu, kClosedFormTolerance) << "mu = " << mu;
    // The clamp holds the beam against the applied moment.
    EXPECT_NEAR(r.reaction.M, -mu, kClosedFormTolerance);
  }
}

TEST(ShootingClosedForm, SmallLoadApproachesLinearTheoryAtThirdOrder) {
  const ShootingSolver solver;
  // b/l = alpha2/3 - c alpha2^3 + ... (the correction is odd in the load), so the error falls by
  // 2^3 when alpha2 is halved; a bound of alpha2^2 (the O(alpha^4)) must hold as well.
  double previous_error = 0.0;
  for (double alpha2 : {0.2, 0.1, 0.05}) {
    const ShootingResult r = solver.solve(EndLoad::howell(0.0, alpha2));
    ASSERT_TRUE(r.converged()) << r.message;
    const double error = std::abs(r.tip.y - alpha2 / 3.0);
    EXPECT_LE(error, alpha2 * alpha2) << "alpha2 = " << alpha2;
    if (previous_error > 0.0) {
      const double rate = std::log2(previous_error / error);
      EXPECT_NEAR(rate, 3.0, 0.1) << "alpha2 = " << alpha2;
    }
    previous_error = error;
  }
}

struct HowellRow {
  double theta0;
  double alpha2;
  double a_over_l;
  double b_over_l;
};

TEST(ShootingClosedForm, MatchesHowellTableForVerticalEndLoad) {
  // Exact n = 0 table: Howell eqs. 2.90-2.98 evaluated with mpmath at theta0 = 0.25 ... 1.40 rad.
  const HowellRow rows[] = {
      {0.25, 0.51169274, 0.98336262, 0.16572770},
      {0.50, 1.0996750, 0.93377750, 0.32590739},
      {0.75, 1.8779867, 0.85201234, 0.47544836},
      {1.00, 3.0870030, 0.73835640, 0.61037180},
      {1.25, 5.4691778, 0.58909259, 0.72947569},
      {1.40, 8.8064153, 0.47307789, 0.79655336},
  };
  const ShootingSolver solver;
  for (const HowellRow& row : rows) {
    const ShootingResult r = solver.solve(EndLoad::howell(0.0, row.alpha2));
    ASSERT_TRUE(r.converged()) << r.message;
    // alpha2 carries 8 digits; d(a, b, theta)/d(alpha2) is below 1 on this range, so the table
    // rounding propagates at the same level.
    EXPECT_NEAR(r.tip.x, row.a_over_l, kTableTolerance) << "theta0 = " << row.theta0;
    EXPECT_NEAR(r.tip.y, row.b_over_l, kTableTolerance) << "theta0 = " << row.theta0;
    EXPECT_NEAR(r.tip.theta, row.theta0, 2 * kTableTolerance) << "theta0 = " << row.theta0;
  }
}

TEST(ShootingClosedForm, HowellWorkedExampleRootReaction) {
  // Howell eq. 2.100: theta0 = 1 rad at alpha2 = 3.0870030; the clamp carries -P and the moment
  // -P a (eq. 2.67 at x = 0, n = 0).
  const ShootingResult r = ShootingSolver().solve(EndLoad::howell(0.0, 3.0870030));
  ASSERT_TRUE(r.converged()) << r.message;
  EXPECT_NEAR(r.tip.theta, 1.0, 2 * kTableTolerance);
  EXPECT_NEAR(r.reaction.Fx, 0.0, kClosedFormTolerance);
  EXPECT_NEAR(r.reaction.Fy, -3.0870030, kClosedFormTolerance);
  EXPECT_NEAR(r.reaction.M, -3.0870030 * r.tip.x, kClosedFormTolerance);
}

TEST(ShootingClosedForm, CurvedBeamWithEndMomentStaysCircular) {
  // m = EI (theta' - kappa0) is constant under an end moment alone, so the beam is an arc of
  // curvature kappa0 + M/EI (Howell eq. 2.103 with P = 0); EI = 2 and length 1.5 test the scaling.
  SegmentChain chain;
  const double L = 1.5, EI = 2.0, kappa0 = 0.8, M = 3.0;
  chain.segments.push_back(FlexibleSegment{L, EI, {}, kappa0});
  chain.tip_load.M = M;
  const ShootingResult r = ShootingSolver().solve(chain);
  ASSERT_TRUE(r.converged()) << r.message;
  const double kappa = kappa0 + M / EI;
  EXPECT_NEAR(r.tip.theta, kappa * L, kClosedFormTolerance);
  EXPECT_NEAR(r.tip.x, std::sin(kappa * L) / kappa, kClosedFormTolerance);
  EXPECT_NEAR(r.tip.y, (1.0 - std::cos(kappa * L)) / kappa, kClosedFormTolerance);
}

TEST(ShootingClosedForm, ShapeEndsAtTheTip) {
  ShootingSolver::Options options;
  options.shape_points = 21;
  const ShootingResult r = ShootingSolver(options).solve(EndLoad{0.0, 0.0, 2.0});
  ASSERT_TRUE(r.converged()) << r.message;
  ASSERT_EQ(r.shape.size(), 21u);
  for (const ShapePoint& p : r.shape) {
    // Circle of curvature 2 through the origin.
    EXPECT_NEAR(p.theta, 2.0 * p.s, kClosedFormTolerance);
    EXPECT_NEAR(p.x, std::sin(2.0 * p.s) / 2.0, kClosedFormTolerance);
  }
  EXPECT_NEAR(r.shape.back().x, r.tip.x, kClosedFormTolerance);
}

}  // namespace
}  // namespace flexure
