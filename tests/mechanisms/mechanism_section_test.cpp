// What is checked against what: a mechanism design's flexures described by the library's one
// Section and its material by the one Material (solver/common/section.h; JointDesign::section(),
// MechanismDesign::material) against values written out by hand from the design's
// printed inputs (Howell §10.1.4: polypropylene E = 1655 MPa, every flexure 5.08 mm long and
// 12.70 mm wide; thesis design example 1: steel E = 30000 ksi, b = 5 in, h = 0.04865 in):
//  * I = b h^3/12 and the section modulus S = b h^2/6 of each flexure (to rounding, 1e-15);
//  * the spring constants the PRBM uses, K = E I/l for a small-length pivot (Howell eq. 5.14) and
//    gamma K_theta E I/l with Howell's averages gamma = 0.85, K_theta = 2.65 for a fixed-pinned
//    segment (eq. 5.72), to 1e-14 relative (1e-10 for the steel design: the code rounds psi to
//    6894.757293 Pa); example 1's k1 also against the printed 151 N mm/rad;
//  * the PRBM stress of each flexure, |M|/S + |P|/(b h) with the printed section (1e-13 relative:
//    the code divides by I/(h/2), the test by b h^2/6);
//  * a design assembled by hand around a Material (E, nu, S_y) has the springs of the same design
//    from the catalogue, and every catalogue design's springs are coefficient E (b h^3/12)/l from
//    its plain numbers, each to 1e-15 relative (the same products in the same order: rounding
//    alone);
//  * a design holding an invalid Material is refused by finalise(), naming the field.
#include <gtest/gtest.h>

#include <cmath>

