// Chains in physical units read from TOML (io/toml_files.h) and solved by the beam layer
// (beam/physical_beam.h), checked against:
//  * Howell's small-length flexural pivot of sec. 5.1 as a chain file in inches and pounds
//    (polypropylene, 0.096 lb: b = 3 in, sigma = F a c/I = 3900 psi);
//  * the same strip given as flags (PhysicalCantilever) and as a chain file, by two methods;
//  * the same chain built from the library's objects (PhysicalChain): the file is one, and gives
//    bitwise the same answer.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "flexure/beam/physical_beam.h"
#include "flexure/io/toml_files.h"
#include "flexure/solver/common/status.h"
#include "tests/support/physical_beam_support.h"

namespace flexure {
namespace {

using test::kInch;
using test::kPound;
using test::kPsi;
using test::strip;

TEST(PhysicalBeam, HowellSmallLengthFlexuralPivotAsAChainInInches) {
  // Howell sec. 5.1, eqs. 5.26-5.34: polypropylene E = 2e5 psi, flexible l = 0.5 in of 0.75 x
  // 0.03 in, rigid L = 5 in, vertical tip force 0.096 lb: b = 3 in, a = 4.56 in, sigma_max = F a
  // c/I = 3900 psi (the PRBM; the exact answer differs by the pivot's small-length error).
  const io::ChainFile file = io::parse_chain_file(R"(
yield_strength = "4000 psi"
[[segment]]
type = "flexible"
length = "0.5 in"
E = "2e5 psi"
width = "0.75 in"
thickness = "0.03 in"
[[segment]]
type = "rigid"
length = "5 in"
[tip_load]
Fy = "0.096 lbf"
)",
                                                  "pivot.toml");
  ASSERT_TRUE(file.physical);
  BeamProblem problem;
  problem.chain = file.chain;
  const PhysicalBeamSolution got = solve_physical_chain(BeamMethod::kShooting, problem, file);
  ASSERT_TRUE(got.solution.converged()) << got.solution.message;
  const PhysicalResults& p = got.physical;
  EXPECT_NEAR(p.tip_y / kInch, 3.0, 0.06);  // 2 %
  EXPECT_NEAR(p.tip_x / kInch, 4.56, 0.05);
  // A vertical tip force: the moment is largest at the clamp, F times the tip's x (exact statics).
  const double F = 0.096 * kPound;
  EXPECT_NEAR(p.root_moment, F * p.tip_x, 1e-9 * F * p.tip_x);
  EXPECT_NEAR(p.max_moment, p.root_moment, 1e-12 * p.max_moment);
  const double I = 0.75 * std::pow(0.03, 3) / 12.0 * std::pow(kInch, 4);
  ASSERT_TRUE(p.max_stress.has_value());
  EXPECT_NEAR(*p.max_stress, F * p.tip_x * 0.015 * kInch / I, 1e-9 * *p.max_stress);
  EXPECT_NEAR(*p.max_stress / kPsi, 3900.0, 0.02 * 3900.0);
  EXPECT_NEAR(*p.safety_factor, 4000.0 * kPsi / *p.max_stress, 1e-12);
}

TEST(PhysicalBeam, AChainFileAndTheFlagsDescribeOneBeam) {
  // The steel strip of issue 13 both ways, and by two methods.
  const io::ChainFile file = io::parse_chain_file(R"(
[[segment]]
type = "flexible"
length = "50 mm"
E = "200 GPa"
width = "10 mm"
thickness = "0.5 mm"
[tip_load]
Fx = "-2.5 N"
Fy = "4.33 N"
)",
                                                  "strip.toml");
  BeamProblem problem;
  problem.chain = file.chain;
  const PhysicalBeamSolution chain = solve_physical_chain(BeamMethod::kShooting, problem, file);
  const PhysicalBeamSolution flags =
      solve_physical_beam(BeamMethod::kElliptic, strip(-2.5, 4.33, 0.0), {});
  ASSERT_TRUE(chain.solution.converged() && flags.solution.converged());
  EXPECT_NEAR(chain.physical.tip_x, flags.physical.tip_x, 1e-12);
  EXPECT_NEAR(chain.physical.tip_y, flags.physical.tip_y, 1e-12);
  EXPECT_NEAR(*chain.physical.max_stress, *flags.physical.max_stress, 1e-8 * 5.65e8);
  // alpha2 = Fy L^2/EI with EI = 200e9 * 0.01 * 0.0005^3 / 12.
  EXPECT_NEAR(chain.solution.alpha2, 4.33 * 0.0025 / (200e9 * 0.01 * 1.25e-10 / 12.0), 1e-12);
}

