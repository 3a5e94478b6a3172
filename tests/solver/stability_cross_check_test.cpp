// The stability verdict by two independent methods (issue 27; docs/stability.md, "Validation"):
//   method 1, equilibrium_stability(): the discrete second variation on sampled positions,
//     bordered-matrix inertia and Newton/Romberg eigenvalues (segment_chain.h);
//   method 2, JacobiSecondVariation: the continuous Jacobi equation, a Pruefer-angle count with
//     the constraint correction by inhomogeneous Jacobi solutions and bisection for the margin
//     (jacobi_stability.h), on a theta(s) of its own: the elastica integrated from the clamp's
//     reaction, or the elliptic closed form evaluated wherever its integrator asks.
// They share no discretisation. On seeded random equilibria, with loads past limit points (the
// elliptic proportional path after a fold; every exact equilibrium of a load, unstable branches
// included; shooting continuation for the other ends) and on a tapered, curved chain with a rigid
// link, they must report the same index and margins within kMarginAgreement.
//
// Plus the reproducers, solved through the library: the clamped-clamped beam with the tip
// at (0.9, 0.001) returns the antisymmetric second mode (Fx = 83.75): unstable, index 1; with the
// tip angle 0.01 the first mode (Fx = 41.36): stable. The straight cantilever under Fx = -3 (P >
// pi^2/4): unstable, index 1; under Fx = -30: index 2 ((3 pi / 2)^2 = 22.2 < 30 < (5 pi / 2)^2
// = 61.7).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

#include "flexure/solver/chain_model/jacobi_stability.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/scalar_root.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/elliptic/elastica_closed_form.h"
#include "flexure/solver/elliptic/elliptic_solver.h"
#include "flexure/solver/shooting/elastica_integrator.h"
#include "flexure/solver/shooting/shooting_problem.h"
#include "flexure/solver/shooting/shooting_solver.h"
#include "tests/support/stability_test_support.h"

