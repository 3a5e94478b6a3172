// Stability of the exact model of a general mechanism (mechanisms/general/exact_stability.h,
// general_analysis.h; docs/mechanisms.md "Stability of the exact model") against independent
// values: Howell's bistable switch (its verdicts against the sign of the exact model's own energy
// curvature d(input load)/d(input), the PRBM's classification of its equilibria, Table 11.2), a
// parallel-guiding stage (stable, 24 EI/L^3), and a column loaded axially through a mechanism,
// whose verdict must flip at its Euler load 4 pi^2 EI/L^2 (clamped at both ends, axially free) with
// margin 1 - P/P_cr.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "flexure/mechanisms/general/catalogue_general.h"
#include "flexure/mechanisms/general/general_analysis.h"
#include "flexure/mechanisms/general/general_mechanism.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/mechanisms/mechanism_exact.h"

namespace flexure::mechanism::general {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

// Howell's bistable switch, Table 11.1 (as tests/mechanisms/general_mechanism_test.cpp builds it):
// r1 3.61 cm, r2 2.0 cm, r3 1.0 cm, r4 1.23 cm, theta4o = 142 deg, a small-length flexure at O4
// (E = 1.4 GPa, b 6.3 mm, h 2.3 mm, l 4.2 mm), described at theta2 near 0.
GeneralMechanism bistable_switch(double start_deg, double stop_deg, int count) {
  const double r1 = 0.0361, r2 = 0.020, r3 = 0.010, r4 = 0.0123, t4 = 142.0 * kDeg, l4 = 4.2e-3;
  const Vec2 O4{r1, 0.0};
  const Vec2 B{O4.x + r4 * std::cos(t4), O4.y + r4 * std::sin(t4)};
  // A: circle r2 about O2 meets circle r3 about B, on the right of O2 -> B.
  const double d = std::hypot(B.x, B.y);
  const double a = (r2 * r2 - r3 * r3 + d * d) / (2 * d);
  const double h = std::sqrt(r2 * r2 - a * a);
  const Vec2 A{a * B.x / d + h * B.y / d, a * B.y / d - h * B.x / d};
  const Vec2 u{std::cos(t4), std::sin(t4)};
  GeneralMechanism m;
  m.name = "howell-bistable-switch";
  m.body("ground", {{"O2", {0, 0}}, {"F", {O4.x - l4 / 2 * u.x, O4.y - l4 / 2 * u.y}}})
      .body("crank", {{"O2", {0, 0}}, {"A", A}})
      .body("coupler", {{"A", A}, {"B", B}})
      .body("rocker", {{"B", B}, {"F", {O4.x + l4 / 2 * u.x, O4.y + l4 / 2 * u.y}}})
      .pin("O2", "ground.O2", "crank.O2")
      .pin("A", "crank.A", "coupler.A")
      .pin("B", "coupler.B", "rocker.B")
      .flexure("pivot4", "ground.F", "rocker.F", 6.3e-3, 2.3e-3, 1.4e9, PrbmKind::kSmallLengthPivot)
      .input_coordinate(InputCoordinate::kAngle,
                        "crank.O2",
                        "crank.A",
                        InputControl::kDisplacement,
                        start_deg * kDeg,
                        stop_deg * kDeg,
                        count);
  return m;
}

TEST(GeneralExactStability, BistableSwitchVerdictsFollowTheEnergyCurvature) {
  const GeneralMechanism m = bistable_switch(-5.0, 33.0, 77);
  const GeneralPrbmResult prbm = solve_general_prbm(m);
  const GeneralPrbmResult r = solve_general_exact(m);
  ASSERT_TRUE(r.converged()) << r.message;
  ASSERT_EQ(r.points.size(), 77u);
  // Equilibria: the PRBM's classification (Table 11.2: stable near 0 and 32 deg, unstable at
  // 18.7 deg), each judged by the exact model's own Hessian.
  ASSERT_EQ(r.equilibria.size(), 3u);
  ASSERT_EQ(prbm.equilibria.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(r.equilibria[i].stability.kind, prbm.equilibria[i].stability.kind) << i;
  }
  EXPECT_EQ(r.equilibria[0].stability.kind, StabilityKind::kStable);
  EXPECT_EQ(r.equilibria[1].stability.kind, StabilityKind::kUnstable);
  EXPECT_EQ(r.equilibria[1].stability.index, 1);
  EXPECT_EQ(r.equilibria[2].stability.kind, StabilityKind::kStable);
  // Under displacement control the one-degree-of-freedom linkage held at its crank leaves only
  // the flexure with its ends held: stable at every point.
  // Under force control (a dead crank torque) the verdict is the sign of the energy's curvature
  // d2V/dtheta2^2 = d(torque)/d(theta2): central differences of the exact torque.
  const double step = r.points[1].input - r.points[0].input;
  int judged = 0;
  for (std::size_t i = 0; i < r.points.size(); ++i) {
    const GeneralPrbmPoint& p = r.points[i];
    EXPECT_EQ(p.displacement_control.kind, StabilityKind::kStable) << i;
    if (i == 0 || i + 1 == r.points.size()) continue;
    const double curvature = (r.points[i + 1].input_load - r.points[i - 1].input_load) / (2 * step);
    const double energy_curvature =
        (r.points[i + 1].energy - 2 * p.energy + r.points[i - 1].energy) / (step * step);
    ++judged;
    EXPECT_EQ(p.force_control.kind,
              curvature > 0 ? StabilityKind::kStable : StabilityKind::kUnstable)
        << i << " " << p.force_control.message;
  }
  EXPECT_EQ(judged, 75);
  // The energy view: the extrema of the exact energy (the flexure's strain energy integral
  // m^2/2EI, not the input load) are the force-crossing equilibria, its minima the stable ones.
  // On the 0.5 deg grid there are three; on a 0.02 deg grid around each equilibrium the parabola
  // through the three points about it finds the extremum to about step^2 V'''/V''.
  int extrema = 0;
  for (std::size_t i = 1; i + 1 < r.points.size(); ++i) {
    const double em = r.points[i - 1].energy, e0 = r.points[i].energy, ep = r.points[i + 1].energy;
    extrema += (e0 - em) * (ep - e0) <= 0.0 ? 1 : 0;
  }
  EXPECT_EQ(extrema, 3);
  for (const GeneralEquilibrium& e : r.equilibria) {
    const double h = 0.02 * kDeg;
    GeneralMechanism fine = m;
    fine.input.start = e.input - 2 * h;
    fine.input.stop = e.input + 2 * h;
    fine.input.count = 5;
    const GeneralPrbmResult f = solve_general_exact(fine);
    ASSERT_TRUE(f.converged()) << f.message;
    const double em = f.points[1].energy, e0 = f.points[2].energy, ep = f.points[3].energy;
    const double vertex = f.points[2].input - h * (ep - em) / (2.0 * (ep - 2.0 * e0 + em));
    EXPECT_NEAR(vertex, e.input, 1e-3 * kDeg);
    EXPECT_EQ(e.stability.kind,
              ep - 2.0 * e0 + em > 0.0 ? StabilityKind::kStable : StabilityKind::kUnstable);
  }
}

// Two fixed-guided flexures of length L carrying a stage (Howell ch. 5): the stage moved along x
// by 30 % of L.
GeneralMechanism parallel_guide(double L, double spacing, double E, double b, double h, int count) {
  GeneralMechanism m;
  m.body("ground", {{"c1", {0, 0}}, {"c2", {spacing, 0}}})
      .body("stage", {{"c1", {0, L}}, {"c2", {spacing, L}}})
      .flexure("left", "ground.c1", "stage.c1", b, h, E, PrbmKind::kFixedGuided)
      .flexure("right", "ground.c2", "stage.c2", b, h, E, PrbmKind::kFixedGuided)
      .input_coordinate(InputCoordinate::kX,
                        "stage.c1",
                        "",
                        InputControl::kDisplacement,
                        -0.3 * L,
                        0.3 * L,
                        count);
  return m;
}

TEST(GeneralExactStability, ParallelGuideIsStableEverywhere) {
  const double L = 0.05, E = 2e9, b = 0.01, h = 1e-3;
  const GeneralPrbmResult r = solve_general_exact(parallel_guide(L, 0.03, E, b, h, 25));
  ASSERT_TRUE(r.converged()) << r.message;
  ASSERT_EQ(r.points.size(), 25u);
  for (const GeneralPrbmPoint& p : r.points) {
    EXPECT_EQ(p.displacement_control.kind, StabilityKind::kStable)
        << p.displacement_control.message;
    // The guide stiffens as it moves (its flexures are stretched): stable under a dead load too.
    EXPECT_EQ(p.force_control.kind, StabilityKind::kStable) << p.force_control.message;
  }
  // At the rest position the stage's stiffness along x is the unloaded flexures' 24 EI/L^3, the
  // reference of the margin: margin 1, under both controls.
  EXPECT_NEAR(r.points[12].force_control.margin, 1.0, 1e-6);
  EXPECT_NEAR(r.points[12].displacement_control.margin, 1.0, 1e-6);
}

// A column of length L clamped to the ground at one end and to a slide at the other (the slide on
// a slider along the column: it keeps its angle and its y), pushed along its axis through a linear
// spring k by a pusher whose x is the input. The column stays straight (inextensible) and carries
// P = k (x0 - x); clamped at both ends with its far end axially free it buckles at
// P_cr = 4 pi^2 EI/L^2, with the margin 1 - P/P_cr (docs/stability.md). Both controls: the
// pusher's direction is the spring's (margin 1) and the slide cannot move.
GeneralMechanism pushed_column(
    double L, double E, double b, double h, double k, double stop, int count) {
  const double gap = 0.02;
  GeneralMechanism m;
  m.body("ground", {{"C", {0, 0}}, {"S", {L, 0}}, {"T", {L + gap, 0}}})
      .body("slide", {{"Q", {L, 0}}})
      .body("pusher", {{"P", {L + gap, 0}}})
      .slider("slide-guide", "ground.S", "slide.Q", 0.0)
      .slider("pusher-guide", "ground.T", "pusher.P", 0.0)
      .flexure("column", "ground.C", "slide.Q", b, h, E, PrbmKind::kFixedGuided)
      .linear_spring("push", "slide.Q", "pusher.P", k)
      .input_coordinate(
          InputCoordinate::kX, "pusher.P", "", InputControl::kDisplacement, L + gap, stop, count);
  return m;
}

TEST(GeneralExactStability, ColumnPushedThroughAMechanismBucklesAtTheEulerLoad) {
  const double L = 0.05, E = 2e9, b = 0.01, h = 1e-3, k = 1e4;
  const double EI = E * b * h * h * h / 12.0;
  const double P_cr = 4.0 * kPi * kPi * EI / (L * L);
  const double delta_cr = P_cr / k;
  // 1.8 P_cr (below the second clamped-clamped load 8.18 pi^2 EI/L^2 = 2.05 P_cr); 20 points, none
  // at P_cr itself (a bifurcation: the linearisation is singular there).
  const GeneralPrbmResult r =
      solve_general_exact(pushed_column(L, E, b, h, k, L + 0.02 - 1.8 * delta_cr, 20));
  ASSERT_TRUE(r.converged()) << r.message;
  ASSERT_EQ(r.points.size(), 20u);
  int below = 0, above = 0;
  for (const GeneralPrbmPoint& p : r.points) {
    const double P = -p.input_load;
    EXPECT_NEAR(P, k * (L + 0.02 - p.input), 1e-9 * P_cr);
    const double expected = 1.0 - P / P_cr;
    for (const Stability* v : {&p.displacement_control, &p.force_control}) {
      EXPECT_NEAR(v->margin, expected, 1e-6) << "P/P_cr " << P / P_cr << ": " << v->message;
      EXPECT_EQ(v->kind, P < P_cr ? StabilityKind::kStable : StabilityKind::kUnstable)
          << "P/P_cr " << P / P_cr;
      EXPECT_EQ(v->index, P < P_cr ? 0 : 1);
    }
    (P < P_cr ? below : above) += 1;
  }
  EXPECT_EQ(below, 11);
  EXPECT_EQ(above, 9);
}

}  // namespace
}  // namespace flexure::mechanism::general