TEST(PhysicalBeam, AChainOfObjectsEqualsTheSameChainReadFromTomlBitwise) {
  // Two steel flexures joined by a rigid link (docs/examples/two_flexures_rigid_link.toml in SI
  // units, with sections and a yield strength), once as TOML and once as objects.
  const io::ChainFile file = io::parse_chain_file(R"(
yield_strength = "1.5 GPa"
[[segment]]
type = "flexible"
length = "30 mm"
E = "200 GPa"
width = "10 mm"
thickness = "0.5 mm"
[[segment]]
type = "rigid"
length = "40 mm"
[[segment]]
type = "flexible"
length = "30 mm"
E = "200 GPa"
width = "10 mm"
thickness = "0.4 mm"
[tip_load]
Fy = "2 N"
)",
                                                  "two_flexures.toml");
  Material steel;
  steel.E = 200e9;
  steel.yield_strength = 1.5e9;
  const Section thick = Section::rectangle(0.010, 0.0005);
  const Section thin = Section::rectangle(0.010, 0.0004);
  PhysicalChain objects;
  // EI as the reader computes it (E b h^3/12), so that the two chains are the same numbers.
  objects.chain.segments = {FlexibleSegment(0.030, 200e9 * (0.010 * std::pow(0.0005, 3) / 12.0)),
                            RigidSegment{0.040, 0.0},
                            FlexibleSegment(0.030, 200e9 * (0.010 * std::pow(0.0004, 3) / 12.0))};
  objects.chain.tip_load.Fy = 2.0;
  objects.segments = {SegmentProperties{thick, steel, std::nullopt},
                      std::nullopt,
                      SegmentProperties{thin, steel, std::nullopt}};
  // The reader's PhysicalChain is the one built here, field by field.
  ASSERT_EQ(file.segments.size(), 3u);
  ASSERT_TRUE(file.segments[0] && !file.segments[1] && file.segments[2]);
  EXPECT_EQ(file.segments[0]->section.width, thick.width);
  EXPECT_EQ(file.segments[0]->section.thickness, thick.thickness);
  EXPECT_EQ(file.segments[2]->section.thickness, thin.thickness);
  EXPECT_EQ(file.segments[0]->material.E, steel.E);
  EXPECT_EQ(file.segments[2]->material.yield_strength, steel.yield_strength);
  EXPECT_EQ(std::get<FlexibleSegment>(file.chain.segments[0]).EI,
            std::get<FlexibleSegment>(objects.chain.segments[0]).EI);
  EXPECT_EQ(std::get<FlexibleSegment>(file.chain.segments[2]).EI,
            std::get<FlexibleSegment>(objects.chain.segments[2]).EI);
  EXPECT_EQ(file.chain.tip_load.Fy, objects.chain.tip_load.Fy);
  for (BeamMethod method : {BeamMethod::kShooting, BeamMethod::kChain}) {
    const PhysicalBeamSolution a = solve_physical_chain(method, {}, file);
    const PhysicalBeamSolution b = solve_physical_chain(method, {}, objects);
    ASSERT_TRUE(a.solution.converged() && b.solution.converged()) << a.solution.message;
    EXPECT_EQ(a.solution.tip.a_over_l, b.solution.tip.a_over_l);
    EXPECT_EQ(a.solution.tip.b_over_l, b.solution.tip.b_over_l);
    EXPECT_EQ(a.solution.tip.theta0, b.solution.tip.theta0);
    EXPECT_EQ(a.physical.tip_x, b.physical.tip_x);
    EXPECT_EQ(a.physical.tip_y, b.physical.tip_y);
    ASSERT_TRUE(a.physical.max_stress && b.physical.max_stress);
    EXPECT_EQ(*a.physical.max_stress, *b.physical.max_stress);
    ASSERT_TRUE(a.physical.safety_factor && b.physical.safety_factor);
    EXPECT_EQ(*a.physical.safety_factor, *b.physical.safety_factor);
    // And an independent check of the answer: a vertical tip force of 2 N has the root moment
    // F times the tip's x (statics).
    EXPECT_NEAR(a.physical.root_moment, 2.0 * a.physical.tip_x, 1e-9 * 2.0 * a.physical.tip_x);
  }
}

}  // namespace
}  // namespace flexure
