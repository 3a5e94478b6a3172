// What is checked against what: pseudo-arclength continuation of the shooting solver.
//  * snap-through of a clamped-clamped V arch under a central dead load: the path must pass limit
//    points (lambda turns back) and reach the full load on the inverted side; along the whole path
//    the clamp reactions must obey the structure's mirror symmetry (vertical reaction lambda P / 2
//    at each clamp), which the solver does not know about;
//  * large end moments (mu up to 4 pi) through the path output against the circle closed form;
//  * a pinned straight beam: the path runs in two stages and ends at the pin, as solve() does;
//  * a prescribed tip outside the chain's reach: not converged, with the geometric load factor at
//    which the target leaves the reachable disk; a target just inside the reach: stops within its
//    budget and reports the load factor reached (never a hang).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "flexure/solver/chain/chain_algorithm_solver.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/chain_model/tip_reach.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {
namespace {

// Symmetry and closed forms hold to the Newton tolerance (residual 1e-10) times O(1) factors.
constexpr double kPathTolerance = 1e-8;

SegmentChain v_arch(double beta, double P) {
  // Root kinked up by beta, two unit flexible halves curving down by beta each, so the unloaded
  // arch is symmetric about its apex (node 2) and the far end is clamped where it stands.
  SegmentChain c;
  c.segments = {RigidSegment{0.0, beta},
                FlexibleSegment{1.0, 1.0, {}, -beta},
                FlexibleSegment{1.0, 1.0, {}, -beta}};
  c.node_loads = {NodeLoad{2, 0.0, -P, 0.0}};
  c.end = EndCondition::kFixed;
  return c;
}

TEST(ShootingContinuation, ArchSnapsThroughWithSymmetricReactions) {
  const double P = 40.0;
  const LoadPath path = ShootingSolver().load_path(v_arch(0.5, P));
  ASSERT_TRUE(path.converged()) << path.message;
  EXPECT_GE(path.limit_points, 1) << "the path must turn back at a limit point";
  double lambda_max_before_limit = 0.0;
  bool after_limit = false;
  for (const PathPoint& p : path.points) {
    // Mirror symmetry: each clamp carries half the central load.
    EXPECT_NEAR(p.reaction.Fy, 0.5 * p.lambda * P, kPathTolerance) << "lambda = " << p.lambda;
    if (p.status == PathStatus::kLimitPoint) after_limit = true;
    if (!after_limit) lambda_max_before_limit = std::max(lambda_max_before_limit, p.lambda);
  }
  // The limit load is below the applied load, so a load-stepping method would have to jump.
  EXPECT_LT(lambda_max_before_limit, 0.5);

  // The final state is snapped: the apex (s = 1) lies below the chord.
  ShootingSolver::Options options;
  options.shape_points = 3;
  const ShootingResult r = ShootingSolver(options).solve(v_arch(0.5, P));
  ASSERT_TRUE(r.converged()) << r.message;
  ASSERT_EQ(r.shape.size(), 3u);
  EXPECT_LT(r.shape[1].y, 0.0);
  EXPECT_NEAR(r.shape[1].x, 0.5 * r.shape[2].x, kPathTolerance);  // apex on the symmetry line
}

TEST(ShootingContinuation, LargeEndMomentPathFollowsTheCircle) {
  const double mu = 4.0 * std::numbers::pi;
  const LoadPath path = ShootingSolver().load_path(uniform_cantilever(EndLoad{0.0, 0.0, mu}));
  ASSERT_TRUE(path.converged()) << path.message;
  ASSERT_GE(path.points.size(), 2u);
  for (const PathPoint& p : path.points) {
    const double m = p.lambda * mu;
    if (std::abs(m) < 1e-6) continue;
    EXPECT_NEAR(p.tip.x, std::sin(m) / m, kPathTolerance) << "lambda = " << p.lambda;
    EXPECT_NEAR(p.tip.y, (1.0 - std::cos(m)) / m, kPathTolerance) << "lambda = " << p.lambda;
  }
  EXPECT_DOUBLE_EQ(path.points.back().lambda, 1.0);
}

TEST(ShootingContinuation, PinnedStraightBeamPathRunsInTwoStages) {
  // A straight inextensible beam cannot shorten at first order, so the path starts with the loads
  // (x released) and then moves x to its target; the path must end at the prescribed pin and agree
  // with solve().
  SegmentChain chain;
  chain.segments.push_back(FlexibleSegment{1.0, 1.0, {}, 0.0});
  chain.end = EndCondition::kPinned;
  chain.prescribed.x = 0.976;
  chain.prescribed.y = 0.2;
  const LoadPath path = ShootingSolver().load_path(chain);
  ASSERT_TRUE(path.converged()) << path.message;
  ASSERT_FALSE(path.points.empty());
  EXPECT_EQ(path.points.front().stage, 1);
  EXPECT_EQ(path.points.back().stage, 2);
  EXPECT_NEAR(path.points.back().tip.x, 0.976, kPathTolerance);
  EXPECT_NEAR(path.points.back().tip.y, 0.2, kPathTolerance);
  for (const PathPoint& p : path.points) {
    if (p.stage == 1) EXPECT_NEAR(p.tip.y, 0.2 * p.lambda, kPathTolerance);  // y follows lambda
  }
  const ShootingResult r = ShootingSolver().solve(chain);
  ASSERT_TRUE(r.converged()) << r.message;
  EXPECT_NEAR(r.reaction.Fx, path.points.back().reaction.Fx, kPathTolerance);
  EXPECT_NEAR(r.reaction.Fy, path.points.back().reaction.Fy, kPathTolerance);
}

TEST(ShootingContinuation, UnreachableTargetIsBadInputWithTheGeometricLoadFactor) {
  SegmentChain chain;
  chain.segments.push_back(FlexibleSegment{1.0, 1.0, {}, 0.0});
  chain.end = EndCondition::kSlider;
  chain.prescribed.y = 1.25;  // farther than the length: reachable up to y = 1, lambda = 0.8
  EXPECT_NEAR(reachable_load_factor(chain), 0.8, 1e-12);
  try {
    (void)ShootingSolver().solve(chain);
    ADD_FAILURE() << "an unreachable target must be refused before solving";
  } catch (const InvalidInput& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("cannot reach"), std::string::npos) << message;
    EXPECT_NE(message.find("0.8"), std::string::npos) << message;
  }
}

