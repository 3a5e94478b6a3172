// The Jacobi-equation verdict of a uniform cantilever (compressed_cantilever_stability.h) against
// two independent references:
//   * the general verdict (equilibrium_stability(): the discrete second variation on the shooting
//     shape, Romberg-extrapolated; docs/stability.md "Method 1"), on seeded random dead tip loads:
//     forces in every direction with and without an end moment, Howell's (n, alpha2, mu) loads with
//     compressive n, nearly straight and straight columns past the Euler loads, loads whose
//     proportional path passes limit points and other (unstable) equilibria of the same loads
//     found by Newton from spread root moments. Kind and index equal on every one it answers;
//     margin within kMarginTolerance, and within 1e-10 of the general verdict refined to
//     margin_accuracy 1e-12 wherever the default one differs by more than its stated 1e-9; it
//     declines only beams whose general margin is above 0.999;
//   * the closed forms of the straight column: index = the number of Euler loads
//     (2k - 1)^2 pi^2 / 4 below P, margin 1 - P / (pi^2 / 4); the index changes at each P_k; the
//     column at P_1 is critical;
//   * chains and ends it does not cover are declined.
#include "flexure/solver/shooting/compressed_cantilever_stability.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <optional>
#include <random>
#include <sstream>
#include <string>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/elliptic/elliptic_solver.h"
#include "flexure/solver/shooting/shooting_solver.h"
#include "tests/support/cantilever_load_families.h"

