// Unit suffixes (solver/common/section.h) against the exact definitions: 1 in = 0.0254 m and 1 lbf
// = 4.4482216152605 N exactly (NIST SP 811, appendix B), so 1 psi = 6894.757293168361 Pa; SI
// prefixes are powers of ten. Plain numbers are SI. Wrong dimensions, unknown units and near misses
// are errors naming the option; the three unit-mistake warnings fire on the documented thresholds
// only.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "flexure/solver/common/section.h"
#include "flexure/solver/common/status.h"

namespace flexure::io {
namespace {

double si(const char* text, Dimension d) { return parse_quantity(text, d, "--x").si; }

std::string error_of(const char* text, Dimension d) {
  try {
    parse_quantity(text, d, "--opt");
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

TEST(Quantity, ConvertsTheIssueExamplesToSi) {
  const double psi = 4.4482216152605 / (0.0254 * 0.0254);
  EXPECT_NEAR(psi, 6894.757293168361, 1e-9);  // NIST SP 811 table B.8
  EXPECT_DOUBLE_EQ(si("50mm", Dimension::kLength), 0.05);
  EXPECT_DOUBLE_EQ(si("0.5 mm", Dimension::kLength), 0.0005);
  EXPECT_DOUBLE_EQ(si("2in", Dimension::kLength), 0.0508);
  EXPECT_DOUBLE_EQ(si("200GPa", Dimension::kStress), 2e11);
  EXPECT_DOUBLE_EQ(si("30Msi", Dimension::kStress), 30e6 * psi);
  EXPECT_DOUBLE_EQ(si("167ksi", Dimension::kStress), 167e3 * psi);
  EXPECT_DOUBLE_EQ(si("25lbf", Dimension::kForce), 25 * 4.4482216152605);
  EXPECT_DOUBLE_EQ(si("30deg", Dimension::kAngle), std::numbers::pi / 6);
  EXPECT_DOUBLE_EQ(si("1.5", Dimension::kAngle), 1.5);  // plain: radians
  EXPECT_DOUBLE_EQ(si("  -2.5  N ", Dimension::kForce), -2.5);
  EXPECT_DOUBLE_EQ(si("+3e-3 m", Dimension::kLength), 3e-3);
  EXPECT_DOUBLE_EQ(si("2 N  m", Dimension::kMoment), 2.0);
  EXPECT_DOUBLE_EQ(si("10 lbf in", Dimension::kMoment), 10 * 4.4482216152605 * 0.0254);
  EXPECT_DOUBLE_EQ(si("0.1042 mm^4", Dimension::kSecondMoment), 0.1042e-12);
  EXPECT_DOUBLE_EQ(si("1 in^4", Dimension::kSecondMoment), std::pow(0.0254, 4));
  EXPECT_DOUBLE_EQ(si("0.02083 N m^2", Dimension::kRigidity), 0.02083);
  EXPECT_TRUE(parse_quantity("50mm", Dimension::kLength, "--x").has_unit());
  EXPECT_FALSE(parse_quantity("0.05", Dimension::kLength, "--x").has_unit());
}

TEST(Quantity, MistakesAreErrorsThatNameTheOptionAndTheFix) {
  EXPECT_NE(error_of("5 N", Dimension::kLength).find("is a force, but --opt is a length"),
            std::string::npos);
  const std::string near = error_of("200 Gpa", Dimension::kStress);
  EXPECT_NE(near.find("did you mean 'GPa'"), std::string::npos) << near;
  const std::string unknown = error_of("3 furlong", Dimension::kLength);
  EXPECT_NE(unknown.find("unknown unit 'furlong'"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("mm"), std::string::npos) << unknown;  // lists the accepted units
  for (const char* bad : {"", "mm", "nan", "inf m", "abc", "1e999 m"}) {
    const std::string e = error_of(bad, Dimension::kLength);
    EXPECT_NE(e.find("--opt"), std::string::npos) << "'" << bad << "': " << e;
  }
  // 1e300 GPa is finite as written but not in pascals.
  EXPECT_NE(error_of("1e300 GPa", Dimension::kStress).find("overflows"), std::string::npos);
}

TEST(Quantity, WarningsFireOnTheirThresholdsOnly) {
  const Quantity full_turn{2.0 * std::numbers::pi * 1.001, ""};
  EXPECT_NE(angle_warning(full_turn, "--theta0").find("for degrees write"), std::string::npos);
  EXPECT_EQ(angle_warning({6.0, ""}, "--theta0"), "");                              // below 2 pi
  EXPECT_EQ(angle_warning({400 * std::numbers::pi / 180, "deg"}, "--theta0"), "");  // explicit
  EXPECT_NE(thickness_warning(0.0051, 0.05, "--thickness").find("Euler-Bernoulli"),
            std::string::npos);
  EXPECT_EQ(thickness_warning(0.0049, 0.05, "--thickness"), "");
  EXPECT_NE(modulus_warning({2e5, ""}, "--E").find("MPa"), std::string::npos);
  EXPECT_EQ(modulus_warning({1e6, ""}, "--E"), "");
  EXPECT_EQ(modulus_warning({2e11, ""}, "--E"), "");
}

}  // namespace
}  // namespace flexure::io