TEST(ShootingContinuation, TargetOnTheReachCircleOffTheAxisIsBadInput) {
  // (0.6, 0.8) is exactly one length from the clamp but 53 deg off its tangent: only the straight
  // beam reaches that distance, along +x, so the point is unreachable (it ran 730 iterations).
  SegmentChain chain = uniform_cantilever(EndLoad{});
  chain.end = EndCondition::kPinned;
  chain.prescribed.x = 0.6;
  chain.prescribed.y = 0.8;
  EXPECT_THROW((void)ShootingSolver().solve(chain), InvalidInput);
  EXPECT_THROW((void)ChainAlgorithmSolver().solve(chain), InvalidInput);
  // The straight beam's own tip, on the same circle, is reachable (no load at all).
  chain.prescribed.x = 1.0;
  chain.prescribed.y = 0.0;
  EXPECT_DOUBLE_EQ(reachable_load_factor(chain), 1.0);
  // Just inside the circle is reachable.
  chain.prescribed.x = 0.6 * (1.0 - 1e-6);
  chain.prescribed.y = 0.8 * (1.0 - 1e-6);
  EXPECT_DOUBLE_EQ(reachable_load_factor(chain), 1.0);
}

TEST(ShootingContinuation, AsymptoticTargetStopsAndReportsProgress) {
  // y = 0.995 is inside the reach but needs a reaction that grows without bound as y -> 1; with a
  // small step budget the path must stop, say why, and report how far it got.
  SegmentChain chain;
  chain.segments.push_back(FlexibleSegment{1.0, 1.0, {}, 0.0});
  chain.end = EndCondition::kSlider;
  chain.prescribed.y = 0.995;
  ShootingSolver::Options options;
  options.continuation.max_steps = 40;
  const ShootingResult r = ShootingSolver(options).solve(chain);
  if (r.converged()) {
    // Allowed: then the tip must be where it was asked to be.
    EXPECT_NEAR(r.tip.y, 0.995, kPathTolerance);
  } else {
    EXPECT_GT(r.load_factor, 0.5) << r.message;
    EXPECT_LT(r.load_factor, 1.0);
    EXPECT_NE(r.message.find("load factor"), std::string::npos) << r.message;
  }
}

}  // namespace
}  // namespace flexure
