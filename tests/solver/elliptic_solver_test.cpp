// What is checked against what:
// - Howell's worked example (§2.9.2) and exact tables of Howell eqs. 2.90-2.98 (n = 0, and
//   n = 1, -1, 2.5 at theta0 = 0.6 rad; values computed with mpmath) -> forward and inverse
//   elliptic solves, to the tabulated digits.
// - Closed form of the end-moment beam (Howell eqs. 2.53, 2.59, 2.64), including mu = 2 pi.
// - Small-load linear theory: b/l -> alpha2/3 with error O(alpha2^3), 1 - a/l -> alpha2^2/15.
// - An independent RK4 integration of the elastica IVP started with the solver's root moment
//   (tests/support/elastica_reference.h): tip position, tip angle and tip moment, for end moments
//   with and against the force, inflection points, tip angles past 180 deg, tension and
//   compression.
// - Statics: root moment = mu + a Fy - b Fx.
// - Mirror symmetry, forward/inverse agreement, the proportional-loading branch when several
//   equilibria exist, and bad input.
#include "flexure/solver/elliptic/elliptic_solver.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "flexure/solver/common/errors.h"
#include "flexure/solver/elliptic/elastica_closed_form.h"
#include "flexure/solver/shooting/shooting_solver.h"
#include "tests/support/elastica_reference.h"

