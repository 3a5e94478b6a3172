// find_stable_equilibrium (solver/shooting/stable_equilibrium.h): a stable equilibrium from an
// unstable one, checked against independent values:
//   * the buckled cantilever under an axial tip load P (Timoshenko & Gere §2.7; Howell ch. 2's
//     elastica): P L^2 / EI = K(k)^2, k = sin(theta0 / 2), tip x = L (2 E(k) / K(k) - 1),
//     y = 2 k L / K(k) (k by bisection on std::comp_ellint_1): tip to 1e-8 from the straight
//     column (unstable: index 1 at P = 3 and 10, index 2 at P = 30);
//   * the clamped-clamped beam of issue 27 (tip at (0.9, 0.001), angle 0): from the antisymmetric
//     second mode (Fx = 83.75, unstable) to the first: the perfect beam's first mode has
//     P L^2 / EI = 16 K(k)^2 with 2 E(k) / K(k) - 1 = 0.9 (a clamped-clamped beam is four
//     cantilevers of length L/4); the 0.001 offset shifts it by a few 1e-5 (tolerance 1e-4 of P);
//   * seeded random unstable equilibria (Newton from random root loads; uniform beams with a
//     guided, pinned, slider or fixed end, and a tapered curved chain with a kinked rigid link and
//     a node load): the result is stable by the continuous Jacobi count (JacobiSecondVariation,
//     which shares nothing with the search or its verdict), meets the prescribed tip and has a
//     lower energy than the start;
//   * the constrained eigenvector against the dense generalised eigenproblem on ker C.
#include "flexure/solver/shooting/stable_equilibrium.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <iostream>
#include <numbers>
#include <random>
#include <string>

#include "flexure/solver/chain_model/jacobi_stability.h"
#include "flexure/solver/chain_model/second_variation.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/shooting_solver.h"
#include "tests/support/stability_test_support.h"

