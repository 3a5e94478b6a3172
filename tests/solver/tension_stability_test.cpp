// The fast verdict of a cantilever nowhere compressed (tension_stability.h) against the general
// verdict (equilibrium_stability(): the discrete second variation on the shooting shape) and
// against an independent look at the shape (F . t sampled at 2001 points):
//   * seeded random dead tip loads, forces in every direction with and without an end moment,
//     Howell's (n, alpha2, mu) loads, compressive loads past the cantilever's Euler loads
//     (2k - 1)^2 pi^2 / 4 and loads whose proportional path passes limit points: wherever the fast
//     verdict answers it equals the general one exactly (stable, index 0, margin 1, the same
//     message) and the sampled shape is nowhere compressed; wherever it declines the sampled shape
//     is compressed somewhere (it declines nothing it could answer);
//   * every load of the issue-27 sweep (n = 0, mu = 0) and every n < 0 without a moment qualifies;
//   * closed forms: a straight column under tension P has margin 1 (no eigenvalue below 1); under
//     compression P the fast verdict declines and the general one gives index = the number of
//     (2k - 1)^2 pi^2 / 4 below P and margin 1 - P / (pi^2 / 4);
//   * chains and ends the first integral does not cover are declined.
#include "flexure/solver/shooting/tension_stability.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

ShootingSolver::Options solve_options() { return test::fast_verdict_solve_options(); }

// The least F . t over 2001 equally spaced points of the shape (ends included), independent of
// the first integral.
double least_tension(const SegmentChain& chain, const ShootingResult& r) {
  std::vector<double> s;
  for (int i = 0; i <= 2000; ++i) s.push_back(chain.total_length() * i / 2000.0);
  double least = HUGE_VAL;
  for (const ShapePoint& p : shooting_shape_at(chain, r, s)) {
    least = std::min(least,
                     chain.tip_load.Fx * std::cos(p.theta) + chain.tip_load.Fy * std::sin(p.theta));
  }
  return least;
}

struct Tally {
  int solved = 0, answered = 0, declined = 0, unstable = 0, with_limit_points = 0;
};

// One equilibrium: the fast verdict against the general one and the sampled tension.
void check_result(const EndLoad& load, const ShootingResult& r, Tally& tally, bool must_answer) {
  const SegmentChain chain = uniform_cantilever(load);
  if (!r.converged()) return;
  ++tally.solved;
  if (r.limit_points > 0) ++tally.with_limit_points;
  ASSERT_TRUE(std::isfinite(r.largest_curvature)) << describe(load);
  const std::optional<Stability> fast = tensioned_cantilever_stability(chain, r);
  const Stability general = general_verdict(chain, r);
  if (general.kind == StabilityKind::kUnstable) ++tally.unstable;
  const double force = std::hypot(load.Fx, load.Fy);
  const double least = least_tension(chain, r);
  if (fast) {
    ++tally.answered;
    EXPECT_EQ(fast->kind, general.kind) << describe(load);
    EXPECT_EQ(fast->index, general.index) << describe(load);
    EXPECT_EQ(fast->margin, general.margin) << describe(load);
    EXPECT_EQ(fast->margin, 1.0) << describe(load);
    EXPECT_EQ(fast->message, general.message) << describe(load);
    EXPECT_GE(least, -1e-12 * force) << describe(load);
  } else {
    ++tally.declined;
    EXPECT_FALSE(must_answer) << "declined " << describe(load) << " (least F.t " << least << ")";
    // Only a beam compressed somewhere is left to the general verdict. (Its margin is below 1
    // unless the compressed stretch is far shorter than its elements: a slightly negative Fx
    // under a large Fy compresses only the first per mille of the beam, whose chord averages
    // find no compression; the continuous margin is then 1 to within its error.)
    EXPECT_LT(least, 0.0) << describe(load);
  }
}

// The proportional-loading answer of a load.
void check_load(const EndLoad& load, Tally& tally, bool must_answer = false) {
  check_result(load, solve_shooting(uniform_cantilever(load), solve_options()), tally, must_answer);
}

