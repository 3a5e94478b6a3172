// What is checked against what: unique_equilibrium_bound() claims a unique equilibrium when it is
// below 1. A short flexure at the root of a long rigid link under a compressive dead tip force past
// its buckling load has (at least) two equilibria -- the straight chain and a buckled one, found
// here by Newton from the spring-and-rigid-link estimate theta/sin(theta) = N L/(EI/f) -- so the
// bound must be >= 1 there (the earlier L_flex L_total/(2 EI_min) form gave 0.75 and claimed
// uniqueness). Below the buckling load of the straight chain the bound may be below 1, and then the
// shooting solver's direct Newton and its continuation must land on the same equilibrium.
#include <gtest/gtest.h>

#include <cmath>

#include "flexure/solver/common/gsl_guard.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {
namespace {

SegmentChain flexure_and_link(double tip_force_x) {
  SegmentChain chain;
  FlexibleSegment f;
  f.length = 0.1;  // f: the flexure; EI = 1
  f.EI = 1.0;
  chain.segments.emplace_back(f);
  chain.segments.emplace_back(RigidSegment{0.9, 0.0});  // total length L = 1
  chain.tip_load.Fx = tip_force_x;
  return chain;
}

TEST(ShootingUniqueness, TwoEquilibriaPastBucklingMeanTheBoundIsAtLeastOne) {
  disable_gsl_abort();
  // Spring-link estimate: k = EI/f = 10, N L/k = 1.5 -> theta/sin(theta) = 1.5 at theta ~ 1.50.
  const double N = 15.0;
  const SegmentChain chain = flexure_and_link(-N);
  ShootingSolver::Options o;
  o.strategy = ShootingStrategy::kDirect;
  const double theta_guess = 1.50;
  const ShootingResult buckled =
      ShootingSolver(o).solve_from(chain, {N * 1.0 * std::sin(theta_guess)});
  ASSERT_TRUE(buckled.converged()) << buckled.message;
  EXPECT_GT(std::abs(buckled.tip.y), 0.3) << "a buckled equilibrium, far from the straight one";
  // The straight chain (m0 = 0) is the other equilibrium; two equilibria -> no contraction.
  EXPECT_GE(unique_equilibrium_bound(chain), 1.0);
}

TEST(ShootingUniqueness, BelowTheBoundDirectNewtonAndContinuationAgree) {
  disable_gsl_abort();
  SegmentChain chain = flexure_and_link(-2.0);
  chain.tip_load.Fy = 1.0;  // a transverse component too, so the equilibrium is not straight
  ASSERT_LT(unique_equilibrium_bound(chain), 1.0);
  ShootingSolver::Options direct, continuation;
  direct.strategy = ShootingStrategy::kDirect;
  continuation.strategy = ShootingStrategy::kContinuation;
  const ShootingResult a = ShootingSolver(direct).solve(chain);
  const ShootingResult b = ShootingSolver(continuation).solve(chain);
  ASSERT_TRUE(a.converged() && b.converged()) << a.message << " / " << b.message;
  constexpr double kSameEquilibrium = 1e-9;  // both at rtol 1e-12 Newton tolerances
  EXPECT_NEAR(a.tip.x, b.tip.x, kSameEquilibrium);
  EXPECT_NEAR(a.tip.y, b.tip.y, kSameEquilibrium);
  EXPECT_NEAR(a.tip.theta, b.tip.theta, kSameEquilibrium);
}

}  // namespace
}  // namespace flexure