namespace flexure {
namespace {

using test::mixed_chain;

constexpr double kPi = std::numbers::pi;
// Margins of the two methods agree to this times max(1, |margin|). Method 1 (the ShapeAtStations
// form, which refines its stations until its margin's error estimate is below 1e-9) is accurate to
// about 1e-10 (against closed forms in stability_closed_form_test.cpp), method 2 to about 1e-10
// (bisection to 1e-11 at rtol 1e-12) where its growth exponent is moderate (kTrustedGrowth). The
// largest differences measured are printed by each test (at most 1e-10 when written).
constexpr double kMarginAgreement = 2e-9;

std::string describe(const EndLoad& load) {
  std::ostringstream out;
  out.precision(17);
  out << "Fx = " << load.Fx << ", Fy = " << load.Fy << ", mu = " << load.mu;
  return out.str();
}

std::string describe(const SegmentChain& chain) {
  std::ostringstream out;
  out.precision(17);
  out << to_string(chain.end) << " end, " << chain.segment_count() << " segments, tip load ("
      << chain.tip_load.Fx << ", " << chain.tip_load.Fy << ", " << chain.tip_load.M
      << "), prescribed (" << chain.prescribed.x.value_or(NAN) << ", "
      << chain.prescribed.y.value_or(NAN) << ", " << chain.prescribed.theta.value_or(NAN) << ")";
  return out.str();
}

// Method 1 on a shooting result: the support's reaction from the total tip load.
Stability discrete_of(const SegmentChain& chain, const ShootingResult& r) {
  const Reaction support = tip_support_reaction(chain, r.tip_load);
  return equilibrium_stability(
      chain, support, [&](const std::vector<double>& s) { return shooting_shape_at(chain, r, s); });
}

// Method 2's constraint correction loses about e^G digits, G its growth exponent
// (jacobi_stability.h): where G exceeds this at the margin (chains largely in tension, margins
// close to 1) the margins are not compared, and where it does at the threshold neither the index.
constexpr double kTrustedGrowth = 12.0;

struct Agreement {
  int compared = 0;
  int unstable = 0;
  int margins_skipped = 0;
  double worst = 0.0;  // largest |margin difference| / max(1, |margin|)
  std::string summary() const {
    std::ostringstream out;
    out << compared << " compared, " << unstable << " unstable, worst margin difference " << worst
        << " (" << margins_skipped << " margins not compared: growth exponent > " << kTrustedGrowth
        << ")";
    return out.str();
  }
  void check(const Stability& d, const JacobiSecondVariation& method2, const std::string& what) {
    const Stability j = method2.verdict();
    if (method2.growth_exponent(-kCriticalMarginTolerance) > kTrustedGrowth) return;
    ++compared;
    if (d.index > 0) ++unstable;
    EXPECT_EQ(d.index, j.index) << what << "\n  discrete: " << d.message
                                << "\n  Jacobi: " << j.message;
    if (method2.growth_exponent(std::min(j.margin, 1.0 - 1e-9)) > kTrustedGrowth) {
      ++margins_skipped;
      return;
    }
    EXPECT_EQ(d.kind, j.kind) << what << "\n  discrete: " << d.message
                              << "\n  Jacobi: " << j.message;
    const double difference = std::fabs(d.margin - j.margin) / std::max(1.0, std::fabs(j.margin));
    EXPECT_LE(difference, kMarginAgreement)
        << what << ": margins " << d.margin << " and " << j.margin;
    worst = std::max(worst, difference);
  }
};

// ---- the reproducers ------------------------------------------------------------------

SegmentChain clamped_clamped(double tip_angle) {
  SegmentChain chain = uniform_cantilever(EndLoad{});
  chain.end = EndCondition::kFixed;
  chain.prescribed.x = 0.9;
  chain.prescribed.y = 0.001;
  chain.prescribed.theta = tip_angle;
  return chain;
}

TEST(StabilityReproducer, ClampedClampedSecondModeIsUnstable) {
  const SegmentChain chain = clamped_clamped(0.0);
  const ShootingResult r = ShootingSolver().solve(chain);
  ASSERT_TRUE(r.converged()) << r.message;
  EXPECT_NEAR(r.tip_load.Fx, -83.75, 0.01);  // the antisymmetric mode the issue quotes
  const Stability d = discrete_of(chain, r);
  EXPECT_EQ(d.kind, StabilityKind::kUnstable) << d.message;
  EXPECT_EQ(d.index, 1);
  const Stability j = JacobiSecondVariation(chain, r.reaction).verdict();
  EXPECT_EQ(j.index, 1);
  EXPECT_NEAR(d.margin, j.margin, kMarginAgreement);
}

TEST(StabilityReproducer, ClampedClampedFirstModeIsStable) {
  const SegmentChain chain = clamped_clamped(0.01);
  const ShootingResult r = ShootingSolver().solve(chain);
  ASSERT_TRUE(r.converged()) << r.message;
  EXPECT_NEAR(r.tip_load.Fx, -41.36, 0.01);
  const Stability d = discrete_of(chain, r);
  EXPECT_EQ(d.kind, StabilityKind::kStable) << d.message;
  EXPECT_EQ(d.index, 0);
  const Stability j = JacobiSecondVariation(chain, r.reaction).verdict();
  EXPECT_EQ(j.kind, StabilityKind::kStable);
  EXPECT_NEAR(d.margin, j.margin, kMarginAgreement);
}

TEST(StabilityReproducer, StraightCantileverBeyondEulerLoad) {
  for (const auto& [Fx, index] : {std::pair{-3.0, 1}, std::pair{-30.0, 2}}) {
    const SegmentChain chain = uniform_cantilever(EndLoad{Fx, 0.0, 0.0});
    const ShootingResult r = ShootingSolver().solve(chain);
    ASSERT_TRUE(r.converged()) << r.message;
    ASSERT_NEAR(r.tip.y, 0.0, 1e-12);  // the straight column, as the issue reports
    const Stability d = discrete_of(chain, r);
    EXPECT_EQ(d.kind, StabilityKind::kUnstable) << d.message;
    EXPECT_EQ(d.index, index) << "Fx = " << Fx;
    EXPECT_NEAR(d.margin, 1.0 + 4.0 * Fx / (kPi * kPi), 1e-8) << "Fx = " << Fx;
    EXPECT_EQ(JacobiSecondVariation(chain, r.reaction).verdict().index, index);
  }
}

TEST(ShootingShape, ReproducesTheSolutionAtAnyStations) {
  // The two-stage solve of a straight clamped-clamped beam, a guided beam and a cantilever: the
  // shape at the stations ends at the result's tip, and is refused for an unconverged result.
  for (const SegmentChain& chain : {clamped_clamped(0.0),
                                    [] {
                                      SegmentChain c = uniform_cantilever(EndLoad{0.0, 8.0, 0.0});
                                      c.end = EndCondition::kGuided;
                                      return c;
                                    }(),
                                    uniform_cantilever(EndLoad::howell(1.0, 5.0, 1.0))}) {
    const ShootingResult r = ShootingSolver().solve(chain);
    ASSERT_TRUE(r.converged()) << r.message;
    const std::vector<double> s =
        stability_stations(chain, tip_support_reaction(chain, r.tip_load));
    const std::vector<ShapePoint> shape = shooting_shape_at(chain, r, s);
    ASSERT_EQ(shape.size(), s.size());
    EXPECT_NEAR(shape.back().x, r.tip.x, 1e-10);
    EXPECT_NEAR(shape.back().y, r.tip.y, 1e-10);
    EXPECT_NEAR(shape.back().theta, r.tip.theta, 1e-10);
    // The support's force from the clamp's reaction equals that of the total tip load.
    const Reaction from_tip = tip_support_reaction(chain, r.tip_load);
    const Reaction from_root = tip_support_reaction_from_root(chain, r.reaction);
    EXPECT_NEAR(from_root.Fx, from_tip.Fx, 1e-9);
    EXPECT_NEAR(from_root.Fy, from_tip.Fy, 1e-9);
    ShootingResult unconverged = r;
    unconverged.set_converged(false);
    EXPECT_THROW(shooting_shape_at(chain, unconverged, s), InvalidInput);
    EXPECT_THROW(shooting_shape_at(chain, r, {0.0, 2.0}), InvalidInput);
  }
}

// ---- seeded random cross-check -----------------------------------------------------------------

// The closed-form tangent angle of an elliptic result at s (mirrored like
// EllipticSolver::shape_at).
SegmentAngle elliptic_angle(const EllipticResult& r) {
  auto evaluator = std::make_shared<elliptic::ShapeEvaluator>(r.parameters);
  const bool mirrored = r.parameters.mirrored;
  return [evaluator, mirrored](int, double s) {
    const double theta = evaluator->at(s).theta;
    return mirrored ? -theta : theta;
  };
}

// The equilibrium of a chain at arc lengths s from its root unknowns (m(0), then the force
// components the problem shoots for), integrated from the clamp by the shooting solver's
// integrator.
std::vector<ShapePoint> shape_from_root(const SegmentChain& chain,
                                        const std::vector<double>& root_unknowns,
                                        const std::vector<double>& s) {
  const ShootingSolver::Options o;
  const ShootingProblem problem(chain, o.multiple_shooting);
  ElasticaIntegrator integrator(o.integrator_options());
  Eigen::VectorXd root(problem.root_unknown_count());
  for (int i = 0; i < root.size(); ++i) root[i] = root_unknowns[static_cast<std::size_t>(i)];
  Eigen::VectorXd z;
  std::string error;
  EXPECT_TRUE(problem.complete_guess(root, 1.0, integrator, z, error)) << error;
  TipState tip;
  std::vector<ShapePoint> shape;
  EXPECT_TRUE(problem.integrate_solution(z, 1.0, integrator, tip, error, &s, &shape)) << error;
  return shape;
}

TEST(StabilityCrossCheck, CantileverPathsThroughLimitPoints) {
  // The proportional load paths (shooting continuation) of cantilever loads whose path folds:
  // every 3rd point, including those between the folds. Method 1 on the shape integrated from the
  // path point's root moment, method 2 on its own integration. Independently of both, the path
  // says what to expect: stable while the load factor rises (before the first fold and after the
  // second), index 1 while it falls (between two folds: a fold of a one-parameter path exchanges
  // stability, Maddocks 1987); points within 1e-4 of a critical state are compared in margin only.
  std::mt19937_64 rng(27001u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Agreement agreement;
  int paths = 0, attempts = 0, by_path = 0;
  ShootingSolver::Options fine_steps;
  fine_steps.continuation.max_step = 0.03;  // enough points between the folds
  while (paths < 3 && attempts < 5000) {
    ++attempts;
    // Folds are rare: about 1 load in 700 of this region has two (the elliptic solver says).
    const EndLoad load = EndLoad::howell(
        -8.0 + 23.0 * unit(rng), 60.0 * unit(rng), (2.0 * unit(rng) - 1.0) * 2.0 * kPi);
    if (EllipticSolver().solve(load).limit_points < 2) continue;
    const SegmentChain chain = uniform_cantilever(load);
    const LoadPath path = ShootingSolver(fine_steps).load_path(chain);
    ASSERT_TRUE(path.converged()) << describe(load) << ": " << path.message;
    ASSERT_GE(path.limit_points, 2) << describe(load);
    ++paths;
    for (std::size_t i = 1; i + 1 < path.points.size(); i += 3) {
      const PathPoint& p = path.points[i];
      const SegmentChain at = chain.at_load_factor(p.lambda);
      const Stability d = equilibrium_stability(at, Reaction{}, [&](const std::vector<double>& s) {
        return shape_from_root(at, {-p.reaction.M}, s);
      });
      const JacobiSecondVariation method2(at, p.reaction);
      const std::string what = describe(load) + ", load factor " + std::to_string(p.lambda);
      if (std::fabs(d.margin) < 1e-4) {
        EXPECT_NEAR(d.margin, method2.eigenvalue(1), kMarginAgreement) << what;
        continue;
      }
      agreement.check(d, method2, what);
      const double before = path.points[i - 1].lambda, after = path.points[i + 1].lambda;
      if ((before < p.lambda) == (p.lambda < after)) {
        EXPECT_EQ(d.index, after < before ? 1 : 0) << what;
        ++by_path;
      }
    }
  }
  EXPECT_EQ(paths, 3);
  EXPECT_GE(agreement.unstable, 5);
  EXPECT_GE(by_path, 30);
  std::cout << "cantilever paths: " << agreement.summary() << "\n";
}

TEST(StabilityCrossCheck, EveryExactEquilibriumOfALoad) {
  // All equilibria of five cantilever loads (the sign changes of the elliptic tip-angle residual
  // over three turns), one with an end moment past 2 pi: stable ones and unstable ones of index 1
  // and more.
  std::mt19937_64 rng(27002u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Agreement agreement;
  int highest_index = 0;
  for (int i = 0; i < 5; ++i) {
    // The fifth: an end moment past 2 pi (the beam wound more than once).
    const EndLoad load =
        EndLoad::howell(-2.0 + 12.0 * unit(rng),
                        2.0 + 10.0 * unit(rng),
                        i < 4 ? (2.0 * unit(rng) - 1.0) * 2.0 * kPi : 2.0 * kPi + 1.5 * unit(rng));
    const double F = std::hypot(load.Fx, load.Fy), psi = std::atan2(load.Fy, load.Fx);
    const elliptic::PendulumProblem p = elliptic::make_pendulum_problem(F, psi, load.mu);
    auto g = [&](double t) { return elliptic::tip_angle_residual(p, t); };
    const int samples = 6000;
    const double lo = -3.0 * kPi - psi, hi = 3.0 * kPi - psi;
    double a = lo, ga = g(a);
    for (int k = 1; k <= samples; ++k) {
      const double b = lo + (hi - lo) * k / samples;
      const double gb = g(b);
      if ((ga > 0.0) != (gb > 0.0) && std::fabs(gb - ga) < 1.0) {
        const ScalarRootResult root = brent_root(g, a, b, ga, gb);
        ASSERT_TRUE(root.converged());
        EllipticResult e;
        e.set_converged(true);
        e.load = load;
        e.branch_kind = EllipticBranch::kProportionalContinued;
        e.parameters = elliptic::integrate_from_tip(p, root.x).parameters;
        const SegmentChain chain = uniform_cantilever(load);
        const Stability d =
            equilibrium_stability(chain, Reaction{}, [&](const std::vector<double>& s) {
              return EllipticSolver().shape_at(e, s);
            });
        agreement.check(
            d,
            JacobiSecondVariation(chain, Reaction{-load.Fx, -load.Fy, 0.0}, elliptic_angle(e)),
            describe(load) + ", tip angle " + std::to_string(root.x + psi));
        highest_index = std::max(highest_index, d.index);
      }
      a = b;
      ga = gb;
    }
  }
  EXPECT_GE(agreement.compared, 12);
  EXPECT_GE(agreement.unstable, 6);
  EXPECT_GE(highest_index, 2);
  std::cout << "exact equilibria: " << agreement.summary() << ", highest index " << highest_index
            << "\n";
}

TEST(StabilityCrossCheck, PrescribedTipCoordinatesByShooting) {
  // Uniform beams with a guided, pinned, slider or fixed end, random targets and loads: the
  // equilibrium of the load path (shooting continuation from the unloaded beam) and those Newton
  // reaches from two random root loads (often another branch, unstable); method 2 integrates the
  // elastica from the clamp's reaction.
  std::mt19937_64 rng(27003u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const EndCondition ends[] = {
      EndCondition::kGuided, EndCondition::kPinned, EndCondition::kSlider, EndCondition::kFixed};
  Agreement agreement;
  int attempts = 0;
  while (agreement.compared < 48 && attempts < 200) {
    const EndCondition end = ends[attempts % 4];
    ++attempts;
    SegmentChain chain = uniform_cantilever(EndLoad{});
    chain.end = end;
    const PrescribedMask mask = prescribed_mask(end);
    if (mask.x) chain.prescribed.x = 0.3 + 0.65 * unit(rng);
    if (mask.y) chain.prescribed.y = (2.0 * unit(rng) - 1.0) * 0.4;
    if (mask.theta) chain.prescribed.theta = (2.0 * unit(rng) - 1.0) * 2.0;
    if (!mask.x) chain.tip_load.Fx = -25.0 + 40.0 * unit(rng);
    if (!mask.y) chain.tip_load.Fy = -10.0 + 20.0 * unit(rng);
    if (!mask.theta) chain.tip_load.M = (2.0 * unit(rng) - 1.0) * 4.0;
    std::vector<ShootingResult> equilibria;
    try {
      equilibria.push_back(ShootingSolver().solve(chain));
      for (int guess = 0; guess < 2; ++guess) {
        std::vector<double> root{(2.0 * unit(rng) - 1.0) * 15.0};
        if (mask.x) root.push_back((2.0 * unit(rng) - 1.0) * 40.0);
        if (mask.y) root.push_back((2.0 * unit(rng) - 1.0) * 40.0);
        equilibria.push_back(ShootingSolver().solve_from(chain, root));
      }
    } catch (const InvalidInput&) {
      continue;  // an unreachable target
    }
    for (const ShootingResult& r : equilibria) {
      if (!r.converged()) continue;
      agreement.check(
          discrete_of(chain, r), JacobiSecondVariation(chain, r.reaction), describe(chain));
    }
  }
  EXPECT_GE(agreement.compared, 48);
  EXPECT_GE(agreement.unstable, 8);
  std::cout << "prescribed tips: " << agreement.summary() << "\n";
}

TEST(StabilityCrossCheck, TaperedCurvedChainWithRigidLink) {
  // The load path's equilibrium and those Newton reaches from two random root loads, every end.
  std::mt19937_64 rng(27004u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const EndCondition ends[] = {EndCondition::kFree,
                               EndCondition::kGuided,
                               EndCondition::kPinned,
                               EndCondition::kSlider,
                               EndCondition::kFixed};
  Agreement agreement;
  int attempts = 0;
  while (agreement.compared < 24 && attempts < 100) {
    const EndCondition end = ends[attempts % 5];
    ++attempts;
    const SegmentChain chain = mixed_chain(end, rng);
    const PrescribedMask mask = prescribed_mask(end);
    std::vector<ShootingResult> equilibria;
    try {
      equilibria.push_back(ShootingSolver().solve(chain));
      for (int guess = 0; guess < 2; ++guess) {
        std::vector<double> root{(2.0 * unit(rng) - 1.0) * 10.0};
        if (mask.x) root.push_back((2.0 * unit(rng) - 1.0) * 30.0);
        if (mask.y) root.push_back((2.0 * unit(rng) - 1.0) * 30.0);
        equilibria.push_back(ShootingSolver().solve_from(chain, root));
      }
    } catch (const InvalidInput&) {
      continue;
    }
    for (const ShootingResult& r : equilibria) {
      if (!r.converged()) continue;
      // The support's force from the clamp's reaction, through the node load.
      const Reaction from_root = tip_support_reaction_from_root(chain, r.reaction);
      EXPECT_NEAR(from_root.Fx, tip_support_reaction(chain, r.tip_load).Fx, 1e-9);
      EXPECT_NEAR(from_root.Fy, tip_support_reaction(chain, r.tip_load).Fy, 1e-9);
      agreement.check(
          discrete_of(chain, r), JacobiSecondVariation(chain, r.reaction), describe(chain));
    }
  }
  EXPECT_GE(agreement.compared, 24);
  EXPECT_GE(agreement.unstable, 2);
  std::cout << "mixed chain: " << agreement.summary() << "\n";
}

}  // namespace
}  // namespace flexure
