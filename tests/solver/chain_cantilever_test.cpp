// What is checked against what: Howell's chain algorithm (both variants) on the uniform cantilever
// with an end load, against
//   * linear beam theory at a small load (b = F/3, theta0 = F/2) and the exact circular arc of an
//     end moment (Howell eqs. 2.53, 2.59, 2.64);
//   * the exact elliptic-integral solution (Howell eqs. 2.90-2.98, n = 0: theta0 = 1 rad at
//     alpha2 = 3.0870030, theta0 = 1.40 rad at alpha2 = 8.8064153; computed values, 8 digits);
//   * EllipticSolver at alpha2 = 10, n = 0 (the 1e-4 requirement at N = 100);
//   * the observed convergence order in N (Howell: 2, corrected: 3, docs/theory-chain.md) and in
//     the number of load increments without iteration at full load (1), measured as N or the
//     increment count doubles;
//   * where a path that cannot continue stops: one element under pure compression stops at its
//     discrete buckling load (root of eq. 7.30's denominator).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "flexure/solver/chain/chain_algorithm_solver.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/elliptic/elliptic_solver.h"

namespace flexure {
namespace {

using Options = ChainAlgorithmSolver::Options;

struct Oracle {
  double alpha2, theta0, a, b;
};
// Exact n = 0 solution, Howell eqs. 2.90-2.98 (computed with mpmath, 8 digits).
constexpr Oracle kTheta1 = {3.0870030, 1.00, 0.73835640, 0.61037180};
constexpr Oracle kTheta14 = {8.8064153, 1.40, 0.47307789, 0.79655336};

// The accuracy requirement for N = 100.
constexpr double kTipTolerance = 1e-4;

Options options(ChainVariant variant, int N, int increments = 10) {
  Options o;
  o.variant = variant;
  o.elements = N;
  o.increments = increments;
  return o;
}

double tip_error(const ChainResult& r, const Oracle& ref) {
  return std::max({std::abs(r.tip_pose.a_over_l - ref.a),
                   std::abs(r.tip_pose.b_over_l - ref.b),
                   std::abs(r.tip_pose.theta0 - ref.theta0)});
}

class BothVariants : public ::testing::TestWithParam<ChainVariant> {};

TEST_P(BothVariants, SmallLoadFollowsLinearBeamTheory) {
  // F = 1e-3: nonlinear terms are O(F^2) relative (about 1e-7), and cubic elements are exact for
  // linear end-loaded beams, so 1e-6 relative is a safe bound.
  const double F = 1e-3;
  const ChainResult r = ChainAlgorithmSolver(options(GetParam(), 20)).solve(EndLoad{0.0, F, 0.0});
  ASSERT_TRUE(r.converged()) << r.message;
  EXPECT_NEAR(r.tip.y / (F / 3.0), 1.0, 1e-6);      // delta = F l^3 / 3EI (eq. 2.13 form)
  EXPECT_NEAR(r.tip.theta / (F / 2.0), 1.0, 1e-6);  // theta = F l^2 / 2EI
  EXPECT_NEAR(r.root_moment, F * r.tip.x, 1e-15);   // statics in the deflected position
  EXPECT_NEAR(r.root_reaction.Fy, -F, 1e-15);
}

TEST_P(BothVariants, EndMomentGivesTheCircularArc) {
  // Constant moment: every element turns by mu L/EI, so theta0 = mu exactly; positions carry the
  // O(1/N^2) chain error (Howell eqs. 2.53, 2.59, 2.64).
  const double mu = 1.0;
  const ChainResult r = ChainAlgorithmSolver(options(GetParam(), 100)).solve(EndLoad{0, 0, mu});
  ASSERT_TRUE(r.converged()) << r.message;
  EXPECT_NEAR(r.tip.theta, mu, 1e-12);
  EXPECT_NEAR(r.tip.x, std::sin(mu) / mu, kTipTolerance);
  EXPECT_NEAR(r.tip.y, (1.0 - std::cos(mu)) / mu, kTipTolerance);
}

TEST_P(BothVariants, MatchesTheExactOracleTableAtN100) {
  for (const Oracle& ref : {kTheta1, kTheta14}) {
    const ChainResult r =
        ChainAlgorithmSolver(options(GetParam(), 100)).solve(EndLoad::howell(0.0, ref.alpha2));
    ASSERT_TRUE(r.converged()) << r.message;
    EXPECT_LT(tip_error(r, ref), kTipTolerance) << "alpha2 = " << ref.alpha2;
  }
}

TEST_P(BothVariants, MatchesEllipticSolverAtAlpha2Of10) {
  const EndLoad load = EndLoad::howell(0.0, 10.0);
  const EllipticResult exact = EllipticSolver().solve(load);
  ASSERT_TRUE(exact.converged()) << exact.message;
  const ChainResult r = ChainAlgorithmSolver(options(GetParam(), 100)).solve(load);
  ASSERT_TRUE(r.converged()) << r.message;
  EXPECT_NEAR(r.tip_pose.a_over_l, exact.tip.a_over_l, kTipTolerance);
  EXPECT_NEAR(r.tip_pose.b_over_l, exact.tip.b_over_l, kTipTolerance);
  EXPECT_NEAR(r.tip_pose.theta0, exact.tip.theta0, kTipTolerance);
  EXPECT_NEAR(r.root_moment, exact.root_moment, 10.0 * kTipTolerance);  // = alpha2 * a/l
}

TEST_P(BothVariants, MatchesTheOracleForHorizontalLoadComponents) {
  // Howell eqs. 2.90-2.98 (computed), theta0 = 0.6 rad: n = 1 and 2.5 compress the beam (the axial
  // force enters the element flexibility, eq. 7.30), n = -1 pulls it.
  struct NOracle {
    double n, alpha, a, b;
  };
  for (const NOracle& ref : {NOracle{1.0, 0.9439966, 0.9071300, 0.3809919},
                             NOracle{-1.0, 1.7993680, 0.8975785, 0.4067666},
                             NOracle{2.5, 0.7647424, 0.9086205, 0.3767408}}) {
    const ChainResult r = ChainAlgorithmSolver(options(GetParam(), 100))
                              .solve(EndLoad::howell(ref.n, ref.alpha * ref.alpha));
    ASSERT_TRUE(r.converged()) << r.message;
    // The oracle's 7-8 digits limit the check to about 1e-6 on top of the chain's own error.
    EXPECT_LT(tip_error(r, Oracle{ref.alpha * ref.alpha, 0.6, ref.a, ref.b}), kTipTolerance)
        << "n = " << ref.n;
  }
}

INSTANTIATE_TEST_SUITE_P(Chain,
                         BothVariants,
                         ::testing::Values(ChainVariant::kHowell, ChainVariant::kCorrected),
                         [](const auto& info) { return std::string(to_string(info.param)); });

// Observed order log2(e_N / e_2N) for N = 25, 50, 100 at theta0 = 1 rad (the exact values are good
// to 5e-9, below the smallest error used here).
std::vector<double> observed_orders_in_N(ChainVariant variant, const Oracle& ref) {
  std::vector<double> errors;
  for (int N : {25, 50, 100}) {
    const ChainResult r =
        ChainAlgorithmSolver(options(variant, N, 1)).solve(EndLoad::howell(0.0, ref.alpha2));
    EXPECT_TRUE(r.converged()) << r.message;
    errors.push_back(tip_error(r, ref));
  }
  return {std::log2(errors[0] / errors[1]), std::log2(errors[1] / errors[2])};
}

TEST(ChainConvergence, HowellIsSecondOrderInElements) {
  // Per element the transverse deflection is placed perpendicular to the clamp tangent without
  // shortening the chord: an O(L^3) length error per element, O(1/N^2) at the tip.
  for (double order : observed_orders_in_N(ChainVariant::kHowell, kTheta1)) {
    EXPECT_GT(order, 1.8);
    EXPECT_LT(order, 2.2);
  }
}

TEST(ChainConvergence, CorrectedIsThirdOrderInElements) {
  // With the chord shortened by the element's own bending the O(L^3) length error is gone; what
  // remains is O(L^4) per element (docs/theory-chain.md).
  for (double order : observed_orders_in_N(ChainVariant::kCorrected, kTheta1)) {
    EXPECT_GT(order, 2.7);
    EXPECT_LT(order, 3.3);
  }
}

TEST(ChainConvergence, OrdersHoldAtAlpha2Of10AgainstEllipticSolver) {
  // The load case; the exact tip comes from the elliptic solver (14 digits).
  const EndLoad load = EndLoad::howell(0.0, 10.0);
  const EllipticResult exact = EllipticSolver().solve(load);
  ASSERT_TRUE(exact.converged()) << exact.message;
  const Oracle ref{10.0, exact.tip.theta0, exact.tip.a_over_l, exact.tip.b_over_l};
  for (ChainVariant variant : {ChainVariant::kHowell, ChainVariant::kCorrected}) {
    const double expected = variant == ChainVariant::kHowell ? 2.0 : 3.0;
    double previous = 0.0;
    for (int N : {25, 50, 100}) {
      const ChainResult r = ChainAlgorithmSolver(options(variant, N, 1)).solve(load);
      ASSERT_TRUE(r.converged()) << r.message;
      const double e = tip_error(r, ref);
      if (previous > 0.0) {
        EXPECT_NEAR(std::log2(previous / e), expected, 0.1 * expected) << to_string(variant);
      }
      previous = e;
    }
  }
}

TEST(ChainConvergence, HowellIncrementsWithoutIterationAreFirstOrder) {
  // Moment arms lag one increment behind the load (eqs. 7.24-7.27): an O(1/n_inc) error. Measured
  // against the converged fixed point of the same discretisation, so that only the increment
  // error is seen.
  const EndLoad load = EndLoad::howell(0.0, kTheta14.alpha2);
  const ChainResult limit = ChainAlgorithmSolver(options(ChainVariant::kHowell, 50, 1)).solve(load);
  ASSERT_TRUE(limit.converged()) << limit.message;
  std::vector<double> errors;
  for (int M : {40, 80, 160}) {
    Options o = options(ChainVariant::kHowell, 50, M);
    o.iterate_at_full_load = false;
    const ChainResult r = ChainAlgorithmSolver(o).solve(load);
    ASSERT_TRUE(r.converged()) << r.message;
    EXPECT_EQ(r.iterations, M);
    errors.push_back(std::abs(r.tip.theta - limit.tip.theta) + std::abs(r.tip.x - limit.tip.x) +
                     std::abs(r.tip.y - limit.tip.y));
  }
  for (int k = 0; k + 1 < static_cast<int>(errors.size()); ++k) {
    const double order = std::log2(errors[k] / errors[k + 1]);
    EXPECT_GT(order, 0.9);
    EXPECT_LT(order, 1.1);
  }
}

TEST(ChainContinuation, FailedStepsAreRetriedSmallerAndThePathIsRecorded) {
  // alpha2 = 200 in one step needs more passes than allowed here, so the adaptive stepping must
  // cut the step; the answer must not depend on the path taken.
  const EndLoad load = EndLoad::howell(0.0, 200.0);
  Options tight = options(ChainVariant::kCorrected, 40, 1);
  tight.max_iterations = 40;
  // Steps limited by the pass count, not by the turn of a node (whose default limit, 0.25 rad,
  // would make the steps small from the start and the tight pass limit fail at the last one).
  tight.max_angle_step = 1.5;
  const ChainResult r = ChainAlgorithmSolver(tight).solve(load);
  ASSERT_TRUE(r.converged()) << r.message;
  EXPECT_GT(r.failed_increments, 0);
  ASSERT_EQ(static_cast<int>(r.load_path.size()), r.increments);
  for (std::size_t k = 1; k < r.load_path.size(); ++k) {
    EXPECT_GT(r.load_path[k].load_factor, r.load_path[k - 1].load_factor);
  }
  EXPECT_DOUBLE_EQ(r.load_path.back().load_factor, 1.0);
  Options loose = options(ChainVariant::kCorrected, 40, 20);
  const ChainResult reference = ChainAlgorithmSolver(loose).solve(load);
  ASSERT_TRUE(reference.converged()) << reference.message;
  // Both are the same discrete fixed point, converged to 1e-12.
  EXPECT_NEAR(r.tip.theta, reference.tip.theta, 1e-9);
  EXPECT_NEAR(r.tip.x, reference.tip.x, 1e-9);
}

TEST(ChainContinuation, OneIncrementToStartWithAddsIncrementsWhereThePathNeedsThem) {
  // The defaults start with one increment (the whole load) and a coarse chain's path. alpha2 =
  // 10 turns the tip by 1.43 rad, beyond max_angle_step (0.25 rad) for one step, so increments are
  // added by halving; alpha2 = 60 (tip turned 1.7 rad, post-buckled-like bending) needs more. The
  // answer must be the same discrete equilibrium as the former default (10 increments on the
  // requested chain, no coarse path) to the pass tolerance, and the exact tip to the N = 100
  // discretisation error.
  for (const EndLoad& load : {EndLoad::howell(0.0, 10.0), EndLoad::howell(-2.0, 60.0, 1.0)}) {
    const ChainResult r = ChainAlgorithmSolver().solve(load);
    ASSERT_TRUE(r.converged()) << r.message;
    EXPECT_GT(r.increments, 1) << r.message;
    EXPECT_GT(r.failed_increments, 0) << r.message;
    ASSERT_EQ(static_cast<int>(r.load_path.size()), r.increments);
    EXPECT_DOUBLE_EQ(r.load_path.back().load_factor, 1.0);
    Options former;
    former.increments = 10;
    former.coarse_path = false;
    const ChainResult f = ChainAlgorithmSolver(former).solve(load);
    ASSERT_TRUE(f.converged()) << f.message;
    EXPECT_NEAR(r.tip.x, f.tip.x, 1e-10);
    EXPECT_NEAR(r.tip.y, f.tip.y, 1e-10);
    EXPECT_NEAR(r.tip.theta, f.tip.theta, 1e-10);
    const EllipticResult e = EllipticSolver().solve(load);
    ASSERT_TRUE(e.converged()) << e.message;
    EXPECT_NEAR(r.tip_pose.theta0, e.tip.theta0, kTipTolerance);
    EXPECT_NEAR(r.tip_pose.a_over_l, e.tip.a_over_l, kTipTolerance);
    EXPECT_NEAR(r.tip_pose.b_over_l, e.tip.b_over_l, kTipTolerance);
  }
  // A small load needs no more than the one increment.
  const ChainResult small = ChainAlgorithmSolver().solve(EndLoad::howell(0.0, 0.3));
  ASSERT_TRUE(small.converged()) << small.message;
  EXPECT_EQ(small.increments, 1) << small.message;
  EXPECT_EQ(small.failed_increments, 0) << small.message;
}

TEST(ChainContinuation, ReportsWhereAPathCannotContinue) {
  // One element under pure compression Fx = -5 ceases to have a flexibility at the root of eq.
  // 7.30's denominator, L^2 P/EI = -2.4857, i.e. at load factor 2.4857 / 5.
  const double p_root = (-104.0 + std::sqrt(104.0 * 104.0 - 2880.0)) / 6.0;
  Options o = options(ChainVariant::kCorrected, 1, 4);
  const ChainResult r = ChainAlgorithmSolver(o).solve(EndLoad{-5.0, 0.0, 0.0});
  EXPECT_FALSE(r.converged());
  EXPECT_NEAR(r.load_factor, -p_root / 5.0, 1e-3);
  EXPECT_LE(r.load_factor, -p_root / 5.0);
  EXPECT_NE(r.message.find("stopped at load factor"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("buckled"), std::string::npos) << r.message;
}

TEST(ChainOptions, RejectsInvalidInput) {
  const EndLoad load{0.0, 1.0, 0.0};
  Options o;
  o.elements = 0;
  EXPECT_THROW(ChainAlgorithmSolver(o).solve(load), InvalidInput);
  o = Options{};
  o.increments = 0;
  EXPECT_THROW(ChainAlgorithmSolver(o).solve(load), InvalidInput);
  o = Options{};
  o.tolerance = -1.0;
  EXPECT_THROW(ChainAlgorithmSolver(o).solve(load), InvalidInput);
  EXPECT_THROW(ChainAlgorithmSolver().solve(EndLoad{NAN, 1.0, 0.0}), InvalidInput);
  EXPECT_THROW(chain_variant_from_string("plain"), InvalidInput);
  EXPECT_EQ(chain_variant_from_string("howell"), ChainVariant::kHowell);
}

}  // namespace
}  // namespace flexure
