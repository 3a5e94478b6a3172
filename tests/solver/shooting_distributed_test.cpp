// What is checked against what (issue 29, items 1 and 2; docs/distributed-loads.md,
// docs/extensible.md):
//   * a uniform dead load w = q L^3/EI on a cantilever: b/L -> w/8 and theta0 -> w/6
//   (Euler-Bernoulli
//     linear theory), the nonlinear remainder falling at third order; a triangular load against
//     w0 L^4/(30 EI) and w0 L^3/(24 EI) (q_profile);
//   * the chain algorithm with the dead load lumped on its nodes converges to the shooting answer
//     at the measured order 2 in the element count N;
//   * a follower pressure against an independent integration written here (fixed-step RK4 of
//     (x, y, theta, m, N_x, N_y) with N' = -p n, shot by finite-difference Newton);
//   * an extensible bar under an axial tip force stretches by P L/EA (exact for a straight bar),
//     and by q L^2/(2 EA) under its own axial load; a shear-flexible cantilever adds P L/GAs to the
//     linear tip deflection;
//   * EA, GAs -> infinity recovers the inextensible elastica, and the Reissner right-hand side at
//     EA = GAs = 1e15 agrees with the elastica's own (two code paths);
//   * the identity of issue 29: a stress-free curvature kappa0 under any load has the tip of the
//     straight beam under the same load plus an end moment kappa0 EI (both code paths of kappa0);
//   * seeded random cross-check: extensible, shear-flexible, distributed-load shooting with rk8pd
//     against the Dormand-Prince 5(4) backend, EA L^2/EI in [1e2, 1e6].
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <random>