namespace flexure::mechanism::general {
namespace {

// Under torque control (a dead crank torque from 0 to 1.2 N m) the exact switch snaps where its
// torque curve under displacement control peaks: the limit points are the extremes of the
// displacement-controlled torque (a parabola through a 0.01 deg grid about each), the path turns
// back there and reaches the range's end on the far stable branch; its points' verdicts are those
// of the displacement-controlled curve's slope, and its unloaded equilibria are the displacement
// path's.
TEST(GeneralExactStability, SwitchUnderTorqueControlPassesItsLimitPoints) {
  GeneralMechanism m = bistable_switch(-5.0, 33.0, 77);
  const GeneralPrbmResult held = solve_general_exact(m);
  ASSERT_TRUE(held.converged()) << held.message;
  m.input.control = InputControl::kForce;
  m.input.start = 0.0;
  m.input.stop = 1.2;
  m.input.count = 19;
  const GeneralPrbmResult r = solve_general_exact(m);
  ASSERT_TRUE(r.converged()) << r.message;
  ASSERT_EQ(r.limit_inputs.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const double h = 0.01 * kDeg;
    GeneralMechanism fine = bistable_switch(0, 1, 5);
    fine.input.start = r.limit_inputs[k] - 2 * h;
    fine.input.stop = r.limit_inputs[k] + 2 * h;
    const GeneralPrbmResult f = solve_general_exact(fine);
    ASSERT_TRUE(f.converged()) << f.message;
    const double tm = f.points[1].input_load, t0 = f.points[2].input_load,
                 tp = f.points[3].input_load;
    const double vertex = f.points[2].input - h * (tp - tm) / (2.0 * (tp - 2.0 * t0 + tm));
    const double extreme = t0 - (tp - tm) * (tp - tm) / (8.0 * (tp - 2.0 * t0 + tm));
    // Measured: 1e-5 deg and 1e-10 N m.
    EXPECT_NEAR(r.limit_inputs[k], vertex, 1e-4 * kDeg);
    EXPECT_NEAR(r.limit_loads[k], extreme, 1e-8);
  }
  EXPECT_GT(r.limit_loads[0], 0.26);   // the snap-through torque
  EXPECT_LT(r.limit_loads[1], -0.39);  // the snap back
  // Points in path order: up the first stable branch to the limit, down the unstable one, then
  // (past the second limit, below zero torque) up the second stable branch to 1.2 N m.
  ASSERT_EQ(r.points.size(), 4u + 4u + 19u);
  for (const GeneralPrbmPoint& p : r.points) {
    const bool unstable_branch = p.input > r.limit_inputs[0] && p.input < r.limit_inputs[1];
    EXPECT_EQ(p.force_control.kind,
              unstable_branch ? StabilityKind::kUnstable : StabilityKind::kStable)
        << p.input / kDeg;
    EXPECT_EQ(p.displacement_control.kind, StabilityKind::kStable) << p.input / kDeg;
  }
  EXPECT_NEAR(r.points.back().input_load, 1.2, 1e-12);
  ASSERT_EQ(r.equilibria.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(r.equilibria[i].input, held.equilibria[i].input, 1e-8);
    EXPECT_EQ(r.equilibria[i].stability.kind, held.equilibria[i].stability.kind);
  }
}

// Driven past the end of its travel (the coupler and rocker aligned), the exact switch's crank
// angle has a limit point: the natural-parameter continuation stops there and the path is
// followed by arclength, which records the points it reaches (the natural path's, to 1e-9) and
// reports the limit: the rigid four-bar's travel limit |A - O4| = r3 + r4, theta2 = 33.376 deg,
// within 0.02 deg (the flexure's centre moves a little; measured 33.372 deg).
TEST(GeneralExactStability, CrankDrivenPastItsTravelStopsAtTheLimitPoint) {
  const GeneralPrbmResult below = solve_general_exact(bistable_switch(-5.0, 33.0, 20));
  ASSERT_TRUE(below.converged()) << below.message;
  const GeneralPrbmResult r = solve_general_exact(bistable_switch(-5.0, 35.0, 21));
  EXPECT_EQ(r.termination, Termination::kLimitPoint) << r.message;
  ASSERT_GE(r.limit_inputs.size(), 1u);
  const double r1 = 0.0361, r2 = 0.020, r3 = 0.010, r4 = 0.0123;
  const double travel = std::acos((r2 * r2 + r1 * r1 - (r3 + r4) * (r3 + r4)) / (2 * r1 * r2));
  EXPECT_NEAR(r.limit_inputs[0], travel, 0.02 * kDeg);
  // The grid points before the limit (every 2 deg from -5 to 33) are the natural path's.
  ASSERT_GE(r.points.size(), 20u);
  for (std::size_t i = 0; i < 20; ++i) {
    EXPECT_NEAR(r.points[i].input, below.points[i].input, 1e-12);
    EXPECT_NEAR(r.points[i].input_load, below.points[i].input_load, 1e-9) << i;
  }
}

// The catalogue's constant-force designs rebuilt as general mechanisms (catalogue_general.h):
// the general exact model's verdicts against the catalogue's own exact verdicts
// (exact_point_stability, mechanism_analysis.h: its chains' second variation along the path it
// judges, independent code), kind and index under both controls at every stroke point.
TEST(GeneralExactStability, CatalogueDesignsVerdictsMatchTheCatalogueExactModel) {
  int compared = 0, unstable = 0;
  for (const char* name : {"3A-sss", "2A-ssp", "1A-spp", "1A-lpp", "2B-sps"}) {
    const MechanismDesign d = find_builtin_mechanism(name);
    const int points = 10;
    const GeneralPrbmResult r = solve_general_exact(general_from_design(d, points));
    ASSERT_TRUE(r.converged()) << name << ": " << r.message;
    const std::vector<double> dx = stroke_displacements(d, points);
    const ExactStrokeResult c = exact_stroke(d, dx);
    ASSERT_TRUE(c.converged()) << c.message;
    for (int i = 0; i < points; ++i) {
      const std::size_t k = static_cast<std::size_t>(i);
      const PointStability v = exact_point_stability(d, c.points[k]);
      const GeneralPrbmPoint& p = r.points[k];
      EXPECT_EQ(p.displacement_control.kind, v.displacement_control.kind) << name << " " << i;
      EXPECT_EQ(p.displacement_control.index, v.displacement_control.index) << name << " " << i;
      EXPECT_EQ(p.force_control.kind, v.force_control.kind) << name << " " << i;
      EXPECT_EQ(p.force_control.index, v.force_control.index) << name << " " << i;
      compared += 2;
      unstable += (v.displacement_control.index > 0) + (v.force_control.index > 0);
    }
  }
  EXPECT_EQ(compared, 100);
  // Measured: every kind and index agrees; the catalogue finds 10 of them unstable (force control
  // on 2A-ssp and 1A-spp, where the force falls).
  EXPECT_EQ(unstable, 10);
}

// The inclined bistable beam (issue 31; docs/examples/inclined_bistable_beam.toml): a beam
// 70 mm long clamped at 5.5 deg, 12.55 mm x 1.5 mm, E = 1.379 GPa, clamped into a shuttle guided
// along y, moved 12 mm down. `axial` sets EA through the flexure's E b h.
GeneralMechanism inclined_beam(double start_travel, double stop_travel, int count) {
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
  return m;
}

// The extensible exact model against two independent computations of the same beam:
// * an independent Reissner shooting (scipy's DOP853 at rtol 1e-13 and fsolve on the root loads,
//   the beam alone clamped at 5.5 deg with its tip prescribed at a travel of 0.5 mm): pushing
//   force 1.5605303807118 N, root moment 1.9981080274e-3 N m (to 1e-11 here);
// * the beam path (docs/paths.md, `flexure path` on docs/examples/inclined_bistable_path.toml,
//   EA = E b h): the first bifurcation at 1.289366 mm under 3.045947 N, the largest pull
//   -0.562119 N at 8.046628 mm, the stable zero at 9.696183 mm (where its unbuckled branch is the
//   mechanism's). Measured: within 2e-7 of the force and 1e-6 mm. (That file once gave EA =
//   25960.2 N, E b h rounded up by 2.0e-5, and the path's forces differed by that much.)
// The verdicts: held at the shuttle (displacement control) the unbuckled beam is stable up to the
// path's first bifurcation, 1.289366 mm, unstable up to the second, about 7.6618 mm, where the
// buckled branch rejoins it, and stable after (the flexure judged with its ends held by the
// extensible second variation). Under force control a point is unstable where the pushing force
// falls (the shuttle's condensed stiffness) or where it is unstable held, and stable elsewhere.
// Points within 0.05 mm of a bifurcation are not asserted (the margin is near 0 there).
TEST(GeneralExactStability, InclinedBistableBeamMatchesTheBeamPath) {
  const double y0 = 0.070 * std::sin(5.5 * kDeg);
  const GeneralPrbmResult r = solve_general_exact(inclined_beam(0.0, 12e-3, 121));
  ASSERT_TRUE(r.converged()) << r.message;
  ASSERT_EQ(r.points.size(), 121u);
  const GeneralPrbmResult b =
      solve_general_exact(inclined_beam(1.289366e-3, 1.289366e-3 + 1e-9, 2));
  ASSERT_TRUE(b.converged()) << b.message;
  EXPECT_NEAR(-b.points[0].input_load, 3.045947, 2e-6 * 3.045947);
  const GeneralPrbmResult half = solve_general_exact(inclined_beam(0.5e-3, 0.5e-3 + 1e-9, 2));
  ASSERT_TRUE(half.converged()) << half.message;
  EXPECT_NEAR(-half.points[0].input_load, 1.5605303807118, 1e-11 * 1.56);
  // The largest pull: a parabola through a 0.01 mm grid about it.
  const double h = 1e-5;
  const GeneralPrbmResult c =
      solve_general_exact(inclined_beam(8.046628e-3 - 2 * h, 8.046628e-3 + 2 * h, 5));
  ASSERT_TRUE(c.converged()) << c.message;
  const double fm = -c.points[1].input_load, f0 = -c.points[2].input_load,
               fp = -c.points[3].input_load;
  const double travel = 8.046628e-3 + h * (fp - fm) / (2.0 * (fp - 2.0 * f0 + fm));
  const double pull = f0 - (fp - fm) * (fp - fm) / (8.0 * (fp - 2.0 * f0 + fm));
  EXPECT_NEAR(pull, -0.562119, 1e-6);
  // The path locates this flat maximum at 8.0466283, 8.0466289 and 8.0466296 mm (--min-points
  // 61, 121, 201); the parabola here gives 8.0466321 mm.
  EXPECT_NEAR(travel, 8.046628e-3, 5e-9);
  // The stable zero (the last equilibrium) and the sign changes of the force along the range.
  ASSERT_FALSE(r.equilibria.empty());
  EXPECT_NEAR(y0 - r.equilibria.back().input, 9.696183e-3, 1e-9);
  int sign_changes = 0;
  for (std::size_t i = 2; i < r.points.size(); ++i) {
    sign_changes += r.points[i].input_load * r.points[i - 1].input_load < 0.0 ? 1 : 0;
  }
  EXPECT_EQ(sign_changes, 2);
  // Verdicts.
  const double first = 1.289366e-3, second = 7.6618e-3, skip = 5e-5;
  int judged = 0;
  for (std::size_t i = 1; i + 1 < r.points.size(); ++i) {
    const GeneralPrbmPoint& p = r.points[i];
    const double travel = y0 - p.input;
    if (std::abs(travel - first) < skip || std::abs(travel - second) < skip) continue;
    const bool held_unstable = travel > first && travel < second;
    EXPECT_EQ(p.displacement_control.kind,
              held_unstable ? StabilityKind::kUnstable : StabilityKind::kStable)
        << travel * 1e3 << " mm";
    // The pushing force -lambda against the travel y0 - y: it falls where d(lambda)/dy < 0 ...
    const double slope = (r.points[i + 1].input_load - r.points[i - 1].input_load) /
                         (r.points[i + 1].input - r.points[i - 1].input);
    EXPECT_EQ(p.force_control.kind,
              slope < 0.0 || held_unstable ? StabilityKind::kUnstable : StabilityKind::kStable)
        << travel * 1e3 << " mm";
    ++judged;
  }
  EXPECT_GE(judged, 115);
}

// An extensible flexure as a bar: clamped to the ground and to a slide guided along it, the slide
// pulled and pushed along the axis by the input. A straight Reissner beam carries N = EA (x - L)/L
// exactly (strain N/EA); inextensible it could not move at all. Measured: 4e-11 relative.
TEST(GeneralExactStability, ExtensibleFlexureIsABarAlongItsAxis) {
  const double L = 0.07, E = 1.379e9, b = 12.55e-3, h = 1.5e-3;
  GeneralMechanism m;
  m.body("ground", {{"C", {0, 0}}, {"S", {L, 0}}})
      .body("slide", {{"Q", {L, 0}}})
      .slider("guide", "ground.S", "slide.Q", 0.0)
      .flexure("bar", "ground.C", "slide.Q", b, h, E, PrbmKind::kFixedGuided)
      .input_coordinate(
          InputCoordinate::kX, "slide.Q", "", InputControl::kDisplacement, L - 2e-5, L + 2e-5, 5);
  m.flexures[0].extensible = true;
  const GeneralPrbmResult r = solve_general_exact(m);
  ASSERT_TRUE(r.converged()) << r.message;
  for (const GeneralPrbmPoint& p : r.points) {
    const double N = E * b * h * (p.input - L) / L;
    EXPECT_NEAR(p.input_load, N, 1e-9 * E * b * h * 2e-5 / L);
    // Its energy N^2 L/(2 EA), from the sampled shape.
    EXPECT_NEAR(p.energy, N * N * L / (2 * E * b * h), 1e-8 * 5.4e-3);
  }
}

}  // namespace
}  // namespace flexure::mechanism::general
