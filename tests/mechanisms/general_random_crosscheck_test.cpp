// Seeded random cross-checks of the general mechanism models (issue 31 item 6; docs/mechanisms.md
// "Seeded random cross-checks"):
// * random parallel-guiding stages: the exact model's small-displacement stiffness is two
//   clamped-guided beams, 24 EI/l^3, and the PRBM's is its own 2 x 4 K_Theta/gamma EI/l^3 (Table
//   5.1, n = 0): their ratio is the PRBM's small-deflection limit;
// * random four-bars with a small-length pivot at every joint: PRBM against exact at small motion;
// * exact equilibria re-solved flexure by flexure: every flexure of the exact solution solved
//   alone, by the elliptic solution (another method: elliptic integrals, not the shooting
//   integrator), under the tip loads the mechanism put on it, lands where the mechanism's bodies
//   put its tip.
// (The random four-bars' PRBM load against the slope of its own energy, and its verdicts against
// the energy's curvature: general_mechanism_test.cpp. The catalogue's designs rebuilt, PRBM and
// exact against the catalogue's own models: general_mechanism_test.cpp, general_exact_stability_
// test.cpp. Mixed models' tips against the elliptic solution: mixed_flexure_models_test.cpp.)
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "flexure/elements/prbm_element.h"
#include "flexure/mechanisms/general/general_analysis.h"
#include "flexure/mechanisms/general/general_mechanism.h"

namespace flexure::mechanism::general {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

double stiffness(const GeneralPrbmResult& r) {
  return (r.points[2].input_load - r.points[0].input_load) /
         (r.points[2].input - r.points[0].input);
}

// A stage on two fixed-guided flexures of length l, spacing w, moved along x by +-dx.
GeneralMechanism parallel_guide(double l, double w, double b, double h, double E, double dx) {
  GeneralMechanism m;
  m.body("ground", {{"A", {0, 0}}, {"B", {w, 0}}})
      .body("stage", {{"A", {0, l}}, {"B", {w, l}}})
      .flexure("f1", "ground.A", "stage.A", b, h, E, PrbmKind::kFixedGuided)
      .flexure("f2", "ground.B", "stage.B", b, h, E, PrbmKind::kFixedGuided)
      .input_coordinate(
          InputCoordinate::kX, "stage.A", "", InputControl::kDisplacement, -dx, dx, 3);
  return m;
}

TEST(GeneralRandomCrossChecks, ParallelGuidesPrbmAndExactAtSmallMotion) {
  std::mt19937 rng(3101);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const FixedPinnedConstants c = FixedPinnedConstants::from_table(0.0);
  const double prbm_ratio = 4.0 * c.K_theta / c.gamma / 12.0;  // 1.0474
  double worst_exact = 0.0, worst_ratio = 0.0;
  for (int trial = 0; trial < 10; ++trial) {
    const double l = 0.01 + 0.04 * U(rng), w = 0.005 + 0.05 * U(rng), b = 0.003 + 0.01 * U(rng);
    const double h = l * (0.005 + 0.02 * U(rng)), E = 1e9 * (1.0 + 200.0 * U(rng));
    const GeneralMechanism m = parallel_guide(l, w, b, h, E, 1e-6 * l);
    const GeneralPrbmResult p = solve_general_prbm(m);
    const GeneralPrbmResult e = solve_general_exact(m);
    ASSERT_TRUE(p.converged()) << trial << ": " << p.message;
    ASSERT_TRUE(e.converged()) << trial << ": " << e.message;
    const double EI = m.flexures[0].flexural_rigidity();
    const double k_beam = 24.0 * EI / (l * l * l);
    worst_exact = std::max(worst_exact, std::fabs(stiffness(e) / k_beam - 1.0));
    worst_ratio = std::max(worst_ratio, std::fabs(stiffness(p) / stiffness(e) / prbm_ratio - 1.0));
  }
  // Measured: 3.4e-10 and 4.0e-10 (10 stages, l 10-50 mm, h/l 0.005-0.025, E 1-201 GPa).
  EXPECT_LT(worst_exact, 1e-6);
  EXPECT_LT(worst_ratio, 1e-6);
}

// A random four-bar (as general_mechanism_test.cpp builds them): ground pivots 0 and r1 = 50 mm,
// crank r2 20-40 mm, coupler 40-70 mm, rocker 30-60 mm at a random rest angle, a small-length
// pivot (l = 2 mm, h 0.2-0.6 mm, b = 5 mm, E = 1.4 GPa) at every joint; input: the crank's angle.
GeneralMechanism random_four_bar(std::mt19937& rng, double* theta2_rest) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (;;) {
    const double r1 = 0.05, r2 = 0.02 + 0.02 * U(rng), r3 = 0.04 + 0.03 * U(rng),
                 r4 = 0.03 + 0.03 * U(rng);
    const double theta2 = (30.0 + 90.0 * U(rng)) * kDeg;
    const Vec2 A{r2 * std::cos(theta2), r2 * std::sin(theta2)};
    const Vec2 d{r1 - A.x, -A.y};
    const double dist = std::hypot(d.x, d.y);
    if (dist >= r3 + r4 - 0.005 || dist <= std::fabs(r3 - r4) + 0.005) continue;
    const double a = (r3 * r3 - r4 * r4 + dist * dist) / (2 * dist);
    const double hh = std::sqrt(r3 * r3 - a * a);
    const Vec2 u{d.x / dist, d.y / dist};
    const Vec2 B{A.x + a * u.x - hh * u.y, A.y + a * u.y + hh * u.x};
    const Vec2 O4{r1, 0};
    const double l = 0.002;
    auto ends = [&](Vec2 J, Vec2 along) {
      const double n = std::hypot(along.x, along.y);
      const Vec2 e{along.x / n * l / 2, along.y / n * l / 2};
      return std::pair<Vec2, Vec2>{{J.x - e.x, J.y - e.y}, {J.x + e.x, J.y + e.y}};
    };
    const auto f1 = ends({0, 0}, A);
    const auto f2 = ends(A, {B.x - A.x, B.y - A.y});
    const auto f3 = ends(B, {O4.x - B.x, O4.y - B.y});
    const auto f4 = ends(O4, {B.x - O4.x, B.y - O4.y});
    auto thickness = [&] { return 2e-4 + 4e-4 * U(rng); };
    GeneralMechanism m;
    m.body("ground", {{"f1", f1.first}, {"f4", f4.first}})
        .body("crank", {{"O2", {0, 0}}, {"A", A}, {"f1", f1.second}, {"f2", f2.first}})
        .body("coupler", {{"f2", f2.second}, {"f3", f3.first}})
        .body("rocker", {{"f3", f3.second}, {"f4", f4.second}})
        .flexure(
            "j1", "ground.f1", "crank.f1", 5e-3, thickness(), 1.4e9, PrbmKind::kSmallLengthPivot)
        .flexure(
            "j2", "crank.f2", "coupler.f2", 5e-3, thickness(), 1.4e9, PrbmKind::kSmallLengthPivot)
        .flexure(
            "j3", "coupler.f3", "rocker.f3", 5e-3, thickness(), 1.4e9, PrbmKind::kSmallLengthPivot)
        .flexure(
            "j4", "ground.f4", "rocker.f4", 5e-3, thickness(), 1.4e9, PrbmKind::kSmallLengthPivot);
    *theta2_rest = theta2;
    return m;
  }
}

