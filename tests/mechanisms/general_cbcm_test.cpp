// The chained BCM as a flexure of a general mechanism (`--model mixed`, a flexure's model
// "cbcm"; elements/cbcm_march.h, docs/mechanisms.md "The inclined bistable beam with the CBCM"):
// * the march from root loads against the tip-loaded CBCM (ChainedBcmSolver, proportional loading
//   from the unloaded chain: another solution path of the same equations);
// * the inclined bistable beam (issue 31, docs/examples/inclined_bistable_beam.toml) traced with a
//   CBCM flexure through both sign changes of its force, its force zeros, extrema and verdicts
//   against the extensible exact model's (the CBCM is an approximation: the tolerances are its
//   measured errors, and they fall with the number of elements).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "flexure/elements/cbcm_march.h"
#include "flexure/elements/ladder_models.h"
#include "flexure/mechanisms/general/general_analysis.h"
#include "flexure/mechanisms/general/general_mechanism.h"

namespace flexure::mechanism::general {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// The march's tip and tip moment, used as the dead tip loads of the tip-loaded CBCM (the same
// elements, the same axial stiffness), give back the march's tip: one equilibrium of one set of
// equations reached two ways. 40 seeded random root loads, bending up to about 1 rad, with and
// without extension. Measured: all 40 converge on the load path, and meet to 1.6e-13 of the length.
TEST(CbcmMarch, MeetsTheTipLoadedCbcmOnSeededRandomLoads) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int compared = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const int elements = 2 + trial % 11;
    const double slenderness = trial % 2 == 0 ? 0.0 : 20.0 + 30.0 * (u(rng) + 1.0);
    const double inverse_d = slenderness > 0.0 ? 1.0 / (12.0 * slenderness * slenderness) : 0.0;
    const double m0 = 1.2 * u(rng), Fx = 2.0 * u(rng), Fy = 1.5 * u(rng);
    CbcmMarchResult march;
    ASSERT_TRUE(cbcm_march(elements, inverse_d, m0, Fx, Fy, march, true)) << trial;
    ASSERT_EQ(march.nodes.size(), static_cast<std::size_t>(elements + 1));
    // The moment at the tip from statics: m(1) = m0 + Fx y - Fy x.
    EXPECT_NEAR(march.m, m0 + Fx * march.y - Fy * march.x, 1e-12) << trial;
    CantileverCase c;
    c.load = EndLoad{Fx, Fy, march.m};
    ChainedBcmSolver::Options o;
    o.elements = elements;
    o.slenderness = slenderness;
    const CbcmResult r = ChainedBcmSolver(o).solve(c);
    if (!r.converged()) continue;  // the dead-load path from rest folds: nothing to compare
    EXPECT_NEAR(r.tip.x, march.x, 1e-10) << trial;
    EXPECT_NEAR(r.tip.y, march.y, 1e-10) << trial;
    EXPECT_NEAR(r.tip.theta, march.theta, 1e-10) << trial;
    ++compared;
  }
  EXPECT_EQ(compared, 40);
}

TEST(CbcmMarch, RefusesWhatItCannotMarch) {
  CbcmMarchResult r;
  EXPECT_FALSE(cbcm_march(0, 0.0, 0.0, 0.0, 0.0, r));
  EXPECT_FALSE(cbcm_march(6, 0.0, std::nan(""), 0.0, 0.0, r));
  EXPECT_FALSE(cbcm_march(6, -1.0, 0.0, 0.0, 0.0, r));
  // Unloaded: straight.
  ASSERT_TRUE(cbcm_march(6, 0.0, 0.0, 0.0, 0.0, r));
  EXPECT_DOUBLE_EQ(r.x, 1.0);
  EXPECT_DOUBLE_EQ(r.y, 0.0);
}

