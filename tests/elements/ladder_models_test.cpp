// The cheaper models of the ladder (docs/models.md) against limits derived independently here and
// against flexure's exact solvers:
//  * every model reduces to linear theory at small loads: b/l = alpha2/3 + mu/2 and
//    theta0 = alpha2/2 + mu for the free end, b/l = alpha2/12 for the guided one (linear, BCM,
//    CBCM exactly; PR-3R to its own linear limit, which the test computes from the link lengths
//    and springs: Su's constants give b/l = 0.34066 alpha2, 2.2 % softer than alpha2/3);
//  * the linear model against the exact elastica at small loads;
//  * the BCM: its buckling loads (guided element near -pi^2, cantilever near -pi^2/4), its
//    stiffness against the Taylor expansion of the exact beam-column stiffness (solved here from
//    the beam-column ODE in closed form), its closed form against the chained solver with one
//    element (different code), the axial term p/d, the refusal past buckling;
//  * the CBCM against the elastica on seeded random loads at a measured order (3, see
//    docs/models.md), and against the shooting method on chains of every end condition with rigid
//    links at both ends (reactions included);
//  * PR-3R against its own statics and stability, and the guided end's small-load limit;
//  * what each model refuses, with the reason and the model that can.
#include "flexure/elements/ladder_models.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>