// Small motion: the PRBM's pins are the flexures' midpoints, K = EI/l each (Howell eq. 5.14); the
// exact flexures also give a little in translation (their 12 EI/l^3 across), so the exact
// stiffness lies a little below the PRBM's, by about the pivots' length over the links' squared.
// Measured on 8 seeded four-bars: PRBM / exact - 1 between 1.8e-4 and 3.0e-3, at +-0.01 deg.
TEST(GeneralRandomCrossChecks, FourBarsPrbmAndExactAtSmallMotion) {
  std::mt19937 rng(3102);
  double lo = 1.0, hi = -1.0;
  for (int trial = 0; trial < 8; ++trial) {
    double theta2 = 0.0;
    GeneralMechanism m = random_four_bar(rng, &theta2);
    m.input_coordinate(InputCoordinate::kAngle,
                       "crank.O2",
                       "crank.A",
                       InputControl::kDisplacement,
                       theta2 - 0.01 * kDeg,
                       theta2 + 0.01 * kDeg,
                       3);
    const GeneralPrbmResult p = solve_general_prbm(m);
    const GeneralPrbmResult e = solve_general_exact(m);
    ASSERT_TRUE(p.converged()) << trial << ": " << p.message;
    ASSERT_TRUE(e.converged()) << trial << ": " << e.message;
    const double ratio = stiffness(p) / stiffness(e) - 1.0;
    lo = std::min(lo, ratio);
    hi = std::max(hi, ratio);
  }
  EXPECT_GT(lo, 0.0);
  EXPECT_LT(hi, 0.01);
}

// Exact equilibria re-solved flexure by flexure: the all-exact mixed solve records every flexure's
// tip loads and tip at every point (its tip is where the bodies put it, to the Newton tolerance);
// --check-flexures solves each flexure alone under those loads by the elliptic solution. Measured
// on 6 seeded four-bars driven +-4 deg (9 points, 4 flexures: 216 solves): at most 8.5e-14 of the
// length. (At the rest point the loads are of round-off size, 1e-17, where the elliptic solution
// resolved only its tolerance, 1.4e-6; linear theory answers there: flexure_models.cpp.)
TEST(GeneralRandomCrossChecks, ExactEquilibriaResolvedFlexureByFlexure) {
  std::mt19937 rng(3103);
  GeneralExactOptions o;
  o.measure_flexure_errors = true;
  double worst = 0.0;
  int solves = 0;
  for (int trial = 0; trial < 6; ++trial) {
    double theta2 = 0.0;
    GeneralMechanism m = random_four_bar(rng, &theta2);
    m.input_coordinate(InputCoordinate::kAngle,
                       "crank.O2",
                       "crank.A",
                       InputControl::kDisplacement,
                       theta2 - 4.0 * kDeg,
                       theta2 + 4.0 * kDeg,
                       9);
    for (Flexure& f : m.flexures) f.model = FlexureModel::kExact;
    const GeneralPrbmResult r = solve_general_mixed(m, o);
    ASSERT_TRUE(r.converged()) << trial << ": " << r.message;
    ASSERT_EQ(r.flexure_models.size(), 4u);
    for (const FlexureModelReport& f : r.flexure_models) {
      ASSERT_EQ(f.measured_error.size(), 9u);
      for (std::size_t k = 0; k < f.measured_error.size(); ++k) {
        const double e = f.measured_error[k];
        ASSERT_TRUE(std::isfinite(e)) << trial << " " << f.name;
        worst = std::max(worst, e);
        ++solves;
      }
    }
  }
  EXPECT_EQ(solves, 216);
  EXPECT_LT(worst, 1e-8);
}

}  // namespace
}  // namespace flexure::mechanism::general