// The inclined bistable beam of docs/examples/inclined_bistable_beam.toml (as
// tests/mechanisms/general_exact_stability_test.cpp builds it), its flexure `model` (exact or
// cbcm with `elements`), the shuttle moved from `start_travel` to `stop_travel` down.
GeneralMechanism inclined_beam(
    double start_travel, double stop_travel, int count, FlexureModel model, int elements) {
  const double L = 0.070, alpha = 5.5 * kDeg;
  const Vec2 tip{L * std::cos(alpha), L * std::sin(alpha)};
  GeneralMechanism m;
  m.name = "inclined-bistable-beam";
  m.body("ground", {{"C", {0, 0}}, {"G", tip}})
      .body("shuttle", {{"P", tip}})
      .slider("guide", "ground.G", "shuttle.P", 90.0 * kDeg)
      .flexure("beam", "ground.C", "shuttle.P", 12.55e-3, 1.5e-3, 1.379e9, PrbmKind::kFixedGuided)
      .input_coordinate(InputCoordinate::kY,
                        "shuttle.P",
                        "",
                        InputControl::kDisplacement,
                        tip.y - start_travel,
                        tip.y - stop_travel,
                        count);
  m.flexures[0].extensible = true;
  m.flexures[0].model = model;
  m.flexures[0].elements = elements;
  return m;
}

GeneralPrbmResult solve(double start, double stop, int count, FlexureModel model, int n) {
  const GeneralMechanism m = inclined_beam(start, stop, count, model, n);
  return model == FlexureModel::kExact ? solve_general_exact(m) : solve_general_mixed(m);
}

struct Landmarks {
  double unstable_zero = 0.0, stable_zero = 0.0;  // travel (m)
  double push_travel = 0.0, push = 0.0;           // the largest pushing force on the path (N)
  double pull_travel = 0.0, pull = 0.0;           // the largest pull (N, negative)
};

// The vertex of the parabola through three equally spaced points (x0 - h, x0, x0 + h).
void vertex(double x0, double h, double fm, double f0, double fp, double& x, double& f) {
  x = x0 + h * (fm - fp) / (2.0 * (fp - 2.0 * f0 + fm));
  f = f0 - (fp - fm) * (fp - fm) / (8.0 * (fp - 2.0 * f0 + fm));
}

// The force zeros (the equilibria the model refined, travel > 0) and the two extrema of the pushing
// force (-input load): each on a 0.01 mm grid from the described state (the push peak lies on the
// unbuckled branch past the first bifurcation, which a start away from rest would not follow),
// then a parabola through the grid's largest value and its neighbours.
Landmarks landmarks(FlexureModel model, int n) {
  const double y0 = 0.070 * std::sin(5.5 * kDeg);
  Landmarks out;
  const GeneralPrbmResult r = solve(0.0, 12e-3, 121, model, n);
  EXPECT_TRUE(r.converged()) << r.message;
  EXPECT_EQ(r.points.size(), 121u);
  EXPECT_EQ(r.equilibria.size(), 3u);
  if (r.equilibria.size() == 3u) {
    out.unstable_zero = y0 - r.equilibria[1].input;
    out.stable_zero = y0 - r.equilibria[2].input;
  }
  const double h = 1e-5;
  const GeneralPrbmResult a = solve(0.0, 1.85e-3, 186, model, n);
  EXPECT_TRUE(a.converged()) << a.message;
  std::size_t k = 1;
  for (std::size_t i = 1; i + 1 < a.points.size(); ++i) {
    if (-a.points[i].input_load > -a.points[k].input_load) k = i;
  }
  vertex(y0 - a.points[k].input,
         h,
         -a.points[k - 1].input_load,
         -a.points[k].input_load,
         -a.points[k + 1].input_load,
         out.push_travel,
         out.push);
  // After the buckled branch has rejoined it the unbuckled branch is the only one: a start there.
  const GeneralPrbmResult b = solve(8.0e-3, 8.1e-3, 11, model, n);
  EXPECT_TRUE(b.converged()) << b.message;
  k = 1;
  for (std::size_t i = 1; i + 1 < b.points.size(); ++i) {
    if (-b.points[i].input_load < -b.points[k].input_load) k = i;
  }
  vertex(y0 - b.points[k].input,
         h,
         -b.points[k - 1].input_load,
         -b.points[k].input_load,
         -b.points[k + 1].input_load,
         out.pull_travel,
         out.pull);
  return out;
}

