// What is checked against what: the elliptic solver with an end moment against the shooting
// solver's own path following (ShootingSolver, default strategy: direct Newton only where the
// equilibrium is provably unique, pseudo-arclength continuation from the unloaded beam otherwise),
// on a seeded grid of 1000 loads in the region where the elliptic solver's speed goal is set:
// n uniform in [-5, 10], alpha2 uniform in [-20, 20], mu uniform in [-2 pi, 2 pi] (issue 14). Many
// of these loads have several equilibria (large compression, large moments); both methods must
// return the one reached by proportional loading from the unloaded beam. A faster elliptic path
// that landed on another root would show up here as a tip several tenths of a radian away.
//
// Tolerance: 1e-9 on a/l, b/l and theta0 (the shooting solution at rtol 1e-12 agrees with the exact
// one to 1e-10 on this grid; a different equilibrium differs by more than 1e-3). Both must converge
// and agree on whether the path passes a limit point (12 of the loads pass folds). The shooting
// solver uses its Dormand-Prince 5(4) integrator (about 10x faster than CVODES at the same
// tolerance: 7 s for the 1000 loads), as elliptic_shooting_random_test.cpp does; against CVODES the
// same grid agrees as well (docs/theory-elliptic.md). Four shards of 250 loads run in parallel
// under ctest.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

#include "flexure/solver/elliptic/elliptic_solver.h"
#include "flexure/solver/shooting/elastica_integrator.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {
namespace {

constexpr double kTipTolerance = 1e-9;
constexpr int kShards = 4;
constexpr int kLoadsPerShard = 250;  // 1000 loads in all
constexpr unsigned kSeed = 20261214u;

std::string describe(double n, double alpha2, double mu) {
  std::ostringstream out;
  out.precision(17);
  out << "n = " << n << ", alpha2 = " << alpha2 << ", mu = " << mu;
  return out.str();
}

class EllipticBranchGrid : public ::testing::TestWithParam<int> {};

TEST_P(EllipticBranchGrid, ReturnsTheProportionalLoadingBranchOnEveryLoad) {
  // One generator for the whole grid; each shard skips to its own quarter, so the 1000 loads are
  // the same however the shards are run.
  std::mt19937_64 rng(kSeed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double two_pi = 2.0 * std::numbers::pi;
  ShootingSolver::Options options;  // default strategy (kAuto), rtol 1e-12
  options.backend = ElasticaIntegrator::Backend::kDormandPrince;
  const ShootingSolver shooting(options);
  const EllipticSolver elliptic;
  const int first = GetParam() * kLoadsPerShard;
  for (int i = 0; i < first + kLoadsPerShard; ++i) {
    const double n = -5.0 + 15.0 * unit(rng);
    const double alpha2 = -20.0 + 40.0 * unit(rng);
    const double mu = -two_pi + 2.0 * two_pi * unit(rng);
    if (i < first) continue;
    const EndLoad load = EndLoad::howell(n, alpha2, mu);
    const EllipticResult e = elliptic.solve(load);
    ASSERT_TRUE(e.converged()) << describe(n, alpha2, mu) << ": elliptic: " << e.message;
    const ShootingResult s = shooting.solve(load);
    ASSERT_TRUE(s.converged()) << describe(n, alpha2, mu) << ": shooting: " << s.message;
    EXPECT_NEAR(e.tip.a_over_l, s.tip.x, kTipTolerance) << describe(n, alpha2, mu);
    EXPECT_NEAR(e.tip.b_over_l, s.tip.y, kTipTolerance) << describe(n, alpha2, mu);
    EXPECT_NEAR(e.tip.theta0, s.tip.theta, kTipTolerance) << describe(n, alpha2, mu);
    EXPECT_EQ(e.limit_points > 0, s.limit_points > 0) << describe(n, alpha2, mu);
  }
}

INSTANTIATE_TEST_SUITE_P(Shards,
                         EllipticBranchGrid,
                         ::testing::Range(0, kShards),
                         [](const ::testing::TestParamInfo<int>& info) {
                           return "shard" + std::to_string(info.param);
                         });

}  // namespace
}  // namespace flexure
