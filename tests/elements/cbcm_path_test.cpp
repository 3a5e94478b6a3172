// The chained BCM's displacement-controlled path (elements/cbcm_path.h) against the shooting
// method's (trace_controlled_path), on seeded random chains: a segment of length L and rigidity
// EI clamped at an inclination phi (a zero-length kink), its far end guided (the angle held) or
// fixed (x and the angle held; EA L^2/EI in [1e3, 1e4]), a tip force along the root's x for the
// guided ones (applied first), and its tip y moved by up to 0.25 L (guided) or 0.08 L (fixed). At
// the end of the travel the support's reaction, the clamp's reactions and the tip of the CBCM with
// 32 elements agree with the shooting method's (its controlled path for the guided end; its solve
// with y prescribed at the target for the fixed end, as its controlled path does not always finish
// there) to 5e-4 (relative to the largest load, and per L; measured 7.6e-5 and 1.7e-7, printed).
// And the path is a path: every point's moved coordinate is start + lambda (target - start) to 1e-9
// L.
#include "flexure/elements/cbcm_path.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {
namespace {

TEST(CbcmPath, AgreesWithTheShootingPathOnSeededRandomChains) {
  std::mt19937 rng(3032);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst_load = 0.0, worst_tip = 0.0;
  for (int k = 0; k < 8; ++k) {
    const bool fixed = k % 2 == 1;
    const double L = 0.5 + u(rng), EI = 0.5 + 2.0 * u(rng);
    const double phi = -0.2 + 0.4 * u(rng);
    SegmentChain chain;
    chain.segments.push_back(RigidSegment{0.0, phi});
    FlexibleSegment flexible(L, EI);
    if (fixed) flexible.EA = std::pow(10.0, 3.0 + u(rng)) * EI / (L * L);
    chain.segments.push_back(flexible);
    chain.end = fixed ? EndCondition::kFixed : EndCondition::kGuided;
    if (!fixed) chain.tip_load.Fx = (-1.0 + 2.0 * u(rng)) * EI / (L * L);
    const double y0 = L * std::sin(phi);
    const double travel = (fixed ? 0.08 : 0.25) * L * (u(rng) < 0.5 ? -1.0 : 1.0) * (0.5 + u(rng));
    DisplacementControl control;
    control.coordinate = TipCoordinate::kY;
    control.target = y0 + travel;

    CbcmPathOptions options;
    options.elements = 32;
    const CbcmPathResult cbcm = trace_cbcm_controlled_path(chain, control, options);
    ASSERT_TRUE(cbcm.converged()) << k << ": " << cbcm.message;
    // The reference: the shooting method's controlled path (guided), or its solve with the fixed
    // end's y prescribed at the target (the same equilibrium: no bifurcation on the way).
    ShootingSolver::Options shooting_options;
    PathPoint b;
    if (fixed) {
      SegmentChain moved = chain;
      moved.prescribed.y = control.target;
      const ShootingResult r = solve_shooting(moved, shooting_options);
      ASSERT_TRUE(r.converged()) << k << ": " << r.message;
      b.tip = r.tip;
      b.reaction = r.reaction;
      b.tip_load = r.tip_load;
    } else {
      const LoadPath shooting = trace_controlled_path(chain, control, shooting_options);
      ASSERT_TRUE(shooting.converged()) << k << ": " << shooting.message;
      b = shooting.points.back();
    }
    const CbcmPathPoint& a = cbcm.points.back();
    const double scale = std::max({EI / (L * L),
                                   std::fabs(b.tip_load.Fx),
                                   std::fabs(b.tip_load.Fy),
                                   std::fabs(b.tip_load.M) / L});
    const double load = std::max({std::fabs(a.tip_load.Fx - b.tip_load.Fx),
                                  std::fabs(a.tip_load.Fy - b.tip_load.Fy),
                                  std::fabs(a.tip_load.M - b.tip_load.M) / L,
                                  std::fabs(a.reaction.Fx - b.reaction.Fx),
                                  std::fabs(a.reaction.Fy - b.reaction.Fy),
                                  std::fabs(a.reaction.M - b.reaction.M) / L}) /
                        scale;
    const double tip = std::max({std::fabs(a.tip.x - b.tip.x) / L,
                                 std::fabs(a.tip.y - b.tip.y) / L,
                                 std::fabs(a.tip.theta - b.tip.theta)});
    EXPECT_LT(load, 5e-4) << k << (fixed ? " fixed" : " guided");
    EXPECT_LT(tip, 5e-4) << k;
    worst_load = std::max(worst_load, load);
    worst_tip = std::max(worst_tip, tip);
    // The moving stage (after the tip load, where there is one): y = start + lambda (target -
    // start).
    const int moving = cbcm.points.back().stage;
    double start = NAN;
    for (const CbcmPathPoint& p : cbcm.points) {
      if (p.stage != moving) continue;
      if (std::isnan(start)) start = p.tip.y;
      EXPECT_NEAR(p.tip.y, start + p.lambda * (control.target - start), 1e-9 * L) << k;
    }
  }
  std::cout << fmt::format(
      "worst relative load difference {:.3g}, tip {:.3g}\n", worst_load, worst_tip);
}

TEST(CbcmPath, RefusesWhatItDoesNotModel) {
  SegmentChain chain;
  chain.segments.push_back(FlexibleSegment(1.0, 1.0));
  chain.segments.push_back(FlexibleSegment(1.0, 1.0));
  chain.end = EndCondition::kGuided;
  DisplacementControl control;
  control.target = 0.1;
  EXPECT_THROW(trace_cbcm_controlled_path(chain, control, {}), InvalidInput);
  SegmentChain one;
  one.segments.push_back(FlexibleSegment(1.0, 1.0));
  control.target = NAN;
  EXPECT_THROW(trace_cbcm_controlled_path(one, control, {}), InvalidInput);
  CbcmPathOptions bad;
  bad.elements = 0;
  control.target = 0.1;
  EXPECT_THROW(trace_cbcm_controlled_path(one, control, bad), InvalidInput);
}

}  // namespace
}  // namespace flexure