namespace flexure {
namespace {

using test::mixed_chain;

constexpr double kPi = std::numbers::pi;

// The buckled cantilever's modulus k for P L^2/EI = K(k)^2 (L = EI = 1), by bisection.
double cantilever_modulus(double P) {
  double lo = 0.0, hi = 1.0 - 1e-15;
  for (int i = 0; i < 200; ++i) {
    const double k = 0.5 * (lo + hi);
    const double K = std::comp_ellint_1(k);
    (K * K < P ? lo : hi) = k;
  }
  return 0.5 * (lo + hi);
}

StableEquilibrium stable_from(const SegmentChain& chain, const ShootingResult& start) {
  return find_stable_equilibrium(
      chain,
      [&](const std::vector<double>& s) { return shooting_shape_at(chain, start, s); },
      tip_support_reaction(chain, start.tip_load));
}

TEST(StableEquilibrium, BuckledCantileverFromTheStraightColumn) {
  for (const double P : {3.0, 10.0, 30.0}) {
    const SegmentChain chain = uniform_cantilever(EndLoad{-P, 0.0, 0.0});
    const ShootingResult straight = ShootingSolver().solve(chain);
    ASSERT_TRUE(straight.converged()) << straight.message;
    ASSERT_NEAR(straight.tip.theta, 0.0, 1e-12) << "the proportional path stays straight";
    const StableEquilibrium found = stable_from(chain, straight);
    ASSERT_TRUE(found.converged()) << "P = " << P << ": " << found.message;
    EXPECT_EQ(found.stability.kind, StabilityKind::kStable) << found.stability.message;
    const double k = cantilever_modulus(P);
    const double K = std::comp_ellint_1(k), E = std::comp_ellint_2(k);
    const ChainPose& tip = found.equilibrium.tip;
    // Either mirror image; the search returns the first sense on a tie.
    EXPECT_NEAR(std::fabs(tip.theta), 2.0 * std::asin(k), 1e-8) << "P = " << P;
    EXPECT_NEAR(tip.x, 2.0 * E / K - 1.0, 1e-8) << "P = " << P;
    EXPECT_NEAR(std::fabs(tip.y), 2.0 * k / K, 1e-8) << "P = " << P;
    EXPECT_EQ(found.candidates, 2) << "both senses lead to a mirror image";
    EXPECT_LT(found.energy, found.start_energy);
    const Stability jacobi = JacobiSecondVariation(chain, found.equilibrium.reaction).verdict();
    EXPECT_EQ(jacobi.kind, StabilityKind::kStable) << jacobi.message;
    EXPECT_NEAR(jacobi.margin, found.stability.margin, 1e-8);
  }
}

TEST(StableEquilibrium, ClampedClampedFirstModeFromTheSecond) {
  SegmentChain chain = uniform_cantilever(EndLoad{});
  chain.end = EndCondition::kFixed;
  chain.prescribed = {0.9, 0.001, 0.0};
  const ShootingResult second = ShootingSolver().solve(chain);
  ASSERT_TRUE(second.converged()) << second.message;
  ASSERT_NEAR(second.tip_load.Fx, -83.75, 0.01);  // the antisymmetric mode of the issue
  const StableEquilibrium found = stable_from(chain, second);
  ASSERT_TRUE(found.converged()) << found.message;
  // The perfect beam's first mode: 2 E(k)/K(k) - 1 = 0.9 by bisection, P = 16 K(k)^2.
  double lo = 1e-9, hi = 0.999;
  for (int i = 0; i < 200; ++i) {
    const double k = 0.5 * (lo + hi);
    (2.0 * std::comp_ellint_2(k) / std::comp_ellint_1(k) - 1.0 > 0.9 ? lo : hi) = k;
  }
  const double K = std::comp_ellint_1(0.5 * (lo + hi));
  const double P = 16.0 * K * K;  // 41.5703
  EXPECT_NEAR(-found.equilibrium.tip_load.Fx, P, 1e-4 * P);
  EXPECT_NEAR(found.equilibrium.tip.x, 0.9, 1e-10);
  EXPECT_NEAR(found.equilibrium.tip.y, 0.001, 1e-10);
  EXPECT_NEAR(found.equilibrium.tip.theta, 0.0, 1e-10);
  const Stability jacobi = JacobiSecondVariation(chain, found.equilibrium.reaction).verdict();
  EXPECT_EQ(jacobi.kind, StabilityKind::kStable) << jacobi.message;
  EXPECT_NEAR(jacobi.margin, found.stability.margin, 1e-8);
}

TEST(StableEquilibrium, AStableStartStaysWhereItIs) {
  const SegmentChain chain = uniform_cantilever(EndLoad::howell(1.0, 3.0, 0.5));
  const ShootingResult start = ShootingSolver().solve(chain);
  ASSERT_TRUE(start.converged());
  const StableEquilibrium found = stable_from(chain, start);
  ASSERT_TRUE(found.converged()) << found.message;
  EXPECT_NEAR(found.equilibrium.tip.x, start.tip.x, 1e-10);
  EXPECT_NEAR(found.equilibrium.tip.y, start.tip.y, 1e-10);
  EXPECT_NEAR(found.equilibrium.tip.theta, start.tip.theta, 1e-10);
}

TEST(StableEquilibrium, NoStrictlyStableStateAtTheCriticalLoad) {
  // The straight column exactly at its Euler load pi^2/4: critical; the buckled branch starts
  // there (supercritical), so no strictly stable equilibrium exists at this load.
  const SegmentChain chain = uniform_cantilever(EndLoad{-kPi * kPi / 4.0, 0.0, 0.0});
  const ShootingResult straight = ShootingSolver().solve(chain);
  ASSERT_TRUE(straight.converged());
  const StableEquilibrium found = stable_from(chain, straight);
  EXPECT_FALSE(found.converged());
  EXPECT_FALSE(found.message.empty());
}

TEST(StableEquilibrium, RefusesAFollowerForce) {
  SegmentChain chain = uniform_cantilever(EndLoad{});
  chain.tip_load.follower = 2.0;
  const ShootingResult start = ShootingSolver().solve(chain);
  ASSERT_TRUE(start.converged());
  EXPECT_THROW(stable_from(chain, start), InvalidInput);
}

SegmentChain uniform_chain(EndCondition end, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  SegmentChain chain = uniform_cantilever(EndLoad{});
  chain.end = end;
  const PrescribedMask mask = prescribed_mask(end);
  if (mask.x) chain.prescribed.x = 0.3 + 0.65 * unit(rng);
  if (mask.y) chain.prescribed.y = (2.0 * unit(rng) - 1.0) * 0.4;
  if (mask.theta) chain.prescribed.theta = (2.0 * unit(rng) - 1.0) * 2.0;
  if (!mask.x) chain.tip_load.Fx = -25.0 + 40.0 * unit(rng);
  if (!mask.y) chain.tip_load.Fy = -10.0 + 20.0 * unit(rng);
  if (!mask.theta) chain.tip_load.M = (2.0 * unit(rng) - 1.0) * 4.0;
  return chain;
}

TEST(StableEquilibrium, SeededRandomUnstableEquilibria) {
  // Unstable equilibria reached by Newton from random root loads, every end condition: the search
  // must find a stable one, stable by the Jacobi count too, on the prescribed tip, lower in energy.
  std::mt19937_64 rng(27101u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const EndCondition ends[] = {EndCondition::kFree,
                               EndCondition::kGuided,
                               EndCondition::kPinned,
                               EndCondition::kSlider,
                               EndCondition::kFixed};
  int started = 0, found_count = 0, attempts = 0, mixed = 0, highest_index = 0;
  while (started < 30 && attempts < 400) {
    const EndCondition end = ends[attempts % 5];
    const bool use_mixed = attempts % 3 == 2;
    ++attempts;
    const SegmentChain chain = use_mixed ? mixed_chain(end, rng) : uniform_chain(end, rng);
    const PrescribedMask mask = prescribed_mask(end);
    ShootingResult start;
    try {
      std::vector<double> root{(2.0 * unit(rng) - 1.0) * 15.0};
      if (mask.x) root.push_back((2.0 * unit(rng) - 1.0) * 40.0);
      if (mask.y) root.push_back((2.0 * unit(rng) - 1.0) * 40.0);
      start = ShootingSolver().solve_from(chain, root);
    } catch (const InvalidInput&) {
      continue;  // an unreachable target
    }
    if (!start.converged()) continue;
    const Reaction support = tip_support_reaction(chain, start.tip_load);
    const Stability before = equilibrium_stability(
        chain, support, [&](const auto& s) { return shooting_shape_at(chain, start, s); });
    if (before.kind != StabilityKind::kUnstable) continue;
    ++started;
    mixed += use_mixed ? 1 : 0;
    highest_index = std::max(highest_index, before.index);
    const StableEquilibrium found = stable_from(chain, start);
    const std::string what = std::string(to_string(end)) + (use_mixed ? " mixed" : " uniform") +
                             " chain, start index " + std::to_string(before.index);
    EXPECT_TRUE(found.converged()) << what << ": " << found.message;
    if (!found.converged()) continue;
    ++found_count;
    EXPECT_EQ(found.stability.kind, StabilityKind::kStable) << what;
    const JacobiSecondVariation jacobi(chain, found.equilibrium.reaction);
    if (jacobi.growth_exponent(-kCriticalMarginTolerance) < 12.0) {
      EXPECT_EQ(jacobi.verdict().index, 0) << what << ": " << jacobi.verdict().message;
    }
    EXPECT_LT(found.energy, found.start_energy) << what;
    const ChainPose target = chain.prescribed_tip();
    const ChainPose& tip = found.equilibrium.tip;
    if (mask.x) EXPECT_NEAR(tip.x, target.x, 1e-9) << what;
    if (mask.y) EXPECT_NEAR(tip.y, target.y, 1e-9) << what;
    if (mask.theta) EXPECT_NEAR(tip.theta, target.theta, 1e-9) << what;
  }
  EXPECT_GE(started, 30);
  EXPECT_GE(mixed, 5);
  EXPECT_GE(highest_index, 2);
  std::cout << started << " unstable starts (" << mixed << " on the mixed chain, highest index "
            << highest_index << "), " << found_count << " stable equilibria found\n";
}

TEST(ConstrainedEigenvector, MatchesTheDenseEigenproblemOnTheConstraints) {
  std::mt19937_64 rng(27102u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 5; ++trial) {
    const int n = 40;
    DiscreteSecondVariation q;
    q.bending_diag.assign(n, 0.0);
    q.bending_off.assign(n - 1, 0.0);
    q.axial.assign(n, 0.0);
    for (int e = 0; e < n; ++e) {  // elements between nodes e-1 (the clamp for e = 0) and e
      const double k = 0.5 + unit(rng);
      q.bending_diag[e] += k;
      if (e > 0) {
        q.bending_diag[e - 1] += k;
        q.bending_off[e - 1] -= k;
      }
    }
    double gamma = 0.0, flexibility = 0.0;
    for (int i = 0; i < n; ++i) {
      q.axial[i] = (unit(rng) - 0.8) * 40.0 / n;
      flexibility += 2.0;  // 1/k <= 2
      gamma += std::max(0.0, -q.axial[i]) * flexibility;
    }
    q.compression_bound = gamma;
    const int m = trial % 3;
    for (int a = 0; a < m; ++a) {
      std::vector<double> row(n);
      for (double& c : row) c = unit(rng) - 0.5;
      q.constraints.push_back(row);
    }
    const PencilEigenvalue lowest = constrained_eigenvalue(q, 1, 1e-13);
    ASSERT_TRUE(lowest.exists);
    const std::vector<double> eta = constrained_eigenvector(q, lowest.value);
    // Dense reference: Z^T (B + W) Z v = lambda Z^T B Z v on a basis Z of ker C.
    Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, n), W = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i) {
      B(i, i) = q.bending_diag[i];
      W(i, i) = q.axial[i];
      if (i + 1 < n) B(i, i + 1) = B(i + 1, i) = q.bending_off[i];
    }
    Eigen::MatrixXd Z = Eigen::MatrixXd::Identity(n, n);
    if (m > 0) {
      Eigen::MatrixXd C(m, n);
      for (int a = 0; a < m; ++a) {
        for (int i = 0; i < n; ++i) C(a, i) = q.constraints[a][i];
      }
      Z = Eigen::FullPivLU<Eigen::MatrixXd>(C).kernel();
    }
    const Eigen::MatrixXd Bz = Z.transpose() * B * Z, Az = Z.transpose() * (B + W) * Z;
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(Az, Bz);
    EXPECT_NEAR(dense.eigenvalues()[0], lowest.value, 1e-10);
    Eigen::VectorXd reference = Z * dense.eigenvectors().col(0);
    reference /= std::sqrt(reference.dot(B * reference));
    Eigen::Index largest = 0;
    reference.cwiseAbs().maxCoeff(&largest);
    if (reference[largest] < 0.0) reference = -reference;
    const Eigen::Map<const Eigen::VectorXd> v(eta.data(), n);
    EXPECT_NEAR(v.dot(B * v), 1.0, 1e-10);
    EXPECT_LE((v - reference).cwiseAbs().maxCoeff(), 1e-8) << "trial " << trial;
    for (int a = 0; a < m; ++a) {
      const Eigen::Map<const Eigen::VectorXd> c(q.constraints[a].data(), n);
      EXPECT_NEAR(c.dot(v), 0.0, 1e-12);
    }
  }
}

TEST(InterpolatedShape, LinearBetweenSamplesAndTheFarSideAtAKink) {
  const ShapeAtStations f = interpolated_shape(
      {{0.0, 0.0, 0.0, 0.0}, {1.0, 1.0, 0.0, 0.5}, {1.0, 1.0, 0.0, 1.5}, {2.0, 1.0, 1.0, 2.0}});
  const std::vector<ShapePoint> p = f({0.5, 1.0, 1.5});
  EXPECT_DOUBLE_EQ(p[0].theta, 0.25);
  EXPECT_DOUBLE_EQ(p[1].theta, 1.5);  // the far side of the kink
  EXPECT_DOUBLE_EQ(p[2].theta, 1.75);
  EXPECT_DOUBLE_EQ(p[2].y, 0.5);
  EXPECT_THROW(interpolated_shape({{0.0, 0.0, 0.0, 0.0}}), InvalidInput);
}

}  // namespace
}  // namespace flexure
