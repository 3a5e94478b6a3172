// What a general mechanism's solve reports at every point besides its input load (issue 31 item
// 2; mechanisms/general/general_analysis.h): reactions, joint positions, each flexure's end
// loads, largest stress and shape, checked against independent values -- the statics of the whole
// mechanism (the ground's reaction balances the input load), the linear fixed-guided beam's stress
// 6 E I delta/l^2 c/I at small motion, a standalone solve of one flexure (the elliptic elastica,
// beam/physical_beam.h) under the end loads the mechanism reports, and Howell's fixed-pinned
// stress at the clamp (eqs. 5.21-5.23) and PRB spring torque (eqs. 5.67-5.72); every moving body's
// statics in five shipped examples (pins, a slider, flexures alone; both models); curved and
// tapered flexures (issue 31 item 1) against a standalone beam, fixed and seeded random, and
// Howell's initially curved cantilever (§5.5, Table 5.2).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <string>

#include "flexure/beam/physical_beam.h"
#include "flexure/elements/prbm_element.h"
#include "flexure/io/toml_files.h"
#include "flexure/mechanisms/general/general_analysis.h"
#include "flexure/mechanisms/general/general_mechanism.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism::general {
namespace {

constexpr double kPi = std::numbers::pi;

// A stage on two parallel fixed-guided flexures of length l (Howell §5.3), input: the stage's x.
GeneralMechanism parallel_guide(double l, double E, double b, double h, double stop, int count) {
  GeneralMechanism m;
  m.body("ground", {{"c1", {0, 0}}, {"c2", {0.03, 0}}})
      .body("stage", {{"c1", {0, l}}, {"c2", {0.03, l}}})
      .flexure("left", "ground.c1", "stage.c1", b, h, E, PrbmKind::kFixedGuided)
      .flexure("right", "ground.c2", "stage.c2", b, h, E, PrbmKind::kFixedGuided)
      .input_coordinate(
          InputCoordinate::kX, "stage.c1", "", InputControl::kDisplacement, -stop, stop, count);
  return m;
}

// The statics of the moving bodies: the ground's reaction, the input load (a force along x on
// stage.c1 here) and the dead loads (none) sum to zero, force and moment about the origin; and the
// ground's reaction is the opposite of the flexures' loads on it.
void expect_balanced(const GeneralPrbmPoint& p, double x_c1, double y_c1, double scale) {
  EXPECT_NEAR(p.ground_reaction.fx + p.input_load, 0.0, 1e-8 * scale);
  EXPECT_NEAR(p.ground_reaction.fy, 0.0, 1e-8 * scale);
  EXPECT_NEAR(p.ground_reaction.moment + (x_c1 * 0.0 - y_c1 * p.input_load), 0.0, 1e-8 * scale);
  double fx = 0.0, fy = 0.0;
  for (const FlexurePointResult& f : p.flexures) {
    fx += f.on_a.fx;
    fy += f.on_a.fy;
    // Each flexure is in equilibrium: its loads on its two bodies are opposite.
    EXPECT_NEAR(f.on_a.fx + f.on_b.fx, 0.0, 1e-9 * scale);
    EXPECT_NEAR(f.on_a.fy + f.on_b.fy, 0.0, 1e-9 * scale);
  }
  EXPECT_NEAR(p.ground_reaction.fx, -fx, 1e-9 * scale);
  EXPECT_NEAR(p.ground_reaction.fy, -fy, 1e-9 * scale);
}

TEST(GeneralPointResults, ParallelGuideReactionsBalanceAndSmallMotionStressIsTheLinearBeams) {
  const double l = 0.022, E = 2.9e9, b = 0.007, h = 0.0008;
  const double I = b * h * h * h / 12.0, c = h / 2.0;
  const double delta = 1e-5 * l;
  // The linear clamped-guided beam: end moment 6 E I delta/l^2, stress M c/I at the ends.
  const double linear = 6.0 * E * I * delta / (l * l) * c / I;
  const GeneralMechanism m = parallel_guide(l, E, b, h, delta, 3);
  const GeneralPrbmResult exact = solve_general_exact(m);
  const GeneralPrbmResult prbm = solve_general_prbm(m);
  ASSERT_TRUE(exact.converged()) << exact.message;
  ASSERT_TRUE(prbm.converged()) << prbm.message;
  const double F = std::fabs(exact.points[2].input_load);
  for (const GeneralPrbmResult* r : {&exact, &prbm}) {
    for (const GeneralPrbmPoint& p : r->points) {
      ASSERT_EQ(p.flexures.size(), 2u);
      ASSERT_EQ(p.joints.size(), 0u);
      expect_balanced(p, p.input, l + p.body_y[0], F);
    }
  }
  // At +delta both flexures carry the linear beam's end moment, largest at an end; and the stage's
  // moment balance puts axial forces +-N in them: the input force F acts at the flexures' tips'
  // height, so the two tip moments F l/4 each are held by the couple N s (s = 0.03 m the
  // spacing): N = F l/(2 s). The largest stress is M c/I + |N|/A.
  const double spacing = 0.03, A = b * h;
  auto check = [&](const GeneralPrbmPoint& p, double moment_ratio, double tol, const char* from) {
    const double N = std::fabs(p.input_load) * l / (2.0 * spacing);
    for (const FlexurePointResult& f : p.flexures) {
      EXPECT_NEAR(std::fabs(f.moment) * c / I, linear * moment_ratio, tol * linear);
      EXPECT_NEAR(std::fabs(f.axial_force), N, tol * N);
      EXPECT_NEAR(f.max_stress, linear * moment_ratio + N / A, tol * linear);
      EXPECT_TRUE(f.max_stress_at == 0.0 || std::fabs(f.max_stress_at - l) < 1e-12 * l);
      EXPECT_STREQ(f.max_from, from);
    }
  };
  check(exact.points[2], 1.0, 1e-4, "shape");
  for (const FlexurePointResult& f : exact.points[2].flexures) {
    EXPECT_EQ(f.shape_x.size(), 33u);
    // The shape runs from the clamp to the stage.
    EXPECT_NEAR(f.shape_y.front(), 0.0, 1e-15);
    EXPECT_NEAR(f.shape_x.back() - f.shape_x.front(), delta, 1e-9 * delta);
  }
  // The PRBM's end moment is F l/4 per flexure as the beam's, with its stiffness 4 K_Theta/gamma
  // EI/l^3 per flexure against 12 (Table 5.1, n = 0): its moment is that much higher (4.7 %).
  const FixedPinnedConstants c0 = FixedPinnedConstants::from_table(0.0);
  // (The axial forces +-N shift the two flexures' moments apart by N times the pivots' sideways
  // offset, of order delta/l = 1e-5 relative.)
  check(prbm.points[2], (4.0 * c0.K_theta / c0.gamma) / 12.0, 1e-5, "ends");
  for (const FlexurePointResult& f : prbm.points[2].flexures) {
    EXPECT_NEAR(std::fabs(f.moment) * c / I, linear, 0.05 * linear);
    EXPECT_EQ(f.shape_x.size(), 4u);  // end a, the two pivots, end b
  }
}

TEST(GeneralPointResults, ExactFlexureStressIsAStandaloneBeamsUnderTheReportedEndLoads) {
  const double l = 0.022, E = 2.9e9, b = 0.007, h = 0.0008;
  const GeneralPrbmResult r = solve_general_exact(parallel_guide(l, E, b, h, 0.004, 5));
  ASSERT_TRUE(r.converged()) << r.message;
  int compared = 0;
  for (const GeneralPrbmPoint& p : r.points) {
    for (const FlexurePointResult& f : p.flexures) {
      // The loads body b (the stage) puts on the flexure's tip, in the frame of its clamp (the
      // flexure points along +y: its x is the global y).
      const double gx = -f.on_b.fx, gy = -f.on_b.fy;
      PhysicalCantilever beam;
      beam.length = l;
      beam.material.E = E;
      beam.section = Section::rectangle(b, h);
      beam.Fx = gy;   // along the flexure
      beam.Fy = -gx;  // across it, to its left
      beam.M = -f.on_b.moment;
      if (std::fabs(p.input) < 1e-9) continue;  // the middle point: unloaded
      BeamProblem settings;
      settings.shape_points = 257;
      settings.tolerance = 1e-12;
      const PhysicalBeamSolution s = solve_physical_beam(BeamMethod::kShooting, beam, settings);
      ASSERT_TRUE(s.solution.converged()) << s.solution.message;
      double largest = 0.0;
      for (const PhysicalShapePoint& q : s.physical.shape) {
        largest =
            std::max({largest, std::fabs(*q.stress_pos_fibre), std::fabs(*q.stress_neg_fibre)});
      }
      EXPECT_NEAR(f.max_stress, largest, 1e-8 * largest);
      // The clamp's moment is the flexure's moment on the ground.
      EXPECT_NEAR(f.on_a.moment, s.physical.root_moment, 1e-8 * std::fabs(s.physical.root_moment));
      // Its tip is where the stage put it.
      EXPECT_NEAR(s.physical.tip_y, -(p.input - 0.0), 1e-8 * l);
      ++compared;
    }
  }
  EXPECT_EQ(compared, 8);
}

// A flexure clamped into the ground along +x, its far end pinned to a block that the input moves
// along y (a carriage on the ground's x guide carries the block's y guide, so the tip is free in
// x) under a dead load Q pushing the block towards the clamp: Howell's fixed-pinned segment under
// a transverse force P and an axial compression nP = Q.
GeneralMechanism pushed_cantilever(double l, double E, double b, double h, double Q, double stop) {
  GeneralMechanism m;
  m.body("ground", {{"O", {0, 0}}, {"T", {l, 0}}})
      .body("carriage", {{"T", {l, 0}}})
      .body("block", {{"T", {l, 0}}})
      .flexure("beam", "ground.O", "block.T", b, h, E, PrbmKind::kFixedPinned)
      .slider("x-guide", "ground.T", "carriage.T", 0.0)
      .slider("y-guide", "carriage.T", "block.T", kPi / 2)
      .load("Q", "block.T", -Q, 0.0)
      .input_coordinate(
          InputCoordinate::kY, "block.T", "", InputControl::kDisplacement, 0.0, stop, 6);
  return m;
}

TEST(GeneralPointResults, PrbmFixedPinnedStressIsHowellsAtTheClamp) {
  const double l = 0.05, E = 2e9, b = 0.01, h = 0.001;
  const double I = b * h * h * h / 12.0, c = h / 2.0, A = b * h, EI = E * I;
  const double Q = 0.5 * EI / (l * l);
  const GeneralPrbmResult r = solve_general_prbm(pushed_cantilever(l, E, b, h, Q, 0.02));
  ASSERT_TRUE(r.converged()) << r.message;
  ASSERT_EQ(r.points.size(), 6u);
  const FixedPinnedSegment& element = howell_average_fixed_pinned();
  const double gamma = element.geometry().link_length;
  const double K = element.stiffness_coefficient() * EI / l;  // gamma K_Theta EI/l (eq. 5.72)
  for (const GeneralPrbmPoint& p : r.points) {
    const FlexurePointResult& f = p.flexures.at(0);
    // The tip: the block's point (it slides along y at x = l and does not turn).
    const double a = l + p.body_x[1], bb = p.body_y[1];
    // Howell's P (along +y) and nP (the compressive axial force) on the tip, from the load the
    // flexure puts on the block.
    const double P = -f.on_b.fy, nP = f.on_b.fx;
    const double M = P * a + nP * bb;                                     // eq. 5.21
    const double top = -M * c / I - nP / A, bottom = M * c / I - nP / A;  // eqs. 5.22, 5.23
    const double howell = std::max(std::fabs(top), std::fabs(bottom));
    EXPECT_NEAR(f.max_stress, howell, 1e-9 * std::max(howell, 1.0));
    EXPECT_EQ(f.max_stress_at, 0.0);
    EXPECT_NEAR(f.stress_pos_fibre, top, 1e-9 * std::max(howell, 1.0));
    EXPECT_NEAR(f.stress_neg_fibre, bottom, 1e-9 * std::max(howell, 1.0));
    // The PRB link's angle from the tip (eq. 5.70: b = gamma l sin Theta) and the spring torque
    // K Theta = F_t gamma l (eqs. 5.67-5.72) with F_t the tip force across the link.
    const double Theta = std::asin(bb / (gamma * l));
    const double Ft = P * std::cos(Theta) + nP * std::sin(Theta);
    EXPECT_NEAR(K * Theta, Ft * gamma * l, 1e-8 * std::max(K * std::fabs(Theta), 1e-12));
    // The carriage is free along x, so the y guide carries no force along x: the flexure holds Q
    // (nP = Q), and the input load is P; the ground's reaction balances the input and Q.
    const double scale = std::max(std::fabs(P), Q);
    ASSERT_EQ(p.joints.size(), 2u);
    EXPECT_NEAR(p.joints[1].on_b.fx, 0.0, 1e-9 * scale);
    EXPECT_NEAR(nP, Q, 1e-9 * scale);
    EXPECT_NEAR(p.input_load, P, 1e-9 * scale);
    EXPECT_NEAR(p.joints[1].x, a, 1e-12);
    EXPECT_NEAR(p.joints[1].y, bb, 1e-12);
    EXPECT_NEAR(p.ground_reaction.fy + p.input_load, 0.0, 1e-9 * scale);
    EXPECT_NEAR(p.ground_reaction.fx - Q, 0.0, 1e-9 * scale);
    // Moment about the origin: the input force P at (a, bb) and Q at (a, bb).
    EXPECT_NEAR(p.ground_reaction.moment + a * p.input_load + bb * Q, 0.0, 1e-9 * scale * l);
  }
  EXPECT_GT(r.points.back().flexures[0].max_stress, 1e6);
}

}  // namespace
}  // namespace flexure::mechanism::general

