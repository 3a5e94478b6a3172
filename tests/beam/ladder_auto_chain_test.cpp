// `beam --chain FILE --method auto --tol T` across the model ladder (beam_auto_ladder.cpp,
// mapped_chain; docs/models.md "auto across the ladder"). What is checked against what:
//  * On 32 seeded random chains that are one uniform segment (random L, EI) placed by a rigid link
//    and a kink at its root (random length and angle) and loaded at its tip (random loads inside
//    the map's (n, alpha2, mu) range, turned into the root frame), with tolerances 1e-1, 3e-2,
//    1e-2, 1e-3: the model auto chooses has its tip, measured here against the shooting method on
//    the same chain, within the tolerance (relative to the exact tip displacement, the measure of
//    --tol). The sample must choose cheaper models than the exact methods in several cases.
//  * Chains the map does not cover (a rigid link after the segment, two flexible segments, a
//    fixed end, an extensible segment) go to an exact method and say why in method_reason.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <map>
#include <random>
#include <string>

#include "flexure/beam/beam_problem.h"
#include "flexure/beam/ladder_selector.h"
#include "flexure/solver/chain_model/segment_chain.h"

namespace flexure {
namespace {

struct RandomChain {
  SegmentChain chain;
  double L = 1.0;
};

RandomChain random_chain(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const bench::LadderMapRange range = bench::ladder_map_range();
  RandomChain c;
  c.L = 0.5 + 1.5 * u(rng);
  const double EI = 0.5 + 4.5 * u(rng);
  const double link = u(rng) < 0.5 ? 0.0 : 0.8 * u(rng);
  const double phi = -1.0 + 2.0 * u(rng);
  // Loads inside the map, away from its edges (the map's own cells are checked elsewhere).
  const double n = range.n_min + (range.n_max - range.n_min) * (0.05 + 0.9 * u(rng));
  const double alpha2 =
      range.alpha2_min + (range.alpha2_max - range.alpha2_min) * (0.02 + 0.3 * u(rng));
  const double mu = range.mu_min + (range.mu_max - range.mu_min) * (0.1 + 0.8 * u(rng));
  const double force = EI / (c.L * c.L);
  const double Fx_local = -n * alpha2 * force, Fy_local = alpha2 * force;
  c.chain.segments.push_back(RigidSegment{link, phi});
  c.chain.segments.push_back(FlexibleSegment(c.L, EI));
  c.chain.tip_load.Fx = Fx_local * std::cos(phi) - Fy_local * std::sin(phi);
  c.chain.tip_load.Fy = Fx_local * std::sin(phi) + Fy_local * std::cos(phi);
  c.chain.tip_load.M = mu * EI / c.L;
  return c;
}

BeamProblem chain_problem(const SegmentChain& chain, double tolerance) {
  BeamProblem p;
  p.chain = chain;
  p.tolerance = tolerance;
  return p;
}

TEST(LadderAutoChain, RandomChainsChooseAModelWithinTheTolerance) {
  std::mt19937 rng(3030);
  const double tolerances[] = {1e-1, 3e-2, 1e-2, 1e-3};
  std::map<BeamMethod, int> chosen;
  for (int k = 0; k < 32; ++k) {
    const RandomChain c = random_chain(rng);
    const double T = tolerances[k % 4];
    const BeamSolution s = solve_beam(BeamMethod::kAuto, chain_problem(c.chain, T));
    ASSERT_TRUE(s.converged()) << k << ": " << s.message;
    ASSERT_FALSE(s.method_reason.empty());
    ++chosen[s.method];
    const BeamSolution exact = solve_beam(BeamMethod::kShooting, chain_problem(c.chain, 1e-9));
    ASSERT_TRUE(exact.converged()) << k;
    // Tip poses per the chain's total length; the unloaded tip is the chain's own.
    const double total = c.chain.total_length();
    const ChainPose rest = c.chain.unloaded_tip();
    const double d =
        std::hypot(exact.tip.a_over_l - rest.x / total, exact.tip.b_over_l - rest.y / total);
    const double error =
        std::hypot(s.tip.a_over_l - exact.tip.a_over_l, s.tip.b_over_l - exact.tip.b_over_l);
    EXPECT_LE(error, T * d) << k << ": " << to_string(s.method) << ", " << s.method_reason;
    if (s.method != BeamMethod::kShooting && s.method != BeamMethod::kElliptic) {
      EXPECT_NE(s.method_reason.find("one uniform segment loaded at its end"), std::string::npos)
          << s.method_reason;
      EXPECT_LE(s.expected_error, T) << k;
    }
  }
  int cheaper = 0;
  std::cout << "chosen:";
  for (const auto& [method, count] : chosen) std::cout << ' ' << to_string(method) << ' ' << count;
  std::cout << '\n';
  for (const auto& [method, count] : chosen) {
    if (method != BeamMethod::kShooting && method != BeamMethod::kElliptic) cheaper += count;
  }
  EXPECT_GE(cheaper, 6) << "the sample must exercise the ladder's cheap models";
  EXPECT_GE(chosen.size(), 2u);
}

// Guided ends (the guided map): the same chains with the tip angle held at its stress-free value
// and no end moment (the guide's reaction); loads inside the guided map.
TEST(LadderAutoChain, RandomGuidedChainsChooseAModelWithinTheTolerance) {
  std::mt19937 rng(3033);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const bench::LadderMapRange range = bench::ladder_guided_map_range();
  int cheaper = 0;
  for (int k = 0; k < 16; ++k) {
    const double L = 0.5 + 1.5 * u(rng), EI = 0.5 + 4.5 * u(rng);
    const double phi = -1.0 + 2.0 * u(rng), link = 0.5 * u(rng);
    const double n = range.n_min + (range.n_max - range.n_min) * (0.05 + 0.9 * u(rng));
    const double alpha2 =
        range.alpha2_min + (range.alpha2_max - range.alpha2_min) * (0.02 + 0.3 * u(rng));
    const double force = EI / (L * L);
    const double Fx = -n * alpha2 * force, Fy = alpha2 * force;
    SegmentChain chain;
    chain.segments.push_back(RigidSegment{link, phi});
    chain.segments.push_back(FlexibleSegment(L, EI));
    chain.end = EndCondition::kGuided;
    chain.tip_load.Fx = Fx * std::cos(phi) - Fy * std::sin(phi);
    chain.tip_load.Fy = Fx * std::sin(phi) + Fy * std::cos(phi);
    const double T = k % 2 == 0 ? 3e-2 : 3e-3;
    const BeamSolution s = solve_beam(BeamMethod::kAuto, chain_problem(chain, T));
    ASSERT_TRUE(s.converged()) << k << ": " << s.message;
    const BeamSolution exact = solve_beam(BeamMethod::kShooting, chain_problem(chain, 1e-9));
    ASSERT_TRUE(exact.converged()) << k;
    const double total = chain.total_length();
    const ChainPose rest = chain.unloaded_tip();
    const double d =
        std::hypot(exact.tip.a_over_l - rest.x / total, exact.tip.b_over_l - rest.y / total);
    const double error =
        std::hypot(s.tip.a_over_l - exact.tip.a_over_l, s.tip.b_over_l - exact.tip.b_over_l);
    EXPECT_LE(error, T * d) << k << ": " << to_string(s.method) << ", " << s.method_reason;
    if (s.method != BeamMethod::kShooting) {
      ++cheaper;
      EXPECT_NE(s.method_reason.find("guided tip angle"), std::string::npos) << s.method_reason;
    }
  }
  std::cout << "guided: " << cheaper << " of 16 by a cheaper model\n";
  EXPECT_GE(cheaper, 4);
}

TEST(LadderAutoChain, ChainsOutsideTheMapFallBackToAnExactMethodAndSayWhy) {
  SegmentChain base;
  base.segments.push_back(FlexibleSegment(1.0, 1.0));
  base.tip_load.Fy = 0.5;
  struct Case {
    const char* what;
    SegmentChain chain;
    const char* reason;
  };
  std::vector<Case> cases;
  SegmentChain trailing = base;
  trailing.segments.push_back(RigidSegment{0.3, 0.2});
  cases.push_back({"trailing link", trailing, "after the flexible segment"});
  SegmentChain two = base;
  two.segments.push_back(FlexibleSegment(0.5, 1.0));
  cases.push_back({"two flexible segments", two, "2 flexible segments"});
  SegmentChain fixed = base;
  fixed.end = EndCondition::kFixed;
  fixed.tip_load = {};
  fixed.prescribed.x = 0.99;
  fixed.prescribed.y = 0.05;
  cases.push_back({"fixed end", fixed, "fixed end"});
  SegmentChain extensible = base;
  std::get<FlexibleSegment>(extensible.segments[0]).EA = 1e4;
  cases.push_back({"extensible", extensible, "extensible"});
  for (const Case& c : cases) {
    const BeamSolution s = solve_beam(BeamMethod::kAuto, chain_problem(c.chain, 1e-2));
    ASSERT_TRUE(s.converged()) << c.what << ": " << s.message;
    EXPECT_EQ(s.method, BeamMethod::kShooting) << c.what;
    EXPECT_NE(s.method_reason.find("do not cover this chain"), std::string::npos)
        << c.what << ": " << s.method_reason;
    EXPECT_NE(s.method_reason.find(c.reason), std::string::npos)
        << c.what << ": " << s.method_reason;
  }
}

}  // namespace
}  // namespace flexure