#include "flexure/solver/chain/chain_algorithm_solver.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/elastica_integrator.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {
namespace {

SegmentChain cantilever(double qx, double qy) {
  SegmentChain chain;
  FlexibleSegment f(1.0, 1.0);
  f.qx = qx;
  f.qy = qy;
  chain.segments.push_back(f);
  return chain;
}

TEST(ShootingDistributed, UniformDeadLoadSmallLoadLimits) {
  const ShootingSolver solver;
  double previous_b = 0.0, previous_theta = 0.0;
  for (double w : {0.04, 0.02, 0.01}) {
    const ShootingResult r = solver.solve(cantilever(0.0, w));
    ASSERT_TRUE(r.converged()) << r.message;
    const double error_b = std::abs(r.tip.y - w / 8.0);
    const double error_theta = std::abs(r.tip.theta - w / 6.0);
    // The remainder is odd in the load: O(w^3).
    EXPECT_LE(error_b, w * w * w) << "w = " << w;
    EXPECT_LE(error_theta, w * w * w) << "w = " << w;
    if (previous_b > 0.0) {
      EXPECT_NEAR(std::log2(previous_b / error_b), 3.0, 0.1) << "w = " << w;
      EXPECT_NEAR(std::log2(previous_theta / error_theta), 3.0, 0.1) << "w = " << w;
    }
    previous_b = error_b;
    previous_theta = error_theta;
    // The clamp carries the whole load and its moment w/2 (the beam's own moment arm at first
    // order).
    EXPECT_NEAR(r.reaction.Fy, -w, 1e-12);
    EXPECT_NEAR(r.reaction.M, -w * r.tip.x / 2.0, 0.05 * w * w);
  }
}

TEST(ShootingDistributed, TriangularProfileSmallLoadLimit) {
  // q(s) = w0 (1 - s/L): tip deflection w0 L^4/(30 EI), slope w0 L^3/(24 EI) (Roark, Table 8.1).
  const double w0 = 1e-3;
  SegmentChain chain;
  FlexibleSegment f(1.0, 1.0);
  f.q_profile = {{0.0, w0}, {0.0, 0.5 * w0}, {0.0, 0.0}};
  chain.segments.push_back(f);
  const ShootingResult r = ShootingSolver().solve(chain);
  ASSERT_TRUE(r.converged()) << r.message;
  EXPECT_NEAR(r.tip.y / (w0 / 30.0), 1.0, 1e-5);
  EXPECT_NEAR(r.tip.theta / (w0 / 24.0), 1.0, 1e-5);
  EXPECT_NEAR(r.reaction.Fy, -0.5 * w0, 1e-14);
}

TEST(ShootingDistributed, LargeSelfWeightAgainstLumpedChainAtSecondOrder) {
  // A heavy cantilever (w = 5, tip turns ~0.7 rad) with a tip moment and a horizontal load.
  SegmentChain chain = cantilever(0.5, -5.0);
  chain.tip_load.M = 0.3;
  ShootingSolver::Options so;
  so.strategy = ShootingStrategy::kContinuation;
  const ShootingResult exact = ShootingSolver(so).solve(chain);
  ASSERT_TRUE(exact.converged()) << exact.message;
  std::vector<double> errors;
  for (int N : {20, 40, 80, 160}) {
    ChainAlgorithmSolver::Options co;
    co.elements = N;
    co.refine_elements = false;
    const ChainResult c = ChainAlgorithmSolver(co).solve(chain);
    ASSERT_TRUE(c.converged()) << c.message;
    errors.push_back(std::hypot(c.tip.x - exact.tip.x, c.tip.y - exact.tip.y));
  }
  for (std::size_t i = 1; i < errors.size(); ++i) {
    const double order = std::log2(errors[i - 1] / errors[i]);
    EXPECT_NEAR(order, 2.0, 0.15) << "N = " << (20 << i) << ", errors " << errors[i - 1] << ", "
                                  << errors[i];
  }
  EXPECT_LE(errors.back(), 1e-4);
}

// Independent integration of a cantilever under a follower pressure p (and dead tip loads):
// state (x, y, theta, m, N_x, N_y), N' = -p (-sin theta, cos theta), m' = N_x sin - N_y cos,
// fixed-step RK4, shooting for (m, N_x, N_y)(0) with the tip conditions m = M, N = F by Newton with
// finite differences. No code of the library is used.
std::array<double, 6> rk4_tip(double p, const std::array<double, 3>& root, int steps) {
  using State = std::array<double, 6>;
  auto f = [p](const State& y) {
    const double c = std::cos(y[2]), s = std::sin(y[2]);
    return State{c, s, y[3], y[4] * s - y[5] * c, p * s, -p * c};
  };
  State y{0.0, 0.0, 0.0, root[0], root[1], root[2]};
  const double h = 1.0 / steps;
  for (int i = 0; i < steps; ++i) {
    const State k1 = f(y);
    State t;
    for (int j = 0; j < 6; ++j) t[j] = y[j] + 0.5 * h * k1[j];
    const State k2 = f(t);
    for (int j = 0; j < 6; ++j) t[j] = y[j] + 0.5 * h * k2[j];
    const State k3 = f(t);
    for (int j = 0; j < 6; ++j) t[j] = y[j] + h * k3[j];
    const State k4 = f(t);
    for (int j = 0; j < 6; ++j) y[j] += h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
  }
  return y;
}

std::array<double, 6> rk4_follower_cantilever(double p, double Fx, double Fy, double M) {
  std::array<double, 3> z{0.0, 0.0, 0.0};
  const int steps = 4000;
  for (int iteration = 0; iteration < 50; ++iteration) {
    auto residual = [&](const std::array<double, 3>& u) {
      const std::array<double, 6> e = rk4_tip(p, u, steps);
      return std::array<double, 3>{e[3] - M, e[4] - Fx, e[5] - Fy};
    };
    const std::array<double, 3> g = residual(z);
    if (std::max({std::abs(g[0]), std::abs(g[1]), std::abs(g[2])}) < 1e-13) break;
    double J[3][3];
    for (int c = 0; c < 3; ++c) {
      std::array<double, 3> u = z;
      const double h = 1e-7;
      u[c] += h;
      const std::array<double, 3> gp = residual(u);
      for (int r = 0; r < 3; ++r) J[r][c] = (gp[r] - g[r]) / h;
    }
    // Cramer's rule.
    auto det3 = [](double a[3][3]) {
      return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
             a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
             a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    };
    const double d = det3(J);
    for (int c = 0; c < 3; ++c) {
      double A[3][3];
      for (int r = 0; r < 3; ++r) {
        for (int k = 0; k < 3; ++k) A[r][k] = k == c ? g[r] : J[r][k];
      }
      z[c] -= det3(A) / d;
    }
  }
  return rk4_tip(p, z, steps);
}

TEST(ShootingDistributed, FollowerPressureAgainstIndependentRk4) {
  for (const auto& [p, Fx, Fy, M] : {std::array<double, 4>{1.0, 0.0, 0.0, 0.0},
                                     std::array<double, 4>{3.0, -0.5, 0.4, 0.2},
                                     std::array<double, 4>{-2.0, 1.0, 0.0, -0.5}}) {
    SegmentChain chain;
    FlexibleSegment f(1.0, 1.0);
    f.q_follower = p;
    chain.segments.push_back(f);
    chain.tip_load = TipLoad{Fx, Fy, M, 0.0};
    const ShootingResult r = ShootingSolver().solve(chain);
    ASSERT_TRUE(r.converged()) << r.message;
    const std::array<double, 6> e = rk4_follower_cantilever(p, Fx, Fy, M);
    // RK4 with h = 1/4000: error ~ h^4 ~ 4e-15 times the derivatives; Newton to 1e-13.
    EXPECT_NEAR(r.tip.x, e[0], 1e-9) << "p = " << p;
    EXPECT_NEAR(r.tip.y, e[1], 1e-9) << "p = " << p;
    EXPECT_NEAR(r.tip.theta, e[2], 1e-9) << "p = " << p;
    // The tip load reported is the given dead one (the pressure ends at the tip).
    EXPECT_NEAR(r.tip_load.Fx, Fx, 1e-9);
    EXPECT_NEAR(r.tip_load.Fy, Fy, 1e-9);
  }
}

TEST(ShootingDistributed, FollowerPressureOnTwoSegmentsAndALinkBalancesTheClamp) {
  // Global balance: the clamp reaction equals minus the pressure's resultant p R90 (r_b - r_a)
  // summed over the loaded segments plus the tip load. Checked against the returned shape.
  SegmentChain chain;
  FlexibleSegment a(0.4, 1.0), b(0.4, 0.7);
  a.q_follower = 2.0;
  b.q_follower = -1.0;
  b.qy = -0.5;
  chain.segments = {a, RigidSegment{0.2, 0.3}, b};
  chain.tip_load = TipLoad{0.3, 0.1, 0.0, 0.0};
  ShootingSolver::Options so;
  so.shape_points = 101;  // s = 0, 0.01, ...: nodes at 0.4 and 0.6
  const ShootingResult r = ShootingSolver(so).solve(chain);
  ASSERT_TRUE(r.converged()) << r.message;
  const auto& shape = r.shape;
  const ShapePoint& n1 = shape[40];
  const ShapePoint& n2 = shape[60];
  ASSERT_NEAR(n1.s, 0.4, 1e-12);
  ASSERT_NEAR(n2.s, 0.6, 1e-12);
  const double Fx = 0.3 + 2.0 * (-(n1.y - 0.0)) - 1.0 * (-(r.tip.y - n2.y));
  const double Fy = 0.1 + 2.0 * (n1.x - 0.0) - 1.0 * (r.tip.x - n2.x) - 0.5 * 0.4;
  EXPECT_NEAR(r.reaction.Fx, -Fx, 1e-10);
  EXPECT_NEAR(r.reaction.Fy, -Fy, 1e-10);
}

TEST(ShootingExtensible, AxialTipForceStretchesByPLOverEA) {
  for (double EA : {100.0, 1e4}) {
    for (double P : {1.0, -0.5, 5.0}) {
      SegmentChain chain;
      FlexibleSegment f(2.0, 1.0);
      f.EA = EA;
      chain.segments.push_back(f);
      chain.tip_load.Fx = P;
      const ShootingResult r = ShootingSolver().solve(chain);
      ASSERT_TRUE(r.converged()) << r.message;
      EXPECT_NEAR(r.tip.x, 2.0 + P * 2.0 / EA, 1e-12) << "EA = " << EA << ", P = " << P;
      EXPECT_NEAR(r.tip.y, 0.0, 1e-12);
    }
  }
  // Its own axial load q: stretch int_0^L q (L - s)/EA ds = q L^2 / (2 EA).
  SegmentChain chain;
  FlexibleSegment f(1.0, 1.0);
  f.EA = 50.0;
  f.qx = 3.0;
  chain.segments.push_back(f);
  const ShootingResult r = ShootingSolver().solve(chain);
  ASSERT_TRUE(r.converged()) << r.message;
  EXPECT_NEAR(r.tip.x, 1.0 + 3.0 / (2.0 * 50.0), 1e-12);
}

TEST(ShootingExtensible, ShearFlexibleCantileverAddsPLOverGAs) {
  for (double GAs : {10.0, 100.0, 1e3}) {
    const double P = 1e-5;
    SegmentChain chain;
    FlexibleSegment f(1.0, 1.0);
    f.GAs = GAs;
    chain.segments.push_back(f);
    chain.tip_load.Fy = P;
    const ShootingResult r = ShootingSolver().solve(chain);
    ASSERT_TRUE(r.converged()) << r.message;
    // Linear theory (Timoshenko): P L^3/(3 EI) + P L/GAs; the nonlinear remainder is O(P^3).
    EXPECT_NEAR(r.tip.y / P, 1.0 / 3.0 + 1.0 / GAs, 1e-8) << "GAs = " << GAs;
    // The section turns by the bending slope only: P L^2/(2 EI).
    EXPECT_NEAR(r.tip.theta / P, 0.5, 1e-8);
  }
}

TEST(ShootingExtensible, StiffLimitRecoversTheElastica) {
  // EA = GAs = 1e15 runs the Reissner right-hand side; its answer must be the elastica's (the
  // other right-hand side) to the solver tolerance.
  ShootingSolver::Options so;
  so.strategy = ShootingStrategy::kContinuation;
  for (const auto& [Fx, Fy, M] : {std::array<double, 3>{-2.0, 3.0, 0.5},
                                  std::array<double, 3>{1.0, -4.0, 0.0},
                                  std::array<double, 3>{0.0, 0.0, 4.0}}) {
    SegmentChain plain;
    plain.segments.push_back(FlexibleSegment(1.0, 1.0));
    plain.tip_load = TipLoad{Fx, Fy, M, 0.0};
    SegmentChain stiff = plain;
    std::get<FlexibleSegment>(stiff.segments[0]).EA = 1e15;
    std::get<FlexibleSegment>(stiff.segments[0]).GAs = 1e15;
    const ShootingResult a = ShootingSolver(so).solve(plain);
    const ShootingResult b = ShootingSolver(so).solve(stiff);
    ASSERT_TRUE(a.converged() && b.converged()) << a.message << b.message;
    EXPECT_NEAR(a.tip.x, b.tip.x, 1e-10);
    EXPECT_NEAR(a.tip.y, b.tip.y, 1e-10);
    EXPECT_NEAR(a.tip.theta, b.tip.theta, 1e-10);
  }
  // And the stretch vanishes like 1/EA.
  double previous = 0.0;
  for (double EA : {1e3, 1e4, 1e5}) {
    SegmentChain chain;
    FlexibleSegment f(1.0, 1.0);
    f.EA = EA;
    chain.segments.push_back(f);
    chain.tip_load = TipLoad{-1.0, 2.0, 0.0, 0.0};
    const ShootingResult r = ShootingSolver(so).solve(chain);
    SegmentChain plain = chain;
    std::get<FlexibleSegment>(plain.segments[0]).EA = std::numeric_limits<double>::infinity();
    const ShootingResult q = ShootingSolver(so).solve(plain);
    const double difference = std::hypot(r.tip.x - q.tip.x, r.tip.y - q.tip.y);
    if (previous > 0.0) EXPECT_NEAR(previous / difference, 10.0, 0.05);
    previous = difference;
  }
}

SegmentChain loaded_chain(double kappa0, double M, double EA, double qy, double Fx, double Fy) {
  SegmentChain chain;
  FlexibleSegment f(1.0, 2.0, {}, kappa0);
  f.EA = EA;
  f.qy = qy;
  chain.segments.push_back(f);
  chain.tip_load = TipLoad{Fx, Fy, M, 0.0};
  return chain;
}

TEST(ShootingDistributed, CurvatureIdentityAcrossCodePaths) {
  // m = EI (theta' - kappa0): m + kappa0 EI obeys the straight beam's equations, so a free tip of
  // the curved beam with tip moment M is the straight beam's with M + kappa0 EI (issue 29).
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 12; ++trial) {
    const double kappa0 = 1.2 * u(rng), M = u(rng), Fx = 2.0 * u(rng), Fy = 2.0 * u(rng);
    const double qy = trial % 2 == 0 ? 1.5 * u(rng) : 0.0;
    const double EA = trial % 3 == 0 ? 300.0 : std::numeric_limits<double>::infinity();
    const double EI = 2.0;
    const ShootingResult curved = ShootingSolver().solve(loaded_chain(kappa0, M, EA, qy, Fx, Fy));
    const ShootingResult straight =
        ShootingSolver().solve(loaded_chain(0.0, M + kappa0 * EI, EA, qy, Fx, Fy));
    ASSERT_TRUE(curved.converged() && straight.converged()) << curved.message << straight.message;
    EXPECT_NEAR(curved.tip.x, straight.tip.x, 1e-10) << "trial " << trial;
    EXPECT_NEAR(curved.tip.y, straight.tip.y, 1e-10) << "trial " << trial;
    EXPECT_NEAR(curved.tip.theta, straight.tip.theta, 1e-10) << "trial " << trial;
  }
}