// The CBCM follows the inclined beam through both sign changes of its force, on the exact model's
// (unbuckled) branch. Measured, CBCM - exact (travel in mm, force in N; exact: zeros 6.068895 and
// 9.696183, push peak 3.285525 at 1.7584, pull peak -0.562119 at 8.0466):
//   elements   unstable zero   stable zero   push peak          pull peak          pull travel
//   6          +5.6e-4         +5.4e-4       -4.8e-5 (1.4e-5)   -1.4e-4 (2.5e-4)   +3.3e-4
//   24         +3.8e-5         +1.9e-5       -1.4e-5 (4.1e-6)   +1.9e-5 (3.3e-5)   +3.4e-5
// (relative in brackets; docs/mechanisms.md). The tolerances are the 6-element errors rounded up;
// with 24 elements every error is at least 3.5 times smaller (the zeros 15 and 29 times).
TEST(GeneralCbcm, InclinedBistableBeamAgreesWithTheExtensibleExactModel) {
  const Landmarks ex = landmarks(FlexureModel::kExact, 6);
  // The exact model's own landmarks, as docs/mechanisms.md states them (the stable zero and the
  // pull peak are the beam path's too: general_exact_stability_test.cpp).
  EXPECT_NEAR(ex.stable_zero, 9.696183e-3, 1e-9);
  EXPECT_NEAR(ex.unstable_zero, 6.068895e-3, 1e-9);
  EXPECT_NEAR(ex.pull, -0.562119, 1e-6);
  EXPECT_NEAR(ex.push, 3.285525, 2e-6);
  const Landmarks c6 = landmarks(FlexureModel::kCbcm, 6);
  EXPECT_NEAR(c6.unstable_zero, ex.unstable_zero, 6e-7);
  EXPECT_NEAR(c6.stable_zero, ex.stable_zero, 6e-7);
  EXPECT_NEAR(c6.push, ex.push, 2e-5 * ex.push);
  EXPECT_NEAR(c6.pull, ex.pull, 3e-4 * std::fabs(ex.pull));
  EXPECT_NEAR(c6.pull_travel, ex.pull_travel, 4e-7);
  EXPECT_NEAR(c6.push_travel, ex.push_travel, 1e-7);  // a flat maximum
  const Landmarks c24 = landmarks(FlexureModel::kCbcm, 24);
  EXPECT_LT(std::fabs(c24.unstable_zero - ex.unstable_zero),
            std::fabs(c6.unstable_zero - ex.unstable_zero) / 10.0);
  EXPECT_LT(std::fabs(c24.stable_zero - ex.stable_zero),
            std::fabs(c6.stable_zero - ex.stable_zero) / 10.0);
  EXPECT_LT(std::fabs(c24.pull - ex.pull), std::fabs(c6.pull - ex.pull) / 3.5);
  EXPECT_LT(std::fabs(c24.push - ex.push), std::fabs(c6.push - ex.push) / 3.0);
}

// The verdicts with a CBCM flexure (the elastica's second variation on the CBCM's shape with its
// ends held, plus the shuttle's condensed stiffness) equal the exact model's at every point of the
// 121 but those within 0.05 mm of the two bifurcations (1.289366 and about 7.6618 mm, where the
// margin passes 0), under both controls; the input load agrees to the CBCM's error (6 elements:
// at most 7.7e-3 N, at the end of the travel where the force is 3.85 N).
TEST(GeneralCbcm, InclinedBistableBeamVerdictsAreTheExactModels) {
  const double y0 = 0.070 * std::sin(5.5 * kDeg);
  const GeneralPrbmResult ex = solve(0.0, 12e-3, 121, FlexureModel::kExact, 6);
  const GeneralPrbmResult cb = solve(0.0, 12e-3, 121, FlexureModel::kCbcm, 6);
  ASSERT_TRUE(ex.converged()) << ex.message;
  ASSERT_TRUE(cb.converged()) << cb.message;
  ASSERT_EQ(ex.points.size(), cb.points.size());
  int compared = 0, unstable = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < ex.points.size(); ++i) {
    const GeneralPrbmPoint& e = ex.points[i];
    const GeneralPrbmPoint& c = cb.points[i];
    worst = std::max(worst, std::fabs(e.input_load - c.input_load));
    const double travel = y0 - e.input;
    if (std::fabs(travel - 1.289366e-3) < 5e-5 || std::fabs(travel - 7.6618e-3) < 5e-5) continue;
    EXPECT_EQ(c.displacement_control.kind, e.displacement_control.kind) << travel;
    EXPECT_EQ(c.displacement_control.index, e.displacement_control.index) << travel;
    EXPECT_EQ(c.force_control.kind, e.force_control.kind) << travel;
    unstable += c.displacement_control.index > 0 ? 1 : 0;
    ++compared;
  }
  EXPECT_GE(compared, 119);
  EXPECT_GE(unstable, 60);  // held, the unbuckled beam is unstable between the bifurcations
  EXPECT_LT(worst, 8e-3);
  EXPECT_TRUE(std::isnan(cb.points[5].energy));  // the CBCM gives no strain energy here
}