namespace flexure {
namespace {

using test::CantileverLoadFamilies;
using test::describe;
using test::for_each_cantilever_load;
using test::general_verdict;

constexpr double kPi = std::numbers::pi;
// The general verdict's margin is accurate to about 1e-9 (docs/stability.md, "Accuracy"), the
// Jacobi margin to about 1e-12: they must agree within a few times the former.
constexpr double kMarginTolerance = 1e-8;
// A guessed start changes only the Newton iterates: the margin is the same root of the same
// eigen-condition, to about the integration's 1e-12.
constexpr double kGuessedMarginTolerance = 1e-10;
// The verdict leaves margins above 1 - 1e-4 (and beams it finds nowhere compressed) to the
// general verdict.
constexpr double kDeclinedAbove = 0.999;

ShootingSolver::Options solve_options() { return test::fast_verdict_solve_options(); }

struct Tally {
  int solved = 0, answered = 0, declined = 0, refined = 0, unstable = 0, index2 = 0,
      with_limit_points = 0;
  double worst = 0.0;
  double worst_guessed = 0.0;
};

void check_result(const EndLoad& load, const ShootingResult& r, Tally& tally) {
  const SegmentChain chain = uniform_cantilever(load);
  if (!r.converged()) return;
  ++tally.solved;
  if (r.limit_points > 0) ++tally.with_limit_points;
  const std::optional<Stability> fast = compressed_cantilever_stability(chain, r);
  const Stability general = general_verdict(chain, r);
  if (general.kind == StabilityKind::kUnstable) ++tally.unstable;
  if (general.index >= 2) ++tally.index2;
  if (!fast) {
    // Declined only where the beam is nearly nowhere compressed: margins close to 1.
    ++tally.declined;
    EXPECT_GT(general.margin, kDeclinedAbove) << describe(load);
    return;
  }
  ++tally.answered;
  // Started from a guessed margin (a sweep's prediction from its neighbours), near the answer or
  // far from it, the verdict is the same: kind and index equal, the margin the same root.
  for (const double guess : {fast->margin,
                             fast->margin + 1e-4 * (1.0 - fast->margin),
                             0.5 * (1.0 + fast->margin),
                             fast->margin - 0.3,
                             -4.0,
                             0.0,
                             0.999}) {
    const std::optional<Stability> guessed =
        compressed_cantilever_stability(chain, r, StabilityOptions{}, guess);
    ASSERT_TRUE(guessed.has_value()) << describe(load) << " guess " << guess;
    EXPECT_EQ(guessed->kind, fast->kind) << describe(load) << " guess " << guess;
    EXPECT_EQ(guessed->index, fast->index) << describe(load) << " guess " << guess;
    EXPECT_NEAR(guessed->margin, fast->margin, kGuessedMarginTolerance)
        << describe(load) << " guess " << guess;
    tally.worst_guessed = std::max(tally.worst_guessed, std::fabs(guessed->margin - fast->margin));
  }
  EXPECT_EQ(fast->kind, general.kind) << describe(load);
  EXPECT_EQ(fast->index, general.index) << describe(load);
  EXPECT_NEAR(fast->margin, general.margin, kMarginTolerance) << describe(load);
  if (std::fabs(fast->margin - general.margin) > 1e-9) {
    // Beyond the general verdict's stated accuracy (weakly compressed beams, margins close to 1):
    // refined to margin_accuracy 1e-12 it must meet the Jacobi margin closely.
    StabilityOptions fine;
    fine.margin_accuracy = 1e-12;
    const Stability refined = equilibrium_stability(
        chain,
        Reaction{},
        [&](const std::vector<double>& s) { return shooting_shape_at(chain, r, s); },
        fine);
    EXPECT_NEAR(fast->margin, refined.margin, 1e-10) << describe(load);
    ++tally.refined;
  }
  tally.worst = std::max(tally.worst, std::fabs(fast->margin - general.margin));
}

void check_load(const EndLoad& load, Tally& tally) {
  check_result(load, solve_shooting(uniform_cantilever(load), solve_options()), tally);
}

TEST(CompressedCantileverStability, RandomLoadsAgreeWithTheGeneralVerdict) {
  std::mt19937_64 rng(2727);
  Tally tally;
  // Compressive Howell loads (the sweep of docs/performance.md has n = 2), straight and nearly
  // straight columns past the Euler loads, folding paths, and other equilibria found by Newton
  // from spread root moments (unstable ones among them).
  CantileverLoadFamilies families;
  families.any_direction = 60;
  families.howell = 60;
  families.howell_n_min = 0.0;
  families.howell_without_moment = 0.5;
  families.near_straight = 20;
  families.straight = 10;
  families.folding = 6;
  families.with_other_equilibria = 12;
  const ShootingSolver newton(solve_options());
  for_each_cantilever_load(
      rng,
      families,
      [&](const EndLoad& load) { check_load(load, tally); },
      [&](const EndLoad& load, double m0) {
        check_result(load, newton.solve_from(uniform_cantilever(load), {m0}), tally);
      });
  std::cout << "solved " << tally.solved << ": answered " << tally.answered << " (declined "
            << tally.declined << ", compared with the refined general verdict " << tally.refined
            << "), unstable " << tally.unstable << " (index >= 2: " << tally.index2 << "), "
            << tally.with_limit_points << " paths with limit points; largest margin difference "
            << tally.worst << "; from guessed margins at most " << tally.worst_guessed
            << " from the unguessed\n";
  EXPECT_GE(tally.solved, 200);
  EXPECT_GE(tally.answered, 180);
  EXPECT_GE(tally.unstable, 30);
  EXPECT_GE(tally.index2, 3);
  EXPECT_GE(tally.with_limit_points, 6);
}

TEST(CompressedCantileverStability, StraightColumnsMatchTheirClosedForms) {
  const double euler = kPi * kPi / 4.0;
  for (const double P : {0.5, 2.0, 2.4, 3.0, 10.0, 22.0, 30.0, 65.0}) {
    const SegmentChain chain = uniform_cantilever(EndLoad{-P, 0.0, 0.0});
    const ShootingResult r = solve_shooting(chain, solve_options());
    ASSERT_TRUE(r.converged()) << P;
    ASSERT_NEAR(r.tip.y, 0.0, 1e-12) << "the straight column, P = " << P;
    const std::optional<Stability> v = compressed_cantilever_stability(chain, r);
    ASSERT_TRUE(v.has_value()) << P;
    int below = 0;
    for (int k = 1; (2 * k - 1) * (2 * k - 1) * euler < P; ++k) ++below;
    EXPECT_EQ(v->index, below) << P;
    EXPECT_NEAR(v->margin, 1.0 - P / euler, 1e-10 * std::max(1.0, P / euler)) << P;
    // The same from a guess 1e-3 off (a sweep's start).
    const std::optional<Stability> g =
        compressed_cantilever_stability(chain, r, StabilityOptions{}, v->margin + 1e-3);
    ASSERT_TRUE(g.has_value()) << P;
    EXPECT_EQ(g->index, below) << P;
    EXPECT_NEAR(g->margin, 1.0 - P / euler, 1e-10 * std::max(1.0, P / euler)) << P;
  }
  // The index changes at the k-th Euler load: k - 1 at P_k (1 - 1e-4), k at P_k (1 + 1e-4).
  for (int k = 1; k <= 3; ++k) {
    const double Pk = (2 * k - 1) * (2 * k - 1) * euler;
    for (const double side : {-1.0, 1.0}) {
      const double P = Pk * (1.0 + side * 1e-4);
      const SegmentChain chain = uniform_cantilever(EndLoad{-P, 0.0, 0.0});
      const ShootingResult r = solve_shooting(chain, solve_options());
      ASSERT_TRUE(r.converged());
      const std::optional<Stability> v = compressed_cantilever_stability(chain, r);
      ASSERT_TRUE(v.has_value());
      EXPECT_EQ(v->index, side < 0.0 ? k - 1 : k) << "P_" << k << " " << side;
      const std::optional<Stability> g =
          compressed_cantilever_stability(chain, r, StabilityOptions{}, v->margin - 1e-3);
      ASSERT_TRUE(g.has_value());
      EXPECT_EQ(g->index, side < 0.0 ? k - 1 : k) << "P_" << k << " " << side << " guessed";
    }
  }
  // Critical within the tolerance at the first Euler load itself.
  const SegmentChain chain = uniform_cantilever(EndLoad{-euler, 0.0, 0.0});
  const ShootingResult r = solve_shooting(chain, solve_options());
  ASSERT_TRUE(r.converged());
  const std::optional<Stability> v = compressed_cantilever_stability(chain, r);
  ASSERT_TRUE(v.has_value());
  EXPECT_EQ(v->kind, StabilityKind::kCritical);
  EXPECT_NEAR(v->margin, 0.0, 1e-10);
  for (const double guess : {-1e-3, 1e-3}) {
    const std::optional<Stability> g =
        compressed_cantilever_stability(chain, r, StabilityOptions{}, guess);
    ASSERT_TRUE(g.has_value());
    EXPECT_EQ(g->kind, StabilityKind::kCritical) << guess;
    EXPECT_EQ(g->index, 0) << guess;
    EXPECT_NEAR(g->margin, 0.0, 1e-10) << guess;
  }
}

TEST(CompressedCantileverStability, OtherChainsAndEndsAreDeclined) {
  const ShootingSolver::Options o = solve_options();
  const SegmentChain chain = uniform_cantilever(EndLoad{-2.0, 1.0, 0.0});
  SegmentChain guided = chain;
  guided.end = EndCondition::kGuided;
  const ShootingResult rg = solve_shooting(guided, o);
  ASSERT_TRUE(rg.converged());
  EXPECT_FALSE(compressed_cantilever_stability(guided, rg).has_value());
  SegmentChain two = chain;
  two.segments = {FlexibleSegment(0.5, 1.0), FlexibleSegment(0.5, 1.0)};
  const ShootingResult r2 = solve_shooting(two, o);
  ASSERT_TRUE(r2.converged());
  EXPECT_FALSE(compressed_cantilever_stability(two, r2).has_value());
  // A result that is not this chain's (another load's root moment): the re-integrated tip does
  // not meet it, so the verdict declines rather than judge a different shape.
  const ShootingResult other = solve_shooting(uniform_cantilever(EndLoad{-2.0, 1.5, 0.0}), o);
  ASSERT_TRUE(other.converged());
  EXPECT_FALSE(compressed_cantilever_stability(chain, other).has_value());
}

}  // namespace
}  // namespace flexure
