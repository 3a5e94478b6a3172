// What is checked against what (`flexure dynamics` and `flexure mechanism analyze` on one design,
// 2B-lplm, through the built binary; docs/mechanisms.md "Half or whole mechanism"):
//  - the same quantity by the same rule: dynamics' static nominal force (mean over Delta x =
//    k stroke/1000) with --force-of half --spring-rule pure-bending against analyze's PRBM mean
//    force over --points 1000 with its defaults (one half, pure bending). Two implementations of
//    the virtual-work force (the Lagrangian model's V'/(-r1'), docs/dynamics.md D6; the assembler's
//    Weight eq. 2.14 with the link statics) agree to 1e-10;
//  - the defaults differ by exactly the two documented factors: dynamics (whole, Table 5's printed
//    springs) = 2 x analyze --spring-rule table5 (one half, Table 5's rule from the strips) x
//    k_printed/k_rule (the PRBM force is linear in the springs, and both strips of 2B-lplm have
//    the same k);
//  - force_of and spring_rule say so in JSON, text and HDF5 of both commands, and --force-of
//    whole/half rescales every force by exactly 2 (the per-half dynamics model itself is checked
//    in tests/mechanisms/dynamics_inverse_test.cpp).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/cli_test_support.h"

namespace flexure {
namespace {

using nlohmann::json;
using test::run_flexure;
using test::ScratchDir;

// Two evaluations of the same closed form along different code paths.
constexpr double kSameForceTolerance = 1e-10;
// A factor of exactly 2 (or 1/2) applied to a printed 17-digit number.
constexpr double kFactorTolerance = 1e-15;

json run_json(const std::string& args) {
  const test::CommandResult r = run_flexure(args + " --json");
  EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
  return json::parse(r.out.empty() ? "{}" : r.out);
}

// `dynamics` at zero frequency and without inertia: the quasi-static force only.
const std::string kStaticDynamics =
    "dynamics --mechanism 2B-lplm --omega 0:0:1 --zero-inertia --history 0";

TEST(ForceOfCli, SameQuantityAndSpringRuleGiveTheSameStaticForce) {
  const json dyn = run_json(kStaticDynamics + " --force-of half --spring-rule pure-bending");
  const json ana = run_json("mechanism analyze 2B-lplm --method prbm --points 1000");
  EXPECT_EQ(dyn["force_of"], "one half");
  EXPECT_EQ(ana["force_of"], "one half");
  EXPECT_EQ(dyn["spring_rule"], "pure-bending");
  EXPECT_EQ(ana["spring_rule"], "pure-bending");
  ASSERT_EQ(dyn["static_nominal_force_points"], 1000);
  // Same springs: dynamics takes them from the strips of analyze's design.
  for (int p : {0, 2}) {
    EXPECT_DOUBLE_EQ(dyn["spring_constants"][p].get<double>(),
                     ana["design"]["joints"][p]["spring_constant"].get<double>());
  }
  EXPECT_EQ(dyn["spring_constants"][1], 0.0);  // the middle pin
  // Same stroke, 40 % of r2 + r3.
  EXPECT_NEAR(dyn["stroke"].get<double>(), ana["design"]["stroke"].get<double>(), 1e-15);
  const double F_dyn = dyn["static_nominal_force"].get<double>();
  const double F_ana = ana["mean_force_prbm"].get<double>();
  EXPECT_NEAR(F_dyn, F_ana, kSameForceTolerance * F_ana);
  EXPECT_NEAR(F_ana, 40.1348, 1e-4);  // docs/mechanisms.md "Half or whole mechanism"

  // Whole mechanism both ways: twice that.
  const json dyn2 = run_json(kStaticDynamics + " --spring-rule pure-bending");
  const json ana2 =
      run_json("mechanism analyze 2B-lplm --method prbm --points 1000 --force-of whole");
  EXPECT_EQ(dyn2["force_of"], "whole symmetric mechanism");
  EXPECT_EQ(ana2["force_of"], "whole symmetric mechanism");
  EXPECT_NEAR(dyn2["static_nominal_force"].get<double>(), 2.0 * F_dyn, kFactorTolerance * F_dyn);
  EXPECT_NEAR(ana2["mean_force_prbm"].get<double>(), 2.0 * F_ana, 2 * kFactorTolerance * F_ana);
  ASSERT_EQ(ana2["force_prbm"].size(), 1000u);
  for (std::size_t k = 0; k < 1000; k += 111) {
    const double half = ana["force_prbm"][k].get<double>();
    EXPECT_NEAR(ana2["force_prbm"][k].get<double>(), 2.0 * half, kFactorTolerance * half);
  }
}

TEST(ForceOfCli, DefaultsDifferByTwoHalvesAndTheSpringRule) {
  // The numbers: dynamics 108.5 N, analyze 40.2 N PRBM / 42.6 N exact (50 points).
  const json dyn = run_json(kStaticDynamics);
  EXPECT_EQ(dyn["force_of"], "whole symmetric mechanism");
  EXPECT_EQ(dyn["spring_rule"], "table5-printed");
  EXPECT_NEAR(dyn["static_nominal_force"].get<double>(), 108.5105, 1e-4);
  const json ana = run_json("mechanism analyze 2B-lplm --method prbm");
  EXPECT_EQ(ana["force_of"], "one half");
  EXPECT_EQ(ana["spring_rule"], "pure-bending");
  EXPECT_NEAR(ana["mean_force_prbm"].get<double>(), 40.191, 1e-3);

  // Decomposition: 2 halves x Table 5's rule x the printed rounding of k.
  const json t5 = run_json(
      "mechanism analyze 2B-lplm --method prbm --points 1000 --spring-rule "
      "table5");
  const double k_rule = t5["design"]["joints"][0]["spring_constant"].get<double>();
  const double k_printed = dyn["spring_constants"][0].get<double>();
  EXPECT_DOUBLE_EQ(k_printed, 3.4322);         // Table 5 as printed
  EXPECT_NEAR(k_rule / k_printed, 1.0, 5e-4);  // the printed 4 digits
  EXPECT_NEAR(dyn["static_nominal_force"].get<double>(),
              2.0 * t5["mean_force_prbm"].get<double>() * k_printed / k_rule,
              kSameForceTolerance * 108.5);
}

TEST(ForceOfCli, DynamicsForceOfHalfHalvesEveryForceWithInertia) {
  const std::string args = "dynamics --mechanism 2B-lplm --omega 0:40:3 --history 31.416";
  const json whole = run_json(args);
  const json half = run_json(args + " --force-of half");
  EXPECT_EQ(half["force_of"], "one half");
  for (const char* key :
       {"mean_force", "median_force", "min_force", "max_force", "peak_to_peak_force"}) {
    for (std::size_t i = 0; i < 3; ++i) {
      const double w = whole[key][i].get<double>();
      EXPECT_NEAR(half[key][i].get<double>(), 0.5 * w, kFactorTolerance * w) << key;
    }
  }
  EXPECT_EQ(half["percent_constant_force"], whole["percent_constant_force"]);
  for (const char* key : {"static_nominal_force", "paper_nominal_force"}) {
    const double w = whole[key].get<double>();
    EXPECT_NEAR(half[key].get<double>(), 0.5 * w, kFactorTolerance * w) << key;
  }
  const double w = whole["history"][0]["force"][5].get<double>();
  EXPECT_NEAR(half["history"][0]["force"][5].get<double>(), 0.5 * w, kFactorTolerance * w);
}

TEST(ForceOfCli, TextAndHdf5SayWhatTheForceIsOf) {
  ScratchDir dir;
  const test::CommandResult dyn = run_flexure(
      "dynamics --mechanism 2B-lplm --omega 0:0:1 --history 0 --force-of half --out d.h5",
      dir.path());
  ASSERT_EQ(dyn.exit_code, 0) << dyn.err;
  EXPECT_NE(dyn.out.find("force of: one half;"), std::string::npos) << dyn.out;
  EXPECT_NE(dyn.out.find("table5-printed"), std::string::npos) << dyn.out;
  const test::CommandResult ana = run_flexure(
      "mechanism analyze 2B-lplm --method prbm --force-of whole --out a.h5", dir.path());
  ASSERT_EQ(ana.exit_code, 0) << ana.err;
  EXPECT_NE(ana.out.find("mean force (whole symmetric mechanism, spring rule pure-bending)"),
            std::string::npos)
      << ana.out;
  hid_t file = test::open_read_only(dir / "d.h5");
  ASSERT_GE(file, 0);
  EXPECT_EQ(test::read_string_attribute(file, "/", "force_of"), "one half");
  EXPECT_EQ(test::read_string_attribute(file, "/", "spring_rule"), "table5-printed");
  H5Fclose(file);
  file = test::open_read_only(dir / "a.h5");
  ASSERT_GE(file, 0);
  EXPECT_EQ(test::read_string_attribute(file, "/", "force_of"), "whole symmetric mechanism");
  EXPECT_EQ(test::read_string_attribute(file, "/", "spring_rule"), "pure-bending");
  H5Fclose(file);
}

TEST(ForceOfCli, UnknownForceOfIsRefused) {
  for (const std::string args : {"dynamics --mechanism 2B-lplm --omega 0:1:2 --force-of both",
                                 "mechanism analyze 2B-lplm --force-of both"}) {
    const test::CommandResult r = run_flexure(args);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_NE(r.err.find("--force-of 'both' is unknown"), std::string::npos) << r.err;
  }
}

}  // namespace
}  // namespace flexure