TEST(ShootingExtensible, SeededRandomAgainstDormandPrince) {
  std::mt19937 rng(2029);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_real_distribution<double> decade(2.0, 6.0);
  double worst = 0.0;
  for (int trial = 0; trial < 24; ++trial) {
    SegmentChain chain;
    FlexibleSegment f(1.0, 1.0);
    f.EA = std::pow(10.0, decade(rng));  // EA L^2/EI in [1e2, 1e6]
    if (trial % 2 == 1) f.GAs = f.EA / 2.6;
    if (trial % 3 == 0) f.qy = 3.0 * u(rng);
    if (trial % 4 == 1) f.q_follower = 2.0 * u(rng);
    chain.segments.push_back(f);
    chain.tip_load = TipLoad{3.0 * u(rng), 3.0 * u(rng), u(rng), 0.0};
    if (trial % 5 == 2) {
      chain.end = EndCondition::kGuided;
      chain.tip_load.M = 0.0;
    }
    ShootingSolver::Options a;
    a.strategy = ShootingStrategy::kContinuation;
    ShootingSolver::Options b = a;
    b.backend = ElasticaIntegrator::Backend::kDormandPrince;
    const ShootingResult ra = ShootingSolver(a).solve(chain);
    const ShootingResult rb = ShootingSolver(b).solve(chain);
    ASSERT_TRUE(ra.converged() && rb.converged())
        << "trial " << trial << ": " << ra.message << " / " << rb.message;
    const double d = std::max({std::abs(ra.tip.x - rb.tip.x),
                               std::abs(ra.tip.y - rb.tip.y),
                               std::abs(ra.tip.theta - rb.tip.theta),
                               std::abs(ra.reaction.M - rb.reaction.M)});
    worst = std::max(worst, d);
    EXPECT_LE(d, 1e-8) << "trial " << trial << " EA " << f.EA;
  }
  RecordProperty("worst_difference", std::to_string(worst));
}

TEST(ShootingDistributed, RefusedWhereNotModelled) {
  SegmentChain chain;
  FlexibleSegment f(1.0, 1.0);
  f.q_follower = 1.0;
  chain.segments.push_back(f);
  EXPECT_THROW(ChainAlgorithmSolver().solve(chain), InvalidInput);
  ShootingSolver::Options cv;
  cv.backend = ElasticaIntegrator::Backend::kCvodes;
  EXPECT_FALSE(ShootingSolver(cv).solve(chain).converged());
  FlexibleSegment bad(1.0, 1.0);
  bad.EA = -1.0;
  chain.segments = {bad};
  EXPECT_THROW(chain.validate(), InvalidInput);
  bad.EA = std::numeric_limits<double>::infinity();
  bad.q_profile = {{1.0, 0.0}};
  chain.segments = {bad};
  EXPECT_THROW(chain.validate(), InvalidInput);
}

}  // namespace
}  // namespace flexure
