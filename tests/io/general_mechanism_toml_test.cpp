// The TOML form of a general mechanism (io/toml_files.h): the shipped example reads
// and solves to Howell's Table 11.2, and bad descriptions are errors naming file, line and item.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "flexure/io/toml_files.h"
#include "flexure/mechanisms/general/general_analysis.h"
#include "flexure/mechanisms/materials_fatigue.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism::general {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
const std::string kExample =
    std::string(FLEXURE_SOURCE_DIR) + "/docs/examples/howell_bistable_switch.toml";

TEST(GeneralMechanismToml, HowellBistableSwitchExampleReproducesTable11_2) {
  const GeneralMechanism m = load_general_mechanism_toml(kExample);
  EXPECT_EQ(m.name, "howell-bistable-switch");
  ASSERT_EQ(m.bodies.size(), 4u);
  ASSERT_EQ(m.flexures.size(), 1u);
  EXPECT_NEAR(m.flexures[0].thickness, 2.3e-3, 1e-15);
  EXPECT_NEAR(m.flexures[0].material.E, 1.4e9, 1e-3);
  EXPECT_NEAR(m.input.stop, 33.0 * kDeg, 1e-15);
  const GeneralPrbmResult r = solve_general_prbm(m);
  ASSERT_TRUE(r.converged()) << r.message;
  ASSERT_EQ(r.equilibria.size(), 3u);
  // Table 11.2 (0, 18.7, 32 deg) and, to 1e-3 deg, the position analysis of Table 11.1 with
  // theta4 = 142 deg (stable) and links 2, 3 collinear (unstable): -0.29982, 18.67833, 32.30150.
  EXPECT_NEAR(r.equilibria[0].input / kDeg, 0.0, 0.5);
  EXPECT_NEAR(r.equilibria[1].input / kDeg, 18.7, 0.05);
  EXPECT_NEAR(r.equilibria[2].input / kDeg, 32.0, 0.5);
  EXPECT_NEAR(r.equilibria[0].input / kDeg, -0.29982, 1e-3);
  EXPECT_NEAR(r.equilibria[1].input / kDeg, 18.67833, 1e-3);
  EXPECT_NEAR(r.equilibria[2].input / kDeg, 32.30150, 1e-3);
  EXPECT_TRUE(r.equilibria[0].stability.stable());
  EXPECT_FALSE(r.equilibria[1].stability.stable());
  EXPECT_TRUE(r.equilibria[2].stability.stable());
}

// A minimal valid description: a crank on a small-length pivot, driven by its angle.
std::string pendulum(const std::string& flexure_extra = "",
                     const std::string& crank_points = "{ F = [0.002, 0.0], T = [0.05, 0.0] }",
                     const std::string& more = "") {
  return "name = \"crank\"\n"                // 1
         "[[body]]\n"                        // 2
         "name = \"ground\"\n"               // 3
         "points = { F = [-0.002, 0.0] }\n"  // 4
         "[[body]]\n"                        // 5
         "name = \"crank\"\n"                // 6
         "points = " +
         crank_points +
         "\n"                  // 7
         "[[flexure]]\n"       // 8
         "name = \"f1\"\n"     // 9
         "a = \"ground.F\"\n"  // 10
         "b = \"crank.F\"\n"   // 11
         "width = \"5 mm\"\n" +
         flexure_extra +  // 12
         "[input]\n"
         "coordinate = \"angle\"\n"
         "point = \"crank.F\"\n"
         "to = \"crank.T\"\n"
         "start = \"0 deg\"\n"
         "stop = \"10 deg\"\n"
         "count = 3\n" +
         more;
}

