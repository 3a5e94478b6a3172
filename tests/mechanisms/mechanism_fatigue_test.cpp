// What is checked against what (mechanisms/materials_fatigue.h, io/mechanism_toml.cpp's material):
//  * a mechanism's fatigue check against the same check written out here from Howell's equations
//    (eqs. 3.74, 3.76 with Table 3.3, 3.77/3.81, Table 3.4, 3.84, 3.107-3.110) on the stresses
//    `analyze` reports: the tensile face of each flexure cycles between 0 at rest and its largest
//    stress over the stroke, so sigma_m = sigma_a = sigma_max/2;
//  * the claim of docs/fatigue.md that no built-in design's PRBM bending moment changes sign over
//    its stroke;
//  * the TOML material: material = "NAME", a [material] name the library knows (values replace
//    the library's, with a note), an unknown name without values (error with the closest ids),
//    and the writer's round trip of the fatigue values.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "flexure/io/toml_files.h"
#include "flexure/mechanisms/materials_fatigue.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {
namespace {

constexpr double kInch = 0.0254;

TEST(MechanismFatigue, MatchesHowellsEquationsOnTheReportedStresses) {
  for (const char* name : {"1A-lpp", "2A-ssp", "3A-sss"}) {
    MechanismDesign d = find_builtin_mechanism(name);
    apply_material(d, find_material("ss-410-ht"));  // 1241 MPa: S_e' = 620.5 MPa (eq. 3.70)
    AnalysisOptions o;
    o.points = 40;
    o.stability = false;
    const MechanismAnalysis a = analyze_mechanism(d, o);
    FatigueOptions f;
    f.finish = SurfaceFinish::kMachined;
    f.reliability = 0.999;
    f.K_f = 1.2;
    const MechanismFatigue r = mechanism_fatigue(a, design_fatigue_material(d), f);
    double lowest = 1e300;
    int lowest_pivot = 0;
    for (int p = 1; p <= 3; ++p) {
      const JointDesign& j = d.joints[p - 1];
      ASSERT_EQ(r.pivots[p - 1].present, j.type != PivotType::kPin) << name;
      if (j.type == PivotType::kPin) continue;
      // Howell's equations, written out.
      const double c_surf = 4.45 * std::pow(1241.0, -0.265);        // eq. 3.76, Table 3.3
      const double d_e = 0.808 * std::sqrt(j.width * j.thickness);  // eq. 3.81
      const double c_size = d_e / kInch < 0.11 ? 1.0 : std::pow(d_e / kInch / 0.3, -0.1133);
      const double S_e = c_surf * c_size * 1.0 * 0.753 / 1.2 * 620.5e6;  // eq. 3.74
      const double sigma_max = a.max_stress[p - 1];         // the governing stress analyze reports
      const double sa = sigma_max / 2, sm = sigma_max / 2;  // eqs. 3.107-3.108
      const double sf = 1.0 / (sa / S_e + sm / 1241e6);     // eq. 3.110
      const PivotFatigue& x = r.pivots[p - 1];
      EXPECT_FALSE(x.moment_changes_sign) << name << " pivot " << p;
      EXPECT_NEAR(x.check.endurance_limit / S_e, 1.0, 2e-3) << name << " pivot " << p;  // 0.753
      EXPECT_NEAR(x.check.alternating_stress / sa, 1.0, 1e-12) << name << " pivot " << p;
      EXPECT_NEAR(x.check.mean_stress / sm, 1.0, 1e-12) << name << " pivot " << p;
      EXPECT_NEAR(x.check.safety_factor / sf, 1.0, 2e-3) << name << " pivot " << p;
      if (x.check.safety_factor < lowest) {
        lowest = x.check.safety_factor;
        lowest_pivot = p;
      }
    }
    EXPECT_EQ(r.critical_pivot, lowest_pivot) << name;
    // The static safety factor and the fatigue one measure the same stress: SF_fatigue <
    // S_y/sigma_max whenever S_e < S_y (here always).
    EXPECT_LT(r.critical().check.safety_factor, a.safety_factor) << name;
  }
}

TEST(MechanismFatigue, NoBuiltInDesignsMomentChangesSignOverItsStroke) {
  int checked = 0;
  for (MechanismDesign d : builtin_mechanisms()) {
    apply_material(d, find_material("steel-1095-hr"));
    d.material.E = find_builtin_mechanism(d.name).material.E;  // keep the design's own forces
    AnalysisOptions o;
    o.points = 50;
    o.exact = false;
    o.stability = false;
    const MechanismAnalysis a = analyze_mechanism(d, o);
    const MechanismFatigue r = mechanism_fatigue(a, design_fatigue_material(d), FatigueOptions{});
    for (int p = 0; p < 3; ++p) {
      if (!r.pivots[p].present) continue;
      EXPECT_FALSE(r.pivots[p].moment_changes_sign) << d.name << " pivot " << p + 1;
      EXPECT_NEAR(r.pivots[p].check.mean_stress,
                  r.pivots[p].check.alternating_stress,
                  1e-12 * r.pivots[p].check.mean_stress)
          << d.name;
      ++checked;
    }
  }
  EXPECT_GT(checked, 20);
}

TEST(MechanismFatigue, MissingStrengthsAreNamed) {
  const MechanismDesign d = find_builtin_mechanism("1A-lpp");  // E and S_y only
  try {
    design_fatigue_material(d);
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("ultimate strength"), std::string::npos) << e.what();
  }
  MechanismDesign t = d;
  EXPECT_THROW(apply_material(t, find_material("copper")), InvalidInput);  // no S_y in Table C.1
  apply_material(t, find_material("ti-6al-4v-annealed"));                  // S_y, S_ut, no S_e'
  EXPECT_THROW(design_fatigue_material(t), InvalidInput);
}