namespace flexure {
namespace {

constexpr double kPi = std::numbers::pi;
// The reference values carry 8 significant digits: half a unit in the last place.
constexpr double kOracleRelTol = 6e-8;
// Agreement of the closed form with itself (forward vs inverse, statics): round-off level.
constexpr double kSelfConsistency = 1e-12;
// RK4 + Richardson with 8000 steps: truncation error ~1e-12 for |F| <= 30.
constexpr double kIvpTol = 1e-9;

void expect_rel(double computed, double reference, double tol, const char* what) {
  EXPECT_NEAR(computed, reference, tol * std::fabs(reference)) << what;
}

TEST(EllipticSolver, ReproducesHowellWorkedExampleFromTipAngle) {
  // Howell §2.9.2 example: theta0 = 1 rad, n = 0 -> alpha = 1.7569869, a/l = 0.7383564,
  // b/l = 0.6103718 (eqs. 2.90-2.98 recomputed; the book prints alpha = 1.76, a = 74, b = 61 mm).
  const EllipticSolver solver;
  const EllipticResult r = solver.solve_for_tip_angle(0.0, 1.0);
  ASSERT_TRUE(r.converged()) << r.message;
  expect_rel(std::sqrt(r.load.Fy), 1.7569869, kOracleRelTol, "alpha");
  expect_rel(r.tip.a_over_l, 0.7383564, kOracleRelTol, "a/l");
  expect_rel(r.tip.b_over_l, 0.6103718, kOracleRelTol, "b/l");
  // P = alpha^2 EI / l^2 for the aluminium rod: E = 71.7 GPa, d = 2 mm, l = 0.1 m -> 17.3839 N.
  const double I = kPi * std::pow(2e-3, 4) / 64.0;
  EXPECT_NEAR(r.load.Fy * 71.7e9 * I / (0.1 * 0.1), 17.3839, 5e-4);
}

TEST(EllipticSolver, ReproducesExactOracleTableForVerticalLoad) {
  // Exact n = 0 table: Howell eqs. 2.90-2.98 evaluated with mpmath.
  struct Row {
    double theta0, alpha2, a, b;
  };
  const std::vector<Row> rows = {{0.25, 0.51169274, 0.98336262, 0.16572770},
                                 {0.50, 1.0996750, 0.93377750, 0.32590739},
                                 {0.75, 1.8779867, 0.85201234, 0.47544836},
                                 {1.00, 3.0870030, 0.73835640, 0.61037180},
                                 {1.25, 5.4691778, 0.58909259, 0.72947569},
                                 {1.40, 8.8064153, 0.47307789, 0.79655336}};
  const EllipticSolver solver;
  for (const Row& row : rows) {
    const EllipticResult inv = solver.solve_for_tip_angle(0.0, row.theta0);
    expect_rel(inv.load.Fy, row.alpha2, kOracleRelTol, "alpha2 (inverse)");
    expect_rel(inv.tip.a_over_l, row.a, kOracleRelTol, "a/l (inverse)");
    expect_rel(inv.tip.b_over_l, row.b, kOracleRelTol, "b/l (inverse)");
    const EllipticResult fwd = solver.solve(EndLoad::howell(0.0, row.alpha2));
    ASSERT_TRUE(fwd.converged());
    EXPECT_NEAR(fwd.tip.theta0, row.theta0, 1e-7) << "theta0 (forward) at " << row.theta0;
    expect_rel(fwd.tip.a_over_l, row.a, kOracleRelTol, "a/l (forward)");
    expect_rel(fwd.tip.b_over_l, row.b, kOracleRelTol, "b/l (forward)");
  }
}

TEST(EllipticSolver, ReproducesOracleForForceAtAnAngle) {
  // Howell eqs. 2.90-2.98 at theta0 = 0.6 rad, n = 1, -1, 2.5, with phi1 = atan2(1, -n)
  // (docs/errata.md, eq. 2.87).
  // Printed to 7 decimals: half a unit in the last place is 5e-8.
  struct Row {
    double n, alpha, a, b;
  };
  const std::vector<Row> rows = {{1.0, 0.9439966, 0.9071300, 0.3809919},
                                 {-1.0, 1.7993680, 0.8975785, 0.4067666},
                                 {2.5, 0.7647424, 0.9086205, 0.3767408}};
  const EllipticSolver solver;
  for (const Row& row : rows) {
    const EllipticResult r = solver.solve_for_tip_angle(row.n, 0.6);
    constexpr double kHalfUnit = 5e-8;
    EXPECT_NEAR(std::sqrt(r.load.Fy), row.alpha, kHalfUnit) << "alpha at n = " << row.n;
    EXPECT_NEAR(r.tip.a_over_l, row.a, kHalfUnit) << "a/l at n = " << row.n;
    EXPECT_NEAR(r.tip.b_over_l, row.b, kHalfUnit) << "b/l at n = " << row.n;
  }
}

TEST(EllipticSolver, PureEndMomentIsACircularArcUpToAFullCircle) {
  // Howell eqs. 2.53, 2.59, 2.64: theta0 = mu, a/l = sin(mu)/mu, b/l = (1 - cos mu)/mu, the last
  // written as 2 sin^2(mu/2)/mu so that the reference itself keeps its digits at small mu.
  const EllipticSolver solver;
  for (double mu : {1e-6, 0.5, 1.0, kPi, 2.0 * kPi, 3.0 * kPi, -2.0}) {
    const EllipticResult r = solver.solve(EndLoad{0.0, 0.0, mu});
    ASSERT_TRUE(r.converged());
    EXPECT_NEAR(r.tip.theta0, mu, 1e-15);
    EXPECT_NEAR(r.tip.a_over_l, std::sin(mu) / mu, 1e-15);
    EXPECT_NEAR(r.tip.b_over_l, 2.0 * std::pow(std::sin(0.5 * mu), 2) / mu, 1e-15);
  }
  // mu = 2 pi: the beam closes into a full circle, tip back at the clamp.
  const EllipticResult full = solver.solve(EndLoad{0.0, 0.0, 2.0 * kPi});
  EXPECT_NEAR(full.tip.a_over_l, 0.0, 1e-15);
  EXPECT_NEAR(full.tip.b_over_l, 0.0, 1e-15);
}

TEST(EllipticSolver, SmallLoadsApproachLinearTheory) {
  // Linear theory: b/l = alpha2/3 and theta0 = alpha2/2; the first nonlinear correction is
  // O(alpha2^3) in b and theta0, so the relative error must fall 100-fold per decade of load.
  // Shortening: 1 - a/l = (1/2) int theta^2 ds = alpha2^2 / 15 to leading order.
  const EllipticSolver solver;
  double previous_error = 0.0;
  for (double alpha2 : {1e-1, 1e-2, 1e-3}) {
    const EllipticResult r = solver.solve(EndLoad::howell(0.0, alpha2));
    const double error = std::fabs(r.tip.b_over_l / (alpha2 / 3.0) - 1.0);
    if (previous_error > 0.0) {
      const double order = std::log10(previous_error / error);
      EXPECT_NEAR(order, 2.0, 0.05) << "at alpha2 = " << alpha2;
    }
    previous_error = error;
    EXPECT_NEAR(r.tip.theta0 / (alpha2 / 2.0), 1.0, alpha2 * alpha2);
    EXPECT_NEAR((1.0 - r.tip.a_over_l) / (alpha2 * alpha2 / 15.0), 1.0, alpha2 * alpha2 + 1e-7);
  }
}

struct IvpCase {
  double Fx, Fy, mu;
};

// Cases across the load space: tension and compression, moments with and against the force,
// inflection points, tip angles past 90 and 180 degrees, both pendulum families.
std::vector<IvpCase> ivp_cases() {
  return {
      {0.0, 3.0, 0.0},
      {-3.0, 3.0, 0.0},
      {6.0, 2.0, 0.0},
      {-10.0, 2.0, 0.0},
      {-5.0, 5.0, -2.0},
      {0.0, 10.0, -3.0},
      {30.0, 10.0, 2.0},
      {-30.0, 10.0, 6.28},
      {0.0, 20.0, 6.28},
      {-3.0, -4.0, 1.5},
      {2.0, 1.0, 2.0 * kPi},
      {-8.0, 0.0, 1.0},
      {8.0, 0.0, 1.0},
      {0.0, 1.0, -3.0},
      {0.0, 5.0, 4.0},
      {-12.0, 6.0, -1.0},
  };
}

TEST(EllipticSolver, AgreesWithIndependentIvpIntegration) {
  const EllipticSolver solver;
  for (const IvpCase& c : ivp_cases()) {
    const EllipticResult r = solver.solve(EndLoad{c.Fx, c.Fy, c.mu});
    ASSERT_TRUE(r.converged()) << r.message << " for " << c.Fx << ", " << c.Fy << ", " << c.mu;
    const testing::ElasticaState ivp =
        testing::integrate_elastica_accurate(c.Fx, c.Fy, r.root_moment);
    SCOPED_TRACE(::testing::Message() << "Fx=" << c.Fx << " Fy=" << c.Fy << " mu=" << c.mu);
    EXPECT_NEAR(ivp.x, r.tip.a_over_l, kIvpTol);
    EXPECT_NEAR(ivp.y, r.tip.b_over_l, kIvpTol);
    EXPECT_NEAR(ivp.theta, r.tip.theta0, kIvpTol);
    EXPECT_NEAR(ivp.m, c.mu, kIvpTol * std::max(1.0, std::fabs(r.root_moment)));
  }
}

TEST(EllipticSolver, RootMomentSatisfiesStatics) {
  // M(0) = M + Fy a - Fx b: moment of the tip loads about the clamp.
  const EllipticSolver solver;
  for (const IvpCase& c : ivp_cases()) {
    const EllipticResult r = solver.solve(EndLoad{c.Fx, c.Fy, c.mu});
    const double statics = c.mu + c.Fy * r.tip.a_over_l - c.Fx * r.tip.b_over_l;
    EXPECT_NEAR(r.root_moment, statics, kSelfConsistency * (1.0 + std::fabs(statics)))
        << c.Fx << ", " << c.Fy << ", " << c.mu;
  }
}

TEST(EllipticSolver, ReportsInflectionPointsAndFamilies) {
  const EllipticSolver solver;
  // A moment against the force: the curvature changes sign once inside the beam.
  const EllipticResult against = solver.solve(EndLoad{0.0, 10.0, -3.0});
  EXPECT_EQ(against.parameters.family, ElasticaFamily::kInflectional);
  EXPECT_EQ(against.inflection_points, 1);
  EXPECT_GT(against.root_moment, 0.0);  // root bends with the force, tip against it
  // A large moment with the force: curvature of one sign, family B.
  const EllipticResult with = solver.solve(EndLoad{0.0, 5.0, 4.0});
  EXPECT_EQ(with.parameters.family, ElasticaFamily::kNonInflectional);
  EXPECT_EQ(with.inflection_points, 0);
  // The shape's curvature (finite differences of theta) changes sign exactly once.
  const std::vector<ShapePoint> shape = solver.shape(against, 401);
  int sign_changes = 0;
  double previous = 0.0;
  for (std::size_t i = 1; i < shape.size(); ++i) {
    const double curvature = shape[i].theta - shape[i - 1].theta;
    if (previous != 0.0 && (curvature > 0.0) != (previous > 0.0)) ++sign_changes;
    previous = curvature;
  }
  EXPECT_EQ(sign_changes, 1);
}

TEST(EllipticSolver, ReachesTipAnglesPastHalfATurn) {
  // mu = 2 pi with a compressive force and a small transverse one: tip angle beyond 180 deg.
  const EllipticSolver solver;
  const EllipticResult r = solver.solve(EndLoad{-3.0, 1.0, 2.0 * kPi});
  ASSERT_TRUE(r.converged()) << r.message;
  EXPECT_GT(r.tip.theta0, kPi);
  const testing::ElasticaState ivp = testing::integrate_elastica_accurate(-3.0, 1.0, r.root_moment);
  EXPECT_NEAR(ivp.theta, r.tip.theta0, kIvpTol);
  EXPECT_NEAR(ivp.x, r.tip.a_over_l, kIvpTol);
}

TEST(EllipticSolver, MirrorSymmetryInFy) {
  // Mirroring about the x axis maps (Fx, Fy, mu) to (Fx, -Fy, -mu) and (a, b, theta0) to
  // (a, -b, -theta0); in Howell's parameters that is (n, alpha2) -> (-n, -alpha2).
  const EllipticSolver solver;
  for (const IvpCase& c : ivp_cases()) {
    const EllipticResult up = solver.solve(EndLoad{c.Fx, c.Fy, c.mu});
    const EllipticResult down = solver.solve(EndLoad{c.Fx, -c.Fy, -c.mu});
    EXPECT_NEAR(up.tip.a_over_l, down.tip.a_over_l, 1e-14);
    EXPECT_NEAR(up.tip.b_over_l, -down.tip.b_over_l, 1e-14);
    EXPECT_NEAR(up.tip.theta0, -down.tip.theta0, 1e-14);
  }
  const EllipticResult a = solver.solve(EndLoad::howell(1.5, 4.0));
  const EllipticResult b = solver.solve(EndLoad::howell(-1.5, -4.0));
  EXPECT_NEAR(a.tip.b_over_l, -b.tip.b_over_l, 1e-14);
}

TEST(EllipticSolver, ForwardAndInverseAgree) {
  const EllipticSolver solver;
  for (double n : {-5.0, -2.0, -1.0, 0.0, 1.0, 3.0, 10.0}) {
    const double psi = std::atan2(1.0, -n);
    for (double fraction : {0.05, 0.3, 0.6, 0.9, 0.99}) {
      const double theta0 = fraction * psi;
      const EllipticResult inv = solver.solve_for_tip_angle(n, theta0);
      ASSERT_TRUE(inv.converged());
      const EllipticResult fwd = solver.solve(EndLoad::howell(n, inv.load.Fy));
      ASSERT_TRUE(fwd.converged());
      SCOPED_TRACE(::testing::Message() << "n=" << n << " theta0=" << theta0);
      EXPECT_NEAR(fwd.tip.theta0, theta0, kSelfConsistency * std::max(1.0, theta0));
      EXPECT_NEAR(fwd.tip.a_over_l, inv.tip.a_over_l, kSelfConsistency);
      EXPECT_NEAR(fwd.tip.b_over_l, inv.tip.b_over_l, kSelfConsistency);
      // b/l is not monotonic in the load for compressive n (the tip curls past the top), so the
      // deflection inverse returns the smallest load that reaches b/l: never more than this one.
      const EllipticResult by_b = solver.solve_for_deflection(n, inv.tip.b_over_l);
      EXPECT_NEAR(by_b.tip.b_over_l, inv.tip.b_over_l, kSelfConsistency);
      EXPECT_LE(by_b.load.Fy, inv.load.Fy * (1.0 + 1e-10));
    }
  }
  // With an end moment the inverse searches alpha2 through forward solves.
  const EllipticResult fwd = solver.solve(EndLoad::howell(0.5, 6.0, -1.0));
  const EllipticResult inv = solver.solve_for_tip_angle(0.5, fwd.tip.theta0, -1.0);
  EXPECT_NEAR(inv.load.Fy, 6.0, 1e-9);
}

TEST(EllipticSolver, ClosedFormPathsAgreeNearMomentFreeLoads) {
  // The mu = 0 branch (split-modulus Howell form) and the general continuation path (tip-angle
  // shooting with Jacobi amplitudes) share no evaluation code; a vanishing moment must join them.
  const EllipticSolver solver;
  for (double n : {-5.0, -1.0, 0.0, 2.0, 10.0}) {
    for (double alpha2 : {0.5, 5.0, 20.0}) {
      const EllipticResult howell = solver.solve(EndLoad::howell(n, alpha2, 0.0));
      const EllipticResult general = solver.solve(EndLoad::howell(n, alpha2, 1e-13));
      ASSERT_TRUE(general.converged()) << general.message;
      SCOPED_TRACE(::testing::Message() << "n=" << n << " alpha2=" << alpha2);
      EXPECT_NEAR(howell.tip.a_over_l, general.tip.a_over_l, 1e-10);
      EXPECT_NEAR(howell.tip.b_over_l, general.tip.b_over_l, 1e-10);
      EXPECT_NEAR(howell.tip.theta0, general.tip.theta0, 1e-10);
    }
  }
}

TEST(EllipticSolver, ReturnsProportionalLoadingBranchAmongSeveralEquilibria) {
  // n = 1, alpha2 = 5 (compression past buckling): the tip-angle residual has several roots
  // (docs/theory-elliptic.md). The solver must return the root reached by loading from zero, found
  // here independently by stepping the load up in small increments with the general path.
  const EllipticSolver solver;
  const EndLoad load = EndLoad::howell(1.0, 5.0);
  const double force = std::hypot(load.Fx, load.Fy);
  const double psi = std::atan2(load.Fy, load.Fx);
  const elliptic::PendulumProblem problem = elliptic::make_pendulum_problem(force, psi, 0.0);
  int roots = 0;
  double previous = elliptic::tip_angle_residual(problem, -9.0);
  for (double t = -9.0 + 1e-3; t < 3.0; t += 1e-3) {
    const double r = elliptic::tip_angle_residual(problem, t);
    if ((r > 0.0) != (previous > 0.0)) ++roots;
    previous = r;
  }
  EXPECT_GE(roots, 3);
  const EllipticResult r = solver.solve(load);
  EXPECT_GT(r.tip.theta0, 0.0);
  EXPECT_LT(r.tip.theta0, psi);
  double theta0 = 0.0;
  for (int step = 1; step <= 50; ++step) {
    theta0 = solver.solve(EndLoad::howell(1.0, 5.0 * step / 50.0, 1e-12 * step / 50.0)).tip.theta0;
  }
  EXPECT_NEAR(r.tip.theta0, theta0, 1e-9);
}

// Number of sign changes of the tip-angle residual over t in [-12, 4]: equilibria of the load.
int count_equilibria(const EndLoad& load) {
  const double force = std::hypot(load.Fx, load.Fy);
  const double psi = std::atan2(load.Fy, load.Fx);
  const elliptic::PendulumProblem problem = elliptic::make_pendulum_problem(force, psi, load.mu);
  int roots = 0;
  double previous = elliptic::tip_angle_residual(problem, -12.0);
  for (double t = -12.0 + 1e-3; t < 4.0; t += 1e-3) {
    const double r = elliptic::tip_angle_residual(problem, t);
    if ((r > 0.0) != (previous > 0.0)) ++roots;
    previous = r;
  }
  return roots;
}

TEST(EllipticSolver, PassesTheLimitPointAndSaysWhereTheBeamSnaps) {
  // alpha2 = 10, n = 0 with mu = -2 pi: along proportional loading two equilibria merge at
  // lambda ~ 0.5958 (a fold: under load control the beam snaps there). Just before it three roots
  // exist, just after only one (counted independently by sampling the residual). The solver
  // follows the equilibrium path through the fold, as the shooting solver's arclength
  // continuation does, returns the equilibrium where the path reaches full load, and reports the
  // fold and its load factor.
  const EllipticSolver solver;
  const EndLoad full = EndLoad::howell(0.0, 10.0, -2.0 * kPi);
  const EllipticResult r = solver.solve(full);
  ASSERT_TRUE(r.converged()) << r.message;
  EXPECT_GE(r.limit_points, 1);
  EXPECT_NE(r.branch.find("limit point"), std::string::npos) << r.branch;
  EXPECT_EQ(count_equilibria(full.scaled(0.5950)), 3);
  EXPECT_EQ(count_equilibria(full.scaled(0.5965)), 1);
  EXPECT_GT(r.first_limit_load_factor, 0.5950);
  EXPECT_LT(r.first_limit_load_factor, 0.5965);
  // Independent method: shooting's pseudo-arclength continuation (CVODES), same equilibrium.
  const ShootingResult s = ShootingSolver().solve(full);
  ASSERT_TRUE(s.converged()) << s.message;
  EXPECT_GE(s.limit_points, 1);
  EXPECT_NEAR(r.tip.a_over_l, s.tip.x, 1e-9);
  EXPECT_NEAR(r.tip.b_over_l, s.tip.y, 1e-9);
  EXPECT_NEAR(r.tip.theta0, s.tip.theta, 1e-9);
}

TEST(EllipticSolver, TensionNearTheSeparatrixKeepsPrecision) {
  // Large tension: 1 - k is below 1e-8 here. Forward solve, the explicit inverse and the general
  // path must agree to round-off. (Beyond alpha2 ~ 50 at n = -5 the tip angle is within 1e-9 of
  // the force angle and no longer determines alpha2 to more than ~1e-7: physics, not round-off.)
  const EllipticSolver solver;
  for (double alpha2 : {5.0, 10.0, 20.0}) {
    const EllipticResult fwd = solver.solve(EndLoad::howell(-5.0, alpha2));
    const EllipticResult inv = solver.solve_for_tip_angle(-5.0, fwd.tip.theta0);
    EXPECT_NEAR(inv.load.Fy, alpha2, 1e-9 * alpha2);
    EXPECT_NEAR(inv.tip.a_over_l, fwd.tip.a_over_l, 1e-12);
    EXPECT_NEAR(inv.tip.b_over_l, fwd.tip.b_over_l, 1e-12);
    EXPECT_LT(fwd.tip.theta0, std::atan2(1.0, 5.0));
  }
  // The general path needs a nonzero moment; near the separatrix the tip responds to the moment
  // with a gain of order e^{sqrt F} (~1e10 at alpha2 = 100), so it must be far below 1e-13 here.
  for (double alpha2 : {50.0, 100.0}) {
    const EllipticResult howell = solver.solve(EndLoad::howell(-5.0, alpha2));
    const EllipticResult general = solver.solve(EndLoad::howell(-5.0, alpha2, 1e-25));
    ASSERT_TRUE(general.converged()) << general.message;
    EXPECT_NEAR(howell.tip.a_over_l, general.tip.a_over_l, 1e-11);
    EXPECT_NEAR(howell.tip.b_over_l, general.tip.b_over_l, 1e-11);
  }
}

TEST(EllipticSolver, ShapeIsInextensibleAndEndsAtTheTip) {
  const EllipticSolver solver;
  for (const IvpCase& c : ivp_cases()) {
    const EllipticResult r = solver.solve(EndLoad{c.Fx, c.Fy, c.mu});
    const std::vector<ShapePoint> shape = solver.shape(r, 2001);
    EXPECT_NEAR(shape.front().x, 0.0, 1e-13);
    EXPECT_NEAR(shape.front().y, 0.0, 1e-13);
    EXPECT_NEAR(shape.front().theta, 0.0, 1e-13);
    EXPECT_NEAR(shape.back().x, r.tip.a_over_l, 1e-12);
    EXPECT_NEAR(shape.back().y, r.tip.b_over_l, 1e-12);
    EXPECT_NEAR(shape.back().theta, r.tip.theta0, 1e-12);
    // Chord of each small interval equals its arc length to second order.
    for (std::size_t i = 1; i < shape.size(); i += 97) {
      const double ds = shape[i].s - shape[i - 1].s;
      const double chord = std::hypot(shape[i].x - shape[i - 1].x, shape[i].y - shape[i - 1].y);
      EXPECT_NEAR(chord / ds, 1.0, 1e-4);
      const double mid_theta = 0.5 * (shape[i].theta + shape[i - 1].theta);
      EXPECT_NEAR((shape[i].x - shape[i - 1].x) / ds, std::cos(mid_theta), 1e-4);
    }
  }
}

TEST(EllipticSolver, RejectsBadInput) {
  const EllipticSolver solver;
  EXPECT_THROW(solver.solve(EndLoad{std::nan(""), 1.0, 0.0}), InvalidInput);
  EXPECT_THROW(solver.solve(EndLoad{0.0, INFINITY, 0.0}), InvalidInput);
  EXPECT_THROW(solver.solve(EndLoad{0.0, 1.0, -INFINITY}), InvalidInput);
  EXPECT_THROW(solver.solve(EndLoad{0.0, 1e7, 0.0}), InvalidInput);
  EXPECT_THROW(solver.solve(EndLoad{0.0, 1e5, 0.0}), InvalidInput);  // k'^2 would underflow
  // The largest accepted force still solves (1 - k ~ e^{-2 sqrt F}, about 1e-87 here).
  const EllipticResult edge = solver.solve(EndLoad{0.0, 1e4, 0.0});
  EXPECT_TRUE(edge.converged()) << edge.message;
  EXPECT_NEAR(edge.root_moment, 1e4 * edge.tip.a_over_l, 1e-8 * 1e4);  // statics
  // theta0 must lie below the force angle: pi/2 for n = 0, atan2(1, -1) = 45 deg for n = -1.
  EXPECT_THROW(solver.solve_for_tip_angle(0.0, 2.0), InvalidInput);
  EXPECT_THROW(solver.solve_for_tip_angle(-1.0, 0.8), InvalidInput);
  EXPECT_THROW(solver.solve_for_tip_angle(0.0, std::nan("")), InvalidInput);
  EXPECT_THROW(solver.solve_for_deflection(0.0, 1.2), InvalidInput);
  EXPECT_THROW(solver.solve_for_deflection(-3.0, 0.9), InvalidInput);  // tension caps b/l
  try {
    solver.solve_for_tip_angle(0.0, 2.0);
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("theta0"), std::string::npos);
  }
}

}  // namespace
}  // namespace flexure
