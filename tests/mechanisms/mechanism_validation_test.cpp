// One row of `flexure mechanism validate` (mechanisms/mechanism_validation.h) and the design sets
// it goes through (mechanisms/mechanism_catalogue.h), checked against:
//  * the sources' counts: nine thesis designs (Weight 2001, one per configuration), eleven modified
//    designs (paper 004 Tables 1-6), nine of Howell's (Table 10.1 and §10.1.4's examples), and an
//    inversion for each design of a type-asymmetric configuration (spp, lpp, plp, ssp, slp, lps:
//    six thesis designs and five of Howell's; inversion.h), the modified designs not inverted;
//  * an independent method: Howell's chain algorithm on the last exact point agrees with the
//    shooting solution to the accuracy docs/validation.md states for N = 100 elements
//    (1e-9-1e-5 r2; 1e-4 r2 allowed here at 10 stroke points);
//  * geometry: --toggle-fraction f gives the stroke f (r2 + r3) for R = 1 (a crank and coupler of
//    equal length reach the toggle position folded back onto the ground pivot, Delta x = r2 + r3);
//  * the row's own analysis: every column is the documented field (docs/hdf5-schema.md), NaN
//    exactly where the schema says, and the status follows from the exact model and the check.
#include "flexure/mechanisms/mechanism_validation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "flexure/mechanisms/inversion.h"
#include "flexure/mechanisms/mechanism_catalogue.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {
namespace {

std::vector<std::string> names(const std::vector<MechanismDesign>& designs) {
  std::vector<std::string> out;
  for (const MechanismDesign& d : designs) out.push_back(d.name);
  return out;
}

TEST(MechanismCatalogue, DesignSetsHaveTheSourcesCounts) {
  const auto thesis = mechanism_designs(DesignSet::kThesis);
  const auto modified = mechanism_designs(DesignSet::kModified);
  const auto howell = mechanism_designs(DesignSet::kHowell);
  const auto inversions = mechanism_designs(DesignSet::kInversions);
  const auto builtin = mechanism_designs(DesignSet::kBuiltin);
  const auto all = mechanism_designs(DesignSet::kAll);
  EXPECT_EQ(thesis.size(), 9u);
  EXPECT_EQ(modified.size(), 11u);
  EXPECT_EQ(howell.size(), 9u);
  EXPECT_EQ(inversions.size(), 6u + 5u);
  // builtin = thesis then modified; all = builtin, Howell, inversions.
  std::vector<std::string> expected = names(thesis);
  for (const std::string& n : names(modified)) expected.push_back(n);
  EXPECT_EQ(names(builtin), expected);
  for (const auto* part : {&howell, &inversions}) {
    for (const std::string& n : names(*part)) expected.push_back(n);
  }
  EXPECT_EQ(names(all), expected);
  std::set<std::string> unique(expected.begin(), expected.end());
  EXPECT_EQ(unique.size(), expected.size());
  for (const MechanismDesign& d : inversions) {
    EXPECT_TRUE(d.inverted) << d.name;
    EXPECT_TRUE(config_has_inversion(d.config)) << d.name;
    EXPECT_TRUE(d.paper_config.empty()) << d.name;
  }
  for (const MechanismDesign& d : modified) EXPECT_FALSE(d.paper_config.empty()) << d.name;
}

TEST(MechanismCatalogue, SetNamesRoundTripAndAnUnknownOneIsRefused) {
  for (DesignSet s : {DesignSet::kBuiltin,
                      DesignSet::kThesis,
                      DesignSet::kModified,
                      DesignSet::kHowell,
                      DesignSet::kInversions,
                      DesignSet::kAll}) {
    EXPECT_EQ(design_set_from_string(to_string(s)), s);
  }
  EXPECT_EQ(design_set_from_string("Howell"), DesignSet::kHowell);
  try {
    design_set_from_string("thesis-designs");
    FAIL() << "no exception";
  } catch (const InvalidInput& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("'thesis-designs'"), std::string::npos) << m;
    EXPECT_NE(m.find("builtin, thesis, modified, howell, inversions, all"), std::string::npos);
  }
}

