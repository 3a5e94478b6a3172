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
// - Loads alpha2 = 100-1000 (tension, compression, end moments) against an mpmath solution of the
//   elastica written by scripts/elliptic_large_load_oracle.py (tests/data/).
// - Mirror symmetry, forward/inverse agreement, the proportional-loading branch when several
//   equilibria exist, and bad input.
#include "flexure/solver/elliptic/elliptic_solver.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "flexure/solver/common/csv_table.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/elliptic/elastica_closed_form.h"
#include "flexure/solver/elliptic/tip_chart.h"
#include "flexure/solver/shooting/shooting_solver.h"
#include "tests/support/data_file_support.h"
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
// alpha2 100-1000 against the mpmath elastica (30+ digits): the solver's round-off.
constexpr double kLargeLoadTolerance = 1e-12;

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

TEST(EllipticSolver, ForwardMatchesHowellEquationsToRoundOffOnASeededGrid) {
  // The mu = 0 forward solve (secant iteration in zeta, docs/theory-elliptic.md) against Howell
  // eqs. 2.90, 2.96 and 2.98 with phi1 = atan2(1, -n), evaluated with mpmath at 40 digits on 40
  // seeded (n, theta0) pairs: n uniform in [-5, 10], theta0 uniform in (0.02, 0.97) times the
  // force angle (the loads come out at alpha2 = 0.099 to 9.67, tension and compression; larger
  // loads: LargeLoadsMatchAnIndependentMpmathElastica). The load alpha2 is given to 20 digits;
  // the tip must come back to 1e-12 (round-off level: the iteration's shortcuts may not cost
  // accuracy).
  struct Row {
    double n, theta0, alpha2, a, b;
  };
  const Row rows[] = {
      {2.759813,
       0.13600507012915578,
       0.2086685327622959483,
       0.99513881636473106078,
       0.089629143041284821937},
      {6.761616,
       0.5645073395454019,
       0.29067385166175343948,
       0.92018537958434276487,
       0.35216444219803144979},
      {5.466296,
       0.06380522241098902,
       0.099121057430299768327,
       0.99892870514827150566,
       0.042129377328490195405},
      {-0.96595,
       0.4440380180856755,
       1.5512568868178922006,
       0.94582630836551666382,
       0.29787434283622811119},
      {5.279244,
       2.584259369093947,
       1.6767911405410514954,
       -0.2399034039744023646,
       0.70900208527749132919},
      {1.167313,
       0.669339253575665,
       0.92188560579810661338,
       0.88531564031491596205,
       0.42008282355553030787},
      {0.223254,
       1.2979761188677867,
       4.1578201001681862493,
       0.57205913310124173177,
       0.73428949866017146913},
      {7.200922,
       0.586833826989787,
       0.2805414094346342584,
       0.91397073271143662427,
       0.36476897417521120633},
      {5.966342,
       1.0763707049676787,
       0.42007180036209580018,
       0.72324678092458347136,
       0.6116192523393558085},
      {-1.635011,
       0.4004256220136966,
       2.0674147607301684852,
       0.95417183213097733319,
       0.27657076748223804566},
      {-1.186432,
       0.37355320524729146,
       1.2894649694173780462,
       0.96159252268583856528,
       0.25196748709275634721},
      {-1.080281,
       0.20620130421772317,
       0.5164104633744360077,
       0.98852552919353066685,
       0.13819540956019533577},
      {-2.527725,
       0.3095259670809996,
       2.1412983898541186167,
       0.97158836061130263257,
       0.22015234099884087358},
      {6.976502,
       2.2054398597411105,
       0.75944673738441051198,
       0.034981678115302816421,
       0.79801600105186652923},
      {4.987992,
       1.6032553182090463,
       0.66447633396940495772,
       0.42782341259503406355,
       0.77673868689323956953},
      {3.035532,
       1.7619259894085693,
       1.2020216905563861819,
       0.32004303943095051199,
       0.80535806757231023966},
      {1.562999,
       0.296336955375828,
       0.43981281922482480728,
       0.97703648216292659661,
       0.19366564736029052062},
      {-0.737525,
       0.3068795385226133,
       0.78918360761863501689,
       0.97460344407588026784,
       0.20480485357775640183},
      {4.379437,
       2.3944368980036668,
       1.5671483551999043437,
       -0.10825363316558074044,
       0.76661475904402060233},
      {1.998949,
       1.0674564377563374,
       1.001999191748496523,
       0.72224208307417265916,
       0.6156532862750986371},
      {0.399607,
       1.107289198716663,
       2.4743661890591040543,
       0.69005268112306297555,
       0.64931456914622999793},
      {5.316723,
       1.5366439314939857,
       0.59969525555680274719,
       0.46932788405574152794,
       0.76246962339953009201},
      {-1.006769,
       0.6335714457763431,
       3.9300421618577547244,
       0.88418731848879292733,
       0.43199059979732026576},
      {-4.328708,
       0.07264517434276814,
       0.19794790104563739984,
       0.99856479528258326974,
       0.049078190446631669858},
      {-4.777362,
       0.0566866358586709,
       0.14691804345738521115,
       0.99912909889675028437,
       0.038211413712450181078},
      {4.216964,
       1.8612683360455573,
       0.94285162735164463389,
       0.25960938281124021192,
       0.81100648916287287952},
      {-0.230014,
       0.4473387379517847,
       1.0612296677637990964,
       0.94660528908908257739,
       0.29410525317724014929},
      {4.115716,
       1.9669228220827615,
       1.0562482884256984311,
       0.18831951540826630624,
       0.81488618141282291446},
      {-4.402681,
       0.1537614118001893,
       0.74636866098355303264,
       0.99324283481404596683,
       0.1073117385471853453},
      {2.063812,
       1.1596474151077711,
       1.0520575474055870365,
       0.67590174703485808912,
       0.653373658402740217},
      {2.889706,
       0.5388231648926031,
       0.50565462038209800677,
       0.92613242795534164736,
       0.34055217779791523597},
      {3.392665,
       0.4303989212095317,
       0.40856497664137775241,
       0.95260109535245964587,
       0.27512818683785226772},
      {5.384462,
       2.7678003844030754,
       2.4388631949906066621,
       -0.38776447724909808554,
       0.62375096332089558599},
      {4.409804,
       1.1180467050201026,
       0.55741992994611080255,
       0.70161802222341479326,
       0.63060037722799310971},
      {7.253514,
       2.658223258288113,
       1.3050805817948424397,
       -0.28202883661622909381,
       0.68065945274150784874},
      {7.264557,
       1.868573583690612,
       0.55090041569262394176,
       0.26118747359298546425,
       0.80792534397388406654},
      {0.153885,
       0.5276817776296435,
       1.0938554584450384208,
       0.92660911091521162841,
       0.34206750123234276067},
      {9.389923,
       1.1419274666646981,
       0.28761512599440605834,
       0.69239313625224751093,
       0.63641993771941899761},
      {-0.956414,
       0.5463774991290228,
       2.3811139026496955177,
       0.91669883624298644887,
       0.36749506075846012827},
      {-0.313752,
       1.158157692088036,
       9.674227500774229331,
       0.61536045052927063589,
       0.72470225883711847174},
  };
  const EllipticSolver solver;
  for (const Row& row : rows) {
    const EllipticResult r = solver.solve(EndLoad::howell(row.n, row.alpha2));
    ASSERT_TRUE(r.converged()) << r.message;
    EXPECT_NEAR(r.tip.theta0, row.theta0, kSelfConsistency)
        << "n = " << row.n << ", alpha2 = " << row.alpha2;
    EXPECT_NEAR(r.tip.a_over_l, row.a, kSelfConsistency)
        << "n = " << row.n << ", alpha2 = " << row.alpha2;
    EXPECT_NEAR(r.tip.b_over_l, row.b, kSelfConsistency)
        << "n = " << row.n << ", alpha2 = " << row.alpha2;
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

TEST(EllipticSolver, ResidualByAdditionTheoremAgreesWithTheIntegralForm) {
  // The continuation follows its path with the residual by the Jacobi addition theorem (no
  // incomplete integral at the tip) and polishes with the one through F(phi|m). Seeded tip states
  // in all three charts (tip_chart.h: angle, saddle, separatrix, with windings -2..2 and both
  // sides) for loads n in [-10, 20], |alpha2| <= 100, |mu| <= 4 pi at load factors in (0, 1): the
  // two agree to 1e-12 absolute (2.8e-14 reached; the corrector's tolerance is 1e-7).
  std::mt19937_64 rng(20261215u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int compared = 0;
  for (int i = 0; i < 30000; ++i) {
    const double n = -10.0 + 30.0 * unit(rng);
    const double alpha2 = 100.0 * unit(rng);
    const double mu = -4.0 * kPi + 8.0 * kPi * unit(rng);
    const double lambda = unit(rng);
    const double force = lambda * std::hypot(n * alpha2, alpha2);
    const double psi = std::atan2(alpha2, -n * alpha2);
    const elliptic::PendulumProblem problem =
        elliptic::make_pendulum_problem(force, psi, lambda * mu);
    elliptic::TipChart chart;
    double x = 0.0;
    const double r = unit(rng);
    if (i % 3 == 0) {
      x = -psi + (r - 0.5) * 2.0 * (std::sqrt(problem.mu * problem.mu + 4.0 * force) + 1.0);
    } else {
      chart.kind =
          i % 3 == 1 ? elliptic::TipChart::Kind::kSaddle : elliptic::TipChart::Kind::kSeparatrix;
      chart.winding = static_cast<int>(std::floor(5.0 * unit(rng))) - 2;
      chart.side = unit(rng) < 0.5 ? 1 : -1;
      x = 30.0 * (r - 0.5);
    }
    elliptic::TipState state;
    if (!elliptic::tip_state_in_chart(problem, chart, x, state)) continue;
    ++compared;
    EXPECT_NEAR(elliptic::tip_angle_residual_by_addition(problem, state),
                elliptic::tip_angle_residual(problem, state),
                1e-12)
        << "n = " << n << ", alpha2 = " << alpha2 << ", mu = " << mu << ", lambda = " << lambda
        << ", chart " << static_cast<int>(chart.kind) << ", x = " << x;
  }
  EXPECT_GT(compared, 20000);  // 24821: the rest lie outside their chart
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

TEST(EllipticSolver, LargeLoadsMatchAnIndependentMpmathElastica) {
  // alpha2 = 100, 300, 1000 at n = -5, -1, 0, 1, 5, and with end moments mu = 0.5 (n = -1, 0, 1)
  // and mu = 1 (n = 2, alpha2 = 500): tests/data/elliptic_large_loads_mpmath.csv, written by
  // scripts/elliptic_large_load_oracle.py from the elastica's first integral by mpmath quadrature
  // at 40 digits and checked by an mpmath Taylor-series integration of the ODE (no flexure
  // code). At these loads the tip angle is within 1e-30 to 1e-4 rad of the force angle, past the
  // 40-row grid above (alpha2 <= 9.67).
  const CsvTable t =
      CsvTable::parse(test::read_repository_file("tests/data/elliptic_large_loads_mpmath.csv"),
                      "tests/data/elliptic_large_loads_mpmath.csv");
  ASSERT_GE(t.row_count(), 20u);
  const EllipticSolver solver;
  for (std::size_t i = 0; i < t.row_count(); ++i) {
    const double n = t.number(i, "n"), mu = t.number(i, "mu"), alpha2 = t.number(i, "alpha2");
    SCOPED_TRACE(::testing::Message() << "n = " << n << ", mu = " << mu << ", alpha2 = " << alpha2);
    const EllipticResult r = solver.solve(EndLoad::howell(n, alpha2, mu));
    ASSERT_TRUE(r.converged()) << r.message;
    EXPECT_NEAR(r.tip.a_over_l, t.number(i, "a_over_l"), kLargeLoadTolerance);
    EXPECT_NEAR(r.tip.b_over_l, t.number(i, "b_over_l"), kLargeLoadTolerance);
    EXPECT_NEAR(r.tip.theta0, t.number(i, "theta0"), kLargeLoadTolerance);
  }
}

}  // namespace
}  // namespace flexure
