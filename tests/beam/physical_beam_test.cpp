// Beams in physical units (beam/physical_beam.h), checked against:
//  * the nondimensional solve scaled by hand: alpha2 = Fy L^2/EI, n = -Fx/Fy, mu = M L/EI in
//    (Howell eqs. 2.67, 2.83); a, b, M(0) times L, L, EI/L out; stress M (h/2)/I with I = b h^3/12,
//    over seeded random beams;
//  * another method: the largest moment and stress from the elliptic shape against the shooting
//    method's (independent solvers, 1e-7);
//  * the curvature: the moment from statics equals EI dtheta/ds by central differences of the
//    solved shape, and the tip moment equals the applied M;
//  * Howell's worked examples in units: the aluminium rod of sec. 2.9.2 (P = 17.3839 N gives
//    theta0 = 1 rad, a = 73.8 mm, b = 61.0 mm) and the small-length flexural pivot of sec. 5.1
//    (polypropylene, 0.096 lb: b = 3 in, sigma = F a c/I = 3900 psi), the latter as a chain of
//    the library's objects (PhysicalChain) in inches and pounds. The chain files: tests/io/
//    physical_chain_toml_test.cpp.
#include "flexure/beam/physical_beam.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <string>

#include "flexure/solver/common/status.h"
#include "tests/support/physical_beam_support.h"

