// `material = "NAME"` in a chain file (io/toml_files.h; docs/chain-toml.md "Materials"): at the
// top of the file or in a [[segment]], a row of data/materials.csv supplies E, nu (where plate or
// extensible needs it) and the yield strength; an explicit E, nu or yield_strength replaces the
// library's value with a warning; bad names, a material without physical units, a material with
// EI, and two yield strengths in one chain are refused with the file, line and key. The expected
// values are the printed ones of Howell's Appendix C (Tables C.1, C.5, C.6): 1095 HR steel E =
// 206.8 GPa, nu = 0.28, S_y = 460 MPa; 301 CR stainless E = 189.6 GPa, S_y = 1138 MPa.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <variant>

#include "flexure/io/toml_files.h"
#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

constexpr double kSteelE = 206.8e9, kSteelNu = 0.28, kSteelSy = 460e6;
constexpr double kStainlessE = 189.6e9, kStainlessSy = 1138e6;

double EI_of(const io::ChainFile& f, std::size_t k) {
  return std::get<FlexibleSegment>(f.chain.segments[k]).EI;
}

double rectangle_I(double b, double h) { return b * h * h * h / 12.0; }

std::string error_of(const std::string& text) {
  try {
    io::parse_chain_file(text, "m.toml");
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "(no error)";
}

bool warned(const io::ChainFile& f, const std::string& part) {
  for (const std::string& w : f.warnings) {
    if (w.find(part) != std::string::npos) return true;
  }
  return false;
}

TEST(ChainTomlMaterial, TheFileMaterialGivesEAndTheYieldStrength) {
  const io::ChainFile f = io::parse_chain_file(R"(
units = "SI"
material = "steel-1095-hr"
[[segment]]
type = "flexible"
length = "50 mm"
width = "10 mm"
thickness = "0.5 mm"
[[segment]]
type = "rigid"
length = "20 mm"
[[segment]]
type = "flexible"
length = 0.02
EI = 0.5
[tip_load]
Fy = "1 N"
)",
                                               "m.toml");
  const double I = rectangle_I(10e-3, 0.5e-3);
  EXPECT_NEAR(EI_of(f, 0), kSteelE * I, 1e-12 * kSteelE * I);
  ASSERT_TRUE(f.segments[0].has_value());
  EXPECT_NEAR(f.segments[0]->material.E, kSteelE, 1e-3);
  ASSERT_TRUE(f.segments[0]->material.yield_strength.has_value());
  EXPECT_NEAR(*f.segments[0]->material.yield_strength, kSteelSy, 1e-3);
  ASSERT_TRUE(f.yield_strength.has_value());
  EXPECT_NEAR(*f.yield_strength, kSteelSy, 1e-3);
  EXPECT_NEAR(*f.effective_yield_strength(), kSteelSy, 1e-3);
  // A segment given by EI keeps it: the material is for the segments with a section.
  EXPECT_EQ(EI_of(f, 2), 0.5);
  EXPECT_FALSE(f.segments[2].has_value());
  EXPECT_TRUE(f.warnings.empty());
  // The same chain as the library's objects validate (EI = E I, one yield strength).
  EXPECT_NO_THROW(f.validate());

  // Bitwise the file with the values written out.
  const io::ChainFile written = io::parse_chain_file(R"(
units = "SI"
yield_strength = "460 MPa"
[[segment]]
type = "flexible"
length = "50 mm"
E = "206.8 GPa"
width = "10 mm"
thickness = "0.5 mm"
)",
                                                     "e.toml");
  EXPECT_EQ(EI_of(written, 0), EI_of(f, 0));
  EXPECT_EQ(*written.yield_strength, *f.yield_strength);
}

