// What is checked against what: the chain algorithm with the shooting method of Howell §7.2.1 for
// tip conditions other than a free end, and on chains that are more than one uniform segment:
//   * a fixed-guided beam against the antisymmetry relation (two cantilevers of length l/2 joined
//     at the inflection point) and the exact elliptic solution (Howell eqs. 2.90-2.98,
//     theta0 = 1 rad);
//   * a two-segment chain with a rigid link between flexible pieces (free and guided end), and a
//     follower force, a node load, stress-free curvature and an EI profile, against the
//     independent SUNDIALS shooting solver (solver/shooting/, CVODES at rtol 1e-12, which
//     integrates the elastica ODE and shares no code with the chain algorithm);
//   * guided, pinned, slider and fixed ends placed at the free equilibrium of a curved beam (from
//     the shooting solver): the reactions must equal the removed tip loads;
//   * a straight beam whose pin is moved toward the clamp (a path that starts at a bifurcation):
//     the failure must be reported with the load factor reached.
// Tolerances follow the measured discretisation error at N = 100 (docs/theory-chain.md): Howell's
// plain variant is second order (about 1e-4 at N = 100 for these loads), the corrected variant
// third order (about 1e-6).
#include <gtest/gtest.h>

#include <cmath>

#include "flexure/solver/chain/chain_algorithm_solver.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {
namespace {

using Options = ChainAlgorithmSolver::Options;

// Second-order Howell variant at N = 100: tip errors up to 3e-5 were measured on these chains;
// the bound leaves a margin of 3 or more.
constexpr double kHowellTolerance = 1e-4;
// Third-order corrected variant at N = 100: errors up to 2e-7 were measured.
constexpr double kCorrectedTolerance = 2e-6;

double tolerance(ChainVariant v) {
  return v == ChainVariant::kHowell ? kHowellTolerance : kCorrectedTolerance;
}

ChainResult chain_solve(const SegmentChain& chain, ChainVariant variant, int N = 100) {
  Options o;
  o.variant = variant;
  o.elements = N;
  return solve_chain(chain, o);
}

ShootingResult reference(const SegmentChain& chain) {
  const ShootingResult r = ShootingSolver().solve(chain);
  EXPECT_TRUE(r.converged()) << r.message;
  return r;
}

// Compares tip pose and root reactions; forces scaled by `load_scale` (the largest load).
void expect_agree(const ChainResult& c, const ShootingResult& s, double tol, double load_scale) {
  ASSERT_TRUE(c.converged()) << c.message;
  EXPECT_NEAR(c.tip.x, s.tip.x, tol);
  EXPECT_NEAR(c.tip.y, s.tip.y, tol);
  EXPECT_NEAR(c.tip.theta, s.tip.theta, tol);
  EXPECT_NEAR(c.root_reaction.Fx, s.reaction.Fx, tol * load_scale);
  EXPECT_NEAR(c.root_reaction.Fy, s.reaction.Fy, tol * load_scale);
  EXPECT_NEAR(c.root_reaction.M, s.reaction.M, tol * load_scale);
}

class ChainBoundary : public ::testing::TestWithParam<ChainVariant> {};

TEST_P(ChainBoundary, GuidedBeamIsTwoAntisymmetricHalfCantilevers) {
  // Guided end (theta = 0) with transverse force P: the moment vanishes at mid-length and each
  // half is a cantilever of length l/2 with end force P, i.e. alpha2 = P (l/2)^2 / EI. Choose
  // P = 4 * 3.0870030 so that each half has the exact theta0 = 1 rad solution (Howell §2.9.2)
  // (a/l = 0.73835640, b/l = 0.61037180). Then x_tip = a/l, y_tip = b/l, and the guided end's
  // reaction moment is -P x_tip / 2 (m(1) = -m(0)).
  const double P = 4.0 * 3.0870030;
  SegmentChain chain = uniform_cantilever(EndLoad{0.0, P, 0.0});
  chain.end = EndCondition::kGuided;
  const ChainResult r = chain_solve(chain, GetParam());
  ASSERT_TRUE(r.converged()) << r.message;
  // Each half has N/2 elements: twice the per-half error of an N-element cantilever.
  const double tol = 2.0 * tolerance(GetParam());
  EXPECT_NEAR(r.tip.x, 0.73835640, tol);
  EXPECT_NEAR(r.tip.y, 0.61037180, tol);
  EXPECT_NEAR(r.tip.theta, 0.0, 1e-9);  // the shooting residual
  EXPECT_NEAR(r.tip_reaction.M, -0.5 * P * 0.73835640, tol * P);
  EXPECT_GT(r.newton_iterations, 0);
}

// A flexible piece, a rigid link at a kink, and a softer flexible piece.
SegmentChain two_flexible_pieces_with_a_rigid_link() {
  SegmentChain chain;
  chain.segments.push_back(FlexibleSegment{0.4, 1.0, {}, 0.0});
  chain.segments.push_back(RigidSegment{0.3, 0.3});
  chain.segments.push_back(FlexibleSegment{0.3, 0.5, {}, 0.0});
  return chain;
}

TEST_P(ChainBoundary, TwoFlexiblePiecesWithARigidLinkFreeEnd) {
  SegmentChain chain = two_flexible_pieces_with_a_rigid_link();
  chain.tip_load = TipLoad{-0.5, 2.0, 0.3, 0.0};
  expect_agree(chain_solve(chain, GetParam()), reference(chain), tolerance(GetParam()), 2.0);
}

TEST_P(ChainBoundary, TwoFlexiblePiecesWithARigidLinkGuidedEnd) {
  SegmentChain chain = two_flexible_pieces_with_a_rigid_link();
  chain.end = EndCondition::kGuided;  // tip keeps its stress-free angle 0.3 rad
  chain.tip_load = TipLoad{-0.5, 2.0, 0.0, 0.0};
  const ChainResult c = chain_solve(chain, GetParam());
  expect_agree(c, reference(chain), tolerance(GetParam()), 2.0);
  EXPECT_NEAR(c.tip.theta, 0.3, 1e-9);
}

// A prescribed end placed where the free tip of the same chain comes to rest under a tip load must
// give back that equilibrium: the reactions equal the removed load components. The free tip comes
// from the shooting solver, so the target is exact to its 1e-10 tolerance.
TEST_P(ChainBoundary, PrescribedEndsReproduceTheFreeEquilibrium) {
  SegmentChain free_chain = uniform_cantilever(EndLoad{0.3, -1.0, 0.2});
  std::get<FlexibleSegment>(free_chain.segments[0]).kappa0 = 1.0;  // an arc of 1 rad
  const ShootingResult exact = reference(free_chain);
  for (EndCondition end : {EndCondition::kGuided,
                           EndCondition::kPinned,
                           EndCondition::kSlider,
                           EndCondition::kFixed}) {
    SCOPED_TRACE(to_string(end));
    SegmentChain chain = free_chain;
    chain.end = end;
    const PrescribedMask mask = prescribed_mask(end);
    if (mask.x) {
      chain.prescribed.x = exact.tip.x;
      chain.tip_load.Fx = 0.0;
    }
    if (mask.y) {
      chain.prescribed.y = exact.tip.y;
      chain.tip_load.Fy = 0.0;
    }
    if (mask.theta) {
      chain.prescribed.theta = exact.tip.theta;
      chain.tip_load.M = 0.0;
    }
    const ChainResult c = chain_solve(chain, GetParam());
    ASSERT_TRUE(c.converged()) << c.message;
    const double tol = tolerance(GetParam());
    EXPECT_NEAR(c.tip.x, exact.tip.x, tol);
    EXPECT_NEAR(c.tip.y, exact.tip.y, tol);
    EXPECT_NEAR(c.tip.theta, exact.tip.theta, tol);
    // Reactions: the chain's discretisation error is amplified by the stiffness of the
    // constrained directions (measured reaction errors at N = 100: up to 7e-4 Howell, 1.4e-6
    // corrected, i.e. about 10-20 times the tip-position error).
    const double kReactionAmplification = 30.0;
    if (mask.x) EXPECT_NEAR(c.tip_reaction.Fx, 0.3, kReactionAmplification * tol);
    if (mask.y) EXPECT_NEAR(c.tip_reaction.Fy, -1.0, kReactionAmplification * tol);
    if (mask.theta) EXPECT_NEAR(c.tip_reaction.M, 0.2, kReactionAmplification * tol);
    EXPECT_NEAR(c.root_reaction.M, exact.reaction.M, kReactionAmplification * tol);
  }
}

TEST_P(ChainBoundary, ReportsWhereAStraightPinnedBeamPathCannotStart) {
  // Moving the pin of an initially straight, inextensible beam toward the clamp shortens the chord
  // at first order in the load factor: the path starts at a bifurcation (the axial reaction jumps
  // to a buckling load at lambda = 0+). The chain's proportional continuation cannot take that
  // first step and must say so rather than return a wrong equilibrium.
  SegmentChain chain = uniform_cantilever(EndLoad{});
  chain.end = EndCondition::kPinned;
  chain.prescribed.x = 0.8;
  chain.prescribed.y = 0.4;
  Options o;
  o.variant = GetParam();
  o.elements = 20;
  o.max_newton_iterations = 10;
  o.min_load_step = 1e-3;
  const ChainResult c = solve_chain(chain, o);
  EXPECT_FALSE(c.converged());
  EXPECT_LT(c.load_factor, 0.01);
  EXPECT_NE(c.message.find("stopped at load factor"), std::string::npos) << c.message;
}

TEST_P(ChainBoundary, FollowerForceNodeLoadCurvatureAndStiffnessProfile) {
  SegmentChain chain;
  chain.segments.push_back(FlexibleSegment{0.5, 1.0, {1.0, 2.0}, 0.5});
  chain.segments.push_back(FlexibleSegment{0.5, 1.5, {}, -0.3});
  chain.node_loads.push_back(NodeLoad{1, 0.3, -0.8, 0.1});
  chain.tip_load = TipLoad{0.0, 0.5, 0.0, 1.5};
  expect_agree(chain_solve(chain, GetParam()), reference(chain), tolerance(GetParam()), 2.0);
}

INSTANTIATE_TEST_SUITE_P(Chain,
                         ChainBoundary,
                         ::testing::Values(ChainVariant::kHowell, ChainVariant::kCorrected),
                         [](const auto& info) { return std::string(to_string(info.param)); });

}  // namespace
}  // namespace flexure
