// What is checked against what: the shooting solver's end conditions, loads and segment types.
//  * pinned, slider and fixed ends: the support reactions found by shooting, applied as dead end
//    loads to a free cantilever, must reproduce the prescribed tip in the elliptic solver;
//  * a follower tip force: the same, with the dead force equal to the follower's final direction;
//  * a node load and a rigid segment: small-load limit against linear beam formulas (Howell
//    App. D; superposition), with the O(F^3) nonlinear remainder far below the tolerance;
//  * a tapered EI profile under an end moment: theta = M ln(1 + s) and its closed-form x, y.
#include <gtest/gtest.h>

#include <cmath>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/elliptic/elliptic_solver.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {
namespace {

// Two independent exact methods (shooting at rtol 1e-12, elliptic at 1e-14): agreement to 1e-9 as
// for the grid.
constexpr double kCrossMethodTolerance = 1e-9;
// Closed forms evaluated in double precision.
constexpr double kClosedFormTolerance = 1e-10;

SegmentChain unit_beam(EndCondition end) {
  SegmentChain chain;
  chain.segments.push_back(FlexibleSegment{1.0, 1.0, {}, 0.0});
  chain.end = end;
  return chain;
}

// The elliptic solver returns the proportional-loading branch of the dead-load problem, which is
// the equilibrium found by shooting when loads are moderate (no compression beyond buckling); the
// cases below are chosen there. Agreement to 1e-9 cannot happen by accident.
void expect_tip_from_end_load(const ShootingResult& r, const EndLoad& load) {
  const EllipticResult e = EllipticSolver().solve(load);
  ASSERT_TRUE(e.converged()) << "elliptic: " << e.message;
  EXPECT_NEAR(e.tip.a_over_l, r.tip.x, kCrossMethodTolerance);
  EXPECT_NEAR(e.tip.b_over_l, r.tip.y, kCrossMethodTolerance);
  EXPECT_NEAR(e.tip.theta0, r.tip.theta, kCrossMethodTolerance);
}

TEST(ShootingEndConditions, PinnedEndReactionsReproduceTheTip) {
  SegmentChain chain = unit_beam(EndCondition::kPinned);
  // Near the natural shortening of a tip-loaded cantilever (x ~ 0.976 at y = 0.2), so the
  // reactions stay in the unique range; a straight chain with both coordinates prescribed is
  // solved in two stages (shooting_solver.h).
  chain.prescribed.x = 0.976;
  chain.prescribed.y = 0.2;
  chain.tip_load.M = 0.1;
  const ShootingResult r = ShootingSolver().solve(chain);
  ASSERT_TRUE(r.converged()) << r.message;
  EXPECT_NEAR(r.tip.x, 0.976, kClosedFormTolerance);
  EXPECT_NEAR(r.tip.y, 0.2, kClosedFormTolerance);
  EXPECT_NEAR(r.tip_load.M, 0.1, kClosedFormTolerance);
  expect_tip_from_end_load(r, EndLoad{r.tip_load.Fx, r.tip_load.Fy, 0.1});
}

TEST(ShootingEndConditions, SliderEndReactionReproducesTheTip) {
  SegmentChain chain = unit_beam(EndCondition::kSlider);
  chain.prescribed.y = 0.4;
  chain.tip_load.Fx = -1.0;
  chain.tip_load.M = 0.5;
  const ShootingResult r = ShootingSolver().solve(chain);
  ASSERT_TRUE(r.converged()) << r.message;
  EXPECT_NEAR(r.tip.y, 0.4, kClosedFormTolerance);
  EXPECT_NEAR(r.tip_load.Fx, -1.0, kClosedFormTolerance);
  expect_tip_from_end_load(r, EndLoad{-1.0, r.tip_load.Fy, 0.5});
}

TEST(ShootingEndConditions, FixedEndReactionsReproduceTheTip) {
  SegmentChain chain = unit_beam(EndCondition::kFixed);
  chain.prescribed.x = 0.976;
  chain.prescribed.y = 0.2;
  chain.prescribed.theta = 0.35;
  const ShootingResult r = ShootingSolver().solve(chain);
  ASSERT_TRUE(r.converged()) << r.message;
  EXPECT_NEAR(r.tip.theta, 0.35, kClosedFormTolerance);
  expect_tip_from_end_load(r, EndLoad{r.tip_load.Fx, r.tip_load.Fy, r.tip_load.M});
}

TEST(ShootingLoads, FollowerForceEqualsDeadForceInItsFinalDirection) {
  for (double P : {0.5, 1.2, 2.0}) {
    SegmentChain chain = unit_beam(EndCondition::kFree);
    chain.tip_load.follower = P;
    const ShootingResult r = ShootingSolver().solve(chain);
    ASSERT_TRUE(r.converged()) << "P = " << P << ": " << r.message;
    // The follower acts along the deflected tip normal (-sin theta, cos theta).
    EXPECT_NEAR(r.tip_load.Fx, -P * std::sin(r.tip.theta), kClosedFormTolerance);
    EXPECT_NEAR(r.tip_load.Fy, P * std::cos(r.tip.theta), kClosedFormTolerance);
    expect_tip_from_end_load(r, EndLoad{r.tip_load.Fx, r.tip_load.Fy, 0.0});
  }
}

TEST(ShootingLoads, NodeLoadAndRigidLinkMatchLinearTheoryForSmallLoads) {
  // The nonlinear remainder is O(F^3) ~ 1e-12 for F = 1e-4.
  const double F = 1e-4;
  constexpr double kLinearTolerance = 1e-12;

  // (a) Point load F at mid-length of a uniform cantilever (two segments of 1/2):
  //     tip deflection F a^2 (3L - a) / (6 EI) with a = 1/2, L = 1 (Howell App. D).
  SegmentChain two;
  two.segments = {FlexibleSegment{0.5, 1.0, {}, 0.0}, FlexibleSegment{0.5, 1.0, {}, 0.0}};
  two.node_loads = {NodeLoad{1, 0.0, F, 0.0}};
  const ShootingResult a = ShootingSolver().solve(two);
  ASSERT_TRUE(a.converged()) << a.message;
  EXPECT_NEAR(a.tip.y, F * 0.25 * 2.5 / 6.0, kLinearTolerance);
  EXPECT_NEAR(a.tip.theta, F * 0.25 / 2.0, kLinearTolerance);  // F a^2 / (2 EI)

  // (b) Flexible half (EI = 2) then a rigid half, end force F: moment F (1 - s) on the flexible
  //     part, so theta(1/2) = F (1/2 - 1/8) / 2, y(1/2) = F (1/8 - 1/48) / 2, and the link adds
  //     (1/2) theta(1/2).
  SegmentChain link;
  link.segments = {FlexibleSegment{0.5, 2.0, {}, 0.0}, RigidSegment{0.5, 0.0}};
  link.tip_load.Fy = F;
  const ShootingResult b = ShootingSolver().solve(link);
  ASSERT_TRUE(b.converged()) << b.message;
  const double theta_half = F * (0.5 - 0.125) / 2.0;
  EXPECT_NEAR(b.tip.theta, theta_half, kLinearTolerance);
  EXPECT_NEAR(b.tip.y, F * (0.125 - 1.0 / 48.0) / 2.0 + 0.5 * theta_half, kLinearTolerance);
  EXPECT_NEAR(b.reaction.M, -F, kLinearTolerance);  // lever arm = full length to first order
}

TEST(ShootingLoads, TaperedBeamUnderEndMoment) {
  // EI(s) = 1 + s tabulated at 5 stations (exactly linear), moment M: theta' = M / (1 + s).
  const double M = 1.3;
  SegmentChain chain;
  chain.segments.push_back(FlexibleSegment{1.0, 1.0, {1.0, 1.25, 1.5, 1.75, 2.0}, 0.0});
  chain.tip_load.M = M;
  const ShootingResult r = ShootingSolver().solve(chain);
  ASSERT_TRUE(r.converged()) << r.message;
  const double u = std::log(2.0);  // s = e^u - 1
  EXPECT_NEAR(r.tip.theta, M * u, kClosedFormTolerance);
  // x = int_0^ln2 e^u cos(M u) du, y = int_0^ln2 e^u sin(M u) du.
  const double x = (2.0 * (std::cos(M * u) + M * std::sin(M * u)) - 1.0) / (1.0 + M * M);
  const double y = (2.0 * (std::sin(M * u) - M * std::cos(M * u)) + M) / (1.0 + M * M);
  EXPECT_NEAR(r.tip.x, x, kClosedFormTolerance);
  EXPECT_NEAR(r.tip.y, y, kClosedFormTolerance);
}

TEST(ShootingLoads, InvalidChainThrowsInvalidInput) {
  SegmentChain chain = unit_beam(EndCondition::kFree);
  chain.segments[0] = FlexibleSegment{1.0, -1.0, {}, 0.0};
  EXPECT_THROW(ShootingSolver().solve(chain), InvalidInput);
  chain.segments[0] = FlexibleSegment{1.0, 1.0, {}, 0.0};
  chain.tip_load.Fy = std::nan("");
  EXPECT_THROW(ShootingSolver().solve(chain), InvalidInput);
}

}  // namespace
}  // namespace flexure