TEST(TensionStability, RandomLoadsAgreeWithTheGeneralVerdict) {
  std::mt19937_64 rng(27027);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Tally tally;
  // Forces in every direction, Howell's loads with compressive n up to 10 and end moments (whose
  // proportional paths fold), straight and nearly straight columns past the Euler loads, folding
  // paths, and other equilibria found by Newton from spread root moments (unstable ones among
  // them).
  const ShootingSolver newton(solve_options());
  for_each_cantilever_load(
      rng,
      CantileverLoadFamilies{},
      [&](const EndLoad& load) { check_load(load, tally); },
      [&](const EndLoad& load, double m0) {
        check_result(load, newton.solve_from(uniform_cantilever(load), {m0}), tally, false);
      });
  // The sweep's loads (n = 0) and tension with a transverse force (n < 0), mu = 0: all answered.
  for (int i = 0; i < 40; ++i) {
    const double n = i < 20 ? 0.0 : -20.0 * unit(rng), alpha2 = 0.5 + 40.0 * unit(rng);
    check_load(EndLoad{-n * alpha2, alpha2, 0.0}, tally, true);
  }
  std::cout << "solved " << tally.solved << ": fast verdict " << tally.answered << ", declined "
            << tally.declined << " (of them unstable " << tally.unstable << "); "
            << tally.with_limit_points << " paths with limit points\n";
  // The sample covers what it claims.
  EXPECT_GE(tally.solved, 300);
  EXPECT_GE(tally.answered, 80);
  EXPECT_GE(tally.declined, 80);
  EXPECT_GE(tally.unstable, 30);
  EXPECT_GE(tally.with_limit_points, 8);
}

// The verdict from the tip angle of a shape without inflection (the elliptic solution's,
// tensioned_cantilever_stability(chain, tip_angle, inflection_points)) against the general verdict
// on the elliptic shape and F . t sampled at 2001 points of it: Howell's loads with n from -5 to 2
// and end moments, seeded. Wherever it answers it equals the general verdict exactly and the
// shape is nowhere compressed; wherever the shape has no inflection and is nowhere compressed it
// answers.
TEST(TensionStability, EllipticTipAngleVerdictAgreesWithTheGeneralVerdict) {
  std::mt19937_64 rng(28028);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const EllipticSolver solver;
  int solved = 0, answered = 0, declined_compressed = 0, declined_inflection = 0;
  for (int i = 0; i < 400; ++i) {
    const double n = -5.0 + 7.0 * unit(rng), alpha2 = 0.1 + 15.0 * unit(rng);
    const double mu = unit(rng) < 0.4 ? 0.0 : -2.0 + 4.0 * unit(rng);
    const EndLoad load = EndLoad::howell(n, alpha2, mu);
    EllipticResult r;
    try {
      r = solver.solve(load);
    } catch (const std::exception&) {
      continue;  // beyond the elliptic solver's domain
    }
    if (!r.converged()) continue;
    ++solved;
    const SegmentChain chain = uniform_cantilever(r.load);
    const std::optional<Stability> fast =
        tensioned_cantilever_stability(chain, r.tip.theta0, r.inflection_points);
    std::vector<double> s;
    for (int k = 0; k <= 2000; ++k) s.push_back(k / 2000.0);
    double least = HUGE_VAL;
    for (const ShapePoint& p : solver.shape_at(r, s)) {
      least = std::min(least, r.load.Fx * std::cos(p.theta) + r.load.Fy * std::sin(p.theta));
    }
    const double force = std::hypot(r.load.Fx, r.load.Fy);
    const std::string what = "n " + std::to_string(n) + ", alpha2 " + std::to_string(alpha2) +
                             ", mu " + std::to_string(mu);
    if (fast) {
      ++answered;
      const Stability general = equilibrium_stability(
          chain, Reaction{}, [&](const std::vector<double>& at) { return solver.shape_at(r, at); });
      EXPECT_EQ(fast->kind, general.kind) << what;
      EXPECT_EQ(fast->index, general.index) << what;
      EXPECT_EQ(fast->margin, general.margin) << what;
      EXPECT_EQ(fast->message, general.message) << what;
      EXPECT_GE(least, -1e-12 * force) << what;
    } else if (r.inflection_points != 0) {
      ++declined_inflection;
    } else {
      ++declined_compressed;
      EXPECT_LT(least, 1e-12 * force) << "declined a shape nowhere compressed: " << what;
    }
  }
  std::cout << "elliptic: solved " << solved << ", answered " << answered
            << ", declined (compressed) " << declined_compressed << ", declined (inflection) "
            << declined_inflection << "\n";
  EXPECT_GE(solved, 300);
  EXPECT_GE(answered, 60);
  EXPECT_GE(declined_compressed, 60);
}

