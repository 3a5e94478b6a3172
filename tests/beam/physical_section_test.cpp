// The physical cantilever's Section and Material (beam/physical_beam.h, solver/common/section.h),
// checked against:
//  * the rigidity written out by hand: a 50 mm x 10 mm x 0.5 mm steel strip (E = 200 GPa) has
//    EI = 200e9 * 0.01 * 0.0005^3 / 12 = 0.0208333 N m^2 (Howell sec. 2.1, I = b h^3/12);
//  * the same beam given as the rectangle and as a general section of that I: the same tip (one
//    nondimensional problem, alpha2 = Fy L^2/EI), and with the general section's thickness the
//    same stress M c/I; the tip also equals Howell's nondimensional solve scaled by L;
//  * every field of the section and material refused when bad, naming the field (by the flag the
//    tool reads it from, or Section::/Material:: for what no flag gives), and the section given
//    twice or half a rectangle refused where the values are read one by one.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "flexure/beam/physical_beam.h"
#include "flexure/solver/common/section.h"
#include "flexure/solver/common/status.h"
#include "tests/support/physical_beam_support.h"

namespace flexure {
namespace {

using test::strip;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// 0.01 * 0.0005^3 / 12, written out: b h^3/12 of the strip (m^4).
constexpr double kStripI = 0.01 * 1.25e-10 / 12.0;

std::string message_of(const PhysicalCantilever& b) {
  try {
    b.validate();
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

TEST(PhysicalSection, RectangleAndGeneralSectionOfTheSameIGiveTheSameTip) {
  const PhysicalCantilever rectangle = strip(-2.5, 4.33, 0.01);
  // The rigidity by hand (independent of Section::second_moment's arithmetic).
  EXPECT_NEAR(rectangle.flexural_rigidity(), 200e9 * kStripI, 1e-15 * 200e9 * kStripI);
  EXPECT_NEAR(rectangle.flexural_rigidity(), 0.0208333333333333, 1e-15);

  PhysicalCantilever general = rectangle;
  general.section = Section::general(kStripI);
  EXPECT_NEAR(general.flexural_rigidity(), rectangle.flexural_rigidity(), 1e-15 * 0.0208);

  for (BeamMethod method : {BeamMethod::kElliptic, BeamMethod::kShooting}) {
    const PhysicalBeamSolution r = solve_physical_beam(method, rectangle, {});
    const PhysicalBeamSolution g = solve_physical_beam(method, general, {});
    ASSERT_TRUE(r.converged() && g.converged()) << r.solution.message << g.solution.message;
    // One EI to the last bits: the same nondimensional problem, the same tip.
    EXPECT_NEAR(g.physical.tip_x, r.physical.tip_x, 1e-13 * rectangle.length);
    EXPECT_NEAR(g.physical.tip_y, r.physical.tip_y, 1e-13 * rectangle.length);
    EXPECT_NEAR(g.physical.theta0, r.physical.theta0, 1e-13);
    EXPECT_NEAR(g.physical.root_moment, r.physical.root_moment, 1e-13);
    // A general section without its thickness has no stress; the rectangle has one.
    EXPECT_TRUE(r.physical.max_stress.has_value());
    EXPECT_FALSE(g.physical.max_stress.has_value());

    // Howell's problem by hand: alpha2 = Fy L^2/EI, n = -Fx/Fy, mu = M L/EI (eqs. 2.67, 2.83),
    // its tip times L.
    BeamProblem by_hand;
    by_hand.given = BeamProblem::Given::kAlpha2;
    const double EI = 200e9 * kStripI, L = 0.05;
    by_hand.value = 4.33 * L * L / EI;
    by_hand.load_ratio_n = 2.5 / 4.33;
    by_hand.mu = 0.01 * L / EI;
    const BeamSolution expected = solve_beam(method, by_hand);
    ASSERT_TRUE(expected.converged());
    EXPECT_NEAR(g.physical.tip_x, expected.tip.a_over_l * L, 1e-11 * L);
    EXPECT_NEAR(g.physical.tip_y, expected.tip.b_over_l * L, 1e-11 * L);
  }

  // Given its thickness, the general section has the rectangle's stress M c/I, c = h/2.
  PhysicalCantilever with_h = rectangle;
  with_h.section = Section::general(kStripI, 0.0005);
  with_h.material.yield_strength = 1.5e9;
  PhysicalCantilever rectangle_sy = rectangle;
  rectangle_sy.material.yield_strength = 1.5e9;
  const PhysicalBeamSolution g = solve_physical_beam(BeamMethod::kElliptic, with_h, {});
  const PhysicalBeamSolution r = solve_physical_beam(BeamMethod::kElliptic, rectangle_sy, {});
  ASSERT_TRUE(g.converged() && r.converged());
  ASSERT_TRUE(g.physical.max_stress && r.physical.max_stress);
  EXPECT_NEAR(*g.physical.max_stress, *r.physical.max_stress, 1e-12 * *r.physical.max_stress);
  EXPECT_NEAR(*g.physical.max_stress,
              g.physical.max_moment * 0.00025 / kStripI,
              1e-12 * *g.physical.max_stress);
  EXPECT_NEAR(*g.physical.safety_factor, 1.5e9 / *g.physical.max_stress, 1e-12);
}

TEST(PhysicalSection, ABadSectionOrMaterialFieldIsRefusedNamingIt) {
  EXPECT_EQ(message_of(strip(0, 1, 0)), "");
  struct Case {
    const char* what;
    void (*change)(PhysicalCantilever&);
    const char* names;
  };
  const std::vector<Case> cases = {
      {"width 0", [](PhysicalCantilever& b) { b.section.width = 0.0; }, "--width (section width"},
      {"width NaN", [](PhysicalCantilever& b) { b.section.width = kNaN; }, "--width"},
      {"thickness < 0", [](PhysicalCantilever& b) { b.section.thickness = -1e-3; }, "--thickness"},
      {"I on a rectangle", [](PhysicalCantilever& b) { b.section.I = 1e-12; }, "Section::I"},
      {"general I 0",
       [](PhysicalCantilever& b) {
         b.section = {Section::Shape::kGeneral, 0.0, 0.0, 0.0};
       },
       "--I (area moment of inertia"},
      {"general I NaN",
       [](PhysicalCantilever& b) {
         b.section = {Section::Shape::kGeneral, 0.0, 0.0, kNaN};
       },
       "--I"},
      {"general thickness NaN",
       [](PhysicalCantilever& b) {
         b.section = {Section::Shape::kGeneral, 0.0, kNaN, 1e-12};
       },
       "--thickness"},
      {"general with a width",
       [](PhysicalCantilever& b) {
         b.section = {Section::Shape::kGeneral, 0.01, 0.0, 1e-12};
       },
       "Section::width"},
      {"E 0", [](PhysicalCantilever& b) { b.material.E = 0.0; }, "--E (Young's modulus"},
      {"E inf",
       [](PhysicalCantilever& b) { b.material.E = std::numeric_limits<double>::infinity(); },
       "--E"},
      {"yield strength < 0",
       [](PhysicalCantilever& b) { b.material.yield_strength = -1.0; },
       "--yield-strength (Pa)"},
      {"yield strength without a thickness",
       [](PhysicalCantilever& b) {
         b.section = Section::general(kStripI);
         b.material.yield_strength = 1e9;
       },
       "the stress M c/I needs the thickness"},
      {"density 0", [](PhysicalCantilever& b) { b.material.density = 0.0; }, "--density (kg/m^3)"},
      {"density NaN", [](PhysicalCantilever& b) { b.material.density = kNaN; }, "--density"},
      {"density of a general section",
       [](PhysicalCantilever& b) {
         b.section = Section::general(kStripI);
         b.material.density = 7850.0;
       },
       "need the section's area"},
      {"nu set without set_nu",
       [](PhysicalCantilever& b) { b.material.nu = 0.35; },
       "Material::nu"},
      {"nu out of range, plate on",
       [](PhysicalCantilever& b) {
         b.set_nu(0.7);
         b.plate = PlateRule::kOn;
         b.plate_given = true;
       },
       "--nu must be in (-1, 0.5) (got 0.7)"},
      {"nu NaN, plate off given",
       [](PhysicalCantilever& b) {
         b.set_nu(kNaN);
         b.plate_given = true;
       },
       "--nu must be in (-1, 0.5)"},
      {"nu NaN, extensible",
       [](PhysicalCantilever& b) {
         b.set_nu(kNaN);
         b.extensible = true;
       },
       "--nu must be in (-1, 0.5)"},
      {"nu unused", [](PhysicalCantilever& b) { b.set_nu(0.3); }, "--nu is used with"},
      {"extensible without nu",
       [](PhysicalCantilever& b) { b.extensible = true; },
       "--extensible needs Poisson's ratio --nu"},
      {"taper of a general section",
       [](PhysicalCantilever& b) {
         b.section = Section::general(kStripI);
         b.thickness_tip = 0.0004;
       },
       "a taper (--width-tip, --thickness-tip) varies the rectangle"},
  };
  for (const Case& c : cases) {
    PhysicalCantilever b = strip(0, 1, 0);
    c.change(b);
    const std::string message = message_of(b);
    EXPECT_NE(message.find(c.names), std::string::npos) << c.what << ": '" << message << "'";
    // The solver refuses it too (it validates what it is given).
    EXPECT_THROW(solve_physical_beam(BeamMethod::kElliptic, b, {}), InvalidInput) << c.what;
  }
  // set_nu keeps material.nu and nu_given together; an empty one returns Material's default.
  PhysicalCantilever b = strip(0, 1, 0);
  b.set_nu(0.25);
  EXPECT_EQ(b.given_nu(), std::optional<double>(0.25));
  b.set_nu(std::nullopt);
  EXPECT_FALSE(b.given_nu().has_value());
  EXPECT_EQ(message_of(b), "");
}

TEST(PhysicalSection, ASectionReadValueByValueIsOneFormAfterTheLengthAndModulus) {
  auto message = [](double length,
                    std::optional<double> I,
                    std::optional<double> width,
                    std::optional<double> thickness) -> std::string {
    PhysicalCantilever b = strip(0, 1, 0);
    b.length = length;
    try {
      b.set_section(I, width, thickness);
      b.validate();
    } catch (const InvalidInput& e) {
      return e.what();
    }
    return "";
  };
  // validate()'s order: the length before the section's form.
  EXPECT_NE(message(-1.0, 1e-12, 0.01, std::nullopt).find("--length"), std::string::npos);
  EXPECT_NE(message(0.05, 1e-12, 0.01, std::nullopt).find("give exactly one of them"),
            std::string::npos);
  EXPECT_NE(message(0.05, std::nullopt, std::nullopt, 0.0005).find("needs both --width"),
            std::string::npos);
  // A 0 or NaN value is a given value, refused by validate() naming it.
  EXPECT_NE(message(0.05, std::nullopt, 0.0, 0.0005).find("--width (section width, m) must be"),
            std::string::npos);
  EXPECT_NE(message(0.05, kNaN, std::nullopt, std::nullopt).find("--I (area moment"),
            std::string::npos);
  EXPECT_EQ(message(0.05, kStripI, std::nullopt, std::nullopt), "");
  PhysicalCantilever b = strip(0, 1, 0);
  b.set_section(std::nullopt, 0.02, 0.001);
  EXPECT_EQ(b.section.shape, Section::Shape::kRectangle);
  EXPECT_NEAR(b.second_moment(), 0.02 * 1e-9 / 12.0, 1e-25);
  b.set_section(kStripI, std::nullopt, std::nullopt);
  EXPECT_EQ(b.section.shape, Section::Shape::kGeneral);
  EXPECT_EQ(b.section.thickness, 0.0);
  EXPECT_EQ(b.second_moment(), kStripI);
}

}  // namespace
}  // namespace flexure