#include "flexure/solver/common/status.h"
#include "flexure/solver/elliptic/elliptic_solver.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {
namespace {

constexpr double kPi = std::numbers::pi;

CantileverCase free_case(double n, double alpha2, double mu) {
  CantileverCase c;
  c.load = EndLoad::howell(n, alpha2, mu);
  return c;
}

CantileverCase guided_case(double n, double alpha2, double angle = 0.0) {
  CantileverCase c;
  c.load = EndLoad::howell(n, alpha2, 0.0);
  c.end = EndCondition::kGuided;
  c.guided_tip_angle = angle;
  return c;
}

ChainedBcmSolver cbcm(int elements) {
  ChainedBcmSolver::Options o;
  o.elements = elements;
  return ChainedBcmSolver(o);
}

// --- Linear theory ------------------------------------------------------------------------------

TEST(LinearBeam, MatchesTheElasticaAtSmallLoads) {
  // The elastica departs from linear theory by the beam-column effect of the axial force (relative
  // about 2|Fx|/5) and by terms of relative order (load)^2 (1e-6 at loads of 1e-3).
  std::mt19937 rng(301);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const EllipticSolver exact;
  for (int i = 0; i < 20; ++i) {
    const CantileverCase c = free_case(u(rng), 1e-3 * u(rng), 1e-3 * u(rng));
    const LinearBeamResult r = LinearBeamSolver().solve(c);
    const EllipticResult e = exact.solve(c.load);
    const double scale =
        (std::fabs(e.tip.b_over_l) + std::fabs(e.tip.theta0)) * (2e-6 + 0.5 * std::fabs(c.load.Fx));
    EXPECT_NEAR(r.tip.b_over_l, e.tip.b_over_l, scale);
    EXPECT_NEAR(r.tip.theta0, e.tip.theta0, scale);
    // Linear theory leaves out the moment b Fx of the axial force about the clamp.
    EXPECT_NEAR(r.root_moment,
                e.root_moment,
                2e-6 * std::fabs(e.root_moment) + 2.0 * std::fabs(e.tip.b_over_l * c.load.Fx));
  }
}

TEST(LinearBeam, GuidedEndAgainstTheShootingMethodAtSmallLoads) {
  for (double angle : {0.0, 2e-4}) {
    const CantileverCase c = guided_case(0.0, 1e-3, angle);
    const LinearBeamResult r = LinearBeamSolver().solve(c);
    EXPECT_NEAR(r.tip.b_over_l, 1e-3 / 12.0 + angle / 2.0, 1e-15);
    const ShootingResult s = solve_shooting(c.to_chain(), ShootingSolver::Options{});
    ASSERT_TRUE(s.converged());
    EXPECT_NEAR(r.tip.b_over_l, s.tip.y, 1e-6 * std::fabs(s.tip.y));
    EXPECT_NEAR(r.end_moment, s.tip_load.M, 1e-5 * std::fabs(s.tip_load.M));
  }
}

// --- Every model at small loads -----------------------------------------------------------------

struct LinearLimit {
  double b_per_force, b_per_moment, theta_per_force, theta_per_moment;
};

// What each model gives for b and theta0 per unit load at eps-small loads (free end).
LinearLimit measured_free_limit(const std::function<TipPose(const CantileverCase&)>& solve) {
  const double eps = 1e-6;
  const TipPose f = solve(free_case(0.0, eps, 0.0));
  const TipPose m = solve(free_case(0.0, 0.0, eps));
  return {f.b_over_l / eps, m.b_over_l / eps, f.theta0 / eps, m.theta0 / eps};
}

TEST(LadderSmallLoads, LinearBcmAndCbcmReduceToLinearTheory) {
  const std::vector<std::pair<std::string, std::function<TipPose(const CantileverCase&)>>> models =
      {{"linear", [](const CantileverCase& c) { return LinearBeamSolver().solve(c).tip; }},
       {"bcm", [](const CantileverCase& c) { return BcmSolver().solve(c).tip; }},
       {"cbcm N=1", [](const CantileverCase& c) { return cbcm(1).solve(c).tip_pose(); }},
       {"cbcm N=3", [](const CantileverCase& c) { return cbcm(3).solve(c).tip_pose(); }},
       {"cbcm N=6", [](const CantileverCase& c) { return cbcm(6).solve(c).tip_pose(); }}};
  for (const auto& [name, solve] : models) {
    SCOPED_TRACE(name);
    const LinearLimit l = measured_free_limit(solve);
    EXPECT_NEAR(l.b_per_force, 1.0 / 3.0, 1e-5);
    EXPECT_NEAR(l.b_per_moment, 0.5, 1e-5);
    EXPECT_NEAR(l.theta_per_force, 0.5, 1e-5);
    EXPECT_NEAR(l.theta_per_moment, 1.0, 1e-5);
    // The guided end: b = alpha2/12, with the guide's moment alpha2/2 (antisymmetric shape).
    const TipPose g = solve(guided_case(0.0, 1e-6));
    EXPECT_NEAR(g.b_over_l / 1e-6, 1.0 / 12.0, 1e-5);
    EXPECT_NEAR(g.theta0, 0.0, 1e-12);
  }
}

TEST(LadderSmallLoads, Prbm3rWithSusConstantsIsTwoPercentSoft) {
  // The linear limit of the PR-3R model (elements/ladder_models.h), computed here from the
  // published link lengths (joints at s = 0.10, 0.45, 0.85) and springs.
  const double s[3] = {0.10, 0.45, 0.85};
  const double k[3] = {3.51, 2.99, 2.58};
  double bF = 0, tF = 0, tM = 0;
  for (int i = 0; i < 3; ++i) {
    bF += (1 - s[i]) * (1 - s[i]) / k[i];
    tF += (1 - s[i]) / k[i];
    tM += 1 / k[i];
  }
  EXPECT_NEAR(bF, 0.34066, 5e-6);  // the "about 0.3406 lambda"
  EXPECT_NEAR(bF / (1.0 / 3.0) - 1.0, 0.0220, 5e-5);
  const LinearLimit l =
      measured_free_limit([](const CantileverCase& c) { return Prbm3rSolver().solve(c).tip; });
  EXPECT_NEAR(l.b_per_force, bF, 1e-5);
  EXPECT_NEAR(l.b_per_moment, tF, 1e-5);
  EXPECT_NEAR(l.theta_per_force, tF, 1e-5);
  EXPECT_NEAR(l.theta_per_moment, tM, 1e-5);
  const Prbm3rConstants su = Prbm3rConstants::su();
  EXPECT_NEAR(su.small_load_b_per_force(), bF, 1e-15);
  // Su's load-specific sets: the force set is fitted to a transverse force (b = alpha2/3 within
  // 0.02 %), the moment set to an end moment (theta0 = mu within 0.07 %).
  EXPECT_NEAR(Prbm3rConstants::su_force().small_load_b_per_force() * 3.0, 1.0, 2e-4);
  EXPECT_NEAR(Prbm3rConstants::su_moment().small_load_theta_per_moment(), 1.0, 7e-4);
}

TEST(LadderSmallLoads, Prbm3rGuidedEndMatchesItsLinearLimit) {
  // Guided, linear: k_i theta_i = (1 - s_i) F + M with sum theta_i = 0 gives
  // M = -F sum((1 - s_i)/k_i) / sum(1/k_i) and b = F sum((1-s_i)^2/k_i) + M sum((1-s_i)/k_i).
  const Prbm3rConstants c = Prbm3rConstants::su();
  const double bF = c.small_load_b_per_force(), tF = c.small_load_theta_per_force(),
               tM = c.small_load_theta_per_moment();
  const double M_per_F = -tF / tM;
  const double b_per_F = bF + M_per_F * tF;
  const Prbm3rResult r = Prbm3rSolver().solve(guided_case(0.0, 1e-6));
  ASSERT_TRUE(r.converged());
  EXPECT_NEAR(r.tip.b_over_l / 1e-6, b_per_F, 1e-5);
  EXPECT_NEAR(r.end_moment / 1e-6, M_per_F, 1e-5);
  EXPECT_NEAR(r.tip.theta0, 0.0, 1e-13);
  // 12.6 % softer than alpha2/12: Su's constants are not fitted to a guided end.
  EXPECT_NEAR(b_per_F * 12.0, 1.1264, 5e-4);
}

// --- BCM
// ------------------------------------------------------------------------------------------

// Bisection for a sign change of f on [a, b].
double root_of(const std::function<double(double)>& f, double a, double b) {
  for (int i = 0; i < 200; ++i) {
    const double m = 0.5 * (a + b);
    (f(a) * f(m) <= 0.0 ? b : a) = m;
  }
  return 0.5 * (a + b);
}

TEST(Bcm, BucklingLoadsOfTheGuidedElementAndTheCantilever) {
  // theta = 0: f/y = K11(p) vanishes near the clamped-guided Euler load -pi^2.
  const double guided = root_of([](double p) { return bcm::stiffness(p).a11; }, -12.0, -8.0);
  EXPECT_NEAR(guided / -(kPi * kPi), 1.0, 2e-3);
  // f = m = 0: det K(p) vanishes near the cantilever's -pi^2/4.
  const double free = root_of([](double p) { return bcm::stiffness(p).determinant(); }, -3.0, -2.0);
  EXPECT_NEAR(free / -(kPi * kPi / 4.0), 1.0, 5e-4);
}

// The exact stiffness of a beam-column element (EI = l = 1, axial tension P at the tip): with
// M(s) = m + (1 - s) f - (Y - y(s)) P the moment of the tip loads about s, y'' = M(s) gives
// y = A c(ks) + B s(ks) + Y - (m + (1 - s) f)/P (cosh/sinh for P > 0, cos/sin for P < 0); the
// four end conditions y(0) = y'(0) = 0, y(1) = Y, y'(1) = Theta fix A, B, f, m.
Eigen::Matrix2d exact_beam_column_stiffness(double P) {
  const bool tension = P > 0.0;
  const double k = std::sqrt(std::fabs(P));
  const double c1 = tension ? std::cosh(k) : std::cos(k);
  const double s1 = tension ? std::sinh(k) : std::sin(k);
  const double dc1 = tension ? k * std::sinh(k) : -k * std::sin(k);  // d/ds of c(ks) at s = 1
  const double ds1 = k * c1;                                         // d/ds of s(ks) at s = 1
  Eigen::Matrix2d K;
  for (int column = 0; column < 2; ++column) {
    const double Y = column == 0 ? 1.0 : 0.0, Theta = column == 0 ? 0.0 : 1.0;
    // Unknowns A, B, f, m.
    Eigen::Matrix4d A;
    Eigen::Vector4d b;
    A << 1, 0, -1 / P, -1 / P, 0, k, 1 / P, 0, c1, s1, 0, -1 / P, dc1, ds1, 1 / P, 0;
    b << -Y, 0, 0, Theta;
    const Eigen::Vector4d x = A.fullPivLu().solve(b);
    K(0, column) = x[2];
    K(1, column) = x[3];
  }
  return K;
}

TEST(Bcm, StiffnessIsTheSecondOrderExpansionOfTheExactBeamColumn) {
  // At p = 0 the exact matrix is G; the BCM's error then shrinks as p^3 (8x for half the load).
  for (double p : {-2.0, -1.0, 1.0, 2.0}) {
    SCOPED_TRACE(p);
    const auto error = [](double q) {
      const bcm::Symmetric2 K = bcm::stiffness(q);
      const Eigen::Matrix2d E = exact_beam_column_stiffness(q);
      return std::max({std::fabs(K.a11 - E(0, 0)),
                       std::fabs(K.a12 - E(0, 1)),
                       std::fabs(K.a12 - E(1, 0)),
                       std::fabs(K.a22 - E(1, 1))});
    };
    EXPECT_NEAR(error(p) / error(p / 2.0), 8.0, 0.5);
    EXPECT_LT(error(p), 2e-4 * std::fabs(p * p * p));
  }
  // Near p = 0 both are G + p P (the exact matrix is symmetric: Maxwell-Betti).
  const Eigen::Matrix2d E = exact_beam_column_stiffness(1e-2);
  const bcm::Symmetric2 K = bcm::stiffness(1e-2);
  EXPECT_NEAR(E(0, 0), K.a11, 1e-8);
  EXPECT_NEAR(E(0, 1), K.a12, 1e-8);
  EXPECT_NEAR(E(1, 0), K.a12, 1e-8);
  EXPECT_NEAR(E(1, 1), K.a22, 1e-8);
}

TEST(Bcm, ClosedFormAgreesWithTheChainedSolverOfOneElement) {
  std::mt19937 rng(302);
  std::uniform_real_distribution<double> n(-1.0, 0.4), a(0.1, 3.0), mu(-1.0, 1.0), t(-0.3, 0.3);
  for (int i = 0; i < 20; ++i) {
    const CantileverCase c =
        i % 2 == 0 ? free_case(n(rng), a(rng), mu(rng)) : guided_case(n(rng), a(rng), t(rng));
    SCOPED_TRACE(i);
    const BcmResult closed = BcmSolver().solve(c);
    const CbcmResult chained = cbcm(1).solve(c);
    ASSERT_TRUE(chained.converged()) << chained.message;
    EXPECT_NEAR(closed.tip.a_over_l, chained.tip.x, 1e-10);
    EXPECT_NEAR(closed.tip.b_over_l, chained.tip.y, 1e-10);
    EXPECT_NEAR(closed.tip.theta0, chained.tip.theta, 1e-10);
    EXPECT_NEAR(closed.root_moment, chained.root_moment, 1e-9);
    EXPECT_NEAR(closed.end_moment, chained.tip_load.M, 1e-9);
  }
}

TEST(Bcm, GuidedElementFollowsItsStiffnessEntry) {
  // f = (12 + 6p/5 - p^2/700) y with theta held at 0; the guide's moment is K12 y.
  for (double p : {-5.0, 0.0, 3.0}) {
    const double f = 0.5;
    const BcmResult r = BcmSolver().solve(guided_case(-p / f, f));
    EXPECT_NEAR(r.y, f / (12.0 + 6.0 * p / 5.0 - p * p / 700.0), 1e-14);
    EXPECT_NEAR(r.m, (-6.0 - p / 10.0 + p * p / 1400.0) * r.y, 1e-14);
  }
}

TEST(Bcm, AxialStiffnessOfTheExtensibleElement) {
  // A pure axial load on a beam of slenderness l/t = 20: x = p/d, d = 12 (l/t)^2 = 4800.
  BcmSolver::Options o;
  o.slenderness = 20.0;
  CantileverCase c;
  c.load = EndLoad{2.0, 0.0, 0.0};
  const BcmResult r = BcmSolver(o).solve(c);
  EXPECT_NEAR(r.x, 2.0 / 4800.0, 1e-16);
  EXPECT_NEAR(BcmSolver().solve(c).x, 0.0, 1e-16);  // inextensible by default
}

TEST(Bcm, RefusesALoadPastBucklingAndNamesTheModelsThatCan) {
  try {
    BcmSolver().solve(free_case(1.0, 3.0, 0.0));  // p = -3 < -pi^2/4
    FAIL() << "expected OutsideMethodDomain";
  } catch (const OutsideMethodDomain& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("buckling"), std::string::npos) << what;
    EXPECT_NE(what.find("cbcm"), std::string::npos) << what;
  }
  EXPECT_NO_THROW(BcmSolver().solve(guided_case(1.0, 3.0)));  // guided: -pi^2 is further
}

