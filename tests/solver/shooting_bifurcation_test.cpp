// What is checked against what: the special points of the shooting continuation path
// (continuation.h), branch switching, displacement control, step control and path shapes.
//  * bifurcations of straight columns under a pure axial tip force, located on the path, against
//    the closed-form critical loads: cantilever (2k - 1)^2 pi^2/4 (two below P = 30), guided end
//    pi^2 (sway, no rotation), clamped end on a transverse roller (slider) x^2 with tan x = x
//    (root found here by bisection), all to 1e-8 relative;
//  * folds against the elliptic solver's first_limit_load_factor on seeded random end loads, and
//    the fold of n = 0, alpha2 = 10, mu = -2 pi against an independent maximisation of lambda
//    over the root moment m0 (each m0 solved for lambda by Newton), to 1e-8; the row marked as a
//    limit point holds the largest (smallest) load factor of its neighbourhood;
//  * the buckled cantilever and guided column reached by switching at the first bifurcation
//    against the elastica of a pure end force: for the cantilever K(k) = sqrt(P L^2/EI),
//    x = 2E/K - 1, y = 2k/K (Timoshenko & Gere §2.7); the guided column is two such half-length
//    cantilevers (antisymmetry), to 1e-8; the clamped-clamped beam's first mode (four quarter
//    waves: P = 16 K^2) reached from its second-mode path, to 1e-5 (its tip offset's effect);
//  * displacement control of a guided beam moved transversely: the support force against the
//    linear stiffness 12 EI/L^3 at small deflection, and every path point against a force-
//    controlled shooting solve with the path's force (tip y to 1e-9);
//  * the clamped-clamped beam's switch on all four combinations of offset sign and branch side
//    (issue 27: two of them stopped next to the bifurcation): each reaches the first mode, and
//    the half-branch of one offset is the mirror image (y -> -y) of the opposite half-branch of
//    the other offset, point by point; every point's stability verdict under its own held
//    coordinates (PathPoint::held) is stable, critical at the bifurcation, unstable past it on
//    the second mode;
//  * step control: no arclength step above max_step, no load-factor step above max_load_step;
//  * shapes: the path's last shape against ShootingSolver's shape, and its moment from statics
//    against m = mu (end moment circle) and m(s) = Fy (x_tip - x(s)) (tip force).
#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_ellint.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "flexure/solver/common/gsl_guard.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/elliptic/elliptic_solver.h"
#include "flexure/solver/shooting/elastica_integrator.h"
#include "flexure/solver/shooting/path_point_stability.h"
#include "flexure/solver/shooting/shooting_problem.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {
namespace {

constexpr double kPi = std::numbers::pi;
// Issue requirement: special points to 1e-8 in the load factor (measured: 1e-12 and better).
constexpr double kLocation = 1e-8;
// Path states and closed forms: the Newton tolerance 1e-10 times O(1) factors.
constexpr double kState = 1e-8;

SegmentChain axial_column(double P, EndCondition end) {
  SegmentChain c = uniform_cantilever(EndLoad{-P, 0.0, 0.0});
  c.end = end;
  return c;
}

std::vector<double> bifurcation_loads(const LoadPath& path, double P) {
  std::vector<double> loads;
  for (const SpecialPoint& sp : path.special_points) {
    EXPECT_EQ(sp.kind, SpecialPointKind::kBifurcation);
    EXPECT_TRUE(sp.located);
    loads.push_back(sp.lambda * P);
  }
  return loads;
}

// Smallest positive root of tan x = x above pi (bisection on sin x - x cos x in (pi, 3 pi / 2)).
double tan_x_equals_x() {
  double lo = kPi, hi = 1.5 * kPi - 1e-12;
  auto f = [](double x) { return std::sin(x) - x * std::cos(x); };
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    ((f(lo) > 0.0) == (f(mid) > 0.0) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double K_of(double k) {
  gsl_sf_result r;
  EXPECT_EQ(gsl_sf_ellint_Kcomp_e(k, GSL_PREC_DOUBLE, &r), GSL_SUCCESS);
  return r.val;
}
double E_of(double k) {
  gsl_sf_result r;
  EXPECT_EQ(gsl_sf_ellint_Ecomp_e(k, GSL_PREC_DOUBLE, &r), GSL_SUCCESS);
  return r.val;
}
// k with K(k) = target (K rises from pi/2 at k = 0), by bisection.
double modulus_for(double target) {
  double lo = 0.0, hi = 1.0 - 1e-15;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (K_of(mid) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(ShootingBifurcation, CantileverColumnPassesBothEulerLoadsBelowThirty) {
  const double P = 30.0;
  const LoadPath path = ShootingSolver().load_path(axial_column(P, EndCondition::kFree));
  ASSERT_TRUE(path.converged()) << path.message;
  EXPECT_EQ(path.limit_points, 0);
  ASSERT_EQ(path.bifurcation_points, 2);  // (2k - 1)^2 pi^2/4: 2.467, 22.21; the third is 61.7
  const std::vector<double> loads = bifurcation_loads(path, P);
  ASSERT_EQ(loads.size(), 2u);
  EXPECT_NEAR(loads[0] / (kPi * kPi / 4.0), 1.0, kLocation);
  EXPECT_NEAR(loads[1] / (9.0 * kPi * kPi / 4.0), 1.0, kLocation);
  // Each is a row of its own (status 4), between the rows before and after it.
  for (const SpecialPoint& sp : path.special_points) {
    ASSERT_GE(sp.index, 1);
    ASSERT_EQ(sp.index_after, sp.index + 1);
    const PathPoint& p = path.points[sp.index];
    EXPECT_EQ(p.status, PathStatus::kBifurcation);
    EXPECT_DOUBLE_EQ(p.lambda, sp.lambda);
    EXPECT_LT(path.points[sp.index - 1].lambda, sp.lambda);
    EXPECT_GT(path.points[sp.index_after].lambda, sp.lambda);
    // Still the straight column, with the clamp holding the axial force.
    EXPECT_NEAR(sp.tip.x, 1.0, kState);
    EXPECT_NEAR(sp.tip.y, 0.0, kState);
    EXPECT_NEAR(sp.reaction.Fx, sp.lambda * P, kState);
  }
}

TEST(ShootingBifurcation, GuidedAndSliderColumnsBuckleAtTheirClosedForms) {
  const double P = 30.0;
  const LoadPath guided = ShootingSolver().load_path(axial_column(P, EndCondition::kGuided));
  ASSERT_TRUE(guided.converged()) << guided.message;
  const std::vector<double> g = bifurcation_loads(guided, P);
  ASSERT_EQ(g.size(), 1u);  // pi^2 = 9.87; the next, 4 pi^2 = 39.5, is beyond P
  EXPECT_NEAR(g[0] / (kPi * kPi), 1.0, kLocation);

  // Clamped, the far end on a roller that holds y (a slider end): x^2 with tan x = x (20.19).
  const LoadPath slider = ShootingSolver().load_path(axial_column(P, EndCondition::kSlider));
  ASSERT_TRUE(slider.converged()) << slider.message;
  const std::vector<double> s = bifurcation_loads(slider, P);
  ASSERT_EQ(s.size(), 1u);
  const double x = tan_x_equals_x();
  EXPECT_NEAR(s[0] / (x * x), 1.0, kLocation);
}

TEST(ShootingBifurcation, FoldsAgreeWithTheEllipticSolverOnSeededLoads) {
  // Seeded random end loads; those where the elliptic solver's proportional path folds.
  std::mt19937 rng(27);
  std::uniform_real_distribution<double> n_of(-3.0, 3.0), alpha2_of(1.0, 20.0),
      mu_of(-3.0 * kPi, 3.0 * kPi);
  int compared = 0;
  for (int i = 0; i < 200; ++i) {
    const double n = n_of(rng);  // drawn in this order (argument order is unspecified)
    const double alpha2 = alpha2_of(rng);
    const double mu = mu_of(rng);
    const EndLoad load = EndLoad::howell(n, alpha2, mu);
    const EllipticResult e = EllipticSolver().solve(load);
    if (!e.converged() || e.limit_points == 0) continue;
    const LoadPath path = ShootingSolver().load_path(uniform_cantilever(load));
    ASSERT_TRUE(path.converged()) << path.message;
    ASSERT_GE(path.limit_points, 1);
    ++compared;
    EXPECT_NEAR(path.first_limit_load_factor, e.first_limit_load_factor, kLocation)
        << "Fx = " << load.Fx << ", Fy = " << load.Fy << ", mu = " << load.mu;
    // The first fold is a row of its own, marked where it happens: the largest load factor of
    // the path up to the row after it.
    const SpecialPoint& fold = path.special_points.front();
    ASSERT_EQ(fold.kind, SpecialPointKind::kLimitPoint);
    ASSERT_GE(fold.index, 1);
    EXPECT_EQ(path.points[fold.index].status, PathStatus::kLimitPoint);
    for (int k = 0; k <= fold.index_after; ++k) {
      EXPECT_LE(path.points[k].lambda, fold.lambda + 1e-15) << "row " << k;
    }
  }
  EXPECT_GE(compared, 15);  // 20 of the 200 seeded loads fold (one of them twice, an S within
                            // 0.15 rad of tip angle: found by the level control of the step)
}

TEST(ShootingBifurcation, FoldIsTheMaximumOfTheLoadFactorOverTheRootMoment) {
  // n = 0, alpha2 = 10, mu = -2 pi: along the path lambda(m0) (each m0 solved for lambda and the
  // cut states by Newton) has its maximum at the fold; golden-section search over m0.
  const SegmentChain chain = uniform_cantilever(EndLoad::howell(0.0, 10.0, -2.0 * kPi));
  const LoadPath path = ShootingSolver().load_path(chain);
  ASSERT_TRUE(path.converged()) << path.message;
  ASSERT_GE(path.limit_points, 1);
  const ShootingProblem problem(chain);
  ElasticaIntegrator integrator(ElasticaIntegrator::Options{});
  const Eigen::VectorXd z_fold = path.special_points.front().z;
  auto lambda_of = [&](double m0) {
    Eigen::VectorXd z = z_fold;
    z[0] = m0;
    double lambda = path.first_limit_load_factor;
    const int nz = problem.size();
    for (int it = 0; it < 30; ++it) {
      ShootingEvaluation e;
      EXPECT_TRUE(problem.evaluate(z, lambda, true, true, integrator, e));
      Eigen::MatrixXd A(nz, nz);  // unknowns: lambda and everything but m0
      A.col(0) = e.d_lambda;
      A.rightCols(nz - 1) = e.jacobian.rightCols(nz - 1);
      const Eigen::VectorXd d = A.fullPivLu().solve(-e.residual);
      lambda += d[0];
      z.tail(nz - 1) += d.tail(nz - 1);
      if (d.norm() < 1e-15) break;
    }
    return lambda;
  };
  double a = z_fold[0] - 1e-3, b = z_fold[0] + 1e-3;
  for (int i = 0; i < 60; ++i) {
    const double m1 = a + 0.381966 * (b - a), m2 = a + 0.618034 * (b - a);
    if (lambda_of(m1) > lambda_of(m2)) {
      b = m2;
    } else {
      a = m1;
    }
  }
  EXPECT_NEAR(path.first_limit_load_factor, lambda_of(0.5 * (a + b)), kLocation);
}

TEST(ShootingBifurcation, BranchSwitchingReachesTheBuckledCantileverOfTheClosedForm) {
  disable_gsl_abort();
  const double P = 3.0;
  ShootingSolver::Options options;
  options.continuation.switch_at_bifurcation = 1;
  const LoadPath up = ShootingSolver(options).load_path(axial_column(P, EndCondition::kFree));
  ASSERT_TRUE(up.converged()) << up.message;
  ASSERT_TRUE(up.switched_branch);
  ASSERT_EQ(up.special_points.size(), 1u);
  EXPECT_TRUE(up.special_points[0].switched);
  EXPECT_NEAR(up.special_points[0].lambda * P / (kPi * kPi / 4.0), 1.0, kLocation);
  // K(k) = sqrt(P) (length 1, EI 1), k = sin(theta0 / 2).
  const double k = modulus_for(std::sqrt(P));
  const double K = K_of(k), E = E_of(k);
  const PathPoint& end = up.points.back();
  EXPECT_EQ(end.branch, 1);
  EXPECT_NEAR(end.tip.theta, 2.0 * std::asin(k), kState);
  EXPECT_NEAR(end.tip.x, 2.0 * E / K - 1.0, kState);
  EXPECT_NEAR(end.tip.y, 2.0 * k / K, kState);  // branch_side +1: the tip moves to +y
  // The other side is the mirror image.
  options.continuation.branch_side = -1;
  const LoadPath down = ShootingSolver(options).load_path(axial_column(P, EndCondition::kFree));
  ASSERT_TRUE(down.converged()) << down.message;
  EXPECT_NEAR(down.points.back().tip.y, -2.0 * k / K, kState);
  EXPECT_NEAR(down.points.back().tip.x, 2.0 * E / K - 1.0, kState);
  // Every point on the buckled branch: the same closed form at its own load (beyond the first
  // ones next to the bifurcation, where the state is still within the Newton tolerance of it).
  for (const PathPoint& p : up.points) {
    if (p.branch != 1 || p.lambda * P < 1.001 * kPi * kPi / 4.0) continue;
    const double kp = modulus_for(std::sqrt(p.lambda * P));
    EXPECT_NEAR(p.tip.y, 2.0 * kp / K_of(kp), kState) << "P = " << p.lambda * P;
  }
}

TEST(ShootingBifurcation, BranchSwitchingReachesTheBuckledGuidedColumn) {
  disable_gsl_abort();
  // The guided column buckles antisymmetrically: two cantilevers of length 1/2 meeting at the
  // inflection point, each with K(k) = sqrt(P) / 2.
  const double P = 30.0;
  ShootingSolver::Options options;
  options.continuation.switch_at_bifurcation = 1;
  const LoadPath path = ShootingSolver(options).load_path(axial_column(P, EndCondition::kGuided));
  ASSERT_TRUE(path.converged()) << path.message;
  ASSERT_TRUE(path.switched_branch);
  const double k = modulus_for(0.5 * std::sqrt(P));
  const double K = K_of(k), E = E_of(k);
  EXPECT_NEAR(path.points.back().tip.x, 2.0 * E / K - 1.0, kState);
  EXPECT_NEAR(path.points.back().tip.y, 2.0 * k / K, kState);
  EXPECT_NEAR(path.points.back().tip.theta, 0.0, kState);
}

TEST(ShootingBifurcation, ClampedClampedBeamSwitchesToItsFirstMode) {
  disable_gsl_abort();
  // Both ends clamped, the far end moved to x = 0.9 with a tip offset y = 1e-3 (a straight beam
  // cannot start shortening): proportional loading follows the antisymmetric second mode and
  // passes the first mode's bifurcation at 4 pi^2 early in its second stage; switching there gives
  // the symmetric first mode: four quarter waves, each a cantilever of length 1/4 under P, so
  // P = 16 K(k)^2 with x = 2E/K - 1 = 0.9 and the clamp moment 2 k sqrt(P). The offset shifts
  // these by about 1e-6 relative.
  SegmentChain chain = uniform_cantilever(EndLoad{});
  chain.end = EndCondition::kFixed;
  chain.prescribed.x = 0.9;
  chain.prescribed.y = 1e-3;
  ShootingSolver::Options options;
  options.continuation.switch_at_bifurcation = 1;
  const LoadPath path = ShootingSolver(options).load_path(chain);
  ASSERT_TRUE(path.converged()) << path.message;
  ASSERT_TRUE(path.switched_branch);
  const SpecialPoint& b = path.special_points.front();
  EXPECT_EQ(b.kind, SpecialPointKind::kBifurcation);
  EXPECT_EQ(b.stage, 2);
  EXPECT_NEAR(b.reaction.Fx / (4.0 * kPi * kPi), 1.0, 1e-5);
  double lo = 0.0, hi = 0.99;  // E(k)/K(k) = 0.95 falls with k
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (E_of(mid) / K_of(mid) > 0.95 ? lo : hi) = mid;
  }
  const double k = 0.5 * (lo + hi);
  const double P = 16.0 * K_of(k) * K_of(k);
  const PathPoint& end = path.points.back();
  EXPECT_NEAR(end.tip.x, 0.9, 1e-9);
  EXPECT_NEAR(end.reaction.Fx / P, 1.0, 1e-5);
  EXPECT_NEAR(std::abs(end.reaction.M) / (2.0 * k * std::sqrt(P)), 1.0, 1e-5);
  // Without switching the path ends on the second mode (the clamp moment nearly vanishes).
  const LoadPath second = ShootingSolver().load_path(chain);
  ASSERT_TRUE(second.converged()) << second.message;
  EXPECT_GT(second.points.back().reaction.Fx, 80.0);
}

// Issue 27: with the offset y = +1e-3, the half-branch with branch_side -1 (and with y = -1e-3 the
// one with +1) stopped right after the switch: the first step left the bifurcation along the null
// vector orthogonal to the path, which meets the other branch at 70 degrees here, and the branch
// bends to the load factor within 1e-7 of the point. The branch tangent now comes from the
// algebraic bifurcation equation and the step floor from the switch's own scale.
LoadPath clamped_clamped_switch(double y, int side) {
  SegmentChain chain = uniform_cantilever(EndLoad{});
  chain.end = EndCondition::kFixed;
  chain.prescribed.x = 0.9;
  chain.prescribed.y = y;
  ShootingSolver::Options options;
  options.continuation.switch_at_bifurcation = 1;
  options.continuation.branch_side = side;
  return ShootingSolver(options).load_path(chain);
}

TEST(ShootingBifurcation, ClampedClampedBeamReachesItsFirstModeOnEitherSide) {
  disable_gsl_abort();
  double lo = 0.0, hi = 0.99;  // the first mode at x = 0.9: four quarter waves (test above)
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (E_of(mid) / K_of(mid) > 0.95 ? lo : hi) = mid;
  }
  const double k = 0.5 * (lo + hi);
  const double P = 16.0 * K_of(k) * K_of(k);
  SegmentChain chain = uniform_cantilever(EndLoad{});
  chain.end = EndCondition::kFixed;
  chain.prescribed.x = 0.9;
  for (const double y : {1e-3, -1e-3}) {
    chain.prescribed.y = y;
    for (const int side : {1, -1}) {
      const LoadPath path = clamped_clamped_switch(y, side);
      ASSERT_TRUE(path.converged()) << "y = " << y << ", side " << side << ": " << path.message;
      ASSERT_TRUE(path.switched_branch);
      const PathPoint& end = path.points.back();
      EXPECT_NEAR(end.tip.x, 0.9, 1e-9);
      EXPECT_NEAR(end.reaction.Fx / P, 1.0, 1e-5);
      EXPECT_NEAR(std::abs(end.reaction.M) / (2.0 * k * std::sqrt(P)), 1.0, 1e-5);
      // The side: the clamp's moment m(0) (the clamp applies -m(0)) grows for side +1.
      const double m0_change = -(end.reaction.M - path.special_points.front().reaction.M);
      EXPECT_GT(m0_change * side, 0.0) << "y = " << y << ", side " << side;
      // Verdicts under the coordinates each point holds: stage 1 (x released) and the first
      // mode are stable with x, y and the angle held; the bifurcation itself is critical.
      for (const PathPoint& p : path.points) {
        const Stability v = path_point_stability(chain, p, p.held);
        const StabilityKind expected = p.status == PathStatus::kBifurcation
                                           ? StabilityKind::kCritical
                                           : StabilityKind::kStable;
        EXPECT_EQ(v.kind, expected) << "y = " << y << ", side " << side << ", stage " << p.stage
                                    << ", load factor " << p.lambda << ": " << v.message;
        EXPECT_EQ(p.held.x, p.stage == 2);
        EXPECT_TRUE(p.held.y && p.held.theta);
      }
    }
  }
  // Mirror images: (y, side -1) against (-y, side +1). The mirror y -> -y maps one problem onto
  // the other and m(0) onto -m(0); the step control sees the same path up to rounding, so the
  // points correspond one to one (the load factors drift apart by rounding, measured 4.6e-7).
  const LoadPath a = clamped_clamped_switch(1e-3, -1);
  const LoadPath b = clamped_clamped_switch(-1e-3, 1);
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    const PathPoint& p = a.points[i];
    const PathPoint& q = b.points[i];
    EXPECT_EQ(p.stage, q.stage);
    EXPECT_EQ(p.status, q.status);
    EXPECT_NEAR(p.lambda, q.lambda, 2e-6) << i;
    EXPECT_NEAR(p.tip.x, q.tip.x, 2e-7) << i;
    EXPECT_NEAR(p.tip.y, -q.tip.y, 1e-12) << i;
    EXPECT_NEAR(p.tip.theta, -q.tip.theta, 1e-12) << i;
    EXPECT_NEAR(p.reaction.Fx, q.reaction.Fx, 1e-5 * (1.0 + std::abs(p.reaction.Fx))) << i;
    EXPECT_NEAR(p.reaction.Fy, -q.reaction.Fy, 1e-5 * (1.0 + std::abs(p.reaction.Fy))) << i;
    EXPECT_NEAR(p.reaction.M, -q.reaction.M, 1e-5 * (1.0 + std::abs(p.reaction.M))) << i;
  }
  // The ends, both at load factor 1: to the Newton tolerance.
  EXPECT_NEAR(a.points.back().reaction.Fx, b.points.back().reaction.Fx, 1e-8);
  EXPECT_NEAR(a.points.back().reaction.M, -b.points.back().reaction.M, 1e-8);
  EXPECT_NEAR(a.special_points.front().lambda, b.special_points.front().lambda, 1e-8);
  // Without switching: past the bifurcation the second mode is unstable (index 1).
  chain.prescribed.y = 1e-3;
  const LoadPath second = ShootingSolver().load_path(chain);
  ASSERT_TRUE(second.converged()) << second.message;
  const double at = second.special_points.front().lambda;
  for (const PathPoint& p : second.points) {
    if (p.stage != 2 || p.lambda <= at) continue;
    const Stability v = path_point_stability(chain, p, p.held);
    EXPECT_EQ(v.kind, StabilityKind::kUnstable) << p.lambda << ": " << v.message;
    EXPECT_EQ(v.index, 1);
  }
}

TEST(ShootingBifurcation, NoBranchToSwitchToLeavesThePathAlone) {
  ShootingSolver::Options options;
  options.continuation.switch_at_bifurcation = 3;  // only two below P = 30
  const LoadPath path = ShootingSolver(options).load_path(axial_column(30.0, EndCondition::kFree));
  ASSERT_TRUE(path.converged()) << path.message;
  EXPECT_FALSE(path.switched_branch);
  EXPECT_EQ(path.bifurcation_points, 2);
  EXPECT_NEAR(path.points.back().tip.y, 0.0, kState);
}

TEST(ShootingBifurcation, DisplacementControlTracesTheGuidedBeamsForceCurve) {
  SegmentChain guided = uniform_cantilever(EndLoad{});
  guided.end = EndCondition::kGuided;
  ShootingSolver::Options options;
  options.continuation.max_load_step = 0.05;
  // Small deflection: the support force is the linear stiffness 12 EI/L^3 times y; the first
  // correction is relative O(y^2).
  const LoadPath small = ShootingSolver(options).controlled_path(guided, {TipCoordinate::kY, 1e-3});
  ASSERT_TRUE(small.converged()) << small.message;
  EXPECT_NEAR(small.points.back().tip.y, 1e-3, 1e-10);  // the Newton tolerance
  EXPECT_NEAR(small.points.back().tip_load.Fy / (12.0 * 1e-3), 1.0, 1e-5);
  EXPECT_NEAR(small.points.back().tip.theta, 0.0, 1e-10);
  // Large deflection: every point against a force-controlled solve with the path's force.
  const LoadPath large = ShootingSolver(options).controlled_path(guided, {TipCoordinate::kY, 0.4});
  ASSERT_TRUE(large.converged()) << large.message;
  ASSERT_GE(large.points.size(), 21u);  // the load-factor cap: at least 1/0.05 steps
  double previous_y = -1.0;
  for (const PathPoint& p : large.points) {
    EXPECT_NEAR(p.tip.y, 0.4 * p.lambda, 1e-9);  // the path parameter moves y linearly
    EXPECT_GT(p.tip.y, previous_y);
    previous_y = p.tip.y;
    if (p.tip.y == 0.0) continue;
    SegmentChain forced = uniform_cantilever(EndLoad{0.0, p.tip_load.Fy, 0.0});
    forced.end = EndCondition::kGuided;
    const ShootingResult r = ShootingSolver().solve(forced);
    ASSERT_TRUE(r.converged()) << r.message;
    EXPECT_NEAR(r.tip.y, p.tip.y, 1e-9) << "Fy = " << p.tip_load.Fy;
    EXPECT_NEAR(r.tip.x, p.tip.x, 1e-9) << "Fy = " << p.tip_load.Fy;
  }
}

TEST(ShootingBifurcation, DisplacementControlAfterAnAxialPreload) {
  // Stage 1 applies Fx = -5 (below the guided column's pi^2) with y free; stage 2 moves y. The
  // force-controlled solve with both loads must give the path's tip.
  SegmentChain guided = uniform_cantilever(EndLoad{-5.0, 0.0, 0.0});
  guided.end = EndCondition::kGuided;
  const LoadPath path = ShootingSolver().controlled_path(guided, {TipCoordinate::kY, 0.3});
  ASSERT_TRUE(path.converged()) << path.message;
  EXPECT_EQ(path.points.front().stage, 1);
  EXPECT_EQ(path.points.back().stage, 2);
  const PathPoint& end = path.points.back();
  SegmentChain forced = uniform_cantilever(EndLoad{-5.0, end.tip_load.Fy, 0.0});
  forced.end = EndCondition::kGuided;
  const ShootingResult r = ShootingSolver().solve(forced);
  ASSERT_TRUE(r.converged()) << r.message;
  EXPECT_NEAR(r.tip.y, 0.3, 1e-9);
  EXPECT_NEAR(end.tip_load.Fx, -5.0, 1e-12);
}

TEST(ShootingBifurcation, ControlledTargetsOutOfReachAndLoadedCoordinatesAreRefused) {
  SegmentChain guided = uniform_cantilever(EndLoad{});
  guided.end = EndCondition::kGuided;
  EXPECT_THROW((void)ShootingSolver().controlled_path(guided, {TipCoordinate::kY, 1.2}),
               InvalidInput);
  EXPECT_THROW((void)ShootingSolver().controlled_path(
                   guided, {TipCoordinate::kY, std::numeric_limits<double>::quiet_NaN()}),
               InvalidInput);
  SegmentChain loaded = uniform_cantilever(EndLoad{0.0, 1.0, 0.0});
  loaded.end = EndCondition::kGuided;  // Fy given: it cannot also be the support's reaction
  EXPECT_THROW((void)ShootingSolver().controlled_path(loaded, {TipCoordinate::kY, 0.2}),
               InvalidInput);
}

TEST(ShootingBifurcation, StepControlCapsArclengthAndLoadFactorSteps) {
  const SegmentChain chain = uniform_cantilever(EndLoad::howell(0.0, 3.0, 0.0));
  ShootingSolver::Options options;
  options.continuation.max_step = 0.05;
  const LoadPath fine = ShootingSolver(options).load_path(chain);
  ASSERT_TRUE(fine.converged()) << fine.message;
  for (const PathPoint& p : fine.points) EXPECT_LE(p.step, 0.05 + 1e-15);
  options = {};
  options.continuation.max_load_step = 1.0 / 40.0;
  const LoadPath dense = ShootingSolver(options).load_path(chain);
  ASSERT_TRUE(dense.converged()) << dense.message;
  EXPECT_GE(dense.points.size(), 41u);
  for (std::size_t i = 1; i < dense.points.size(); ++i) {
    EXPECT_LE(dense.points[i].lambda - dense.points[i - 1].lambda, 1.0 / 40.0 + 1e-12);
  }
  // Both end where the default path ends.
  const LoadPath plain = ShootingSolver().load_path(chain);
  EXPECT_NEAR(dense.points.back().tip.y, plain.points.back().tip.y, 1e-10);
  EXPECT_NEAR(fine.points.back().tip.y, plain.points.back().tip.y, 1e-10);
  // Invalid settings are refused by name.
  options = {};
  options.continuation.max_step = 0.0;
  EXPECT_THROW((void)ShootingSolver(options).load_path(chain), InvalidInput);
  options = {};
  options.continuation.max_load_step = -1.0;
  EXPECT_THROW((void)ShootingSolver(options).load_path(chain), InvalidInput);
  options = {};
  options.continuation.branch_side = 0;
  EXPECT_THROW((void)ShootingSolver(options).load_path(chain), InvalidInput);
  options = {};
  options.continuation.shape_points = 1;
  EXPECT_THROW((void)ShootingSolver(options).load_path(chain), InvalidInput);
}

TEST(ShootingBifurcation, PathShapesAndMomentsAgreeWithTheSolverAndStatics) {
  ShootingSolver::Options options;
  options.continuation.shape_points = 21;
  options.shape_points = 21;
  // Tip force: m(s) = Fy (x_tip - x(s)) (statics of the part beyond s).
  const SegmentChain force = uniform_cantilever(EndLoad::howell(0.0, 4.0, 0.0));
  const LoadPath path = ShootingSolver(options).load_path(force);
  ASSERT_TRUE(path.converged()) << path.message;
  const ShootingResult r = ShootingSolver(options).solve(force);
  ASSERT_TRUE(r.converged()) << r.message;
  const PathPoint& end = path.points.back();
  ASSERT_EQ(end.shape.size(), 21u);
  ASSERT_EQ(end.moment.size(), 21u);
  for (int i = 0; i < 21; ++i) {
    EXPECT_NEAR(end.shape[i].x, r.shape[i].x, kState);
    EXPECT_NEAR(end.shape[i].y, r.shape[i].y, kState);
    EXPECT_NEAR(end.shape[i].theta, r.shape[i].theta, kState);
    EXPECT_NEAR(end.moment[i], 4.0 * (end.tip.x - end.shape[i].x), kState);
  }
  EXPECT_NEAR(end.moment.front(), -end.reaction.M, kState);  // the clamp's moment
  for (const PathPoint& p : path.points) EXPECT_EQ(p.shape.size(), 21u);
  // End moment: a circle with the constant moment mu.
  const LoadPath circle = ShootingSolver(options).load_path(uniform_cantilever({0.0, 0.0, 2.0}));
  ASSERT_TRUE(circle.converged()) << circle.message;
  for (const PathPoint& p : circle.points) {
    for (double m : p.moment) EXPECT_NEAR(m, 2.0 * p.lambda, kState);
  }
}

TEST(ShootingBifurcation, ShapeMomentsCrossNodeLoadsAndRigidLinks) {
  // A flexure, a rigid link and a flexure, loaded at the middle node and the tip: the moment at
  // the tip end of the shape is the tip moment, at the root the clamp's, and just past the node
  // it drops by the node's moment.
  SegmentChain chain;
  chain.segments = {FlexibleSegment{0.5, 1.0, {}, 0.0},
                    RigidSegment{0.3, 0.0},
                    FlexibleSegment{0.5, 1.0, {}, 0.0}};
  chain.node_loads = {NodeLoad{2, 0.5, -1.0, 0.4}};
  chain.tip_load = TipLoad{0.0, 1.5, 0.3, 0.0};
  ShootingSolver::Options options;
  options.continuation.shape_points = 27;  // s = 0.05 k: node 1 (s = 0.5) is a shape point
  const LoadPath path = ShootingSolver(options).load_path(chain);
  ASSERT_TRUE(path.converged()) << path.message;
  const PathPoint& end = path.points.back();
  EXPECT_NEAR(end.moment.front(), -end.reaction.M, kState);
  EXPECT_NEAR(end.moment.back(), 0.3, kState);
  // Across the rigid link (s in [0.5, 0.8]) the moment is linear in the position.
  const ShapePoint& a = end.shape[10];
  const ShapePoint& b = end.shape[15];
  ASSERT_NEAR(a.s, 0.5, 1e-12);
  ASSERT_NEAR(b.s, 0.75, 1e-12);
  const Eigen::Vector2d N(-end.reaction.Fx, -end.reaction.Fy);  // internal force before node 2
  EXPECT_NEAR(end.moment[15] - end.moment[10], N.x() * (b.y - a.y) - N.y() * (b.x - a.x), kState);
  // Along the link the tangent is constant (a straight link).
  EXPECT_NEAR(end.shape[12].theta, a.theta, 1e-12);
}

}  // namespace
}  // namespace flexure
