// Internal forces along a physical beam's shape (beam/physical_beam.h,
// docs/units.md "Internal forces"), checked against:
//  * statics of a dead tip load F: N and V at every shape point are F resolved on the local
//    tangent t = (cos theta, sin theta) and normal n = (-sin theta, cos theta) (N = F . t,
//    V = F . n), to 1e-12 of |F|;
//  * the equilibrium dm/ds = -V by central differences of the reported moments at the station
//    spacing h (error O(h^2): within 2e-4 |F| at h = L/400, and falling 4x when h halves);
//  * the root stresses by hand: m(0) = M + x_tip Fy - y_tip Fx (the tip load's moment about the
//    clamp), sigma = Fx/(b h) -+ m(0) (h/2)/(b h^3/12) at the +n and -n fibres;
//  * a chain segment given by EI alone: N, V and m reported, no fibre stress.
#include <gtest/gtest.h>

#include <cmath>

#include "flexure/beam/physical_beam.h"

namespace flexure {
namespace {

PhysicalCantilever tutorial_strip() {
  PhysicalCantilever b;
  b.length = 0.05;
  b.material.E = 200e9;
  b.section = Section::rectangle(0.01, 0.0005);
  b.Fx = -2.5;
  b.Fy = 4.330127;
  b.M = 0.01;
  return b;
}

TEST(ShapeForces, TipLoadResolvedOnTheLocalFrame) {
  const PhysicalCantilever b = tutorial_strip();
  BeamProblem settings;
  settings.shape_points = 401;
  const PhysicalBeamSolution s = solve_physical_beam(BeamMethod::kShooting, b, settings);
  ASSERT_TRUE(s.solution.converged());
  const auto& shape = s.physical.shape;
  ASSERT_EQ(shape.size(), 401u);
  const double F = std::hypot(b.Fx, b.Fy);
  for (const PhysicalShapePoint& p : shape) {
    const double c = std::cos(p.theta), sn = std::sin(p.theta);
    EXPECT_NEAR(p.axial_force, b.Fx * c + b.Fy * sn, 1e-12 * F);
    EXPECT_NEAR(p.shear_force, -b.Fx * sn + b.Fy * c, 1e-12 * F);
  }
  // dm/ds = -V by central differences.
  double worst = 0.0;
  for (std::size_t i = 1; i + 1 < shape.size(); ++i) {
    const double dm =
        (shape[i + 1].moment - shape[i - 1].moment) / (shape[i + 1].s - shape[i - 1].s);
    worst = std::max(worst, std::fabs(dm + shape[i].shear_force));
  }
  EXPECT_LT(worst, 2e-4 * F);
  // Halving the spacing divides the difference error by about 4 (second order).
  BeamProblem coarse = settings;
  coarse.shape_points = 201;
  const auto& c = solve_physical_beam(BeamMethod::kShooting, b, coarse).physical.shape;
  double worst_coarse = 0.0;
  for (std::size_t i = 1; i + 1 < c.size(); ++i) {
    const double dm = (c[i + 1].moment - c[i - 1].moment) / (c[i + 1].s - c[i - 1].s);
    worst_coarse = std::max(worst_coarse, std::fabs(dm + c[i].shear_force));
  }
  EXPECT_NEAR(worst_coarse / worst, 4.0, 0.5);
  // Root stresses by hand.
  const double m0 = b.M + s.physical.tip_x * b.Fy - s.physical.tip_y * b.Fx;
  EXPECT_NEAR(shape.front().moment, m0, 1e-9 * std::fabs(m0));
  const double A = 0.01 * 0.0005, I = 0.01 * std::pow(0.0005, 3) / 12.0, cfib = 0.00025;
  ASSERT_TRUE(shape.front().stress_pos_fibre && shape.front().stress_neg_fibre);
  EXPECT_NEAR(*shape.front().stress_pos_fibre, b.Fx / A - m0 * cfib / I, 1e-9 * m0 * cfib / I);
  EXPECT_NEAR(*shape.front().stress_neg_fibre, b.Fx / A + m0 * cfib / I, 1e-9 * m0 * cfib / I);
}

TEST(ShapeForces, RigidityAloneGivesForcesButNoStress) {
  // One 50 mm segment given by EI = 0.02 N m^2 alone (no section), tip force Fy = 1 N.
  PhysicalChain chain;
  chain.chain.segments = {FlexibleSegment(0.05, 0.02)};
  chain.chain.tip_load.Fy = 1.0;
  chain.segments = {std::nullopt};
  BeamProblem problem;
  problem.shape_points = 11;
  const PhysicalBeamSolution s = solve_physical_chain(BeamMethod::kShooting, problem, chain);
  ASSERT_TRUE(s.solution.converged());
  for (const PhysicalShapePoint& p : s.physical.shape) {
    EXPECT_FALSE(p.stress_pos_fibre.has_value());
    EXPECT_NEAR(p.shear_force, std::cos(p.theta), 1e-12);
    EXPECT_NEAR(p.axial_force, std::sin(p.theta), 1e-12);
  }
  EXPECT_NEAR(s.physical.shape.front().moment, s.physical.tip_x * 1.0, 1e-9);
}

}  // namespace
}  // namespace flexure