TEST(TensionStability, StraightColumnsMatchTheirClosedForms) {
  const double euler = kPi * kPi / 4.0;
  for (const double P : {0.5, 2.0, 3.0, 10.0, 30.0, 65.0}) {
    // Tension: no eigenvalue below 1.
    {
      const SegmentChain chain = uniform_cantilever(EndLoad{P, 0.0, 0.0});
      const ShootingResult r = solve_shooting(chain, solve_options());
      ASSERT_TRUE(r.converged()) << P;
      const std::optional<Stability> fast = tensioned_cantilever_stability(chain, r);
      ASSERT_TRUE(fast.has_value()) << P;
      EXPECT_EQ(fast->kind, StabilityKind::kStable);
      EXPECT_EQ(fast->index, 0);
      EXPECT_EQ(fast->margin, 1.0);
    }
    // Compression: left to the general verdict, which meets the closed form.
    const SegmentChain chain = uniform_cantilever(EndLoad{-P, 0.0, 0.0});
    const ShootingResult r = solve_shooting(chain, solve_options());
    ASSERT_TRUE(r.converged()) << P;
    ASSERT_NEAR(r.tip.y, 0.0, 1e-12) << "the straight column, P = " << P;
    EXPECT_FALSE(tensioned_cantilever_stability(chain, r).has_value()) << P;
    const Stability v = general_verdict(chain, r);
    int below = 0;
    for (int k = 1; (2 * k - 1) * (2 * k - 1) * euler < P; ++k) ++below;
    EXPECT_EQ(v.index, below) << P;
    EXPECT_NEAR(v.margin, 1.0 - P / euler, 1e-8) << P;
  }
}

TEST(TensionStability, OtherChainsAndEndsAreDeclined) {
  const ShootingSolver::Options o = solve_options();
  SegmentChain chain = uniform_cantilever(EndLoad{0.0, 2.0, 0.0});
  EXPECT_TRUE(tension_verdict_applies(chain));
  // A follower force.
  SegmentChain follower = chain;
  follower.tip_load.follower = 0.5;
  EXPECT_FALSE(tension_verdict_applies(follower));
  // A guided end.
  SegmentChain guided = chain;
  guided.end = EndCondition::kGuided;
  EXPECT_FALSE(tension_verdict_applies(guided));
  const ShootingResult rg = solve_shooting(guided, o);
  ASSERT_TRUE(rg.converged());
  EXPECT_FALSE(tensioned_cantilever_stability(guided, rg).has_value());
  // Two segments, an EI profile, a curved beam, a distributed load.
  SegmentChain two = chain;
  two.segments = {FlexibleSegment(0.5, 1.0), FlexibleSegment(0.5, 1.0)};
  EXPECT_FALSE(tension_verdict_applies(two));
  SegmentChain tapered = chain;
  tapered.segments = {FlexibleSegment(1.0, 1.0, {1.0, 2.0})};
  EXPECT_FALSE(tension_verdict_applies(tapered));
  SegmentChain curved = chain;
  curved.segments = {FlexibleSegment(1.0, 1.0, {}, 0.3)};
  EXPECT_FALSE(tension_verdict_applies(curved));
  SegmentChain loaded = chain;
  std::get<FlexibleSegment>(loaded.segments.front()).qy = 1.0;
  EXPECT_FALSE(tension_verdict_applies(loaded));
  // Without the recorded moment (no inflection count) the fast verdict does not answer.
  ShootingSolver::Options plain = o;
  plain.count_inflections = false;
  const ShootingResult r = solve_shooting(chain, plain);
  ASSERT_TRUE(r.converged());
  EXPECT_FALSE(tensioned_cantilever_stability(chain, r).has_value());
}

}  // namespace
}  // namespace flexure