// mechanism_fatigue_report: the check `mechanism analyze` prints, with the warning of a finite life
// in the report (not composed by the tool). 1A-lpp in ss-410-ht: over its whole stroke the Goodman
// safety factor of pivot 1 is below 1 (finite life, warned with the critical pivot, the safety
// factor and the cycles of the check); over 30 % of it, above 1 (infinite life, no warning).
// Without S_ut there is no check, and the reason names what is missing.
TEST(MechanismFatigue, ReportWarnsOfAFiniteLife) {
  MechanismDesign d = find_builtin_mechanism("1A-lpp");
  AnalysisOptions o;
  o.points = 20;
  o.exact = false;
  o.stability = false;
  const MechanismFatigueReport none = mechanism_fatigue_report(analyze_mechanism(d, o), {});
  EXPECT_FALSE(none.fatigue.has_value());
  EXPECT_NE(none.not_checked.find("ultimate strength"), std::string::npos) << none.not_checked;
  EXPECT_TRUE(none.warnings.empty());

  apply_material(d, find_material("ss-410-ht"));
  const MechanismFatigueReport finite =
      mechanism_fatigue_report(analyze_mechanism(d, o), FatigueOptions{});
  ASSERT_TRUE(finite.fatigue.has_value()) << finite.not_checked;
  const FatigueCheck& c = finite.fatigue->critical().check;
  // Eq. 3.110 on the reported stresses and strengths.
  const double S_ut = finite.fatigue->material.ultimate_strength;
  EXPECT_NEAR(c.safety_factor,
              1.0 / (c.alternating_stress / c.endurance_limit + c.mean_stress / S_ut),
              1e-12);
  ASSERT_LT(c.safety_factor, 1.0);
  ASSERT_EQ(finite.warnings.size(), 1u);
  EXPECT_EQ(finite.warnings[0].kind, WarningKind::kSafetyFactor);
  const std::string& text = finite.warnings[0].text;
  EXPECT_EQ(text.rfind("1A-lpp: fatigue (rest to full stroke, pivot 1): ", 0), 0u) << text;
  EXPECT_NE(
      text.find(fmt::format("fatigue safety factor {:.3f} (modified Goodman)", c.safety_factor)),
      std::string::npos)
      << text;
  EXPECT_NE(text.find(fmt::format("FINITE LIFE, about {:.3g} cycles", c.cycles_to_failure)),
            std::string::npos)
      << text;
  EXPECT_EQ(text.back(), 's');  // one sentence, no line break

  d.stroke *= 0.3;
  const MechanismFatigueReport infinite =
      mechanism_fatigue_report(analyze_mechanism(d, o), FatigueOptions{});
  ASSERT_TRUE(infinite.fatigue.has_value());
  ASSERT_GE(infinite.fatigue->critical().check.safety_factor, 1.0);
  EXPECT_TRUE(infinite.warnings.empty());
  EXPECT_NE(fatigue_summary(d, *infinite.fatigue).find(", infinite life"), std::string::npos);
}

