// The shipped general-mechanism examples of docs/examples (issue 31 item 5; docs/mechanisms.md
// "Verified examples") against independent values: closed forms derived in the comments, Howell's
// printed numbers and equations, and the position analysis of each linkage done here directly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "flexure/elements/fixed_guided_segment.h"
#include "flexure/io/general_mechanism_toml.h"
#include "flexure/mechanisms/general/general_exact.h"
#include "flexure/mechanisms/general/general_mechanism.h"
#include "flexure/mechanisms/general/general_prbm.h"

namespace flexure::mechanism::general {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

GeneralMechanism example(const std::string& file) {
  return load_general_mechanism_toml(std::string(FLEXURE_SOURCE_DIR) + "/docs/examples/" + file);
}

// The same mechanism with its input range replaced (a small range for a stiffness).
GeneralMechanism with_range(GeneralMechanism m, double start, double stop, int count) {
  m.input.start = start;
  m.input.stop = stop;
  m.input.count = count;
  return m;
}

// Central-difference stiffness of a three-point result about its middle point.
double stiffness(const GeneralPrbmResult& r) {
  return (r.points[2].input_load - r.points[0].input_load) /
         (r.points[2].input - r.points[0].input);
}

int body(const GeneralPrbmResult& r, const std::string& name) {
  const auto it = std::find(r.body_names.begin(), r.body_names.end(), name);
  return it == r.body_names.end() ? -1 : static_cast<int>(it - r.body_names.begin());
}

// Howell's Table 5.1 constants at n = 0, the fixed-guided element's (gamma, K_Theta).
FixedPinnedConstants table_5_1() { return FixedPinnedConstants::from_table(0.0); }

// The Delrin flexures of docs/examples/parallel_guide.toml and double_parallelogram_stage.toml
// (Howell §5.10): E = 2.9 GPa, l = 22 mm, b = 7 mm, h = 0.8 mm.
constexpr double kL = 0.022;
constexpr double kEI = 2.9e9 * 7e-3 * 0.8e-3 * 0.8e-3 * 0.8e-3 / 12.0;

TEST(GeneralExamples, LinearMotionFlexureIsHowells5_10) {
  // Howell §5.10: I = b h^3/12 = 2.99e-13 m^4 and, with gamma = 0.85, K_Theta = 2.65,
  // K = 2 gamma K_Theta EI/l = 0.18 N m/rad (0.1776 unrounded).
  const GeneralMechanism m = example("double_parallelogram_stage.toml");
  ASSERT_EQ(m.flexures.size(), 4u);
  for (const Flexure& f : m.flexures) {
    EXPECT_NEAR(f.flexural_rigidity() / f.youngs_modulus, 2.99e-13, 0.005e-13) << f.name;
    EXPECT_NEAR(2 * 0.85 * 2.65 * f.flexural_rigidity() / f.length, 0.18, 0.005) << f.name;
    EXPECT_NEAR(f.flexural_rigidity(), kEI, 1e-12 * kEI);
  }
}

TEST(GeneralExamples, ParallelGuideStiffnessAndParasiticDrop) {
  const GeneralMechanism m = example("parallel_guide.toml");
  // Small-displacement stiffness: two clamped-guided beams, 12 EI/l^3 each (linear theory).
  const double k_beam = 24.0 * kEI / (kL * kL * kL);
  const GeneralMechanism small = with_range(m, -1e-5 * kL, 1e-5 * kL, 3);
  const GeneralPrbmResult exact = solve_general_exact(small);
  ASSERT_TRUE(exact.converged()) << exact.message;
  EXPECT_NEAR(stiffness(exact), k_beam, 1e-5 * k_beam);
  const GeneralPrbmResult prbm = solve_general_prbm(small);
  ASSERT_TRUE(prbm.converged()) << prbm.message;
  const FixedPinnedConstants c = table_5_1();
  EXPECT_NEAR(stiffness(prbm), 8.0 * c.K_theta / c.gamma * kEI / std::pow(kL, 3), 1e-6 * k_beam);

  // Parasitic motion: a guided beam deflected x takes the shape y = x (3 s^2/l^2 - 2 s^3/l^3)
  // (linear theory), whose arc length exceeds its chord by int y'^2/2 ds = 3/5 x^2/l: the stage
  // drops by that much (inextensible flexures). At x = 0.5 mm (2.3 % of l) the next term is of
  // relative order (x/l)^2. The PRBM's drop is its link's: gamma l (1 - cos Theta), sin Theta =
  // x/(gamma l).
  const GeneralPrbmResult e = solve_general_exact(with_range(m, 0.0, 0.5e-3, 2));
  ASSERT_TRUE(e.converged()) << e.message;
  const int stage = body(e, "stage");
  ASSERT_GE(stage, 0);
  const double x = 0.5e-3;
  EXPECT_NEAR(e.points[1].body_y[stage], -0.6 * x * x / kL, 2e-3 * 0.6 * x * x / kL);
  const GeneralPrbmResult p = solve_general_prbm(with_range(m, 0.0, 0.5e-3, 2));
  ASSERT_TRUE(p.converged()) << p.message;
  const double gl = c.gamma * kL;
  EXPECT_NEAR(p.points[1].body_y[stage], -gl * (1.0 - std::cos(std::asin(x / gl))), 1e-12);
  EXPECT_NEAR(p.points[1].body_phi[stage], 0.0, 1e-12);
}

TEST(GeneralExamples, DoubleParallelogramStageStiffnessHalvesAndParasiticMotionCancels) {
  const GeneralMechanism m = example("double_parallelogram_stage.toml");
  // Each parallelogram 2 x 12 EI/l^3; the two in series: 12 EI/l^3. PRBM: 4 K_Theta/gamma EI/l^3.
  const double k_beam = 12.0 * kEI / (kL * kL * kL);
  const GeneralMechanism small = with_range(m, -1e-5 * kL, 1e-5 * kL, 3);
  const GeneralPrbmResult exact = solve_general_exact(small);
  ASSERT_TRUE(exact.converged()) << exact.message;
  EXPECT_NEAR(stiffness(exact), k_beam, 1e-5 * k_beam);
  const GeneralPrbmResult prbm = solve_general_prbm(small);
  ASSERT_TRUE(prbm.converged()) << prbm.message;
  const FixedPinnedConstants c = table_5_1();
  EXPECT_NEAR(stiffness(prbm), 4.0 * c.K_theta / c.gamma * kEI / std::pow(kL, 3), 1e-6 * k_beam);
  // Two equal springs in series: the intermediate body moves half the stage's travel.
  const int mid = body(exact, "intermediate");
  ASSERT_GE(mid, 0);
  EXPECT_NEAR(exact.points[2].body_x[mid], 0.5 * exact.points[2].input, 1e-6 * kL * 1e-5);
  EXPECT_NEAR(prbm.points[2].body_x[mid], 0.5 * prbm.points[2].input, 1e-9 * kL * 1e-5);

  // Over the example's range (+-4 mm, 18 % of l): the stage's parasitic motion. A single
  // parallelogram drops 3/5 x^2/l (above); here the outer flexures, deflected x/2, drop the
  // intermediate body 3/5 (x/2)^2/l and the inner ones, deflected x/2 the other way up, lift the
  // stage as much: the stage stays at y = 0 to that order, the intermediate body drops
  // 0.15 x^2/l.
  const GeneralPrbmResult full = solve_general_exact(m);
  ASSERT_TRUE(full.converged()) << full.message;
  const int stage = body(full, "stage");
  double largest_y = 0.0, largest_phi = 0.0;
  for (const GeneralPrbmPoint& p : full.points) {
    const double x = p.input;
    largest_y = std::max(largest_y, std::abs(p.body_y[stage]));
    largest_phi = std::max(largest_phi, std::abs(p.body_phi[stage]));
    EXPECT_NEAR(p.body_x[mid], 0.5 * x, 0.01 * std::abs(x) + 1e-12);
    EXPECT_NEAR(p.body_y[mid], -0.15 * x * x / kL, 0.05 * 0.15 * x * x / kL + 1e-12);
  }
  const double x_end = 4e-3;
  const double single_drop = 0.6 * x_end * x_end / kL;  // 0.436 mm
  EXPECT_LT(largest_y, 1e-3 * single_drop);             // measured 8.8e-8 m, 2.0e-4 of 0.436 mm
  // The PRBM: the same cancellation, exact in its kinematics (both links turn alike).
  const GeneralPrbmResult pr = solve_general_prbm(m);
  ASSERT_TRUE(pr.converged()) << pr.message;
  for (const GeneralPrbmPoint& p : pr.points) EXPECT_NEAR(p.body_y[stage], 0.0, 1e-12 * kL);
  // PRBM against exact at the ends of the range: the PRBM's 4.7 % stiffer small-displacement
  // stiffness persists (both stiffen little at 18 % of l).
  const double ratio = pr.points.back().input_load / full.points.back().input_load;
  EXPECT_NEAR(ratio, 4.0 * c.K_theta / c.gamma / 12.0, 0.01);
  RecordProperty("stage_largest_y_m", std::to_string(largest_y));
  RecordProperty("stage_largest_phi_rad", std::to_string(largest_phi));
}

// Cross-axis flexural pivot: two strips of length l crossing at their midpoints.
TEST(GeneralExamples, CrossAxisPivotStiffnessIsTwoEIOverL) {
  const GeneralMechanism m = example("cross_axis_pivot.toml");
  const double l = 0.030, EI = 207e9 * 10e-3 * std::pow(0.3e-3, 3) / 12.0;
  ASSERT_NEAR(m.flexures[0].flexural_rigidity(), EI, 1e-12 * EI);
  const GeneralMechanism small = with_range(m, 90 * kDeg - 1e-5, 90 * kDeg + 1e-5, 3);
  // Inextensible strips let each strip's far end move only across it, so the rotor turns about
  // the crossing point: the far end turns theta and moves theta l/2 across the strip -- the
  // circular arc of a pure end moment (tip deflection M l^2/2EI = theta l/2), M = EI theta/l per
  // strip. Two strips: 2 EI/l.
  const GeneralPrbmResult exact = solve_general_exact(small);
  ASSERT_TRUE(exact.converged()) << exact.message;
  EXPECT_NEAR(stiffness(exact), 2.0 * EI / l, 1e-6 * EI / l);
  // The rotor turns about the crossing point (the origin): the origin, a point of the rotor, does
  // not move. The pose is that of the rotor's centroid c = (0, 7.803 mm): the origin moves by
  // (x, y) + (R(phi) - I)(0 - c).
  const int rotor = body(exact, "rotor");
  for (const GeneralPrbmPoint& p : exact.points) {
    const double cy = (2 * 10.6066017178e-3 + 10e-3) / 4, phi = p.body_phi[rotor];
    EXPECT_NEAR(p.body_x[rotor] + std::sin(phi) * cy, 0.0, 1e-6 * l * 1e-5);
    // to first order: the centre shifts at second order (l theta^2 = 3e-12 m here).
    EXPECT_NEAR(p.body_y[rotor] - (std::cos(phi) - 1) * cy, 0.0, l * 1e-10);
  }
  // The PRBM with Howell's fixed-guided element (pivots (1 - gamma) l/2 from each end, a spring
  // 2 gamma K_Theta EI/l at each): the link between the pivots turns theta/2, each spring takes
  // theta/2, energy 2 x K (theta/2)^2/2: gamma K_Theta EI/l per strip, 2.28 times the beam's.
  const GeneralPrbmResult prbm = solve_general_prbm(small);
  ASSERT_TRUE(prbm.converged()) << prbm.message;
  const FixedPinnedConstants c = table_5_1();
  EXPECT_NEAR(stiffness(prbm), 2.0 * c.gamma * c.K_theta * EI / l, 1e-6 * EI / l);
}

// The same closed form where the strips cross off their midpoints: a strip whose far end turns
// theta about a point at (1 - mu) l from its root (mu l from its far end) has the far end moved
// v = mu l theta across it; the clamped-clamped beam's energy (EI/l^3)(6 v^2 - 6 v l theta +
// 2 l^2 theta^2) gives K = (EI/l)(12 mu^2 - 12 mu + 4): 1 at mu = 1/2, 4 at mu = 0 or 1 (8 EI/l
// for the pair: strips meeting at an end).
TEST(GeneralExamples, CrossedStripsOffTheirMidpointsFollowTheClosedForm) {
  const double l = 0.030, E = 207e9, b = 10e-3, h = 0.3e-3;
  const double EI = E * b * h * h * h / 12.0;
  for (const double lambda : {0.5, 0.3, 0.2}) {  // crossing at lambda l from the ground ends
    const double s = l / std::sqrt(2.0);
    GeneralMechanism m;
    m.body("ground", {{"A", {-lambda * s, -lambda * s}}, {"B", {lambda * s, -lambda * s}}})
        .body("rotor",
              {{"A", {(1 - lambda) * s, (1 - lambda) * s}},
               {"B", {-(1 - lambda) * s, (1 - lambda) * s}},
               {"O", {0, 0}},
               {"T", {0, 0.01}}})
        .flexure("strip1", "ground.A", "rotor.A", b, h, E, PrbmKind::kFixedGuided)
        .flexure("strip2", "ground.B", "rotor.B", b, h, E, PrbmKind::kFixedGuided)
        .input_coordinate(InputCoordinate::kAngle,
                          "rotor.O",
                          "rotor.T",
                          InputControl::kDisplacement,
                          90 * kDeg - 1e-5,
                          90 * kDeg + 1e-5,
                          3);
    const GeneralPrbmResult r = solve_general_exact(m);
    ASSERT_TRUE(r.converged()) << r.message;
    const double mu = 1.0 - lambda;
    const double k = 2.0 * (12 * mu * mu - 12 * mu + 4) * EI / l;
    EXPECT_NEAR(stiffness(r), k, 1e-5 * k) << lambda;
  }
}

}  // namespace
}  // namespace flexure::mechanism::general
