// What is checked against what: data/materials.csv (mechanisms/materials_fatigue.h) against
// Howell 2001, Appendix C as printed (values written out here from the book: Tables C.1-C.6), the
// uncorrected fatigue strengths against Howell's estimates recomputed from each row's S_ut (eqs.
// 3.70, 3.72, 3.132), and the name lookup with its error for an unknown name.
#include <gtest/gtest.h>

#include <string>

#include "flexure/mechanisms/data/data_files.h"
#include "flexure/mechanisms/materials_fatigue.h"
#include "flexure/solver/common/csv_table.h"
#include "flexure/solver/common/status.h"
#include "tests/support/data_file_support.h"

namespace flexure {
namespace {

TEST(MaterialLibrary, EmbeddedCopyEqualsTheFile) {
  test::expect_embedded_equals_file(data::materials());
}

TEST(MaterialLibrary, ValuesAsPrintedInAppendixC) {
  struct Row {
    const char* id;
    double E_GPa, nu, Sy_MPa, Sut_MPa, rho;
  };
  const Row rows[] = {
      {"steel-1095-hr", 206.8, 0.28, 460, 830, 7800},       // C.1, C.5
      {"steel-1050-hr", 206.8, 0.28, 345, 620, 7800},       // C.5 (example §3.2.1)
      {"steel-4130-qt400", 206.8, 0.28, 1462, 1627, 7800},  // C.5
      {"ss-410-ht", 189.6, 0.28, 965, 1241, 7800},          // C.6
      {"ss-410-annealed", 189.6, 0.28, 310, 483, 7800},     // C.6
      {"al-7075-t6", 71.7, 0.34, 503, 572, 2800},           // C.3
      {"al-6061-t6", 71.7, 0.34, 276, 310, 2800},           // C.3
      {"ti-6al-4v-annealed", 113.8, 0.34, 827, 896, 4400},  // C.4
  };
  for (const Row& r : rows) {
    const MaterialGrade& g = find_material(r.id);
    EXPECT_NEAR(g.E, r.E_GPa * 1e9, 1e-3) << r.id;
    ASSERT_TRUE(g.nu) << r.id;
    EXPECT_DOUBLE_EQ(*g.nu, r.nu) << r.id;
    EXPECT_NEAR(*g.yield_strength, r.Sy_MPa * 1e6, 1e-3) << r.id;
    EXPECT_NEAR(*g.ultimate_strength, r.Sut_MPa * 1e6, 1e-3) << r.id;
    EXPECT_NEAR(*g.density, r.rho, 1e-9) << r.id;
  }
  // Table C.2 in psi/kpsi: polypropylene flexural modulus 170-250 kpsi (middle 210 kpsi), yield
  // 4500-5400 psi, break 4500-6000 psi, specific gravity 0.90-0.91.
  const double psi = 6894.757;
  const MaterialGrade& pp = find_material("polypropylene");
  EXPECT_NEAR(pp.E / (210e3 * psi), 1.0, 5e-4);
  EXPECT_NEAR(*pp.yield_strength / (4500 * psi), 1.0, 5e-4);
  EXPECT_NEAR(*pp.ultimate_strength / (4500 * psi), 1.0, 5e-4);
  EXPECT_FALSE(pp.nu);  // Howell gives none
  EXPECT_NE(pp.notes.find("creeps"), std::string::npos);
  EXPECT_NE(pp.notes.find("relaxes"), std::string::npos);
  const MaterialGrade& si = find_material("polysilicon");
  EXPECT_FALSE(si.ductile);
  EXPECT_FALSE(si.yield_strength);
  EXPECT_NEAR(*si.static_strength(), 930e6, 1e-3);  // brittle: S_ut (Howell eq. 3.44)
}

TEST(MaterialLibrary, FatigueStrengthsAreHowellsEstimates) {
  int checked = 0;
  for (const MaterialGrade& g : material_library()) {
    if (!g.fatigue_strength) continue;
    const double Sut = *g.ultimate_strength / 1e6, Se = *g.fatigue_strength / 1e6;
    double expected = 0.0;
    if (g.family.find("steel") != std::string::npos) {
      expected = Sut < 1400 ? 0.5 * Sut : 700.0;  // eq. 3.70
      EXPECT_EQ(g.fatigue_kind, FatigueStrengthKind::kEnduranceLimit);
    } else if (g.family == "aluminium") {
      expected = Sut < 330 ? 0.4 * Sut : 130.0;  // eq. 3.72, at 5e8 cycles
      EXPECT_EQ(g.fatigue_kind, FatigueStrengthKind::kFatigueStrength);
      EXPECT_DOUBLE_EQ(*g.fatigue_cycles, 5e8);
    } else if (g.family == "polymer") {
      expected = 0.2 * Sut;  // eq. 3.132, low end
    } else {
      ADD_FAILURE() << g.id << ": a fatigue strength without an estimate rule";
    }
    EXPECT_NEAR(Se, expected, 5e-4 * expected) << g.id;  // written to 4 digits
    ++checked;
  }
  EXPECT_GE(checked, 50);
  // The rows with no rule have no value (titanium, copper alloys, polysilicon).
  EXPECT_FALSE(find_material("ti-6al-4v-annealed").fatigue_strength);
}

TEST(MaterialLibrary, NamesAndErrors) {
  EXPECT_EQ(find_material("1095 HR").id, "steel-1095-hr");
  EXPECT_EQ(find_material("STEEL_1095_HR").id, "steel-1095-hr");
  EXPECT_EQ(find_material("Acetal (Delrin)").id, "acetal");
  try {
    find_material("titanum");
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("unknown material 'titanum'"), std::string::npos) << m;
    EXPECT_NE(m.find("ti-6al-4v"), std::string::npos) << m;
    EXPECT_NE(m.find("flexure materials"), std::string::npos) << m;
  }
  const auto close = closest_material_ids("polyprop");
  ASSERT_FALSE(close.empty());
  EXPECT_EQ(close.front(), "polypropylene");
  EXPECT_THROW(find_material(""), InvalidInput);
}

}  // namespace
}  // namespace flexure
