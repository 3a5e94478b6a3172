// The material library and the fatigue check through the tool (docs/materials.md,
// docs/fatigue.md): `flexure materials --json` against data/materials.csv's printed values,
// an unknown name (exit 2 with the closest names, JSON error with --json), `--material` in `beam`
// against the same beam with --E and --yield-strength, `mechanism analyze` with and without a
// material (the fatigue keys against the static ones), and `design mechanism --fatigue`: its
// sizing safety factor against Howell's eq. 3.128, and every design it keeps has a fatigue safety
// factor >= --safety-factor.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "tests/support/cli_test_support.h"

namespace flexure {
namespace {

using nlohmann::json;
using test::run_flexure;

TEST(CliMaterials, ListsTheLibraryAsJson) {
  const auto r = run_flexure("materials --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  ASSERT_TRUE(j["materials"].is_array());
  EXPECT_EQ(j["materials"].size(), 66u);
  bool found = false;
  for (const json& m : j["materials"]) {
    if (m["id"] != "steel-1095-hr") continue;
    found = true;
    EXPECT_DOUBLE_EQ(m["E"].get<double>(), 206.8e9);             // Howell Table C.1
    EXPECT_DOUBLE_EQ(m["yield_strength"].get<double>(), 460e6);  // Table C.5
    EXPECT_DOUBLE_EQ(m["ultimate_strength"].get<double>(), 830e6);
    EXPECT_DOUBLE_EQ(m["endurance_limit"].get<double>(), 415e6);  // 0.5 S_ut, eq. 3.70
    EXPECT_EQ(m["source"], "Howell Table C.5 (E nu density: Table C.1)");
  }
  EXPECT_TRUE(found);
  const auto one = run_flexure("materials polypropylene");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_NE(one.out.find("creeps"), std::string::npos) << one.out;
}

TEST(CliMaterials, UnknownNameIsExit2WithTheClosestNames) {
  auto r = run_flexure("materials titanum");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("ti-6al-4v-annealed"), std::string::npos) << r.err;
  r = run_flexure("materials titanum --json");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("\"error\""), std::string::npos) << r.out;
  r = run_flexure(
      "beam --length 50mm --material unobtainium --width 10mm --thickness 0.5mm --Fy 1N");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown material 'unobtainium'"), std::string::npos) << r.err;
  r = run_flexure("mechanism analyze 1A-lpp --material polyproplene --method prbm");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("polypropylene"), std::string::npos) << r.err;
}

TEST(CliMaterials, BeamMaterialEqualsItsValuesGivenByHand) {
  const std::string beam = "beam --length 50mm --width 10mm --thickness 0.5mm --Fy 2N --json";
  const auto by_name = run_flexure(beam + " --material ss-410-ht");
  const auto by_hand = run_flexure(beam + " --E 189.6GPa --yield-strength 965MPa");
  ASSERT_EQ(by_name.exit_code, 0) << by_name.err;
  ASSERT_EQ(by_hand.exit_code, 0) << by_hand.err;
  const json a = json::parse(by_name.out), b = json::parse(by_hand.out);
  EXPECT_DOUBLE_EQ(a["tip_y"].get<double>(), b["tip_y"].get<double>());
  EXPECT_DOUBLE_EQ(a["safety_factor"].get<double>(), b["safety_factor"].get<double>());
  EXPECT_TRUE(by_name.err.empty()) << by_name.err;
  // --E replaces the material's, with a note on stderr.
  const auto both = run_flexure(beam + " --material ss-410-ht --E 200GPa");
  ASSERT_EQ(both.exit_code, 0) << both.err;
  EXPECT_NE(both.err.find("replaces the 1.896e+11 Pa of material 'ss-410-ht'"), std::string::npos)
      << both.err;
}