std::string error_of(const std::string& text) {
  try {
    const GeneralMechanism m = parse_general_mechanism_toml(text, "m.toml");
    solve_general_prbm(m);
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "no error";
}

TEST(GeneralMechanismToml, ValidDescriptionSolvesToItsClosedForm) {
  const std::string text = pendulum("thickness = \"0.5 mm\"\nE = \"2 GPa\"\n");
  ASSERT_TRUE(is_general_mechanism_toml(text, "m.toml"));
  const GeneralPrbmResult r = solve_general_prbm(parse_general_mechanism_toml(text, "m.toml"));
  ASSERT_TRUE(r.converged()) << r.message;
  // One small-length pivot: the moment is K theta with K = EI/l (Howell eq. 5.14).
  const double K = 2e9 * 5e-3 * std::pow(0.5e-3, 3) / 12 / 4e-3;
  ASSERT_EQ(r.points.size(), 3u);
  EXPECT_NEAR(r.points[2].input_load, K * 10 * kDeg, 1e-10 * K);
  EXPECT_NEAR(r.points[2].energy, 0.5 * K * std::pow(10 * kDeg, 2), 1e-10 * K);
}

// `material = "NAME"` gives the flexure the library row's whole Material (data/materials.csv,
// Howell Tables C.5 and C.1: 1095 HR steel, E 206.8 GPa, S_y 460 MPa, 7800 kg/m^3) and its id; a
// flexure's own E is a Material with E alone.
TEST(GeneralMechanismToml, MaterialKeyGivesTheWholeMaterial) {
  const MaterialGrade& row = find_material("steel-1095-hr");
  const GeneralMechanism m = parse_general_mechanism_toml(
      pendulum("thickness = \"0.5 mm\"\nmaterial = \"steel-1095-hr\"\n"), "m.toml");
  const Flexure& f = m.flexures.at(0);
  EXPECT_EQ(f.material_id, "steel-1095-hr");
  EXPECT_EQ(f.material.E, row.E);
  ASSERT_TRUE(f.material.yield_strength && row.yield_strength);
  EXPECT_EQ(*f.material.yield_strength, *row.yield_strength);
  EXPECT_EQ(f.material.density, row.density);
  const double EI = row.E * 5e-3 * std::pow(0.5e-3, 3) / 12.0;
  EXPECT_NEAR(f.flexural_rigidity(), EI, 1e-14 * EI);
  const GeneralMechanism given =
      parse_general_mechanism_toml(pendulum("thickness = \"0.5 mm\"\nE = \"2 GPa\"\n"), "m.toml");
  EXPECT_EQ(given.flexures.at(0).material.E, 2e9);
  EXPECT_TRUE(given.flexures.at(0).material_id.empty());
  EXPECT_FALSE(given.flexures.at(0).material.yield_strength.has_value());
}

TEST(GeneralMechanismToml, CurvedAndTaperedFlexureKeys) {
  // The rest shape's keys with units, as `flexure beam --curvature --width-tip --thickness-tip`.
  const GeneralMechanism m = parse_general_mechanism_toml(
      pendulum("thickness = \"0.5 mm\"\nE = \"2 GPa\"\ncurvature = \"0.02 1/mm\"\n"
               "width_tip = \"4 mm\"\nthickness_tip = \"0.4 mm\"\n"),
      "m.toml");
  ASSERT_EQ(m.flexures.size(), 1u);
  EXPECT_NEAR(m.flexures[0].curvature, 20.0, 1e-12);
  EXPECT_NEAR(m.flexures[0].width_tip, 4e-3, 1e-15);
  EXPECT_NEAR(m.flexures[0].thickness_tip, 0.4e-3, 1e-15);
  // The minor arc of curvature 20 1/m over the pendulum's 4 mm chord: 2 asin(0.04)/20.
  EXPECT_NEAR(m.flexures[0].arc_length(4e-3), 2.0 * std::asin(0.04) / 20.0, 1e-15);
  EXPECT_NE(error_of(pendulum("thickness = \"0.5 mm\"\nE = \"2 GPa\"\nwidth_tip = \"-1 mm\"\n"))
                .find("m.toml:15: flexure 'f1': width_tip must be > 0"),
            std::string::npos)
      << error_of(pendulum("thickness = \"0.5 mm\"\nE = \"2 GPa\"\nwidth_tip = \"-1 mm\"\n"));
}

// An isosceles slider-crank (r2 = r3 = r) described straight, a torsion spring k between ground
// and crank: Delta x = 2 r (1 - cos theta2), V = k theta2^2/2, so the force pushing the slider in
// is dV/dDelta x = k theta2/(2 r sin theta2). The straight position is a dead point of the input.
std::string slider_crank(const std::string& start_rotation) {
  return "[[body]]\nname = \"ground\"\npoints = { O = [0, 0], S = [0.2, 0] }\n"
         "[[body]]\nname = \"crank\"\npoints = { O = [0, 0], A = [0.1, 0] }\n"
         "[[body]]\nname = \"coupler\"\npoints = { A = [0.1, 0], S = [0.2, 0] }\n"
         "[[body]]\nname = \"slider\"\npoints = { S = [0.2, 0] }\n"
         "[[joint]]\nname = \"O\"\ntype = \"pin\"\na = \"ground.O\"\nb = \"crank.O\"\n"
         "[[joint]]\nname = \"A\"\ntype = \"pin\"\na = \"crank.A\"\nb = \"coupler.A\"\n"
         "[[joint]]\nname = \"S\"\ntype = \"pin\"\na = \"coupler.S\"\nb = \"slider.S\"\n"
         "[[joint]]\nname = \"guide\"\ntype = \"slider\"\na = \"ground.S\"\nb = \"slider.S\"\n"
         "axis = 0\n"
         "[[spring]]\nname = \"k\"\ntype = \"torsion\"\na = \"ground\"\nb = \"crank\"\n"
         "stiffness = 3.0\n"
         "[input]\ncoordinate = \"x\"\npoint = \"slider.S\"\nstart = \"199 mm\"\n"
         "stop = \"150 mm\"\ncount = 50\n" +
         start_rotation;
}

TEST(GeneralMechanismToml, DeadPointStartNeedsAStartRotation) {
  EXPECT_NE(error_of(slider_crank(""))
                .find("m.toml:40: input: the input coordinate cannot move "
                      "to first order"),
            std::string::npos)
      << error_of(slider_crank(""));
  const GeneralMechanism m = parse_general_mechanism_toml(
      slider_crank("start_rotation = { crank = \"5 deg\" }\n"), "m.toml");
  const GeneralPrbmResult r = solve_general_prbm(m);
  ASSERT_TRUE(r.converged()) << r.message;
  ASSERT_EQ(r.points.size(), 50u);
  for (const GeneralPrbmPoint& p : r.points) {
    const double dx = 0.2 - p.input;
    const double theta2 = std::acos(1 - dx / 0.2);
    EXPECT_NEAR(p.body_phi[0], theta2, 1e-9);  // the crank turned up (start_rotation > 0)
    EXPECT_NEAR(-p.input_load, 3.0 * theta2 / (0.2 * std::sin(theta2)), 1e-8);
  }
  // The other branch (crank down) from a negative start rotation: the same force.
  const GeneralPrbmResult down = solve_general_prbm(parse_general_mechanism_toml(
      slider_crank("start_rotation = { crank = \"-5 deg\" }\n"), "m.toml"));
  ASSERT_TRUE(down.converged());
  EXPECT_NEAR(down.points[10].body_phi[0], -r.points[10].body_phi[0], 1e-9);
  EXPECT_NEAR(down.points[10].input_load, r.points[10].input_load, 1e-9);
}

TEST(GeneralMechanismToml, BadDescriptionsNameFileLineAndItem) {
  // A missing section: the flexure (line 8) has no thickness.
  EXPECT_NE(error_of(pendulum("E = \"2 GPa\"\n"))
                .find("m.toml:8: flexure 'f1': missing or "
                      "invalid section"),
            std::string::npos)
      << error_of(pendulum("E = \"2 GPa\"\n"));
  // A flexure between two points of the same body.
  const std::string same = pendulum("thickness = \"0.5 mm\"\nE = \"2 GPa\"\n");
  std::string text = same;
  text.replace(text.find("b = \"crank.F\""), 13, "b = \"ground.F\"");
  EXPECT_NE(error_of(text).find("m.toml:8: flexure 'f1': runs between ground.F and ground.F, "
                                "two points of the same body"),
            std::string::npos)
      << error_of(text);
  // An unconstrained body (line 22: after the flexure's two section lines and the input's seven).
  text = same + "[[body]]\nname = \"loose\"\npoints = { P = [0.0, 0.1] }\n";
  EXPECT_NE(error_of(text).find("m.toml:22: body 'loose' is unconstrained"), std::string::npos)
      << error_of(text);
  // A loop that cannot close: a pin whose points are 52 mm apart.
  text = same + "[[joint]]\nname = \"p\"\ntype = \"pin\"\na = \"ground.F\"\nb = \"crank.T\"\n";
  EXPECT_NE(error_of(text).find("m.toml:22: pin 'p': ground.F at"), std::string::npos)
      << error_of(text);
  EXPECT_NE(error_of(text).find("the loop cannot close"), std::string::npos);
  // Unknown keys, units of the wrong kind, unknown element names.
  EXPECT_NE(error_of(pendulum("thickness = \"0.5 mm\"\nE = \"2 GPa\"\ncolour = 1\n"))
                .find("m.toml:15: unknown key 'colour'"),
            std::string::npos)
      << error_of(pendulum("thickness = \"0.5 mm\"\nE = \"2 GPa\"\ncolour = 1\n"));
  EXPECT_NE(
      error_of(pendulum("thickness = \"0.5 N\"\nE = \"2 GPa\"\n")).find("m.toml:13: flexure 'f1':"),
      std::string::npos)
      << error_of(pendulum("thickness = \"0.5 N\"\nE = \"2 GPa\"\n"));
  EXPECT_NE(error_of(pendulum("thickness = \"0.5 mm\"\nE = \"2 GPa\"\nprbm = \"pseudo\"\n"))
                .find("m.toml:15: flexure 'f1': prbm 'pseudo' is not one of"),
            std::string::npos);
  // A point reference without a body.
  text = same;
  text.replace(text.find("a = \"ground.F\""), 14, "a = \"groundF\"");
  EXPECT_NE(error_of(text).find("m.toml:10: flexure 'f1': a: 'groundF' is not a point reference"),
            std::string::npos)
      << error_of(text);
  // The form is told apart from the constant-force form.
  EXPECT_FALSE(is_general_mechanism_toml("config = \"lpp\"\nr2 = 0.1\n", "c.toml"));
}

}  // namespace
}  // namespace flexure::mechanism::general
