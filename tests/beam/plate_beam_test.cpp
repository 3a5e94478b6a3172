// The plate modulus in physical beams and chains (docs/plate-modulus.md), checked against:
//  * the exact scaling: with plate on, every load scaled by 1/(1 - nu^2) gives the same deflected
//    shape as plate off (force control, seeded random loads and nu, shooting and elliptic), and a
//    prescribed tip (displacement control, a slider end held at y) needs reactions exactly
//    1/(1 - nu^2) times plate off's;
//  * pure bending by an end moment: the curvature is M/(E I) (off) or M (1 - nu^2)/(E I) (on), so
//    theta0 = M L/(E_eff I) by hand;
//  * auto's decision against the Searle parameter b^2 kappa/h computed by hand at the constant
//    curvature of pure bending: a 127 mm x 1.31 mm steel strip bent to R = 0.1 m (beta = 123) is a
//    plate, a 1.31 mm square bar at the same curvature (beta = 0.013) a beam;
//  * a PhysicalChain built from objects: each segment's own modulus (on by its EI, auto decided at
//    its largest curvature), the tip angle of pure bending by hand; validate() holds an on
//    segment's EI to E I/(1 - nu^2) and refuses auto on a general section;
//  * errors: plate on without nu, auto with a section given by I. The chain files' plate key:
//    tests/io/plate_chain_toml_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <string>

#include "flexure/beam/physical_beam.h"
#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

PhysicalCantilever steel_strip(double width, double thickness) {
  PhysicalCantilever b;
  b.length = 0.1;
  b.material.E = 200e9;
  b.set_nu(0.3);
  b.plate_given = true;
  b.section = Section::rectangle(width, thickness);
  return b;
}

TEST(PlateBeam, ForceControlScalesExactly) {
  std::mt19937 rng(20261128);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 12; ++trial) {
    PhysicalCantilever off = steel_strip(0.01 + 0.1 * unit(rng), 0.0005 + 0.001 * unit(rng));
    off.set_nu(0.1 + 0.38 * unit(rng));
    const double EI = off.flexural_rigidity();
    off.Fy = (0.2 + 3.0 * unit(rng)) * EI / (off.length * off.length);
    off.Fx = (-1.0 + 2.0 * unit(rng)) * off.Fy;
    off.M = (-0.5 + unit(rng)) * EI / off.length;
    PhysicalCantilever on = off;
    on.plate = PlateRule::kOn;
    const double k = 1.0 / (1.0 - off.material.nu * off.material.nu);
    on.Fx *= k;
    on.Fy *= k;
    on.M *= k;
    for (BeamMethod method : {BeamMethod::kShooting, BeamMethod::kElliptic}) {
      BeamProblem settings;
      const PhysicalBeamSolution a = solve_physical_beam(method, off, settings);
      const PhysicalBeamSolution b = solve_physical_beam(method, on, settings);
      ASSERT_TRUE(a.solution.converged() && b.solution.converged());
      EXPECT_NEAR(b.physical.tip_x, a.physical.tip_x, 1e-12 * off.length);
      EXPECT_NEAR(b.physical.tip_y, a.physical.tip_y, 1e-12 * off.length);
      EXPECT_NEAR(b.physical.root_moment / a.physical.root_moment, k, 1e-11);
      ASSERT_EQ(b.physical.modulus.size(), 1u);
      EXPECT_TRUE(b.physical.modulus[0].plate);
      EXPECT_NEAR(b.physical.modulus[0].effective_E, off.material.E * k, 1e-15 * off.material.E);
      EXPECT_FALSE(a.physical.modulus[0].plate);
    }
  }
}

TEST(PlateBeam, DisplacementControlReactionsScaleExactly) {
  // A slider end (the tip held at y, free along x and in rotation) at y = 20 mm: the reactions of
  // the plate are 1/(1 - nu^2) times the beam's (steel, nu = 0.3: 1.0989).
  PhysicalCantilever off = steel_strip(0.127, 0.00131);
  PhysicalCantilever on = off;
  on.plate = PlateRule::kOn;
  TipPrescription tip;
  tip.y = 0.02;
  double Fy[2] = {0, 0}, M[2] = {0, 0};
  int i = 0;
  for (const PhysicalCantilever* b : {&off, &on}) {
    BeamProblem problem;
    problem.chain = b->to_chain(EndCondition::kSlider, tip);
    problem.boundary = EndCondition::kSlider;
    const BeamSolution s = solve_beam(BeamMethod::kShooting, problem);
    ASSERT_TRUE(s.converged());
    EXPECT_NEAR(s.tip.b_over_l, 0.2, 1e-9);
    const double to_force = b->flexural_rigidity() / (b->length * b->length);
    Fy[i] = s.chain_reactions.Fy * to_force;
    M[i] = s.chain_reactions.M * to_force * b->length;
    ++i;
  }
  EXPECT_NEAR(Fy[1] / Fy[0], 1.0 / 0.91, 1e-10);
  EXPECT_NEAR(M[1] / M[0], 1.0 / 0.91, 1e-10);
}