// --- CBCM
// -----------------------------------------------------------------------------------------

TEST(Cbcm, ConvergesToTheElasticaAtThirdOrderOnSeededRandomLoads) {
  std::mt19937 rng(303);
  std::uniform_real_distribution<double> n(-1.0, 1.0), a(0.5, 5.0), mu(-1.0, 1.0);
  const EllipticSolver exact;
  for (int i = 0; i < 8; ++i) {
    const CantileverCase c = free_case(n(rng), a(rng), mu(rng));
    SCOPED_TRACE(::testing::Message() << "n " << -c.load.Fx / c.load.Fy << " alpha2 " << c.load.Fy
                                      << " mu " << c.load.mu);
    const EllipticResult e = exact.solve(c.load);
    ASSERT_TRUE(e.converged());
    double previous = 0.0;
    for (int N : {8, 16, 32}) {
      const CbcmResult r = cbcm(N).solve(c);
      ASSERT_TRUE(r.converged()) << r.message;
      const double error = std::hypot(r.tip.x - e.tip.a_over_l, r.tip.y - e.tip.b_over_l);
      if (previous > 0.0) {
        const double order = std::log2(previous / error);
        EXPECT_NEAR(order, 3.0, 0.25);
      }
      previous = error;
    }
    EXPECT_LT(previous, 1e-4);  // N = 32
  }
}

