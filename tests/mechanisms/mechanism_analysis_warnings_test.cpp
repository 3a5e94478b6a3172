// What is checked against what: the warnings analyze_mechanism puts on the library's one channel
// (MechanismAnalysis::warnings, solver/common/status.h), which the CLI prints and Python raises as
// FlexureWarning, against the analysis's own numbers:
//  * a strip whose yield strength is lowered below its stress: one kYield warning per yielding
//    pivot quoting that pivot's largest stress (the analysis's max_stress) and the strength; none
//    at the design's own strength, where its safety factor exceeds 1;
//  * the example lpp mechanism driven to 0.99999 of its toggle stroke, whose exact force changes
//    sign (the case of MechanismCli.ForceChangingSignHasNoPercentConstantForce): a kForceVanishes
//    warning quoting the exact force's min and max, renewed by report_forces_of for the whole
//    mechanism (twice the forces, the whole-mechanism label).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "flexure/io/toml_files.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/mechanisms/mechanism_warnings.h"

namespace flexure::mechanism {
namespace {

std::vector<const Warning*> of_kind(const MechanismAnalysis& a, WarningKind kind) {
  std::vector<const Warning*> out;
  for (const Warning& w : a.warnings) {
    if (w.kind == kind) out.push_back(&w);
  }
  return out;
}

TEST(MechanismAnalysisWarnings, YieldingPivotsWarnWithTheirStress) {
  MechanismDesign d = find_builtin_mechanism("1A-lpp");
  AnalysisOptions o;
  o.points = 20;
  o.exact = false;
  const MechanismAnalysis fine = analyze_mechanism(d, o);
  ASSERT_GT(fine.safety_factor, 1.0);
  EXPECT_TRUE(of_kind(fine, WarningKind::kYield).empty());
  d.material.yield_strength = 1e6;  // far below the strip's stress
  const MechanismAnalysis a = analyze_mechanism(d, o);
  ASSERT_TRUE(a.converged()) << a.message;
  const auto yields = of_kind(a, WarningKind::kYield);
  ASSERT_EQ(yields.size(), 1u);  // the one flexible pivot (lpp: pins at 2 and 3)
  EXPECT_EQ(yields[0]->text,
            fmt::format("pivot 1 of 1A-lpp yields: max stress {:.4g} Pa >= yield strength 1e+06 Pa",
                        a.max_stress[0]));
  EXPECT_EQ(a.warnings, analysis_warnings(a));
}

TEST(MechanismAnalysisWarnings, ForceChangingSignWarnsAndFollowsTheReportedForce) {
  MechanismDesign d =
      load_mechanism_toml(std::string(FLEXURE_SOURCE_DIR) + "/docs/examples/mechanism_lpp.toml");
  d.stroke = 0.99999 * d.toggle_stroke();
  AnalysisOptions o;
  o.points = 50;
  MechanismAnalysis a = analyze_mechanism(d, o);
  ASSERT_TRUE(a.converged()) << a.message;
  const auto [lo, hi] = std::minmax_element(a.force_exact.begin(), a.force_exact.end());
  ASSERT_LT(*lo, 0.0);
  ASSERT_GT(*hi, 0.0);
  auto vanishing = of_kind(a, WarningKind::kForceVanishes);
  ASSERT_EQ(vanishing.size(), 1u);  // the exact force; the PRBM's stays positive
  const auto expect_text = [&](const Warning& w, double min, double max, ForceOf of) {
    EXPECT_NE(w.text.find("the exact force changes sign"), std::string::npos) << w.text;
    EXPECT_NE(
        w.text.find(fmt::format("min {:.4g} N, max {:.4g} N, {}", min, max, force_of_label(of))),
        std::string::npos)
        << w.text;
  };
  expect_text(*vanishing[0], *lo, *hi, ForceOf::kOneHalf);
  const double half_min = *lo, half_max = *hi;
  report_forces_of(a, ForceOf::kWholeMechanism);
  vanishing = of_kind(a, WarningKind::kForceVanishes);
  ASSERT_EQ(vanishing.size(), 1u);
  expect_text(*vanishing[0], 2.0 * half_min, 2.0 * half_max, ForceOf::kWholeMechanism);
}

}  // namespace
}  // namespace flexure::mechanism