#include "flexure/elements/prbm_element.h"
#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/solver/common/section.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {
namespace {

constexpr double kInch = 0.0254;
constexpr double kPsi = 6894.757293168361;  // Pa
// Howell §10.1.4, SI as printed.
constexpr double kHowellE = 1655e6;
constexpr double kHowellWidth = 12.70e-3;
constexpr double kHowellLength = 5.08e-3;

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

TEST(MechanismSection, HowellExample3FlexuresAreRectanglesWithKEqualEIOverL) {
  // Example 3 (sss): three small-length flexural pivots of one width and length.
  const MechanismDesign d = find_builtin_mechanism("howell-ex3");
  const Material& m = d.material;
  EXPECT_EQ(m.E, kHowellE);
  ASSERT_TRUE(m.yield_strength.has_value());
  EXPECT_EQ(*m.yield_strength, 4500.0 * 6894.757293);  // Howell Table C.2, lower end
  EXPECT_NO_THROW(m.validate());
  const PrbmState state = prbm_state(d, 0.5 * d.stroke);
  const double P = std::hypot(state.pin_force_x, state.pin_force_y);
  for (int p = 1; p <= 3; ++p) {
    const JointDesign& j = d.joints[p - 1];
    ASSERT_EQ(j.type, PivotType::kSmall) << "pivot " << p;
    EXPECT_EQ(j.width, kHowellWidth);
    EXPECT_EQ(j.length, kHowellLength);
    const double h = j.thickness;
    const double I_hand = kHowellWidth * h * h * h / 12.0;
    const double S_hand = kHowellWidth * h * h / 6.0;
    const Section s = j.section();
    EXPECT_NO_THROW(s.validate());
    EXPECT_LT(rel(s.second_moment(), I_hand), 1e-15) << "pivot " << p;
    ASSERT_TRUE(s.section_modulus().has_value());
    EXPECT_LT(rel(*s.section_modulus(), S_hand), 1e-15) << "pivot " << p;
    ASSERT_TRUE(s.area().has_value());
    EXPECT_LT(rel(*s.area(), kHowellWidth * h), 1e-15);
    // K = E I/l (Howell eq. 5.14), the stiffness the PRBM's forces rest on.
    const double K_hand = kHowellE * I_hand / kHowellLength;
    EXPECT_LT(rel(d.spring_constant(p), K_hand), 1e-14) << "pivot " << p;
    EXPECT_LT(rel(j.flexural_rigidity(m), kHowellE * I_hand), 1e-15);
    // The PRBM stress: bending |M|/S plus the pin force over the area.
    const double sigma_hand = std::abs(state.moment[p - 1]) / S_hand + P / (kHowellWidth * h);
    EXPECT_LT(rel(state.stress[p - 1], sigma_hand), 1e-13) << "pivot " << p;
  }
}

TEST(MechanismSection, HowellExample1ReferenceSpringIsThePrinted151NmmPerRad) {
  // Example 1: the reference flexure h1 = 0.76 mm; k1 = E w h1^3/(12 l) = 151 N mm/rad (printed
  // to three figures: +-0.5 N mm/rad).
  const MechanismDesign d = find_builtin_mechanism("howell-ex1");
  const double h1 = 0.76e-3;
  EXPECT_EQ(d.joints[0].thickness, h1);
  const double K_hand = kHowellE * kHowellWidth * h1 * h1 * h1 / 12.0 / kHowellLength;
  EXPECT_LT(rel(d.spring_constant(1), K_hand), 1e-14);
  EXPECT_NEAR(d.spring_constant(1) * 1e3, 151.0, 0.5);
}

TEST(MechanismSection, ThesisExample1LongSegmentUsesGammaKThetaEIOverL) {
  // Thesis design example 1 (lpp): one fixed-pinned segment, b = 5 in, h = 0.04865 in, steel.
  const MechanismDesign d = find_builtin_mechanism("1A-lpp");
  const JointDesign& j = d.joints[0];
  ASSERT_EQ(j.type, PivotType::kLong);
  const double b = 5.0 * kInch, h = 0.04865 * kInch, E = 30.0e6 * kPsi;
  // The design's psi is 6894.757293 Pa, 2.4e-11 below the exact 6894.757293168: 1e-10 for E, K.
  constexpr double kPsiRounding = 1e-10;
  EXPECT_LT(rel(d.material.E, E), kPsiRounding);
  EXPECT_LT(rel(j.section().second_moment(), b * h * h * h / 12.0), 1e-15);
  EXPECT_LT(rel(*j.section().section_modulus(), b * h * h / 6.0), 1e-15);
  // Howell's averages gamma = 0.85 (eq. 5.51) and K_theta = 2.65 (eq. 5.64) in eq. 5.72.
  const double K_hand = 0.85 * 2.65 * E * (b * h * h * h / 12.0) / j.length;
  EXPECT_LT(rel(d.spring_constant(1), K_hand), kPsiRounding);
  // The pins have no strip: their "section" is an empty rectangle that does not validate.
  EXPECT_EQ(d.joints[1].type, PivotType::kPin);
  EXPECT_EQ(d.spring_constant(2), 0.0);
  EXPECT_THROW(d.joints[1].section().validate(), InvalidInput);
}

TEST(MechanismSection, DesignBuiltAroundAMaterialHasTheCatalogueSprings) {
  // Howell's example 1 assembled by hand: the printed geometry, and polypropylene as one Material.
  const MechanismDesign catalogue = find_builtin_mechanism("howell-ex1");
  MechanismDesign d;
  d.name = "by hand";
  d.config = catalogue.config;
  d.r2 = catalogue.r2;
  d.r3 = catalogue.r3;
  d.stroke = catalogue.stroke;
  d.joints = catalogue.joints;
  d.material = Material{kHowellE, 0.3, 4500.0 * 6894.757293, std::nullopt};
  d.finalise();
  for (int p = 1; p <= 3; ++p) {
    const double k = catalogue.spring_constant(p);
    if (k == 0.0) {
      EXPECT_EQ(d.spring_constant(p), 0.0) << p;
      continue;
    }
    EXPECT_LE(rel(d.spring_constant(p), k), 1e-15) << p;
    const JointDesign& j = d.joints[p - 1];
    const double b = j.width, h = j.thickness;
    EXPECT_LE(rel(d.spring_constant(p), kHowellE * (b * h * h * h / 12.0) / j.length), 1e-15) << p;
  }
}

TEST(MechanismSection, EveryCatalogueSpringIsCoefficientTimesEIOverL) {
  // The coefficient of each kind of pivot: Howell eq. 5.14 (s), eq. 5.72 with the averages (l),
  // the design's spring rule for a fixed-fixed segment (builtin_designs.h).
  int checked = 0;
  for (const MechanismDesign& d : builtin_mechanisms()) {
    for (int p = 1; p <= 3; ++p) {
      const JointDesign& j = d.joints[p - 1];
      if (j.type == PivotType::kPin) continue;
      const double coefficient =
          j.segment == SegmentKind::kFixedFixed ? spring_rule_factor(d.spring_rule, j)
          : j.type == PivotType::kLong ? howell_average_fixed_pinned().stiffness_coefficient()
                                       : 1.0;
      const double b = j.width, h = j.thickness;
      const double expected = coefficient * (d.material.E * (b * h * h * h / 12.0)) / j.length;
      EXPECT_LE(rel(d.spring_constant(p), expected), 1e-15) << d.name << " pivot " << p;
      ++checked;
    }
  }
  EXPECT_GT(checked, 20);
}

// The message of finalise() for `design`, or "" if it accepts it.
std::string finalise_message(MechanismDesign design) {
  try {
    design.finalise();
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

TEST(MechanismSection, InvalidMaterialIsRefusedNamingTheField) {
  const MechanismDesign good = find_builtin_mechanism("howell-ex1");
  EXPECT_EQ(finalise_message(good), "");
  MechanismDesign d = good;
  d.material.E = -1.0;
  EXPECT_EQ(finalise_message(d), "E (Young's modulus, Pa) must be finite and > 0 (got -1)");
  d = good;
  d.material.E = std::nan("");
  EXPECT_EQ(finalise_message(d), "E (Young's modulus, Pa) must be finite and > 0 (got nan)");
  d = good;
  d.material.yield_strength.reset();
  EXPECT_EQ(finalise_message(d), "yield_strength (Pa) must be finite and > 0 (got 0)");
  d = good;
  d.material.yield_strength = -5.0;
  EXPECT_EQ(finalise_message(d), "yield_strength (Pa) must be finite and > 0 (got -5)");
  d = good;
  d.material.nu = 0.5;
  EXPECT_EQ(finalise_message(d), "Material::nu must be finite and in (-1, 0.5) (got 0.5)");
  d = good;
  d.material.density = 0.0;
  EXPECT_EQ(finalise_message(d), "Material::density must be finite and > 0 (got 0)");
}

}  // namespace
}  // namespace flexure::mechanism