TEST(ChainTomlMaterial, ASegmentsMaterialAndExplicitValuesReplaceTheFilesWithAWarning) {
  const io::ChainFile f = io::parse_chain_file(R"(
units = "SI"
material = "steel-1095-hr"
yield_strength = "500 MPa"
[[segment]]
type = "flexible"
length = "30 mm"
material = "ss-301-cr"
width = "10 mm"
thickness = "0.4 mm"
[[segment]]
type = "flexible"
length = "30 mm"
E = "200 GPa"
width = "10 mm"
thickness = "0.4 mm"
)",
                                               "m.toml");
  const double I = rectangle_I(10e-3, 0.4e-3);
  EXPECT_NEAR(EI_of(f, 0), kStainlessE * I, 1e-12 * kStainlessE * I);
  EXPECT_NEAR(EI_of(f, 1), 200e9 * I, 1e-12 * 200e9 * I);
  EXPECT_NEAR(*f.yield_strength, 500e6, 1e-3);
  EXPECT_NEAR(*f.segments[0]->material.yield_strength, 500e6, 1e-3);
  EXPECT_TRUE(warned(f,
                     "segment 2.E = 2e+11 Pa replaces the 2.068e+11 Pa of material "
                     "'steel-1095-hr'"))
      << ::testing::PrintToString(f.warnings);
  EXPECT_TRUE(warned(f,
                     "yield_strength = 5e+08 Pa replaces the 4.6e+08 Pa of material "
                     "'steel-1095-hr'"));
  EXPECT_TRUE(warned(f, "replaces the 1.138e+09 Pa of material 'ss-301-cr'"));
  EXPECT_NO_THROW(f.validate());
}

TEST(ChainTomlMaterial, PlateOnTakesTheMaterialsPoissonRatio) {
  const io::ChainFile f = io::parse_chain_file(R"(
units = "SI"
[[segment]]
type = "flexible"
length = "40 mm"
material = "1095 HR"
width = "20 mm"
thickness = "0.3 mm"
plate = "on"
)",
                                               "m.toml");
  // E I/(1 - nu^2) (docs/plate-modulus.md) with Table C.1's nu = 0.28.
  const double EI = kSteelE / (1.0 - kSteelNu * kSteelNu) * rectangle_I(20e-3, 0.3e-3);
  EXPECT_NEAR(EI_of(f, 0), EI, 1e-12 * EI);
  EXPECT_NEAR(f.segments[0]->material.nu, kSteelNu, 1e-15);
  EXPECT_NEAR(*f.yield_strength, kSteelSy, 1e-3);
  EXPECT_NO_THROW(f.validate());
}

TEST(ChainTomlMaterial, BadMaterialsAreRefusedWithTheLine) {
  const std::string segment = R"(
[[segment]]
type = "flexible"
length = "40 mm"
width = "10 mm"
thickness = "0.5 mm"
)";
  std::string e = error_of("units = \"SI\"\nmaterial = \"steel-1095-hx\"\n" + segment);
  EXPECT_NE(e.find("m.toml:2: material: "), std::string::npos) << e;
  EXPECT_NE(e.find("steel-1095-hr"), std::string::npos) << e;  // the closest ids
  e = error_of("units = \"SI\"\nmaterial = 3\n" + segment);
  EXPECT_NE(e.find("material must be a material name"), std::string::npos) << e;
  // The library's values are SI: a file in its own units may not name one.
  e = error_of(R"(material = "steel-1095-hr"
[[segment]]
type = "flexible"
length = 0.04
width = 0.01
thickness = 0.0005
)");
  EXPECT_NE(e.find("needs physical units"), std::string::npos) << e;
  // A material and EI describe the rigidity twice.
  e = error_of(R"(units = "SI"
[[segment]]
type = "flexible"
length = 0.04
EI = 0.1
material = "steel-1095-hr"
)");
  EXPECT_NE(e.find("gives both EI and a section"), std::string::npos) << e;
  // A segment's material needs the section's dimensions.
  e = error_of(R"(units = "SI"
[[segment]]
type = "flexible"
length = 0.04
material = "steel-1095-hr"
)");
  EXPECT_NE(e.find("segment 1: give E with either I or both width and thickness"),
            std::string::npos)
      << e;
  // Two yield strengths in one chain: the safety factor needs one.
  e = error_of(R"(units = "SI"
material = "steel-1095-hr"
[[segment]]
type = "flexible"
length = 0.04
width = 0.01
thickness = 0.0005
material = "ss-301-cr"
)");
  EXPECT_NE(e.find("material 'ss-301-cr' of segment 1 has strength 1.138e+09 Pa, material "
                   "'steel-1095-hr' of the file 4.6e+08 Pa: one yield strength per chain"),
            std::string::npos)
      << e;
  // A section without E and without a material.
  e = error_of("units = \"SI\"\n" + segment);
  EXPECT_NE(e.find("a section needs the modulus E (or material = \"NAME\")"), std::string::npos)
      << e;
}

}  // namespace
}  // namespace flexure
