// What is checked against what: `--method auto` across the model ladder (beam_auto_ladder.h,
// ladder_selector.h, data/ladder_auto_error_map.csv).
//  * The embedded map is the file, and a value read from it is the error of linear theory's
//    closed form against the exact elliptic solution at that load, rounded up to 2 digits.
//  * On seeded random free-cantilever loads and tolerances, the model auto chooses has an ACTUAL
//    error, measured here against the elliptic solution, within the tolerance (relative to the
//    exact tip displacement, the measure of --tol) and within its reported
//    expected_error_per_length; and every rung the map lists as cheaper fails the rule when solved
//    here (so the choice is the cheapest within the tolerance by the map's times). The sample must
//    exercise several rungs.
//  * A tolerance tighter than every cheap model's mapped error goes to the exact methods.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <random>
#include <string>

#include "flexure/beam/beam_problem.h"
#include "flexure/beam/data_files.h"
#include "flexure/beam/ladder_selector.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/elliptic/elliptic_solver.h"
#include "tests/support/data_file_support.h"

namespace flexure {
namespace {

BeamProblem cantilever(double n, double alpha2, double mu, double tolerance) {
  BeamProblem p;
  p.load_ratio_n = n;
  p.value = alpha2;
  p.mu = mu;
  p.tolerance = tolerance;
  return p;
}

double displacement(const TipPose& t) { return std::hypot(t.a_over_l - 1.0, t.b_over_l); }
double distance(const TipPose& a, const TipPose& b) {
  return std::hypot(a.a_over_l - b.a_over_l, a.b_over_l - b.b_over_l);
}

TEST(LadderAutoMap, EmbeddedCopyEqualsTheFile) {
  test::expect_embedded_equals_file(data::ladder_auto_error_map());
}

TEST(LadderAutoMap, AxialEmbeddedCopyEqualsTheFile) {
  test::expect_embedded_equals_file(data::ladder_auto_error_map_axial());
}

// Inverse problems (a given theta0 or b/l) by auto: where a rung of the ladder answers, the exact
// elastica under the load it found has its tip within the tolerance (relative to its displacement)
// of the rung's tip, on seeded random targets; the rest go to the exact methods and meet the
// target.
TEST(LadderAuto, InverseProblemsChooseARungWithinTheTolerance) {
  std::mt19937 rng(3031);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::map<BeamMethod, int> chosen;
  int checked = 0;
  for (int trial = 0; trial < 80; ++trial) {
    BeamProblem p;
    p.load_ratio_n = -1.5 + 3.0 * u(rng);
    p.mu = trial % 3 == 0 ? 0.0 : (u(rng) - 0.5) * 0.6;
    p.tolerance = std::pow(10.0, -3.0 + 2.5 * u(rng));
    const bool theta = trial % 2 == 0;
    p.given = theta ? BeamProblem::Given::kTheta0 : BeamProblem::Given::kBOverL;
    // Weighted toward small deflections, where the cheap rungs are accurate.
    p.value = (theta ? 1.2 : 0.6) * std::pow(u(rng), 3.0) + 0.002;
    BeamSolution s;
    try {
      s = solve_beam(BeamMethod::kAuto, p);
    } catch (const InvalidInput&) {
      continue;  // a target no load reaches (e.g. against the end moment)
    }
    if (!s.converged()) continue;
    ++checked;
    ++chosen[s.method];
    const std::string where = fmt::format("n = {}, mu = {}, {} = {}, tol = {}: {}",
                                          p.load_ratio_n,
                                          p.mu,
                                          theta ? "theta0" : "b/l",
                                          p.value,
                                          p.tolerance,
                                          s.method_reason);
    const double reached = theta ? s.tip.theta0 : s.tip.b_over_l;
    EXPECT_NEAR(reached, p.value, 1e-8 * std::max(1.0, std::fabs(p.value))) << where;
    if (s.method == BeamMethod::kElliptic || s.method == BeamMethod::kShooting) continue;
    const BeamSolution exact =
        solve_beam(BeamMethod::kElliptic, cantilever(p.load_ratio_n, s.alpha2, p.mu, 1e-6));
    ASSERT_TRUE(exact.converged()) << where;
    const double error = distance(s.tip, exact.tip);
    EXPECT_LE(error / displacement(exact.tip), p.tolerance) << where;
    EXPECT_LE(error / displacement(exact.tip), s.expected_error) << where;
    EXPECT_LE(error, s.expected_error_per_length) << where;
  }
  EXPECT_GE(checked, 60);
  const int exact = chosen[BeamMethod::kElliptic] + chosen[BeamMethod::kShooting];
  EXPECT_GE(checked - exact, 10) << "rungs chosen: linear " << chosen[BeamMethod::kLinear]
                                 << ", bcm " << chosen[BeamMethod::kBcm] << ", prbm3r "
                                 << chosen[BeamMethod::kPrbm3r] << ", cbcm "
                                 << chosen[BeamMethod::kCbcm];
  std::cout << "inverse auto: " << checked << " problems; linear " << chosen[BeamMethod::kLinear]
            << ", bcm " << chosen[BeamMethod::kBcm] << ", prbm3r " << chosen[BeamMethod::kPrbm3r]
            << ", cbcm " << chosen[BeamMethod::kCbcm] << ", exact " << exact << "\n";
}

// Where the ladder's maps do not apply, auto says why in its reason.
TEST(LadderAuto, FollowerForcesSayWhyTheLadderIsNotTried) {
  BeamProblem follower = cantilever(0.0, 0.0, 0.0, 1e-2);
  follower.follower = 1.0;
  const BeamSolution f = solve_beam(BeamMethod::kAuto, follower);
  ASSERT_TRUE(f.converged()) << f.message;
  EXPECT_NE(f.method_reason.find("not tried for a follower force"), std::string::npos)
      << f.method_reason;
}

TEST(LadderAutoMap, GuidedEmbeddedCopyEqualsTheFile) {
  test::expect_embedded_equals_file(data::ladder_auto_error_map_guided());
}

// The guided end (data/ladder_auto_error_map_guided.csv): on seeded random loads and tip angles
// the chosen rung's tip is within the tolerance (relative to the exact displacement) of the
// shooting method's, and within its expected error.
TEST(LadderAuto, GuidedEndChoosesARungWithinTheTolerance) {
  std::mt19937 rng(3032);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::map<BeamMethod, int> chosen;
  int checked = 0;
  for (int trial = 0; trial < 150; ++trial) {
    BeamProblem p = cantilever(-2.0 + 4.0 * u(rng), 40.0 * std::pow(u(rng), 3.0), 0.0, 0.0);
    p.tolerance = std::pow(10.0, -5.0 + 4.0 * u(rng));
    p.boundary = EndCondition::kGuided;
    if (trial % 3 != 0) p.prescribed.theta = (u(rng) - 0.5) * 2.0 * std::pow(u(rng), 2.0);
    const BeamSolution exact = solve_beam(BeamMethod::kShooting, p);
    if (!exact.converged() || exact.limit_points > 0) continue;
    const BeamSolution s = solve_beam(BeamMethod::kAuto, p);
    ASSERT_TRUE(s.converged()) << s.message;
    ++checked;
    ++chosen[s.method];
    if (s.method == BeamMethod::kShooting || s.method == BeamMethod::kElliptic) continue;
    const std::string where = fmt::format("n = {}, alpha2 = {}, tip angle = {}, tol = {}: {}",
                                          p.load_ratio_n,
                                          p.value,
                                          p.prescribed.theta.value_or(0.0),
                                          p.tolerance,
                                          s.method_reason);
    const double error = distance(s.tip, exact.tip);
    EXPECT_LE(error / displacement(exact.tip), p.tolerance) << where;
    EXPECT_LE(error / displacement(exact.tip), s.expected_error) << where;
    EXPECT_LE(error, s.expected_error_per_length) << where;
    EXPECT_NE(s.method_reason.find("ladder_auto_error_map_guided.csv"), std::string::npos);
  }
  EXPECT_GE(checked, 120);
  int rungs = 0;
  for (const auto& [m, count] : chosen) {
    if (m != BeamMethod::kShooting && m != BeamMethod::kElliptic) rungs += count;
  }
  std::cout << "guided auto: " << checked << " loads; linear " << chosen[BeamMethod::kLinear]
            << ", prbm " << chosen[BeamMethod::kPrbm] << ", bcm " << chosen[BeamMethod::kBcm]
            << ", prbm3r " << chosen[BeamMethod::kPrbm3r] << ", cbcm " << chosen[BeamMethod::kCbcm]
            << ", shooting " << chosen[BeamMethod::kShooting] << ", elliptic "
            << chosen[BeamMethod::kElliptic] << "\n";
  EXPECT_GE(rungs, 20);
}

TEST(LadderAutoMap, ValueIsLinearTheorysErrorAgainstTheEllipticSolution) {
  // The file's row n = 0, alpha2 = 0.1, mu = 0: linear_error 0.00067. Linear theory: a = 1,
  // b = alpha2/3 (docs/models.md).
  const EllipticResult exact = EllipticSolver().solve(EndLoad::howell(0.0, 0.1, 0.0));
  ASSERT_TRUE(exact.converged());
  const double error = std::hypot(1.0 - exact.tip.a_over_l, 0.1 / 3.0 - exact.tip.b_over_l);
  EXPECT_LE(error, 0.00067);
  EXPECT_GE(error, 0.00067 / 1.1);  // rounded up to two significant digits
  EXPECT_EQ(bench::ladder_mapped_error(BeamMethod::kLinear, 0.0, 0.1, 0.0),
            bench::kBetweenNodesMargin * 0.00067);
  EXPECT_TRUE(std::isnan(bench::ladder_mapped_error(BeamMethod::kLinear, 0.0, 10.5, 0.0)));
  EXPECT_TRUE(std::isnan(bench::ladder_mapped_error(BeamMethod::kPrbm, 0.0, 1.0, 0.5)));
}

TEST(LadderAuto, ChosenModelIsWithinTheToleranceAndTheCheapestOnSeededRandomLoads) {
  std::mt19937 rng(30);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::map<BeamMethod, int> chosen;
  int checked = 0;
  for (int trial = 0; trial < 250; ++trial) {
    const double n = -2.0 + 4.0 * u(rng);
    // Weighted toward small loads, where linear theory and the BCM are accurate.
    const double alpha2 = 10.0 * std::pow(u(rng), 3.0);
    const double mu = trial % 4 == 0 ? 0.0 : (u(rng) - 0.5) * 4.0 * std::pow(u(rng), 2.0);
    const double tolerance = std::pow(10.0, -5.0 + 4.0 * u(rng));
    const BeamProblem p = cantilever(n, alpha2, mu, tolerance);
    const BeamSolution exact = solve_beam(BeamMethod::kElliptic, p);
    if (!exact.converged() || exact.limit_points > 0) continue;
    const BeamSolution s = solve_beam(BeamMethod::kAuto, p);
    ASSERT_TRUE(s.converged()) << s.message;
    ++checked;
    ++chosen[s.method];
    const std::string where = fmt::format(
        "n = {}, alpha2 = {}, mu = {}, tol = {}: {}", n, alpha2, mu, tolerance, s.method_reason);
    if (s.method != BeamMethod::kElliptic) {
      const double error = distance(s.tip, exact.tip);
      EXPECT_LE(error / displacement(exact.tip), tolerance) << where;
      EXPECT_LE(error, s.expected_error_per_length) << where;
      EXPECT_LE(error / displacement(exact.tip), s.expected_error) << where;
    }
    // Every rung the map lists before the chosen one fails the rule, solved here.
    const auto rungs = bench::ladder_estimates(n, alpha2, mu);
    ASSERT_TRUE(rungs.has_value());
    for (const bench::LadderEstimate& r : *rungs) {
      if (r.method == s.method || r.method == BeamMethod::kElliptic) break;
      bool meets = false;
      try {
        const BeamSolution other = solve_beam(r.method, p);
        meets =
            other.converged() &&
            bench::relative_error_bound(r.error_per_length, displacement(other.tip)) <= tolerance &&
            (r.method != BeamMethod::kPrbm || other.prbm_inside_validity);
      } catch (const InvalidInput&) {
      }
      EXPECT_FALSE(meets) << to_string(r.method) << " is cheaper and within the tolerance; "
                          << where;
    }
  }
  EXPECT_GE(checked, 200);
  // The sample exercises the ladder: several cheap rungs and the exact solution.
  EXPECT_GE(chosen[BeamMethod::kElliptic], 20);
  int cheap_rungs = 0;
  for (BeamMethod m : {BeamMethod::kLinear,
                       BeamMethod::kBcm,
                       BeamMethod::kPrbm,
                       BeamMethod::kPrbm3r,
                       BeamMethod::kCbcm}) {
    if (chosen[m] >= 3) ++cheap_rungs;
  }
  EXPECT_GE(cheap_rungs, 3) << "linear " << chosen[BeamMethod::kLinear] << ", bcm "
                            << chosen[BeamMethod::kBcm] << ", prbm " << chosen[BeamMethod::kPrbm]
                            << ", prbm3r " << chosen[BeamMethod::kPrbm3r] << ", cbcm "
                            << chosen[BeamMethod::kCbcm];
}

// The margin itself: every rung's actual error at seeded random loads against the largest error
// measured at the loads around it (the bound divided by the margin). The ratio must stay below
// the margin; its largest value is printed (docs/models.md quotes it).
TEST(LadderAuto, MappedBoundHoldsForEveryRungOnSeededRandomLoads) {
  std::mt19937 rng(3030);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::map<BeamMethod, double> worst;
  int compared = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const double n = -2.0 + 4.0 * u(rng);
    const double alpha2 = 10.0 * std::pow(u(rng), 2.0);
    const double mu = trial % 5 == 0 ? 0.0 : (u(rng) - 0.5) * 4.0;
    const BeamProblem p = cantilever(n, alpha2, mu, 1e-6);
    const BeamSolution exact = solve_beam(BeamMethod::kElliptic, p);
    if (!exact.converged() || exact.limit_points > 0) continue;
    const auto rungs = bench::ladder_estimates(n, alpha2, mu);
    ASSERT_TRUE(rungs.has_value());
    for (const bench::LadderEstimate& r : *rungs) {
      if (r.method == BeamMethod::kElliptic) continue;
      const BeamSolution s = solve_beam(r.method, p);
      ASSERT_TRUE(s.converged()) << to_string(r.method) << " at " << n << ", " << alpha2 << ", "
                                 << mu;
      const double ratio =
          distance(s.tip, exact.tip) / (r.error_per_length / bench::kBetweenNodesMargin);
      if (std::isfinite(ratio)) worst[r.method] = std::max(worst[r.method], ratio);
      EXPECT_LE(distance(s.tip, exact.tip), r.error_per_length)
          << to_string(r.method) << " at " << n << ", " << alpha2 << ", " << mu;
      ++compared;
    }
  }
  EXPECT_GE(compared, 600);
  for (const auto& [method, ratio] : worst) {
    std::cout << to_string(method) << ": actual error / largest around it <= " << ratio << "\n";
  }
}

TEST(LadderAuto, ToleranceTighterThanEveryCheapModelGoesToTheExactMethods) {
  // At alpha2 = 0.02 the CBCM's mapped error is about 1e-9 l and the others' larger: 1e-9 of
  // the displacement (0.0067 l) is out of their reach.
  const BeamSolution s = solve_beam(BeamMethod::kAuto, cantilever(0.0, 0.02, 0.0, 1e-9));
  EXPECT_EQ(s.method, BeamMethod::kElliptic) << s.method_reason;
  EXPECT_NE(s.method_reason.find("no model of the ladder meets the tolerance"), std::string::npos)
      << s.method_reason;
  EXPECT_THROW(solve_beam(BeamMethod::kAuto, cantilever(0.0, 0.02, 0.0, 1e-15)),
               bench::ToleranceBelowReach);
  // Loose: linear theory, the cheapest rung, and its reason gives its mapped error and T.
  const BeamSolution loose = solve_beam(BeamMethod::kAuto, cantilever(0.0, 0.02, 0.0, 0.05));
  EXPECT_EQ(loose.method, BeamMethod::kLinear) << loose.method_reason;
  EXPECT_NE(loose.method_reason.find("within the tolerance 0.05"), std::string::npos)
      << loose.method_reason;
}

// Off the ladder's map (n > 2) the 1R PRBM's own measured map (beam_problem.h, to n = 3)
// still applies, and the reason says the load is off the ladder's map.
TEST(LadderAuto, OffTheMapThePrbmsOwnMapStillApplies) {
  const BeamSolution s = solve_beam(BeamMethod::kAuto, cantilever(2.5, 1.0, 0.0, 0.1));
  EXPECT_EQ(s.method, BeamMethod::kPrbm) << s.method_reason;
  EXPECT_NE(s.method_reason.find("off the model ladder's map"), std::string::npos)
      << s.method_reason;
  EXPECT_NE(s.method_reason.find("Theta_max"), std::string::npos) << s.method_reason;
}

TEST(LadderAuto, NamedModelsReportTheirMappedError) {
  const BeamProblem p = cantilever(0.0, 3.0, 1.0, 1e-6);
  const BeamSolution s = solve_beam(BeamMethod::kPrbm3r, p);
  ASSERT_TRUE(s.converged());
  EXPECT_EQ(s.expected_error_per_length,
            bench::ladder_mapped_error(BeamMethod::kPrbm3r, 0.0, 3.0, 1.0));
  const BeamSolution exact = solve_beam(BeamMethod::kElliptic, p);
  EXPECT_LE(distance(s.tip, exact.tip), s.expected_error_per_length);
  EXPECT_TRUE(std::isnan(solve_beam(BeamMethod::kChain, p).expected_error_per_length));
  BeamProblem other_constants = p;
  other_constants.prbm3r_constants = Prbm3rConstantSet::kFlexure;  // not the map's settings
  EXPECT_TRUE(
      std::isnan(solve_beam(BeamMethod::kPrbm3r, other_constants).expected_error_per_length));
}

}  // namespace
}  // namespace flexure