// The shooting method's answer for a chain, and the chained BCM's errors against it at N and 2N.
void expect_converging_to_shooting(const SegmentChain& chain, double tip_bound_at_32) {
  const ShootingResult s = solve_shooting(chain, ShootingSolver::Options{});
  ASSERT_TRUE(s.converged()) << s.message;
  const auto errors = [&](int N) {
    const CbcmResult r = cbcm(N).solve(chain);
    EXPECT_TRUE(r.converged()) << r.message;
    const double tip =
        std::hypot(r.tip.x - s.tip.x, r.tip.y - s.tip.y) + std::fabs(r.tip.theta - s.tip.theta);
    const double reactions = std::max({std::fabs(r.reaction.Fx - s.reaction.Fx),
                                       std::fabs(r.reaction.Fy - s.reaction.Fy),
                                       std::fabs(r.reaction.M - s.reaction.M),
                                       std::fabs(r.tip_load.Fx - s.tip_load.Fx),
                                       std::fabs(r.tip_load.Fy - s.tip_load.Fy),
                                       std::fabs(r.tip_load.M - s.tip_load.M)});
    return std::pair{tip, reactions};
  };
  const auto [tip16, reactions16] = errors(16);
  const auto [tip32, reactions32] = errors(32);
  EXPECT_LT(tip32, tip_bound_at_32);
  // Third order where the error is above round-off; at least second for the reactions.
  if (tip32 > 1e-10) EXPECT_GT(tip16 / tip32, 6.0);
  EXPECT_GT(reactions16 / reactions32, 4.0);
  const double scale = std::max({1.0, std::fabs(s.reaction.Fx), std::fabs(s.reaction.Fy)});
  EXPECT_LT(reactions32, 2e-3 * scale);
}