TEST(PlateBeam, PureBendingAndAutoByTheSearleParameter) {
  const double R = 0.1;
  for (const auto& [width, plate] : {std::pair{0.127, true}, std::pair{0.00131, false}}) {
    PhysicalCantilever b = steel_strip(width, 0.00131);
    b.plate = PlateRule::kAuto;
    const double I = width * std::pow(0.00131, 3) / 12.0;
    b.M = b.material.E * I / R;  // curvature 1/R with the beam modulus
    const PhysicalBeamSolution s = solve_physical_beam(BeamMethod::kShooting, b, BeamProblem{});
    ASSERT_TRUE(s.solution.converged());
    const ModulusChoice& c = s.physical.modulus.at(0);
    EXPECT_NEAR(*c.beta, width * width / (R * 0.00131), 1e-9 * *c.beta);
    EXPECT_EQ(c.plate, plate) << width;
    const double E_eff = plate ? b.material.E / 0.91 : b.material.E;
    EXPECT_NEAR(s.physical.theta0, b.M * b.length / (E_eff * I), 1e-9);
  }
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InvalidInput& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InvalidInput thrown";
  return {};
}

TEST(PlateBeam, ClearErrors) {
  PhysicalCantilever b = steel_strip(0.127, 0.00131);
  b.set_nu(std::nullopt);
  b.plate = PlateRule::kOn;
  b.Fy = 1.0;
  EXPECT_NE(message_of([&] { b.validate(); }).find("--plate on needs Poisson's ratio --nu"),
            std::string::npos);
  PhysicalCantilever general;
  general.length = 0.1;
  general.material.E = 200e9;
  general.section = Section::general(1e-12);
  general.set_nu(0.3);
  general.plate = PlateRule::kAuto;
  general.plate_given = true;
  EXPECT_NE(message_of([&] { general.validate(); }).find("--plate auto needs the strip's width"),
            std::string::npos);
}

// Two 50 mm segments of a 127 mm x 1.31 mm steel strip (nu = 0.3) under an end moment of 10 N m,
// built from the library's objects: the segment's EI is what PhysicalChain::validate() expects.
PhysicalChain two_strip_segments(PlateRule first, PlateRule second) {
  PhysicalChain c;
  for (PlateRule rule : {first, second}) {
    SegmentProperties p{Section::rectangle(0.127, 0.00131), Material{}, std::nullopt};
    p.material.E = 200e9;
    p.material.nu = 0.3;
    p.plate = rule;
    c.chain.segments.push_back(
        FlexibleSegment(0.05, p.chain_modulus() * p.section.second_moment()));
    c.segments.push_back(p);
  }
  c.chain.tip_load.M = 10.0;
  return c;
}

TEST(PlateBeam, ChainSegmentsChooseTheirOwnModulus) {
  // The first segment a plate (on), the second decided by auto at its largest curvature. Under an
  // end moment the curvature is M/(E_eff I) in each: the tip angle by hand.
  const double I = 0.127 * std::pow(0.00131, 3) / 12.0;
  const PhysicalChain chain = two_strip_segments(PlateRule::kOn, PlateRule::kAuto);
  EXPECT_NEAR(std::get<FlexibleSegment>(chain.chain.segments[0]).EI, 200e9 / 0.91 * I, 1e-12);
  EXPECT_NEAR(std::get<FlexibleSegment>(chain.chain.segments[1]).EI, 200e9 * I, 1e-12);
  const PhysicalBeamSolution s = solve_physical_chain(BeamMethod::kShooting, {}, chain);
  ASSERT_TRUE(s.solution.converged());
  ASSERT_EQ(s.physical.modulus.size(), 2u);
  EXPECT_TRUE(s.physical.modulus[0].plate);
  EXPECT_TRUE(s.physical.modulus[1].plate);  // beta = 0.127^2 (10/(200e9 I))/1.31e-3 = 26
  EXPECT_NEAR(*s.physical.modulus[1].beta, 0.127 * 0.127 * 10.0 / (200e9 * I) / 0.00131, 1e-6);
  EXPECT_NEAR(s.solution.tip.theta0, 10.0 * 0.1 / (200e9 / 0.91 * I), 1e-8);
  // Both off: the beam modulus, theta0 = M L/(E I); nu is not reported where off does not use it.
  const PhysicalBeamSolution beam = solve_physical_chain(
      BeamMethod::kShooting, {}, two_strip_segments(PlateRule::kOff, PlateRule::kOff));
  ASSERT_TRUE(beam.solution.converged());
  EXPECT_FALSE(beam.physical.modulus.at(0).plate);
  EXPECT_FALSE(beam.physical.modulus.at(0).nu.has_value());
  EXPECT_NEAR(beam.solution.tip.theta0, 10.0 * 0.1 / (200e9 * I), 1e-8);
}

TEST(PlateBeam, PhysicalChainValidatesThePlateRigidity) {
  // plate on: the segment's EI must be E I/(1 - nu^2); E I is refused, naming the rule.
  PhysicalChain on = two_strip_segments(PlateRule::kOn, PlateRule::kOff);
  const double I = 0.127 * std::pow(0.00131, 3) / 12.0;
  std::get<FlexibleSegment>(on.chain.segments[0]).EI = 200e9 * I;
  EXPECT_NE(message_of([&] { on.validate(); }).find("is not E I/(1 - nu^2) (plate on)"),
            std::string::npos);
  // plate auto needs a rectangle (the Searle parameter's width).
  PhysicalChain general = two_strip_segments(PlateRule::kOff, PlateRule::kAuto);
  general.segments[1]->section = Section::general(I, 0.00131);
  EXPECT_NE(message_of([&] { general.validate(); }).find("plate auto needs a rectangle section"),
            std::string::npos);
}

}  // namespace
}  // namespace flexure