// With 4 elements the CBCM's unbuckled branch has a fold near 7.6 mm (the CBCM path's too,
// docs/models.md): the natural continuation stops there and the arclength path takes over from the
// start. Its equilibria are the zeros of the force along that path (a first version took the
// zeros of the controlled input instead and reported the shuttle's y = 0 as an equilibrium).
// Measured: 0, 6.0685 and 9.6975 mm against the exact 0, 6.0689, 9.6962 (the 4-element error).
TEST(GeneralCbcm, ArclengthPathFindsTheForceZerosAsEquilibria) {
  const double y0 = 0.070 * std::sin(5.5 * kDeg);
  const GeneralPrbmResult r = solve(0.0, 12e-3, 121, FlexureModel::kCbcm, 4);
  ASSERT_TRUE(r.converged()) << r.message;
  EXPECT_EQ(r.points.size(), 121u);
  bool switched = false;
  for (const auto& w : r.warnings) {
    switched = switched || w.text.find("followed by arclength") != std::string::npos;
  }
  EXPECT_TRUE(switched);
  ASSERT_EQ(r.equilibria.size(), 3u);
  EXPECT_NEAR(y0 - r.equilibria[0].input, 0.0, 1e-12);
  EXPECT_NEAR(y0 - r.equilibria[1].input, 6.068895e-3, 2e-6);
  EXPECT_NEAR(y0 - r.equilibria[2].input, 9.696183e-3, 2e-6);
  EXPECT_EQ(r.equilibria[1].stability.kind, StabilityKind::kUnstable);
  EXPECT_EQ(r.equilibria[2].stability.kind, StabilityKind::kStable);
}

// Too few elements: the 2-element CBCM cannot follow the beam past about 8 mm; the failure says
// the flexure is a CBCM of 2 elements and its elements' deflection past the BCM's range.
TEST(GeneralCbcm, PointResultsOfACbcmFlexureFollowTheExactOnes) {
  // A CBCM flexure's end loads come from its root loads (not the tip loads of the other models):
  // its end moments at every point follow the exact flexure's within the CBCM's own error (24
  // elements: its force peaks within 3.3e-5, above). Its stresses are those of its ends (a model
  // flexure has no shape here; the exact flexure's largest stress of the buckled beam lies inside).
  const GeneralPrbmResult exact = solve(0.0, 12e-3, 25, FlexureModel::kExact, 0);
  const GeneralPrbmResult cbcm = solve(0.0, 12e-3, 25, FlexureModel::kCbcm, 24);
  ASSERT_TRUE(exact.converged()) << exact.message;
  ASSERT_TRUE(cbcm.converged()) << cbcm.message;
  ASSERT_EQ(exact.points.size(), cbcm.points.size());
  double largest = 0.0;
  for (const auto& p : exact.points) {
    largest = std::max({largest,
                        std::fabs(p.flexures.at(0).on_a.moment),
                        std::fabs(p.flexures.at(0).on_b.moment)});
  }
  ASSERT_GT(largest, 0.0);
  for (std::size_t i = 0; i < exact.points.size(); ++i) {
    const FlexurePointResult& e = exact.points[i].flexures.at(0);
    const FlexurePointResult& c = cbcm.points[i].flexures.at(0);
    EXPECT_NEAR(c.on_a.moment, e.on_a.moment, 2e-3 * largest) << "point " << i;
    EXPECT_NEAR(c.on_b.moment, e.on_b.moment, 2e-3 * largest) << "point " << i;
    EXPECT_STREQ(c.max_from, "ends");
  }
}

TEST(GeneralCbcm, TooFewElementsFailWithTheReason) {
  const GeneralPrbmResult r = solve(0.0, 12e-3, 121, FlexureModel::kCbcm, 2);
  ASSERT_FALSE(r.converged());
  EXPECT_NE(r.message.find("is a CBCM of 2 elements"), std::string::npos) << r.message;
  bool range = false;
  for (const auto& w : r.warnings) {
    range = range || w.text.find("past the BCM's stated range") != std::string::npos;
  }
  EXPECT_TRUE(range);
}

}  // namespace
}  // namespace flexure::mechanism::general