TEST(Cbcm, AgreesWithTheShootingMethodForEveryEndCondition) {
  {
    SCOPED_TRACE("guided, Howell's fixed-guided beam at alpha2 = 8, n = 0.5");
    expect_converging_to_shooting(guided_case(0.5, 8.0).to_chain(), 1e-5);
  }
  {
    SCOPED_TRACE("guided at a prescribed angle 0.3");
    expect_converging_to_shooting(guided_case(0.5, 8.0, 0.3).to_chain(), 1e-4);
  }
  {
    SCOPED_TRACE("pinned: the tip moved to (0.9, 0.2) with an end moment");
    SegmentChain c = uniform_cantilever(EndLoad{0.0, 0.0, 1.0});
    c.end = EndCondition::kPinned;
    c.prescribed.x = 0.9;
    c.prescribed.y = 0.2;
    expect_converging_to_shooting(c, 1e-4);
  }
  {
    SCOPED_TRACE("slider");
    SegmentChain c = uniform_cantilever(EndLoad{-2.0, 0.0, 0.5});
    c.end = EndCondition::kSlider;
    c.prescribed.y = 0.3;
    expect_converging_to_shooting(c, 1e-5);
  }
  {
    SCOPED_TRACE("fixed: an inclined beam under displacement control");
    SegmentChain c = uniform_cantilever(EndLoad{});
    c.end = EndCondition::kFixed;
    c.prescribed = {0.95, 0.3, 0.2};
    expect_converging_to_shooting(c, 1e-9);
  }
  SegmentChain links;
  links.segments = {RigidSegment{0.2, 0.3}, FlexibleSegment{0.5, 2.0}, RigidSegment{0.4, -0.5}};
  links.node_loads = {NodeLoad{1, 1.0, 2.0, 0.3}, NodeLoad{2, -0.5, 0.7, 0.1}};
  {
    SCOPED_TRACE("rigid links at both ends, free, loads on both links");
    SegmentChain c = links;
    c.tip_load = {0.5, 1.5, 0.2};
    expect_converging_to_shooting(c, 1e-5);
  }
  {
    SCOPED_TRACE("rigid links at both ends, pinned");
    SegmentChain c = links;
    c.tip_load = {0.0, 0.0, 0.2};
    c.end = EndCondition::kPinned;
    c.prescribed.x = 0.9;
    c.prescribed.y = 0.5;
    expect_converging_to_shooting(c, 1e-4);
  }
  {
    SCOPED_TRACE("rigid links at both ends, fixed");
    SegmentChain c = links;
    c.end = EndCondition::kFixed;
    c.prescribed = {1.0, 0.3, 0.0};
    expect_converging_to_shooting(c, 1e-9);
  }
}