// Every column of every built-in design's row is the documented field of its own analysis.
TEST(MechanismValidation, ColumnsAndStatusFollowTheAnalysisForEveryBuiltinDesign) {
  MechanismValidationOptions o;
  o.points = 10;
  const std::vector<ValidationColumn>& columns = validation_columns();
  ASSERT_EQ(columns.size(), 11u);
  int checked = 0;
  for (const MechanismDesign& design : mechanism_designs(DesignSet::kBuiltin)) {
    const MechanismValidationRow row = validate_mechanism(design, o);
    const MechanismAnalysis& a = row.analysis;
    const MechanismDesign& d = a.design;
    SCOPED_TRACE(d.name);
    ASSERT_EQ(row.values.size(), columns.size());
    EXPECT_EQ(d.stroke, design.stroke);
    EXPECT_EQ(static_cast<int>(a.prbm.displacement.size()), o.points);
    EXPECT_EQ(row.exact, a.has_exact && a.exact.converged());
    const bool checked_ok = row.chain_check && row.chain_check->converged();
    const ValidationStatus expected = !a.has_exact ? ValidationStatus::kPrbmOnly
                                      : !row.exact ? ValidationStatus::kExactNotConverged
                                      : row.chain_check && !checked_ok
                                          ? ValidationStatus::kChainCheckNotConverged
                                          : ValidationStatus::kExactConverged;
    EXPECT_EQ(row.status, expected);
    EXPECT_EQ(row.chain_check.has_value(), row.exact);
    EXPECT_EQ(row.values[0], a.prbm.percent_constant_force);
    EXPECT_EQ(row.values[5], a.safety_factor);
    EXPECT_EQ(row.values[7], d.stroke);
    EXPECT_EQ(row.values[4], a.prbm_validity_limit ? *a.prbm_validity_limit / d.stroke : -1.0);
    EXPECT_EQ(row.values[10], a.stability_prbm.force_control.unstable_points);
    if (row.exact) {
      EXPECT_EQ(row.values[1], a.percent_constant_force_exact);
      EXPECT_EQ(row.values[2], a.max_force_error);
      EXPECT_EQ(row.values[3], a.max_force_error_at / d.stroke);
      EXPECT_EQ(row.values[8], a.stability_exact.displacement_control.unstable_points);
      EXPECT_EQ(row.values[9], a.stability_exact.force_control.unstable_points);
    } else {
      for (int k : {1, 2, 3, 8, 9}) EXPECT_TRUE(std::isnan(row.values[k])) << columns[k].name;
    }
    if (checked_ok) {
      // The chain algorithm against the shooting solution: two methods, one mechanism.
      EXPECT_EQ(row.values[6], row.chain_check->tip_error / d.r2);
      EXPECT_LT(row.values[6], 1e-4);
      ++checked;
    } else {
      EXPECT_TRUE(std::isnan(row.values[6]));
    }
    // The exact stroke the mechanism cannot hold with its slider held is named in a warning.
    const bool unstable =
        a.has_exact_stability && a.stability_exact.displacement_control.unstable_points > 0;
    bool named = false;
    for (const std::string& w : row.warnings) {
      EXPECT_EQ(w.rfind(d.name + ": ", 0), 0u) << w;
      named = named || w.find("unstable with the slider held") != std::string::npos;
    }
    EXPECT_EQ(named, unstable);
  }
  EXPECT_GE(checked, 15);  // the chain check converges for most built-in designs
}

TEST(MechanismValidation, ToggleFractionSetsTheStrokeOfAnEqualLinkDesign) {
  const MechanismDesign d = find_builtin_mechanism("1B-psp");
  ASSERT_EQ(d.r2, d.r3);  // R = 1: the toggle position is crank and coupler folded, r2 + r3
  MechanismValidationOptions o;
  o.points = 10;
  o.toggle_fraction = 0.5;
  const MechanismValidationRow row = validate_mechanism(d, o);
  EXPECT_NEAR(row.values[7], 0.5 * (d.r2 + d.r3), 1e-15);
  EXPECT_EQ(row.analysis.design.stroke, row.values[7]);
}

TEST(MechanismValidation, OptionsOutsideTheirRangesAreRefusedByName) {
  const MechanismDesign d = find_builtin_mechanism("1A-spp");
  MechanismValidationOptions o;
  o.points = 1;
  EXPECT_THROW(validate_mechanism(d, o), InvalidInput);
  o.points = 10;
  o.toggle_fraction = 1.0;
  try {
    validate_mechanism(d, o);
    FAIL() << "no exception";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("toggle_fraction"), std::string::npos) << e.what();
  }
  o.toggle_fraction.reset();
  o.chain_check_elements = 0;
  EXPECT_THROW(validate_mechanism(d, o), InvalidInput);
}

}  // namespace
}  // namespace flexure::mechanism