TEST(CliMaterials, BeamReversedCycleIsHowellsCantilever) {
  // Howell eqs. 3.88-3.97: 1095 HR, L = 20 in, b = 3 in, h = 0.2 in, F = 8 lb completely reversed,
  // hot-rolled, 99.99 %, K_f = 1.4: sigma = 8 kpsi, S_e = 12.7 kpsi (12.85 unrounded), SF 1.6.
  // Here S_ut = 830 MPa from Table C.5 (the example's 120 kpsi is 827 MPa) and Table 3.3's MPa
  // fit; the large-deflection root moment is below F L by 4e-4.
  const std::string beam =
      "beam --length 20in --width 3in --thickness 0.2in --Fy 8lbf --material steel-1095-hr "
      "--surface-finish hot-rolled --reliability 0.9999 --Kf 1.4 --json";
  auto r = run_flexure(beam + " --cycle reversed");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  json j = json::parse(r.out);
  const double psi = 6894.757293168361;
  const double sigma = j["max_stress"].get<double>();
  EXPECT_NEAR(sigma / (8000 * psi), 1.0, 1e-3);
  EXPECT_DOUBLE_EQ(j["alternating_stress"].get<double>(), sigma);
  EXPECT_NEAR(j["mean_stress"].get<double>(), 0.0, 1e-9 * sigma);
  const double S_e = 58.1 * std::pow(830.0, -0.719) *
                     std::pow(0.808 * std::sqrt(0.6) / 0.3, -0.1133) *
                     (1 - 0.08 * 3.719016485455709) / 1.4 * 415e6;
  EXPECT_NEAR(j["endurance_limit"].get<double>() / S_e, 1.0, 1e-9);
  EXPECT_NEAR(j["fatigue_safety_factor"].get<double>(), S_e / sigma, 1e-9);
  EXPECT_NEAR(j["fatigue_safety_factor"].get<double>(), 1.6, 0.05);  // eq. 3.97
  EXPECT_EQ(j["fatigue"]["infinite_life"], true);
  // Repeated (0 -> F): sigma_m = sigma_a = sigma/2 (eqs. 3.107-3.108).
  r = run_flexure(beam + " --cycle repeated");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  j = json::parse(r.out);
  EXPECT_DOUBLE_EQ(j["alternating_stress"].get<double>(), j["max_stress"].get<double>() / 2);
  EXPECT_DOUBLE_EQ(j["mean_stress"].get<double>(), j["max_stress"].get<double>() / 2);
  // Twice the load: finite life, warned; exit 0 (an answer, not a failure).
  r = run_flexure(
      "beam --length 20in --width 3in --thickness 0.2in --Fy 16lbf --material steel-1095-hr "
      "--surface-finish hot-rolled --reliability 0.9999 --Kf 1.4 --cycle reversed");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("finite life"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("FINITE LIFE"), std::string::npos) << r.out;
  // A nondimensional beam has no stress to cycle; a material without S_e' is named.
  EXPECT_EQ(run_flexure("beam --alpha2 1 --cycle reversed").exit_code, 2);
  r = run_flexure(
      "beam --length 20in --width 3in --thickness 0.2in --Fy 8lbf --material ti-6al-4v-annealed "
      "--cycle reversed");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("endurance limit"), std::string::npos) << r.err;
}