TEST(Cbcm, ChainUnitsScaleWithTheSegment) {
  // The same cantilever in other units (L = 2, EI = 5): lengths scale with L, forces with EI/L^2.
  const CantileverCase unit = free_case(0.3, 2.0, 0.5);
  SegmentChain scaled;
  scaled.segments = {FlexibleSegment{2.0, 5.0}};
  scaled.tip_load = {unit.load.Fx * 5.0 / 4.0, unit.load.Fy * 5.0 / 4.0, unit.load.mu * 5.0 / 2.0};
  const CbcmResult a = cbcm(6).solve(unit);
  const CbcmResult b = cbcm(6).solve(scaled);
  EXPECT_NEAR(b.tip.x, 2.0 * a.tip.x, 1e-11);
  EXPECT_NEAR(b.tip.y, 2.0 * a.tip.y, 1e-11);
  EXPECT_NEAR(b.tip.theta, a.tip.theta, 1e-11);
  EXPECT_NEAR(b.reaction.M, a.reaction.M * 5.0 / 2.0, 1e-10);
}

// --- PR-3R
// ----------------------------------------------------------------------------------------

TEST(Prbm3r, SatisfiesItsStaticsAndIsStableOnTheLoadPath) {
  std::mt19937 rng(304);
  std::uniform_real_distribution<double> n(-2.0, 1.0), a(0.1, 8.0), mu(-2.0, 2.0);
  for (int i = 0; i < 20; ++i) {
    const CantileverCase c = free_case(n(rng), a(rng), mu(rng));
    const Prbm3rSolver solver;
    const Prbm3rResult r = solver.solve(c);
    ASSERT_TRUE(r.converged()) << r.message;
    // k_i theta_i = moment of the tip loads about joint i (elements/ladder_models.h), recomputed
    // here.
    const auto p = solver.joints(r.joint_angles);
    const Prbm3rConstants& k = solver.options().constants;
    for (int j = 1; j <= 3; ++j) {
      const double arm = (p[4].x - p[j].x) * c.load.Fy - (p[4].y - p[j].y) * c.load.Fx + c.load.mu;
      EXPECT_NEAR(k.k[j - 1] * r.joint_angles[j - 1], arm, 1e-11);
    }
    EXPECT_NEAR(r.tip.theta0, r.joint_angles[0] + r.joint_angles[1] + r.joint_angles[2], 1e-14);
    EXPECT_TRUE(r.stable);
  }
}

TEST(Prbm3r, MirrorSymmetry) {
  // Reflected in the x axis: Fy and M change sign, Fx does not.
  CantileverCase up, down;
  up.load = {-1.5, 3.0, 0.7};
  down.load = {-1.5, -3.0, -0.7};
  const Prbm3rResult r_up = Prbm3rSolver().solve(up);
  const Prbm3rResult r_down = Prbm3rSolver().solve(down);
  EXPECT_NEAR(r_up.tip.b_over_l, -r_down.tip.b_over_l, 1e-12);
  EXPECT_NEAR(r_up.tip.a_over_l, r_down.tip.a_over_l, 1e-12);
  EXPECT_NEAR(r_up.tip.theta0, -r_down.tip.theta0, 1e-12);
}

// --- What the models refuse -------------------------------------------------------------------

TEST(LadderRefusals, EndsOtherThanFreeOrGuidedNameTheModelsThatSolveThem) {
  CantileverCase c = free_case(0.0, 1.0, 0.0);
  c.end = EndCondition::kPinned;
  for (const auto& solve : std::vector<std::function<void()>>{[&] { LinearBeamSolver().solve(c); },
                                                              [&] { Prbm3rSolver().solve(c); },
                                                              [&] { BcmSolver().solve(c); },
                                                              [&] { cbcm(4).solve(c); }}) {
    try {
      solve();
      ADD_FAILURE() << "expected InvalidInput";
    } catch (const InvalidInput& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("pinned"), std::string::npos) << what;
      EXPECT_NE(what.find("shooting"), std::string::npos) << what;
    }
  }
  CantileverCase guided = guided_case(0.0, 1.0);
  guided.load.mu = 0.5;
  EXPECT_THROW(LinearBeamSolver().solve(guided), InvalidInput);
}

