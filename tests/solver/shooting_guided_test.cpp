// What is checked against what: the shooting solver's fixed-guided beam (Howell §5.3: tip angle
// held at zero, end force given) against the antisymmetry relation -- a guided beam of length 1 is
// two cantilevers of length 1/2 joined at the inflection point at mid-length, each carrying the end
// force with zero moment. The half cantilever is solved independently by the elliptic solver
// (nondimensional alpha2 = F (l/2)^2, lengths scaled by 1/2), so tip deflection, shortening and the
// clamp moment of the guided beam must be 2x, 2x and 1x the half-cantilever values.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/elliptic/elliptic_solver.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {
namespace {

// Issue requirement: antisymmetry to 1e-9. Shooting runs at rtol 1e-12 and the elliptic solver at
// 1e-14, so the margin is three orders of magnitude.
constexpr double kAntisymmetryTolerance = 1e-9;

SegmentChain guided_beam(double Fx, double Fy) {
  SegmentChain chain;
  chain.segments.push_back(FlexibleSegment{1.0, 1.0, {}, 0.0});
  chain.end = EndCondition::kGuided;  // theta(tip) = 0 by default for a straight beam
  chain.tip_load.Fx = Fx;
  chain.tip_load.Fy = Fy;
  return chain;
}

struct GuidedCase {
  double load_ratio_n;  // Howell's n: Fx = -n P
  double P;             // transverse end force, P l^2 / EI
};

class ShootingGuidedBeam : public ::testing::TestWithParam<GuidedCase> {};

TEST_P(ShootingGuidedBeam, EqualsTwoHalfCantilevers) {
  const GuidedCase c = GetParam();
  const double Fx = -c.load_ratio_n * c.P, Fy = c.P;
  const ShootingResult guided = ShootingSolver().solve(guided_beam(Fx, Fy));
  ASSERT_TRUE(guided.converged()) << guided.message;

  // Half cantilever, length 1/2, EI 1: nondimensional load F (1/2)^2.
  const EllipticResult half = EllipticSolver().solve(EndLoad{0.25 * Fx, 0.25 * Fy, 0.0});
  ASSERT_TRUE(half.converged()) << "elliptic solver: " << half.message;
  const double half_x = 0.5 * half.tip.a_over_l, half_y = 0.5 * half.tip.b_over_l;

  EXPECT_NEAR(guided.tip.y, 2.0 * half_y, kAntisymmetryTolerance);
  EXPECT_NEAR(1.0 - guided.tip.x, 2.0 * (0.5 - half_x), kAntisymmetryTolerance);
  EXPECT_NEAR(guided.tip.theta, 0.0, kAntisymmetryTolerance);
  // Clamp moment: the half cantilever's root moment F x r(half tip) (Howell eq. 2.67 at x = 0).
  const double half_root_moment = Fy * half_x - Fx * half_y;
  EXPECT_NEAR(-guided.reaction.M, half_root_moment, kAntisymmetryTolerance);
  // The guide carries the opposite moment (antisymmetry about the inflection point).
  EXPECT_NEAR(guided.tip_load.M, -half_root_moment, kAntisymmetryTolerance);
}

INSTANTIATE_TEST_SUITE_P(TransverseAndAxialLoads,
                         ShootingGuidedBeam,
                         ::testing::Values(GuidedCase{0.0, 1.0},
                                           GuidedCase{0.0, 5.0},
                                           GuidedCase{0.0, 12.0},
                                           GuidedCase{0.0, 30.0},
                                           GuidedCase{0.0, 60.0},
                                           GuidedCase{-1.0, 10.0},
                                           GuidedCase{0.5, 8.0},
                                           GuidedCase{1.0, 4.0}),
                         [](const ::testing::TestParamInfo<GuidedCase>& info) {
                           // e.g. "n_minus1_P10", "n0p5_P8": gtest names allow [A-Za-z0-9_].
                           auto label = [](double v) {
                             std::string text = std::to_string(v);
                             text.erase(text.find_last_not_of('0') + 1);
                             if (text.back() == '.') text.pop_back();
                             for (char& c : text) {
                               if (c == '.') c = 'p';
                             }
                             return text[0] == '-' ? "minus" + text.substr(1) : text;
                           };
                           return "n" + label(info.param.load_ratio_n) + "_P" + label(info.param.P);
                         });

}  // namespace
}  // namespace flexure