TEST(CliMaterials, AnalyzeReportsFatigueBesideTheStaticSafetyFactor) {
  auto r = run_flexure("mechanism analyze 1A-lpp --method prbm --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  json j = json::parse(r.out);
  EXPECT_TRUE(j["fatigue_safety_factor"].is_null());
  EXPECT_NE(j["fatigue_note"].get<std::string>().find("ultimate strength"), std::string::npos);

  r = run_flexure(
      "mechanism analyze 1A-lpp --method prbm --json --material steel-1095-hr "
      "--surface-finish hot-rolled --reliability 0.9999 --Kf 1.4");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  j = json::parse(r.out);
  const double sf = j["fatigue_safety_factor"].get<double>();
  const double sa = j["alternating_stress"].get<double>(), sm = j["mean_stress"].get<double>();
  const double Se = j["endurance_limit"].get<double>();
  // Eq. 3.110 on the reported numbers; the cycle 0 -> sigma_max: sigma_a = sigma_m, and sigma_max
  // is the critical pivot's largest stress.
  EXPECT_NEAR(1.0 / sf, sa / Se + sm / 830e6, 1e-12);
  EXPECT_DOUBLE_EQ(sa, sm);
  const int pivot = j["fatigue"]["critical_pivot"].get<int>();
  EXPECT_DOUBLE_EQ(2 * sa, j["max_stress_per_pivot"][pivot - 1].get<double>());
  EXPECT_NEAR(j["fatigue"]["c_reliab"].get<double>(), 0.702, 5e-4);  // Table 3.4
  EXPECT_NEAR(j["fatigue"]["c_misc"].get<double>(), 1 / 1.4, 1e-12);
  EXPECT_DOUBLE_EQ(j["design"]["E"].get<double>(), 206.8e9);
  EXPECT_NE(r.err.find("--material steel-1095-hr"), std::string::npos) << r.err;  // the note
  // Text: the fatigue line.
  r = run_flexure("mechanism analyze 1A-lpp --method prbm --material steel-1095-hr");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("fatigue safety factor"), std::string::npos) << r.out;
  // Bad options: exit 2.
  EXPECT_EQ(run_flexure("mechanism analyze 1A-lpp --material steel-1095-hr --Kf 0.5").exit_code, 2);
  EXPECT_EQ(run_flexure("mechanism analyze 1A-lpp --material steel-1095-hr --surface-finish shiny")
                .exit_code,
            2);
}

TEST(CliMaterials, DesignMechanismFatigueKeepsOnlyDesignsWithInfiniteLife) {
  // 301 cold-rolled stainless: S_y 1138 MPa, S_ut 1379 MPa, S_e' 689.5 MPa (Howell Table C.6,
  // eq. 3.70). Machined, 99 %, K_f 1.2: S_e = 0.6406 x 0.814 / 1.2 x 689.5 MPa at c_size = 1, so
  // the cycle 0 -> sigma_max meets Goodman SF 1.5 up to sigma_max = 2 S_e S_ut/((S_e + S_ut) 1.5)
  // (eq. 3.128): the designs are sized at the static factor S_y/that.
  const std::string spec =
      "design mechanism --force 20N --stroke 10mm --material ss-301-cr --safety-factor 1.5 "
      "--length-range 60mm:100mm --no-exact --json --fatigue --Kf 1.2";
  const auto kept = run_flexure(spec);
  ASSERT_EQ(kept.exit_code, 0) << kept.err;
  const json k = json::parse(kept.out);
  EXPECT_EQ(k["fatigue"], true);
  const double c_surf = 4.45 * std::pow(1379.0, -0.265);
  const double S_e = c_surf * (1 - 0.08 * 2.3263478740408408) / 1.2 * 689.5e6;
  const double sigma_allowed = 2 * S_e * 1379e6 / ((S_e + 1379e6) * 1.5);
  EXPECT_NEAR(k["sizing_safety_factor"].get<double>(), 1138e6 / sigma_allowed, 1e-6);
  ASSERT_FALSE(k["designs"].empty());
  for (const json& d : k["designs"]) {
    EXPECT_GE(d["fatigue_safety_factor"].get<double>(), 1.5 * (1 - 1e-9)) << d["subclass"];
    // Each design's own check on its stresses (its size factor <= 1 can only lower it).
    EXPECT_GE(d["safety_factor_prbm"].get<double>(),
              k["sizing_safety_factor"].get<double>() * (1 - 1e-6));
  }
  for (const json& d : k["rejected"]) {
    const std::string b = d["binding"].get<std::string>();
    if (b.rfind("fatigue:", 0) == 0) EXPECT_NE(b.find("< 1.5"), std::string::npos) << b;
  }
  // Without S_ut and S_e': exit 2 naming them.
  const auto none = run_flexure(
      "design mechanism --force 10N --stroke 15mm --E 200GPa --yield-strength 1GPa "
      "--safety-factor 1.5 --length-range 60mm:80mm --no-exact --fatigue");
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.err.find("ultimate strength"), std::string::npos) << none.err;
}

}  // namespace
}  // namespace flexure