namespace flexure::mechanism::general {
namespace {

// A curved (and optionally tapered) flexure clamped into the ground with its rest tangent along
// +x, its far end clamped into a free body whose x the input moves, under a dead force fy and
// moment M on that body: a cantilever whose tip loads are the input load, fy and M.
GeneralMechanism curved_cantilever(
    double l, double kappa, double thickness_tip, double fy, double M, double stop) {
  const Vec2 tip{std::sin(kappa * l) / kappa, (1.0 - std::cos(kappa * l)) / kappa};
  GeneralMechanism m;
  m.body("ground", {{"O", {0, 0}}})
      .body("tip", {{"T", tip}})
      .flexure("arc", "ground.O", "tip.T", 0.01, 0.001, 2e9, PrbmKind::kSmallLengthPivot)
      .load("P", "tip.T", 0.0, fy, M)
      .input_coordinate(
          InputCoordinate::kX, "tip.T", "", InputControl::kDisplacement, tip.x, tip.x - stop, 4);
  m.flexures.back().curvature = kappa;
  m.flexures.back().length = l;
  m.flexures.back().thickness_tip = thickness_tip;
  return m;
}

TEST(GeneralCurvedFlexures, ExactCurvedAndTaperedCantileverIsTheStandaloneBeam) {
  const double l = 0.05, E = 2e9, b = 0.01, h = 0.001;
  const double EI = E * b * h * h * h / 12.0;
  int interior = 0;
  for (const double kappa : {0.5 / l, -1.5 / l}) {
    for (const double thickness_tip : {0.0, 0.6e-3}) {
      const GeneralPrbmResult r = solve_general_exact(
          curved_cantilever(l, kappa, thickness_tip, 0.8 * EI / (l * l), 0.3 * EI / l, 0.2 * l));
      ASSERT_TRUE(r.converged()) << r.message;
      ASSERT_EQ(r.points.size(), 4u);
      for (const GeneralPrbmPoint& p : r.points) {
        const FlexurePointResult& f = p.flexures.at(0);
        PhysicalCantilever beam;
        beam.length = l;
        beam.material.E = E;
        beam.section = Section::rectangle(b, h);
        beam.curvature = kappa;
        if (thickness_tip > 0.0) beam.thickness_tip = thickness_tip;
        // The tip loads: what the body puts on the flexure, in the clamp's frame (global here).
        beam.Fx = -f.on_b.fx;
        beam.Fy = -f.on_b.fy;
        beam.M = -f.on_b.moment;
        EXPECT_NEAR(beam.Fx, p.input_load, 1e-9 * EI / (l * l));
        EXPECT_NEAR(beam.Fy, 0.8 * EI / (l * l), 1e-9 * EI / (l * l));
        BeamProblem settings;
        settings.shape_points = 4097;
        settings.tolerance = 1e-12;
        const PhysicalBeamSolution s = solve_physical_beam(BeamMethod::kShooting, beam, settings);
        ASSERT_TRUE(s.solution.converged()) << s.solution.message;
        // The body's point and angle (its reference is its only point, T).
        const Vec2 tip0{std::sin(kappa * l) / kappa, (1.0 - std::cos(kappa * l)) / kappa};
        EXPECT_NEAR(s.physical.tip_x, tip0.x + p.body_x[0], 1e-8 * l);
        EXPECT_NEAR(s.physical.tip_y, tip0.y + p.body_y[0], 1e-8 * l);
        EXPECT_NEAR(s.physical.theta0, kappa * l + p.body_phi[0], 1e-8);
        EXPECT_NEAR(f.on_a.moment, s.physical.root_moment, 1e-8 * EI / l);
        double largest = 0.0;
        for (const PhysicalShapePoint& q : s.physical.shape) {
          largest =
              std::max({largest, std::fabs(*q.stress_pos_fibre), std::fabs(*q.stress_neg_fibre)});
        }
        // Where the largest is at an end both take it there. Inside, the mechanism refines the
        // parabola through its largest of 257 samples and its neighbours (error of order
        // (1/256)^3), against the largest of the standalone's 4097 samples (below the true
        // maximum by about (1/4096)^2/8 of |sigma''| l^2): 1e-7.
        const bool at_end = f.max_stress_at == 0.0 || std::fabs(f.max_stress_at - l) < 1e-12;
        EXPECT_NEAR(f.max_stress, largest, (at_end ? 1e-8 : 1e-7) * largest)
            << "kappa " << kappa << " taper " << thickness_tip << " at " << f.max_stress_at;
        interior += at_end ? 0 : 1;
        // The shape ends at the body's point.
        EXPECT_NEAR(f.shape_x.back(), tip0.x + p.body_x[0], 1e-8 * l);
        EXPECT_NEAR(f.shape_y.back(), tip0.y + p.body_y[0], 1e-8 * l);
      }
    }
  }
  EXPECT_GT(interior, 0);  // some maxima lie inside the flexure (the parabola is exercised)
}

TEST(GeneralCurvedFlexures, PrbmCurvedFixedPinnedFlexureIsHowellsTable5_2Element) {
  const double l = 0.05, E = 2e9, b = 0.01, h = 0.001;
  const double I = b * h * h * h / 12.0, EI = E * I, c = h / 2.0;
  const double kappa0 = 0.5, kappa = kappa0 / l;
  const double a_i = std::sin(kappa0) / kappa0, b_i = (1.0 - std::cos(kappa0)) / kappa0;  // 5.117-8
  GeneralMechanism m;
  m.body("ground", {{"O", {0, 0}}, {"T", {a_i * l, b_i * l}}})
      .body("carriage", {{"T", {a_i * l, b_i * l}}})
      .body("block", {{"T", {a_i * l, b_i * l}}})
      .flexure("arc", "ground.O", "block.T", b, h, E, PrbmKind::kFixedPinned)
      .slider("x-guide", "ground.T", "carriage.T", 0.0)
      .slider("y-guide", "carriage.T", "block.T", kPi / 2)
      .input_coordinate(InputCoordinate::kY,
                        "block.T",
                        "",
                        InputControl::kDisplacement,
                        b_i * l,
                        b_i * l + 0.3 * l,
                        5);
  m.flexures.back().curvature = kappa;
  const GeneralPrbmResult r = solve_general_prbm(m);
  ASSERT_TRUE(r.converged()) << r.message;
  // Table 5.2, kappa0 = 0.50: gamma = 0.81, K_Theta = 2.52; rho and Theta_i from eqs. 5.115-5.116
  // (the table's rho 0.807 is these rounded).
  const double gamma = 0.81, K_theta = 2.52;
  const double rho = std::hypot(a_i - (1.0 - gamma), b_i);
  EXPECT_NEAR(rho, 0.807, 5e-4);
  const double Theta_i = std::atan2(b_i, a_i - (1.0 - gamma));
  const double K = rho * K_theta * EI / l;  // eq. 5.127
  for (const GeneralPrbmPoint& p : r.points) {
    const double y = p.input;                       // the tip's b
    const double Theta = std::asin(y / (rho * l));  // eq. 5.120
    // eq. 5.119: a = l (1 - gamma + rho cos Theta), the block's x.
    EXPECT_NEAR(a_i * l + p.body_x[1], l * (1.0 - gamma + rho * std::cos(Theta)), 1e-12);
    // eqs. 5.121-5.126 with phi = 90 deg (n = 0): K (Theta - Theta_i) = rho l F cos Theta.
    const double F = K * (Theta - Theta_i) / (rho * l * std::cos(Theta));
    EXPECT_NEAR(p.input_load, F, 1e-9 * std::max(std::fabs(F), EI / (l * l)));
    // eq. 5.128 with n = 0: sigma = P a c/I at the clamp.
    const double a = a_i * l + p.body_x[1];
    EXPECT_NEAR(p.flexures[0].max_stress, std::fabs(F) * a * c / I, 1e-9 * E * h / l);
    EXPECT_EQ(p.flexures[0].max_stress_at, 0.0);
  }
  EXPECT_GT(r.points.back().input_load, 0.1 * EI / (l * l));
}

TEST(GeneralCurvedFlexures, WhatThePrbmDoesNotCoverIsANamedError) {
  const double l = 0.05;
  auto message = [](const GeneralMechanism& m) {
    try {
      solve_general_prbm(m);
    } catch (const InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // A curved flexure modelled as a small-length pivot; one past Table 5.2; a tapered one.
  GeneralMechanism curved = curved_cantilever(l, 0.5 / l, 0.0, 0.0, 0.0, 0.01 * l);
  EXPECT_NE(message(curved).find("flexure 'arc': initially curved"), std::string::npos)
      << message(curved);
  EXPECT_NE(message(curved).find("fixed-pinned"), std::string::npos);
  GeneralMechanism far = curved_cantilever(l, 2.5 / l, 0.0, 0.0, 0.0, 0.01 * l);
  far.flexures.back().prbm = PrbmKind::kFixedPinned;
  EXPECT_NE(message(far).find("outside Howell's Table 5.2"), std::string::npos) << message(far);
  GeneralMechanism tapered = parallel_guide(l, 2e9, 0.01, 0.001, 1e-4, 3);
  tapered.flexures.back().width_tip = 0.005;
  EXPECT_NE(message(tapered).find("flexure 'right': tapered"), std::string::npos)
      << message(tapered);
  // The mixed model's other models are straight: a curved flexure must be exact there.
  curved.flexures.back().model = FlexureModel::kBcm;
  try {
    solve_general_mixed(curved);
    ADD_FAILURE() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("give it model = \"exact\""), std::string::npos)
        << e.what();
  }
  // No arc of that curvature spans the ends.
  GeneralMechanism impossible = curved_cantilever(l, 0.5 / l, 0.0, 0.0, 0.0, 0.01 * l);
  impossible.flexures.back().length = 0.0;
  impossible.flexures.back().curvature = 100.0 / l;
  EXPECT_THROW(impossible.validate(), InvalidInput);
  // A length whose arc does not span the ends.
  GeneralMechanism misfit = curved_cantilever(l, 0.5 / l, 0.0, 0.0, 0.0, 0.01 * l);
  misfit.flexures.back().length = 1.02 * l;
  try {
    misfit.validate();
    ADD_FAILURE() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("flexure 'arc': length 0.051 m and curvature 10 1/m make "
                                         "an arc whose chord is"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace flexure::mechanism::general

namespace flexure::mechanism::general {
namespace {

// Where point `ref` is at point p of a result: the body's reference (the centroid of its points,
// prbm_assembly.h) moved by its pose.
Vec2 posed(const GeneralMechanism& m,
           const GeneralPrbmResult& r,
           const GeneralPrbmPoint& p,
           const PointRef& ref) {
  const Vec2 q = m.point(ref);
  if (ref.body == "ground") return q;
  const Body* body = m.find_body(ref.body);
  Vec2 c{0, 0};
  for (const NamedPoint& n : body->points) {
    c.x += n.position.x / static_cast<double>(body->points.size());
    c.y += n.position.y / static_cast<double>(body->points.size());
  }
  const auto k = static_cast<std::size_t>(
      std::find(r.body_names.begin(), r.body_names.end(), ref.body) - r.body_names.begin());
  const double phi = p.body_phi.at(k), cs = std::cos(phi), sn = std::sin(phi);
  return {c.x + p.body_x[k] + cs * (q.x - c.x) - sn * (q.y - c.y),
          c.y + p.body_y[k] + sn * (q.x - c.x) + cs * (q.y - c.y)};
}

// Every moving body's statics at every point: the loads of its joints (on_b on body b, the
// opposite on body a, at the joint's point), of its flexures (on_a, on_b at their ends) and the
// input load sum to zero, force and moment about the origin; and the ground's reaction balances the
// input load. Returns the largest imbalance relative to `scale` (N; moments per `length`).
double largest_imbalance(const GeneralMechanism& m, const GeneralPrbmResult& r, double length) {
  double worst = 0.0, scale = 0.0;
  for (const GeneralPrbmPoint& p : r.points) scale = std::max(scale, std::fabs(p.input_load));
  if (m.input.coordinate == InputCoordinate::kAngle) scale /= length;
  for (const GeneralPrbmPoint& p : r.points) {
    std::map<std::string, std::array<double, 3>> net;  // fx, fy, moment about the origin
    auto add = [&](const std::string& body, const PointLoad& l, Vec2 at, double sign) {
      std::array<double, 3>& n = net[body];
      n[0] += sign * l.fx;
      n[1] += sign * l.fy;
      n[2] += sign * (l.moment + at.x * l.fy - at.y * l.fx);
    };
    for (std::size_t j = 0; j < m.joints.size(); ++j) {
      const Vec2 at{p.joints.at(j).x, p.joints[j].y};
      add(m.joints[j].b.body, p.joints[j].on_b, at, 1.0);
      add(m.joints[j].a.body, p.joints[j].on_b, at, -1.0);
    }
    for (std::size_t i = 0; i < m.flexures.size(); ++i) {
      const Flexure& f = m.flexures[i];
      add(f.a.body, p.flexures.at(i).on_a, posed(m, r, p, f.a), 1.0);
      add(f.b.body, p.flexures[i].on_b, posed(m, r, p, f.b), 1.0);
    }
    const Input& in = m.input;
    if (in.coordinate == InputCoordinate::kAngle) {
      net[in.body][2] += p.input_load;
    } else {
      const Vec2 at = posed(m, r, p, {in.body, in.point});
      const PointLoad l = in.coordinate == InputCoordinate::kX ? PointLoad{p.input_load, 0, 0}
                                                               : PointLoad{0, p.input_load, 0};
      add(in.body, l, at, 1.0);
    }
    for (const auto& [body, n] : net) {
      if (body == "ground") {
        // The ground takes what the mechanism puts on it: the opposite of its reaction.
        worst = std::max({worst,
                          std::fabs(n[0] + p.ground_reaction.fx) / scale,
                          std::fabs(n[1] + p.ground_reaction.fy) / scale,
                          std::fabs(n[2] + p.ground_reaction.moment) / (scale * length)});
        continue;
      }
      worst = std::max({worst,
                        std::fabs(n[0]) / scale,
                        std::fabs(n[1]) / scale,
                        std::fabs(n[2]) / (scale * length)});
    }
  }
  return worst;
}

TEST(GeneralPointResults, EveryBodyOfTheShippedExamplesIsInEquilibrium) {
  // Pins (the switch, the brakes, the partially compliant four-bar), a slider (the gripper) and
  // flexures alone (the cross-axis pivot), by both models over four points of each range.
  for (const char* name : {"howell_bistable_switch",
                           "howell_bicycle_brakes",
                           "howell_compliant_gripper",
                           "howell_partially_compliant_fourbar",
                           "cross_axis_pivot"}) {
    GeneralMechanism m = load_general_mechanism_toml(std::string(FLEXURE_SOURCE_DIR) +
                                                     "/docs/examples/" + name + ".toml");
    ASSERT_TRUE(m.loads.empty() && m.linear_springs.empty() && m.torsion_springs.empty()) << name;
    m.input.count = 4;
    const double size = m.size();
    const GeneralPrbmResult prbm = solve_general_prbm(m);
    ASSERT_FALSE(prbm.points.empty()) << name << ": " << prbm.message;
    EXPECT_LT(largest_imbalance(m, prbm, size), 1e-8) << name << " (PRBM)";
    const GeneralPrbmResult exact = solve_general_exact(m);
    ASSERT_FALSE(exact.points.empty()) << name << ": " << exact.message;
    EXPECT_LT(largest_imbalance(m, exact, size), 1e-8) << name << " (exact)";
  }
}

// Seeded random curved and tapered cantilevers: the exact model's flexure against a standalone
// shooting solve of the same beam under the end loads the mechanism reports.
TEST(GeneralCurvedFlexures, SeededRandomCurvedTaperedCantileversAreTheStandaloneBeam) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double l = 0.04, E = 2e9, b = 0.01, h = 0.001;
  const double EI = E * b * h * h * h / 12.0;
  for (int trial = 0; trial < 6; ++trial) {
    const double kappa0 = -2.0 + 4.0 * u(rng);  // kappa l in [-2, 2]
    const double taper = 0.5 + 0.5 * u(rng);    // tip thickness / root's
    // The tip's y driven up to 15 % of the length from its rest value under a dead axial force
    // fx (below the tapered beam's buckling load, about 1.2 EI/l^2 at a tip half as thick: the
    // standalone's proportional loading from the unloaded beam then reaches the same state) and
    // moment M.
    const double fx = (-0.5 + u(rng)) * EI / (l * l);
    const double M = (-0.25 + 0.5 * u(rng)) * EI / l;
    const double stop = (-0.15 + 0.3 * u(rng)) * l;
    GeneralMechanism m = curved_cantilever(l, kappa0 / l, taper * h, 0.0, M, 0.0);
    m.loads.back().fx = fx;
    m.input.coordinate = InputCoordinate::kY;
    m.input.start = m.point({"tip", "T"}).y;
    m.input.stop = m.input.start + stop;
    const GeneralPrbmResult r = solve_general_exact(m);
    ASSERT_TRUE(r.converged()) << "trial " << trial << ": " << r.message;
    const GeneralPrbmPoint& p = r.points.back();
    const FlexurePointResult& f = p.flexures.at(0);
    PhysicalCantilever beam;
    beam.length = l;
    beam.material.E = E;
    beam.section = Section::rectangle(b, h);
    beam.curvature = kappa0 / l;
    beam.thickness_tip = taper * h;
    beam.Fx = -f.on_b.fx;
    beam.Fy = -f.on_b.fy;
    beam.M = -f.on_b.moment;
    BeamProblem settings;
    settings.tolerance = 1e-12;
    const PhysicalBeamSolution s = solve_physical_beam(BeamMethod::kShooting, beam, settings);
    ASSERT_TRUE(s.solution.converged()) << s.solution.message;
    EXPECT_NEAR(beam.Fx, fx, 1e-9 * EI / (l * l));
    const double k = kappa0 / l;
    const Vec2 tip0{std::sin(k * l) / k, (1.0 - std::cos(k * l)) / k};
    EXPECT_NEAR(s.physical.tip_x, tip0.x + p.body_x[0], 1e-8 * l) << "trial " << trial;
    EXPECT_NEAR(s.physical.tip_y, tip0.y + p.body_y[0], 1e-8 * l) << "trial " << trial;
    EXPECT_NEAR(s.physical.theta0, kappa0 + p.body_phi[0], 1e-8) << "trial " << trial;
    EXPECT_NEAR(f.on_a.moment, s.physical.root_moment, 1e-8 * EI / l) << "trial " << trial;
  }
}

}  // namespace
}  // namespace flexure::mechanism::general

namespace flexure::mechanism::general {
namespace {

// The fixed-guided element of a general mechanism with its far body free to turn is Howell's §5.7
// simplified fixed-fixed model (docs/mechanisms.md "PRBM elements in a mechanism"): under a small
// tip force its compliance is (1 + gamma^2)/(4 gamma K_Theta) l^3/EI, from its two springs
// 2 gamma K_Theta EI/l by virtual work, against the beam's 1/3 (the exact model's).
TEST(GeneralPointResults, FixedGuidedFlexureWithAFreeFarEndIsTheSimplifiedFixedFixedModel) {
  const double l = 0.05, E = 2e9, b = 0.01, h = 0.001;
  const double EI = E * b * h * h * h / 12.0, delta = 1e-5 * l;
  GeneralMechanism m;
  m.body("ground", {{"O", {0, 0}}})
      .body("tip", {{"T", {l, 0}}})
      .flexure("f", "ground.O", "tip.T", b, h, E, PrbmKind::kFixedGuided)
      .input_coordinate(
          InputCoordinate::kY, "tip.T", "", InputControl::kDisplacement, 0.0, delta, 2);
  const GeneralPrbmResult prbm = solve_general_prbm(m);
  const GeneralPrbmResult exact = solve_general_exact(m);
  ASSERT_TRUE(prbm.converged()) << prbm.message;
  ASSERT_TRUE(exact.converged()) << exact.message;
  const FixedPinnedConstants c = FixedPinnedConstants::from_table(0.0);
  const double g = c.gamma;
  const double compliance_prbm = (1.0 + g * g) / (4.0 * g * c.K_theta);
  EXPECT_NEAR(delta / prbm.points[1].input_load * EI / (l * l * l), compliance_prbm, 1e-5);
  EXPECT_NEAR(compliance_prbm, 0.189, 5e-4);  // Table 5.1, n = 0
  EXPECT_NEAR(delta / exact.points[1].input_load * EI / (l * l * l), 1.0 / 3.0, 1e-5);
}

}  // namespace
}  // namespace flexure::mechanism::general
