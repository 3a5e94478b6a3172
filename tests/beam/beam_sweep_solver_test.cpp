// What is checked against what: the sweep solver (beam/beam_sweep_solver.h), which
// starts shooting points from their neighbours, against solve_beam, which solves every point
// from zero load (the proportional-loading answer by continuation).
//  * Seeded random sweeps over alpha2, n and mu and (alpha2, n) grids, with and without end
//    moments, among them sweeps whose load paths pass limit points (an end moment against a
//    compressive load): every point has the cold solve's tip (1e-9), limit points and inflection
//    points. Sweeps with a dead tip force alone are mostly started from neighbours (at least 90 %
//    of their points: the test is not satisfied by solving everything from zero).
//  * The same sweep on two threads at once, each taking runs of points as `sweep beam` hands
//    them out: the same tips.
//  * The premise of the dead-force rule: on seeded random loads with mu = 0 (n in [-20, 45],
//    alpha2 in (0, 150]) the elliptic solver's continuation passes no limit point and its answer
//    has no inflection point.
#include "flexure/beam/beam_sweep_solver.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <thread>

#include "flexure/solver/elliptic/elliptic_solver.h"

namespace flexure {
namespace {

struct Compared {
  long points = 0;
  long from_neighbour = 0;
};

// Solves every point of `grid` by the sweep solver, in order, and by solve_beam alone. Margins
// within `margin_tolerance`: the discrete verdict's accuracy (1e-9, docs/stability.md) where a
// sweep may take it.
Compared compare_with_cold(const BeamSweepGrid& grid, double margin_tolerance = 1e-9) {
  const BeamSweepSolver sweep(grid, BeamMethod::kShooting);
  for (long i = 0; i < grid.size(); ++i) {
    const BeamProblem p = grid.at(i);
    SCOPED_TRACE(::testing::Message() << "point " << i << ": n = " << p.load_ratio_n
                                      << ", alpha2 = " << p.value << ", mu = " << p.mu);
    const BeamSolution warm = sweep.solve(i);
    const BeamSolution cold = solve_beam(BeamMethod::kShooting, p);
    EXPECT_EQ(warm.converged(), cold.converged()) << warm.message << " / " << cold.message;
    if (!cold.converged()) continue;
    EXPECT_NEAR(warm.tip.a_over_l, cold.tip.a_over_l, 1e-9);
    EXPECT_NEAR(warm.tip.b_over_l, cold.tip.b_over_l, 1e-9);
    EXPECT_NEAR(warm.tip.theta0, cold.tip.theta0, 1e-9);
    EXPECT_NEAR(warm.root_moment, cold.root_moment, 1e-8 * (1.0 + std::fabs(cold.root_moment)));
    EXPECT_EQ(warm.limit_points, cold.limit_points) << warm.branch << " / " << cold.branch;
    EXPECT_EQ(warm.inflection_points, cold.inflection_points);
    EXPECT_EQ(warm.method, BeamMethod::kShooting);
    EXPECT_EQ(warm.method_reason, cold.method_reason);
    // The stability verdict: a compressed cantilever's starts from the margin extrapolated from
    // the neighbours' (compressed_cantilever_stability.h) and must come out the same.
    EXPECT_EQ(warm.stability.kind, cold.stability.kind) << warm.stability.message;
    EXPECT_EQ(warm.stability.index, cold.stability.index);
    EXPECT_NEAR(warm.stability.margin, cold.stability.margin, margin_tolerance);
  }
  const BeamSweepSolver::Counts c = sweep.counts();
  EXPECT_EQ(c.from_neighbour + c.from_zero, grid.size());
  return {grid.size(), c.from_neighbour};
}

BeamSweepGrid one_axis(
    SweepParameter p, double start, double stop, long count, double n, double alpha2, double mu) {
  BeamSweepGrid grid;
  grid.base.load_ratio_n = n;
  grid.base.value = alpha2;
  grid.base.mu = mu;
  grid.axes = {{p, start, stop, count}};
  grid.validate(100000);
  return grid;
}

TEST(BeamSweepSolver, DeadForceSweepsStartFromNeighboursAndEqualTheColdSolve) {
  std::mt19937 rng(27001);
  std::uniform_real_distribution<double> n(-5.0, 15.0), alpha2(0.2, 20.0), unit(0.0, 1.0);
  for (int k = 0; k < 6; ++k) {
    // Alternately an alpha2 axis (outward and inward) and an n axis.
    BeamSweepGrid grid;
    if (k % 2 == 0) {
      const double a = alpha2(rng), b = alpha2(rng);
      grid = one_axis(SweepParameter::kAlpha2,
                      k == 2 ? std::max(a, b) : std::min(a, b),
                      k == 2 ? std::min(a, b) : std::max(a, b),
                      40,
                      n(rng),
                      0.0,
                      0.0);
    } else {
      const double a = n(rng), b = n(rng);
      grid = one_axis(SweepParameter::kLoadRatioN, a, b, 40, 0.0, alpha2(rng), 0.0);
    }
    SCOPED_TRACE(::testing::Message() << "sweep " << k);
    const Compared c = compare_with_cold(grid);
    EXPECT_GE(c.from_neighbour, 36) << "of " << c.points;
  }
  // A grid over (alpha2, n): rows of n at each alpha2, the first point of a row from zero load.
  BeamSweepGrid grid;
  grid.axes = {{SweepParameter::kAlpha2, 1.0, 12.0, 3}, {SweepParameter::kLoadRatioN, -4, 10, 57}};
  grid.validate(1000);
  const Compared c = compare_with_cold(grid);
  EXPECT_GE(c.from_neighbour, 3 * 56 * 9 / 10);
}

// The compressed sweep (n = 2, docs/performance.md "The edges of issue 27"): every point a
// uniform compressed cantilever, judged by the Jacobi verdict from the extrapolated margin; the
// same kind and index as the point solved and judged alone, margins within 1e-10 (both about
// 1e-12 from the exact root: tests/solver/compressed_cantilever_stability_test.cpp).
TEST(BeamSweepSolver, CompressedSweepKeepsTheVerdictOfEachPointAlone) {
  BeamSweepGrid grid = one_axis(SweepParameter::kAlpha2, 0.5, 10.0, 500, 2.0, 0.0, 0.0);
  const Compared c = compare_with_cold(grid, 1e-10);
  EXPECT_GE(c.from_neighbour, 490);
  // Inward, from the large loads down: the same.
  grid = one_axis(SweepParameter::kAlpha2, 10.0, 0.5, 100, 2.0, 0.0, 0.0);
  compare_with_cold(grid, 1e-10);
}

TEST(BeamSweepSolver, SweepsPastLimitPointsGiveTheProportionalLoadingAnswer) {
  // End moments against compressive loads (limit points on the continuation's path, found by the
  // elliptic solver on seeded random loads): sweeps over mu, alpha2 and n through these loads.
  struct Case {
    SweepParameter axis;
    double start, stop, n, alpha2, mu;
  };
  const Case cases[] = {
      {SweepParameter::kMu, -1.0, -6.2, 0.538, 9.866, 0.0},
      {SweepParameter::kMu, -2.5, -3.5, 1.335, 4.666, 0.0},
      {SweepParameter::kAlpha2, 1.0, 10.0, 0.25, 0.0, -5.748},
      {SweepParameter::kLoadRatioN, -3.0, 2.0, 0.0, 5.674, -5.37},
      {SweepParameter::kMu, 4.0, 6.28, -3.536, 1.534, 0.0},
  };
  int folded = 0;
  for (const Case& c : cases) {
    const BeamSweepGrid grid = one_axis(c.axis, c.start, c.stop, 30, c.n, c.alpha2, c.mu);
    SCOPED_TRACE(::testing::Message() << dataset_name(c.axis) << " " << c.start << ".." << c.stop);
    compare_with_cold(grid);
    for (long i = 0; i < grid.size(); ++i) {
      if (solve_beam(BeamMethod::kShooting, grid.at(i)).limit_points > 0) {
        ++folded;
        break;
      }
    }
  }
  EXPECT_EQ(folded, 5) << "every case must pass loads whose paths fold";
}

TEST(BeamSweepSolver, TwoThreadsTakingRunsOfPointsGiveTheSameTips) {
  const BeamSweepGrid grid = one_axis(SweepParameter::kAlpha2, 0.5, 10.0, 60, 1.5, 0.0, 0.0);
  std::vector<BeamSolution> serial(grid.size()), threaded(grid.size());
  {
    const BeamSweepSolver sweep(grid, BeamMethod::kShooting);
    for (long i = 0; i < grid.size(); ++i) serial[i] = sweep.solve(i);
  }
  const BeamSweepSolver sweep(grid, BeamMethod::kShooting);
  // Runs of 3 points, taken in turn: a thread's neighbour lies 4 points back.
  auto work = [&](int thread) {
    for (long run = thread; run * 3 < grid.size(); run += 2) {
      for (long i = run * 3; i < std::min(grid.size(), run * 3 + 3); ++i) {
        threaded[i] = sweep.solve(i);
      }
    }
  };
  std::thread other(work, 1);
  work(0);
  other.join();
  for (long i = 0; i < grid.size(); ++i) {
    ASSERT_TRUE(threaded[i].converged()) << threaded[i].message;
    EXPECT_NEAR(threaded[i].tip.a_over_l, serial[i].tip.a_over_l, 1e-9) << i;
    EXPECT_NEAR(threaded[i].tip.b_over_l, serial[i].tip.b_over_l, 1e-9) << i;
    EXPECT_NEAR(threaded[i].tip.theta0, serial[i].tip.theta0, 1e-9) << i;
  }
  EXPECT_GE(sweep.counts().from_neighbour, 50);
}

TEST(BeamSweepSolver, DeadTipForceAnswersPassNoLimitPointAndHaveNoInflection) {
  const EllipticSolver solver;
  std::mt19937 rng(27002);
  std::uniform_real_distribution<double> n(-20.0, 45.0), alpha2(1e-3, 150.0);
  for (int i = 0; i < 20000; ++i) {
    const double nn = n(rng), a = (i % 2 ? -1.0 : 1.0) * alpha2(rng);
    const EllipticResult r = solver.solve(EndLoad::howell(nn, a, 0.0));
    ASSERT_TRUE(r.converged()) << "n = " << nn << ", alpha2 = " << a << ": " << r.message;
    ASSERT_EQ(r.limit_points, 0) << "n = " << nn << ", alpha2 = " << a;
    ASSERT_EQ(r.inflection_points, 0) << "n = " << nn << ", alpha2 = " << a;
  }
}

// Issue 29 item 4: a sweep with shapes (`sweep beam --shapes K`) starts its points from their
// neighbours too, and its tips and shapes are those of the cold solve with the same shape points
// (1e-9; every point of the shape, not only the tip). Outward and inward along alpha2 with n and
// mu (a path with limit points for the compressive n), and along n.
TEST(BeamSweepSolver, SweepsWithShapesStartFromNeighboursWithTheColdShapes) {
  struct Line {
    SweepParameter p;
    double start, stop, n, alpha2, mu;
  };
  for (const Line& l : {Line{SweepParameter::kAlpha2, 0.5, 10.0, 0.0, 1.0, 0.0},
                        Line{SweepParameter::kAlpha2, 10.0, 0.5, -0.5, 1.0, 0.3},
                        Line{SweepParameter::kLoadRatioN, -2.0, 6.0, 0.0, 3.0, 0.0}}) {
    BeamSweepGrid grid = one_axis(l.p, l.start, l.stop, 40, l.n, l.alpha2, l.mu);
    grid.base.shape_points = 21;
    const BeamSweepSolver sweep(grid, BeamMethod::kShooting);
    std::vector<TipPose> tips(static_cast<std::size_t>(grid.size()));
    for (long i = 0; i < grid.size(); ++i) {
      const BeamProblem p = grid.at(i);
      const BeamSolution warm = sweep.solve(i);
      tips[static_cast<std::size_t>(i)] = warm.tip;
      const BeamSolution cold = solve_beam(BeamMethod::kShooting, p);
      ASSERT_EQ(warm.converged(), cold.converged()) << warm.message << " / " << cold.message;
      if (!cold.converged()) continue;
      EXPECT_NEAR(warm.tip.a_over_l, cold.tip.a_over_l, 1e-9) << "point " << i;
      EXPECT_NEAR(warm.tip.b_over_l, cold.tip.b_over_l, 1e-9) << "point " << i;
      EXPECT_NEAR(warm.tip.theta0, cold.tip.theta0, 1e-9) << "point " << i;
      ASSERT_EQ(warm.shape.size(), 21u);
      ASSERT_EQ(cold.shape.size(), 21u);
      for (std::size_t k = 0; k < 21; ++k) {
        EXPECT_EQ(warm.shape[k].s, cold.shape[k].s);
        EXPECT_NEAR(warm.shape[k].x, cold.shape[k].x, 1e-9) << "point " << i << " shape " << k;
        EXPECT_NEAR(warm.shape[k].y, cold.shape[k].y, 1e-9) << "point " << i << " shape " << k;
        EXPECT_NEAR(warm.shape[k].theta, cold.shape[k].theta, 1e-9);
      }
      // The shape's last point is the solver's tip.
      EXPECT_NEAR(warm.shape.back().x, warm.tip.a_over_l, 1e-12);
      EXPECT_NEAR(warm.shape.back().y, warm.tip.b_over_l, 1e-12);
    }
    const BeamSweepSolver::Counts c = sweep.counts();
    // Warm-started exactly as the same sweep without shapes (the plain sweep's own fallbacks:
    // inward and along n most points are solved from zero there too), and outward along alpha2
    // nearly every point.
    BeamSweepGrid plain_grid = grid;
    plain_grid.base.shape_points = 0;
    const BeamSweepSolver plain(plain_grid, BeamMethod::kShooting);
    for (long i = 0; i < grid.size(); ++i) {
      // The tips unchanged by the shapes.
      const BeamSolution p = plain.solve(i);
      EXPECT_NEAR(p.tip.a_over_l, tips[i].a_over_l, 1e-12) << "point " << i;
      EXPECT_NEAR(p.tip.b_over_l, tips[i].b_over_l, 1e-12) << "point " << i;
      EXPECT_NEAR(p.tip.theta0, tips[i].theta0, 1e-12) << "point " << i;
    }
    const BeamSweepSolver::Counts cp = plain.counts();
    EXPECT_EQ(c.from_neighbour, cp.from_neighbour) << "from zero " << c.from_zero;
    if (l.p == SweepParameter::kAlpha2 && l.start < l.stop) EXPECT_GE(c.from_neighbour, 35);
  }
}

}  // namespace
}  // namespace flexure
