// What is checked against what:
//  * a rectangle's second moment against the integral of y^2 dA over the section (composite
//    Simpson, exact for a quadratic integrand up to rounding), its area against the sum of the
//    strips, its section modulus against the bending stress of the extreme fibre computed from the
//    integral (sigma = M c/I) and against the textbook b h^2/6;
//  * a general section: I as given, S = 2 I/h when h is known, no area, no S without h;
//  * Material: G = E/(2 (1 + nu)) for steel's textbook values (E = 200 GPa, nu = 0.3: 1000/13
//    GPa); E I of a 10 mm x 1 mm steel strip against the hand value 1/6 N m^2;
//  * every bad field (negative, zero, NaN, infinite, a value that does not belong to the shape) is
//    refused with InvalidInput naming it.
#include "flexure/solver/common/section.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

constexpr double kRounding = 1e-13;  // relative: a few ulps of sums of O(1) terms
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// Integral of f(y) b dy over -h/2 <= y <= h/2 by composite Simpson with `n` (even) intervals.
double simpson_over_thickness(double b, double h, const std::function<double(double)>& f, int n) {
  const double step = h / n;
  double sum = f(-h / 2) + f(h / 2);
  for (int i = 1; i < n; ++i) sum += (i % 2 == 1 ? 4.0 : 2.0) * f(-h / 2 + i * step);
  return b * sum * step / 3.0;
}

// The message of the InvalidInput `f` throws (fails the test when it throws none).
std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InvalidInput& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InvalidInput";
  return {};
}

TEST(Section, RectangleAgainstTheIntegralsOverTheSection) {
  const double b = 12.7e-3, h = 0.9e-3;  // half an inch wide, 0.9 mm thick
  const Section s = Section::rectangle(b, h);
  const double I = simpson_over_thickness(
      b, h, [](double y) { return y * y; }, 64);
  const double A = simpson_over_thickness(
      b, h, [](double) { return 1.0; }, 64);
  EXPECT_NEAR(s.second_moment(), I, kRounding * I);
  ASSERT_TRUE(s.area());
  EXPECT_NEAR(*s.area(), A, kRounding * A);
  // sigma at the extreme fibre of a moment M: M c/I = M/S.
  const double M = 0.37;
  const double sigma = M * (h / 2) / I;
  ASSERT_TRUE(s.section_modulus());
  EXPECT_NEAR(M / *s.section_modulus(), sigma, kRounding * sigma);
  EXPECT_NEAR(*s.section_modulus(), b * h * h / 6.0, kRounding * b * h * h);
}

TEST(Section, GeneralSectionIsWhatIsGiven) {
  const Section known = Section::general(2.5e-12, 1e-3);
  EXPECT_EQ(known.second_moment(), 2.5e-12);
  ASSERT_TRUE(known.section_modulus());
  EXPECT_NEAR(*known.section_modulus(), 2.5e-12 / 0.5e-3, kRounding * 5e-9);
  EXPECT_FALSE(known.area());  // an I beam's area is not determined by I and h
  const Section unknown = Section::general(2.5e-12);
  EXPECT_EQ(unknown.second_moment(), 2.5e-12);
  EXPECT_FALSE(unknown.section_modulus());  // no extreme fibre: no stress
  EXPECT_FALSE(unknown.area());
}

TEST(Material, ShearModulusAndFlexuralRigidity) {
  Material steel;
  steel.E = 200e9;
  steel.nu = 0.3;
  EXPECT_NEAR(steel.shear_modulus(), 76.92307692307692e9, 1e-15 * 76.9e9);  // 1000/13 GPa
  // 10 mm x 1 mm steel strip: E b h^3/12 = 200e9 Pa * 0.01 m * 1e-9 m^3/12 = 1/6 N m^2.
  EXPECT_NEAR(flexural_rigidity(Section::rectangle(0.01, 0.001), steel), 1.0 / 6.0, 1e-15);
}

TEST(Section, BadFieldsAreNamed) {
  for (double bad : {-1.0, 0.0, kNan, kInf}) {
    EXPECT_NE(message_of([&] { Section::rectangle(bad, 1e-3); }).find("Section::width"),
              std::string::npos)
        << bad;
    EXPECT_NE(message_of([&] { Section::rectangle(1e-2, bad); }).find("Section::thickness"),
              std::string::npos)
        << bad;
    EXPECT_NE(message_of([&] { Section::general(bad); }).find("Section::I"), std::string::npos)
        << bad;
    EXPECT_NE(message_of([&] { Section::general(1e-12, bad); }).find("Section::thickness"),
              std::string::npos)
        << bad;
  }
  // A field that does not belong to the shape is refused, not ignored.
  Section rectangle = Section::rectangle(1e-2, 1e-3);
  rectangle.I = 1e-12;
  EXPECT_NE(message_of([&] { rectangle.validate(); }).find("Section::I"), std::string::npos);
  Section general = Section::general(1e-12);
  general.width = 1e-2;
  EXPECT_NE(message_of([&] { general.validate(); }).find("Section::width"), std::string::npos);
  // A default Section is an empty rectangle.
  EXPECT_NE(message_of([] { Section{}.validate(); }).find("Section::width"), std::string::npos);
}

TEST(Material, BadFieldsAreNamed) {
  const auto with = [](const std::function<void(Material&)>& change) {
    Material m;
    m.E = 200e9;
    change(m);
    return message_of([&] { m.validate(); });
  };
  for (double bad : {-1.0, 0.0, kNan, kInf}) {
    EXPECT_NE(with([&](Material& m) { m.E = bad; }).find("Material::E"), std::string::npos);
    EXPECT_NE(with([&](Material& m) { m.yield_strength = bad; }).find("Material::yield_strength"),
              std::string::npos);
    EXPECT_NE(with([&](Material& m) { m.density = bad; }).find("Material::density"),
              std::string::npos);
  }
  for (double bad : {-1.0, 0.5, 0.7, kNan}) {
    EXPECT_NE(with([&](Material& m) { m.nu = bad; }).find("Material::nu"), std::string::npos);
  }
  // Accepted: no yield strength or density, an auxetic nu, nu = 0.
  Material m;
  m.E = 3e9;
  m.nu = -0.2;
  EXPECT_NO_THROW(m.validate());
  m.nu = 0.0;
  m.yield_strength = 60e6;
  m.density = 1200.0;
  EXPECT_NO_THROW(m.validate());
  EXPECT_THROW(flexural_rigidity(Section::rectangle(1e-2, 1e-3), Material{}), InvalidInput);
}

}  // namespace
}  // namespace flexure