// The inclined bistable beam of docs/examples/inclined_bistable_path.toml (SI): 70 mm at 5.5 deg,
// 12.55 x 1.5 mm, E = 1.379 GPa, EA = E b h; its far end fixed at its stress-free x and angle and
// moved to y (the unloaded tip is at y = 6.709 mm).
SegmentChain inclined_bistable_beam(double tip_y) {
  const double E = 1.379e9, b = 12.55e-3, h = 1.5e-3, L = 70e-3;
  FlexibleSegment beam{L, E * b * h * h * h / 12.0};
  beam.EA = E * b * h;
  SegmentChain c;
  c.segments = {RigidSegment{0.0, 5.5 * kPi / 180.0}, beam};
  c.end = EndCondition::kFixed;
  c.prescribed.y = tip_y;
  return c;
}

TEST(Cbcm, TakesTheAxialStiffnessFromTheSegmentsEA) {
  // Against the shooting method (Reissner's extensible beam, docs/extensible.md) past the
  // buckling of the beam (1.29 mm of travel) to beyond the flat position. The chained BCM
  // converges to it as N grows (the clamp's force at second order in h: measured at y = 2 mm,
  // 6/12/24/48/96 elements off by +1.0e-2, -1.6e-3, -6.1e-4, -1.6e-4, -4e-5 N of 52.663 N);
  // the bounds are the largest measured relative force errors over the five positions with a
  // margin (6: 3.1e-4, 24: 1.2e-5), and from 24 to 48 elements the error halves or is below 1e-6
  // (at -2 mm it is 7.7e-7 at 24, 4.4e-7 at 48: near a change of sign).
  for (double tip_y : {6e-3, 4e-3, 2e-3, 0.0, -2e-3}) {
    SCOPED_TRACE(::testing::Message() << "tip y " << tip_y);
    const SegmentChain chain = inclined_bistable_beam(tip_y);
    const ShootingResult s = solve_shooting(chain, ShootingSolver::Options{});
    ASSERT_TRUE(s.converged()) << s.message;
    const double scale = std::hypot(s.reaction.Fx, s.reaction.Fy);
    const auto error = [&](int N) {
      const CbcmResult r = cbcm(N).solve(chain);
      EXPECT_TRUE(r.converged()) << r.message;
      EXPECT_NEAR(r.tip.y, tip_y, 1e-12);
      const double d = 12.0 * (70.0 / 1.5) * (70.0 / 1.5);  // EA L^2/EI of the rectangle
      EXPECT_NEAR(r.axial_stiffness, d, 1e-9 * d);
      return std::max(std::fabs(r.reaction.Fx - s.reaction.Fx),
                      std::fabs(r.reaction.Fy - s.reaction.Fy)) /
             scale;
    };
    const double e6 = error(6), e24 = error(24), e48 = error(48);
    EXPECT_LT(e6, 5e-4);
    EXPECT_LT(e24, 3e-5);
    EXPECT_LT(e48, std::max(0.5 * e24, 1e-6));
  }
}

TEST(Cbcm, AxialStiffnessIsGivenOnceAndShearIsNamed) {
  const SegmentChain chain = inclined_bistable_beam(4e-3);
  ChainedBcmSolver::Options o;
  o.slenderness = 46.667;
  try {
    ChainedBcmSolver(o).solve(chain);
    FAIL() << "EA and a slenderness together";
  } catch (const InvalidInput& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("EA = 25959.7"), std::string::npos) << what;
    EXPECT_NE(what.find("slenderness L/t = 46.667"), std::string::npos) << what;
  }
  // Without EA the slenderness sets d: the same beam, the same answer.
  SegmentChain inextensible = chain;
  std::get<FlexibleSegment>(inextensible.segments[1]).EA = std::numeric_limits<double>::infinity();
  o.slenderness = 70.0 / 1.5;
  const CbcmResult by_slenderness = ChainedBcmSolver(o).solve(inextensible);
  const CbcmResult by_EA = cbcm(6).solve(chain);
  ASSERT_TRUE(by_slenderness.converged()) << by_slenderness.message;
  EXPECT_NEAR(by_slenderness.reaction.Fx, by_EA.reaction.Fx, 1e-9 * std::fabs(by_EA.reaction.Fx));
  EXPECT_NEAR(by_slenderness.reaction.M, by_EA.reaction.M, 1e-9 * std::fabs(by_EA.reaction.M));
  // The BCM is shear-rigid: a segment's GAs is named in a warning, not silently dropped.
  SegmentChain shear = chain;
  std::get<FlexibleSegment>(shear.segments[1]).GAs = 1e4;
  const CbcmResult w = cbcm(6).solve(shear);
  ASSERT_FALSE(w.warnings.empty());
  EXPECT_NE(w.warnings.back().text.find("GAs"), std::string::npos);
}