namespace flexure {
namespace {

using test::kInch;
using test::kPound;
using test::kPsi;
using test::strip;

TEST(PhysicalBeam, EqualsTheNondimensionalSolveScaledByHand) {
  std::mt19937 rng(20261124);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 40; ++trial) {
    PhysicalCantilever b;
    b.length = 0.01 + 0.5 * unit(rng);
    b.material.E = 1e9 + 2e11 * unit(rng);
    const double width = 0.002 + 0.02 * unit(rng);
    const double thickness = b.length * (0.002 + 0.05 * unit(rng));
    b.section = Section::rectangle(width, thickness);
    const double I = width * std::pow(thickness, 3) / 12.0;
    const double EI = b.material.E * I;
    // Loads of Howell's moderate range: alpha2 in (0.1, 4), n in (-2, 2), mu in (-1, 1).
    const double alpha2 = 0.1 + 3.9 * unit(rng);
    const double n = -2.0 + 4.0 * unit(rng);
    const double mu = -1.0 + 2.0 * unit(rng);
    b.Fy = alpha2 * EI / (b.length * b.length);
    b.Fx = -n * b.Fy;
    b.M = mu * EI / b.length;
    b.material.yield_strength = 1e9;
    const PhysicalBeamSolution got = solve_physical_beam(BeamMethod::kElliptic, b, {});
    ASSERT_TRUE(got.solution.converged()) << got.solution.message;
    // One status, the solution's (not a copy).
    ASSERT_EQ(&got.status(), static_cast<const SolveStatus*>(&got.solution));
    ASSERT_TRUE(got.converged());

    BeamProblem by_hand;
    by_hand.value = alpha2;
    by_hand.load_ratio_n = n;
    by_hand.mu = mu;
    const BeamSolution ref = solve_beam(BeamMethod::kElliptic, by_hand);
    ASSERT_TRUE(ref.converged());
    const PhysicalResults& p = got.physical;
    EXPECT_NEAR(got.solution.alpha2, alpha2, 1e-12 * alpha2);
    EXPECT_NEAR(p.tip_x, ref.tip.a_over_l * b.length, 1e-11 * b.length) << trial;
    EXPECT_NEAR(p.tip_y, ref.tip.b_over_l * b.length, 1e-11 * b.length) << trial;
    EXPECT_NEAR(p.theta0, ref.tip.theta0, 1e-11) << trial;
    const double moment_scale = EI / b.length;
    EXPECT_NEAR(p.root_moment, ref.root_moment * moment_scale, 1e-10 * moment_scale) << trial;
    ASSERT_TRUE(p.max_stress.has_value());
    EXPECT_NEAR(*p.max_stress, p.max_moment * 0.5 * thickness / I, 1e-12 * *p.max_stress);
    EXPECT_NEAR(*p.safety_factor, 1e9 / *p.max_stress, 1e-12 * *p.safety_factor);
    EXPECT_GE(p.max_moment, std::fabs(p.root_moment) * (1 - 1e-15));
    EXPECT_GE(p.max_moment, std::fabs(b.M) * (1 - 1e-12));

    // The largest moment from another method.
    const PhysicalBeamSolution shooting = solve_physical_beam(BeamMethod::kShooting, b, {});
    ASSERT_TRUE(shooting.solution.converged());
    EXPECT_NEAR(shooting.physical.max_moment, p.max_moment, 1e-7 * p.max_moment) << trial;
    EXPECT_NEAR(*shooting.physical.max_stress, *p.max_stress, 1e-7 * *p.max_stress) << trial;
  }
}

TEST(PhysicalBeam, MomentFromStaticsIsTheCurvatureTimesEI) {
  // An end moment rolling the strip past 180 deg against a downward force (alpha2 = -1, mu = 3):
  // the moment is largest inside the beam, where the tangent is parallel to the force.
  PhysicalCantilever b = strip(0.0, -8.33, 1.25);
  BeamProblem settings;
  settings.shape_points = 401;
  const PhysicalBeamSolution got = solve_physical_beam(BeamMethod::kElliptic, b, settings);
  ASSERT_TRUE(got.solution.converged());
  const std::vector<PhysicalShapePoint>& shape = got.physical.shape;
  ASSERT_EQ(shape.size(), 401u);
  const double EI = b.flexural_rigidity();
  double worst = 0.0, scale = 0.0;
  for (std::size_t i = 1; i + 1 < shape.size(); ++i) {
    const double curvature =
        (shape[i + 1].theta - shape[i - 1].theta) / (shape[i + 1].s - shape[i - 1].s);
    worst = std::max(worst, std::fabs(EI * curvature - shape[i].moment));
    scale = std::max(scale, std::fabs(shape[i].moment));
  }
  // Central differences at h = L/400: error h^2/6 |M'''| / EI-scaled, about 1e-6 here.
  EXPECT_LT(worst, 1e-5 * scale);
  EXPECT_NEAR(shape.back().moment, b.M, 1e-9 * scale);
  EXPECT_NEAR(shape.front().moment, got.physical.root_moment, 1e-12 * scale);
  // The maximum is interior, and no sample exceeds the refined maximum.
  EXPECT_GT(got.physical.max_moment_at, 0.0);
  EXPECT_LT(got.physical.max_moment_at, b.length);
  for (const PhysicalShapePoint& p : shape) {
    EXPECT_LE(std::fabs(p.moment), got.physical.max_moment * (1 + 1e-14));
  }
}

TEST(PhysicalBeam, HowellAluminiumRodSection292) {
  // Howell sec. 2.9.2, eqs. 2.99-2.100: E = 71.7 GPa, l = 100 mm, d = 2 mm, theta0 = 1 rad, n = 0:
  // P = 17.3839 N, a/l = 0.7383564, b/l = 0.6103718 (elliptic integrals, 8 digits).
  PhysicalCantilever rod;
  rod.length = 0.1;
  rod.material.E = 71.7e9;
  rod.section = Section::general(std::numbers::pi * std::pow(0.002, 4) / 64.0);
  rod.Fy = 17.3839;
  const PhysicalBeamSolution got = solve_physical_beam(BeamMethod::kElliptic, rod, {});
  ASSERT_TRUE(got.solution.converged());
  // P is given to 6 digits: theta0 within 3e-6 rad of 1.
  EXPECT_NEAR(got.physical.theta0, 1.0, 3e-6);
  EXPECT_NEAR(got.physical.tip_x, 0.07383564, 3e-7);
  EXPECT_NEAR(got.physical.tip_y, 0.06103718, 3e-7);
  EXPECT_FALSE(got.physical.max_stress.has_value());  // a round section given by I: no c
}

TEST(PhysicalBeam, HowellSmallLengthFlexuralPivotAsAChainOfObjects) {
  // Howell sec. 5.1, eqs. 5.26-5.34: polypropylene E = 2e5 psi, flexible l = 0.5 in of 0.75 x
  // 0.03 in, rigid L = 5 in, vertical tip force 0.096 lb: b = 3 in, a = 4.56 in, sigma_max = F a
  // c/I = 3900 psi (the PRBM; the exact answer differs by the pivot's small-length error). Built
  // from the library's types, no file (tests/io/physical_chain_toml_test.cpp reads the same chain
  // from TOML and checks the two give the same answer).
  const Section section = Section::rectangle(0.75 * kInch, 0.03 * kInch);
  Material material;
  material.E = 2e5 * kPsi;
  material.yield_strength = 4000.0 * kPsi;
  PhysicalChain pivot;
  pivot.chain.segments = {FlexibleSegment(0.5 * kInch, material.E * section.second_moment()),
                          RigidSegment{5.0 * kInch, 0.0}};
  pivot.chain.tip_load.Fy = 0.096 * kPound;
  pivot.segments = {SegmentProperties{section, material, std::nullopt}, std::nullopt};
  const PhysicalBeamSolution got = solve_physical_chain(BeamMethod::kShooting, {}, pivot);
  ASSERT_TRUE(got.solution.converged()) << got.solution.message;
  const PhysicalResults& p = got.physical;
  EXPECT_NEAR(p.tip_y / kInch, 3.0, 0.06);  // 2 %
  EXPECT_NEAR(p.tip_x / kInch, 4.56, 0.05);
  // A vertical tip force: the moment is largest at the clamp, F times the tip's x (exact statics).
  const double F = 0.096 * kPound;
  EXPECT_NEAR(p.root_moment, F * p.tip_x, 1e-9 * F * p.tip_x);
  const double I = 0.75 * std::pow(0.03, 3) / 12.0 * std::pow(kInch, 4);
  ASSERT_TRUE(p.max_stress.has_value());
  EXPECT_NEAR(*p.max_stress, F * p.tip_x * 0.015 * kInch / I, 1e-9 * *p.max_stress);
  EXPECT_NEAR(*p.max_stress / kPsi, 3900.0, 0.02 * 3900.0);
  ASSERT_TRUE(p.yield_strength.has_value());
  EXPECT_EQ(*p.yield_strength, 4000.0 * kPsi);
  EXPECT_NEAR(*p.safety_factor, 4000.0 * kPsi / *p.max_stress, 1e-12);
}

TEST(PhysicalBeam, PhysicalChainRefusesWhatDoesNotDescribeOneBeam) {
  // Each refusal names what is wrong (InvalidInput, before any solve).
  const Section section = Section::rectangle(0.01, 0.0005);
  Material steel;
  steel.E = 200e9;
  const double EI = steel.E * section.second_moment();
  auto message = [](const PhysicalChain& c) -> std::string {
    try {
      c.validate();
    } catch (const InvalidInput& e) {
      return e.what();
    }
    return "";
  };
  PhysicalChain c;
  c.chain.segments = {FlexibleSegment(0.05, EI), RigidSegment{0.02, 0.0}};
  c.segments = {SegmentProperties{section, steel, std::nullopt}, std::nullopt};
  EXPECT_EQ(message(c), "");
  PhysicalChain wrong = c;
  wrong.segments.pop_back();  // one entry per segment
  EXPECT_NE(message(wrong).find("1 entries for a chain of 2 segments"), std::string::npos);
  wrong = c;
  wrong.segments[1] = wrong.segments[0];  // a section on the rigid link
  EXPECT_NE(message(wrong).find("segment 2 is a rigid link"), std::string::npos);
  wrong = c;
  std::get<FlexibleSegment>(wrong.chain.segments[0]).EI = 2.0 * EI;  // EI is not E I
  EXPECT_NE(message(wrong).find("is not E I"), std::string::npos);
  wrong = c;
  wrong.segments[0]->material.E = -1.0;
  EXPECT_NE(message(wrong).find("segment 1: "), std::string::npos);
  EXPECT_NE(message(wrong).find("Material::E"), std::string::npos);
  // Two flexures of different yield strengths: the safety factor would need one per segment.
  wrong = c;
  wrong.chain.segments.push_back(FlexibleSegment(0.05, EI));
  wrong.segments.push_back(wrong.segments[0]);
  wrong.segments[0]->material.yield_strength = 1e9;
  wrong.segments[2]->material.yield_strength = 2e9;
  EXPECT_NE(message(wrong).find("differs from another segment"), std::string::npos);
  EXPECT_THROW(solve_physical_chain(BeamMethod::kShooting, {}, wrong), InvalidInput);
}

TEST(PhysicalBeam, AxialLoadHasNoLoadRatioAndBadInputNamesTheField) {
  const PhysicalBeamSolution axial =
      solve_physical_beam(BeamMethod::kShooting, strip(-2.5, 0.0, 0.01), {});
  ASSERT_TRUE(axial.solution.converged());
  EXPECT_TRUE(std::isnan(axial.solution.load_ratio_n));
  EXPECT_EQ(axial.solution.alpha2, 0.0);
  EXPECT_THROW(solve_physical_beam(BeamMethod::kElliptic, strip(-2.5, 0.0, 0.01), {}),
               InvalidInput);
  auto message = [](PhysicalCantilever b) -> std::string {
    try {
      b.validate();
    } catch (const InvalidInput& e) {
      return e.what();
    }
    return "";
  };
  PhysicalCantilever b = strip(0, 1, 0);
  b.length = -1;
  EXPECT_NE(message(b).find("--length"), std::string::npos);
  // A section given twice, or half a rectangle, is refused where the values are read one by one.
  auto section_message = [](std::optional<double> I,
                            std::optional<double> width,
                            std::optional<double> thickness) -> std::string {
    PhysicalCantilever b = strip(0, 1, 0);
    try {
      b.set_section(I, width, thickness);
    } catch (const InvalidInput& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(section_message(1e-12, 0.01, std::nullopt).find("exactly one"), std::string::npos);
  EXPECT_NE(section_message(1e-12, std::nullopt, 0.0005).find("exactly one"), std::string::npos);
  EXPECT_NE(section_message({}, {}, {}).find("exactly one"), std::string::npos);
  EXPECT_NE(section_message({}, 0.01, {}).find("needs both --width and --thickness"),
            std::string::npos);
  EXPECT_EQ(section_message(1e-12, {}, {}), "");
  EXPECT_EQ(section_message({}, 0.01, 0.0005), "");
  b = strip(0, 1, 0);
  b.Fy = std::nan("");
  EXPECT_NE(message(b).find("--Fy"), std::string::npos);
  b = strip(0, 1, 0);
  b.section.thickness = 0.0;
  EXPECT_NE(message(b).find("--thickness"), std::string::npos);
}

}  // namespace
}  // namespace flexure