const char* kBody = R"(
config = "lpp"
r2 = 0.05
r3 = 0.0443
stroke = 0.02
[ground]
thickness = 1.0e-3
width = 10e-3
)";

TEST(MechanismTomlMaterial, ByNameTableAndErrors) {
  const MaterialGrade& pp = find_material("polypropylene");
  MechanismFile f =
      parse_mechanism_file(std::string("material = \"Polypropylene\"\n") + kBody, "a.toml");
  EXPECT_EQ(f.design.material_id, "polypropylene");
  EXPECT_DOUBLE_EQ(f.design.material.E, pp.E);
  EXPECT_DOUBLE_EQ(*f.design.material.yield_strength, *pp.yield_strength);
  EXPECT_DOUBLE_EQ(*f.design.ultimate_strength, *pp.ultimate_strength);
  EXPECT_DOUBLE_EQ(*f.design.endurance_limit, *pp.fatigue_strength);
  EXPECT_TRUE(f.warnings.empty());

  // A known name with an E of its own: E replaced, with a note; the rest from the library.
  f = parse_mechanism_file(std::string(kBody) + "[material]\nname = \"polypropylene\"\nE = 1.4e9\n",
                           "b.toml");
  EXPECT_DOUBLE_EQ(f.design.material.E, 1.4e9);
  EXPECT_DOUBLE_EQ(*f.design.material.yield_strength, *pp.yield_strength);
  ASSERT_EQ(f.warnings.size(), 1u);
  EXPECT_NE(f.warnings[0].find("material.E = 1.4e+09 replaces"), std::string::npos)
      << f.warnings[0];

  // An unknown name documents the file when E and S_y are given (the files before the library).
  f = parse_mechanism_file(std::string(kBody) +
                               "[material]\nname = \"spring steel\"\nE = 2e11\n"
                               "yield_strength = 1e9\n",
                           "c.toml");
  EXPECT_TRUE(f.design.material_id.empty());
  EXPECT_FALSE(f.design.ultimate_strength);

  // Without them it must be known.
  try {
    parse_mechanism_file(std::string("material = \"polyproplene\"\n") + kBody, "d.toml");
    FAIL() << "no error";
  } catch (const InvalidInput& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("d.toml:1"), std::string::npos) << m;
    EXPECT_NE(m.find("closest: polypropylene"), std::string::npos) << m;
  }
  EXPECT_THROW(
      parse_mechanism_file(std::string(kBody) + "[material]\nname = \"unobtainium\"\n", "e.toml"),
      InvalidInput);

  // The writer keeps the name and the fatigue values; they read back unchanged.
  MechanismDesign d = parse_mechanism_toml(
      std::string(kBody) +
          "[material]\nE = 2e11\nyield_strength = 1e9\nultimate_strength = \"1200 MPa\"\n"
          "endurance_limit = 5e8\n",
      "g.toml");
  EXPECT_DOUBLE_EQ(*d.ultimate_strength, 1.2e9);
  EXPECT_DOUBLE_EQ(*d.endurance_limit, 5e8);
  const MechanismDesign back = parse_mechanism_toml(mechanism_toml(d), "back");
  EXPECT_EQ(*back.ultimate_strength, *d.ultimate_strength);
  EXPECT_EQ(*back.endurance_limit, *d.endurance_limit);
  EXPECT_FALSE(back.endurance_cycles);
  const MechanismDesign al =
      parse_mechanism_toml(std::string("material = \"al-7075-t6\"\n") + kBody, "al.toml");
  const MechanismDesign al_back = parse_mechanism_toml(mechanism_toml(al), "back");
  EXPECT_EQ(al_back.material_id, "al-7075-t6");
  EXPECT_EQ(*al_back.endurance_cycles, 5e8);
  EXPECT_EQ(al_back.material.E, al.material.E);
}

}  // namespace
}  // namespace flexure::mechanism