TEST(Cbcm, InextensibleSegmentCompressedBetweenFixedEndsSaysSo) {
  // Without EA the beam cannot shorten along its axis; the message names the missing EA instead
  // of leaving a fold of the load path as the likeliest cause.
  SegmentChain chain = inclined_bistable_beam(2e-3);
  std::get<FlexibleSegment>(chain.segments[1]).EA = std::numeric_limits<double>::infinity();
  const CbcmResult r = cbcm(6).solve(chain);
  ASSERT_FALSE(r.converged());
  EXPECT_NE(r.message.find("inextensible (no EA)"), std::string::npos) << r.message;
}

TEST(LadderRefusals, ChainsOutsideTheChainedBcmsClass) {
  SegmentChain two;
  two.segments = {FlexibleSegment{0.5, 1.0}, FlexibleSegment{0.5, 1.0}};
  EXPECT_THROW(cbcm(4).solve(two), InvalidInput);
  SegmentChain curved = uniform_cantilever(EndLoad{0, 1, 0});
  std::get<FlexibleSegment>(curved.segments[0]).kappa0 = 1.0;
  EXPECT_THROW(cbcm(4).solve(curved), InvalidInput);
  SegmentChain loaded = uniform_cantilever(EndLoad{0, 1, 0});
  std::get<FlexibleSegment>(loaded.segments[0]).qy = -1.0;  // a distributed load
  EXPECT_THROW(cbcm(4).solve(loaded), InvalidInput);
  SegmentChain follower = uniform_cantilever(EndLoad{0, 1, 0});
  follower.tip_load.follower = 1.0;
  try {
    cbcm(4).solve(follower);
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("shooting"), std::string::npos);
  }
  // An unreachable prescribed tip (farther than the segment is long) is bad input.
  SegmentChain far = uniform_cantilever(EndLoad{});
  far.end = EndCondition::kFixed;
  far.prescribed = {1.0, 0.2, 0.0};
  EXPECT_THROW(cbcm(4).solve(far), InvalidInput);
}

TEST(LadderRefusals, OptionsNameTheBadField) {
  ChainedBcmSolver::Options o;
  o.elements = 0;
  EXPECT_THROW(ChainedBcmSolver{o}, InvalidInput);
  o.elements = 4;
  o.slenderness = -1.0;
  EXPECT_THROW(ChainedBcmSolver{o}, InvalidInput);
  Prbm3rSolver::Options p;
  p.constants.gamma = {0.5, 0.5, 0.5, -0.5};
  EXPECT_THROW(Prbm3rSolver{p}, InvalidInput);
  EXPECT_THROW(Prbm3rConstants::by_name("howell"), InvalidInput);
  BcmSolver::Options b;
  b.slenderness = std::nan("");
  EXPECT_THROW(BcmSolver{b}, InvalidInput);
}

}  // namespace
}  // namespace flexure

namespace flexure {
namespace {

TEST(LadderLoadPath, StaysOnTheBranchOfProportionalLoading) {
  // A compressive tip force with an opposing end moment: the tip angle of the path stays small
  // while the beam turns into an S. Watching the tip angle alone, one long step converged onto
  // another equilibrium (theta0 = -0.96 for the CBCM, -0.88 and unstable for PR-3R, against the
  // elastica's +0.750, whose load path has no fold here).
  const CantileverCase c = free_case(1.0, 4.0, -2.0);
  const EllipticResult e = EllipticSolver().solve(c.load);
  ASSERT_TRUE(e.converged());
  ASSERT_EQ(e.limit_points, 0);
  const CbcmResult r = cbcm(32).solve(c);
  ASSERT_TRUE(r.converged()) << r.message;
  EXPECT_NEAR(r.tip.theta, e.tip.theta0, 1e-3);
  const Prbm3rResult p = Prbm3rSolver().solve(c);
  ASSERT_TRUE(p.converged()) << p.message;
  EXPECT_TRUE(p.stable);
  EXPECT_NEAR(p.tip.theta0, e.tip.theta0, 0.1);
}

}  // namespace
}  // namespace flexure
