// What is checked against what: the per-configuration PRBM error table behind
// `flexure mechanism analyze --method auto` against freshly computed PRBM-vs-exact strokes of the
// built-in designs (the exact model is the independent reference); the choice of auto at loose and
// tight tolerances; the CLI keys `method` and `method_reason`.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/solver/common/status.h"
#include "tests/support/cli_test_support.h"

namespace flexure::mechanism {
namespace {

TEST(MechanismMethod, MeasuredErrorTableMatchesTheExactModel) {
  // The table was measured at 50 points and rounded to 1e-4; a 50-point stroke reproduces it.
  for (const MechanismDesign& d : builtin_mechanisms()) {
    AnalysisOptions o;
    o.points = 50;
    o.exact = true;
    const MechanismAnalysis a = analyze_mechanism(d, o);
    ASSERT_TRUE(a.has_exact && a.exact.converged()) << d.name;
    EXPECT_NEAR(a.max_force_error, measured_prbm_force_error(d), 5.1e-5) << d.name;
  }
}

TEST(MechanismMethod, AutoUsesThePrbmOnlyWhenItsErrorFitsTheTolerance) {
  const MechanismDesign spp = find_builtin_mechanism("1A-spp");  // measured 0.70 %
  EXPECT_EQ(choose_mechanism_method(spp, MechanismMethod::kAuto, 0.02).method,
            MechanismMethod::kPrbm);
  EXPECT_EQ(choose_mechanism_method(spp, MechanismMethod::kAuto, 0.005).method,
            MechanismMethod::kExact);
  EXPECT_EQ(choose_mechanism_method(spp, MechanismMethod::kAuto, 1e-6).method,
            MechanismMethod::kExact);
  const MechanismDesign plp = find_builtin_mechanism("1B-plp");  // measured 13.8 %
  EXPECT_EQ(choose_mechanism_method(plp, MechanismMethod::kAuto, 0.1).method,
            MechanismMethod::kExact);
  EXPECT_EQ(choose_mechanism_method(plp, MechanismMethod::kPrbm, 1e-6).method,
            MechanismMethod::kPrbm);
  EXPECT_THROW(choose_mechanism_method(plp, MechanismMethod::kAuto, 0.0), InvalidInput);
}

TEST(MechanismMethod, NamesRoundTripAndAnUnknownNameListsTheAllowedOnes) {
  for (MechanismMethod m :
       {MechanismMethod::kAuto, MechanismMethod::kPrbm, MechanismMethod::kExact}) {
    EXPECT_EQ(mechanism_method_from_string(to_string(m)), m);
  }
  try {
    mechanism_method_from_string("elliptic");
    ADD_FAILURE() << "no exception";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("auto, prbm, exact"), std::string::npos) << e.what();
  }
}

TEST(MechanismMethod, CliReportsTheChoice) {
  using nlohmann::json;
  const test::CommandResult loose =
      test::run_flexure("mechanism analyze 1A-spp --points 10 --tol 0.02 --json");
  ASSERT_EQ(loose.exit_code, 0) << loose.err;
  const json l = json::parse(loose.out);
  EXPECT_EQ(l["method"], "prbm");
  EXPECT_TRUE(l["force_exact"].is_null());
  EXPECT_NE(l["method_reason"].get<std::string>().find("0.007"), std::string::npos);
  const test::CommandResult tight =
      test::run_flexure("mechanism analyze 1A-spp --points 10 --json");
  ASSERT_EQ(tight.exit_code, 0) << tight.err;
  const json t = json::parse(tight.out);
  EXPECT_EQ(t["method"], "exact");
  EXPECT_EQ(t["force_exact"].size(), 10u);
  test::expect_refused("mechanism analyze 1A-spp --method newton", {"--method: newton not in"});
  test::expect_refused("mechanism analyze 1A-spp --tol -1",
                       {"tolerance must be finite and > 0 (got -1)"});
}

}  // namespace
}  // namespace flexure::mechanism
