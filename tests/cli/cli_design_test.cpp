// `flexure design cfm` (docs/cli.md, docs/design.md): the JSON contract, Table 2.1's class 1A row
// through the tool, and bad input. The constraints of every answer are judged here from their
// definitions (docs/design.md) on the design's reported R, Xi', C, D_equal and D_min with the
// bounds the test asked for, not by the tool's own "satisfied" verdict.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

using nlohmann::json;

json run_json(const std::string& args) {
  const CommandResult r = run_flexure(args + " --json");
  EXPECT_EQ(r.exit_code, 0) << args << "\nstderr: " << r.err;
  return json::parse(r.out);
}

// Feasibility slack, as the optimiser's (a design on its bound is met).
constexpr double kSlack = 1e-9;

struct Rules {
  double pcf_min = 0.0;                            // Xi' >= this (0: none)
  std::string orientation;                         // thesis flags I, O, o
  double I_D_min_max = 1.0;                        // I: D_min <= 1
  double C_min = 1.0;                              // O, o: C >= 1
  double O_D_equal_lo = 0.5, O_D_equal_hi = 2.0;   // O: 0.5 <= D_equal <= 2
  double o_D_equal_lo = 0.1, o_D_equal_hi = 10.0;  // o: 0.1 <= D_equal <= 10
};

// The answer `j` meets `rules`: the toggle (eq. 2.16: with q = (1 - d/100)^2 the stroke d is
// reached before the toggle position for R in [(1 - q)/(1 + q), (1 + q)/(1 - q)]), Xi' (eq. 6.8)
// and the orientation rules (Table 5.4) at every flexure (a pin has no ratios: null). The tool's
// "satisfied" must agree.
void expect_rules_met(const json& j, const Rules& rules) {
  const double d = j["stroke_percent"].get<double>(), R = j["R"].get<double>();
  const double q = (1.0 - d / 100.0) * (1.0 - d / 100.0);
  EXPECT_GE(R, (1.0 - q) / (1.0 + q) - kSlack) << "toggle";
  EXPECT_LE(R, (1.0 + q) / (1.0 - q) + kSlack) << "toggle";
  if (rules.pcf_min > 0.0) {
    EXPECT_GE(j["percent_constant_force"].get<double>(), rules.pcf_min - kSlack);
  }
  int flexures = 0;
  for (int i = 0; i < 3; ++i) {
    if (j["C"][i].is_null()) continue;
    ++flexures;
    const double C = j["C"][i].get<double>(), De = j["D_equal"][i].get<double>();
    const double Dm = j["D_min"][i].get<double>();
    const std::string pivot = "pivot " + std::to_string(i + 1);
    for (char flag : rules.orientation) {
      if (flag == 'I') EXPECT_LE(Dm, rules.I_D_min_max + kSlack) << pivot << " I: D_min";
      if (flag == 'O' || flag == 'o') EXPECT_GE(C, rules.C_min - kSlack) << pivot << ": C";
      if (flag == 'O') {
        EXPECT_GE(De, rules.O_D_equal_lo - kSlack) << pivot << " O: D_equal";
        EXPECT_LE(De, rules.O_D_equal_hi + kSlack) << pivot << " O: D_equal";
      }
      if (flag == 'o') {
        EXPECT_GE(De, rules.o_D_equal_lo - kSlack) << pivot << " o: D_equal";
        EXPECT_LE(De, rules.o_D_equal_hi + kSlack) << pivot << " o: D_equal";
      }
    }
  }
  EXPECT_GE(flexures, 1);
  for (const json& c : j["constraints"]) EXPECT_TRUE(c["satisfied"].get<bool>()) << c.dump();
}

TEST(CliDesign, MinXiFindsTableTwoOnesClassOneARow) {
  const json j = run_json("design cfm --config lpp --d 40 --objective min-xi");
  // Table 2.1, 1A at 40 %: R = 0.8853, Xi = 1.0241 (the true minimum is 1.02369 at R = 0.8858).
  EXPECT_NEAR(j["R"].get<double>(), 0.8853, 1e-3);
  EXPECT_LE(j["Xi"].get<double>(), 1.0241 + 2e-4);
  EXPECT_EQ(j["subclass"], "lpp-b");
  EXPECT_EQ(j["objective"], "min-xi");
  EXPECT_TRUE(j["converged"].get<bool>());
  for (const char* key : {"K1",
                          "K2",
                          "Phi",
                          "Psi",
                          "percent_constant_force",
                          "stroke_percent",
                          "evaluations",
                          "constraints",
                          "objective_value",
                          "seed"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  expect_rules_met(j, Rules{});
}

TEST(CliDesign, ConstraintsAreReportedAndMet) {
  const json j =
      run_json("design cfm --config lps --d 16 --objective max-psi --pcf-min 95 --orientation I");
  ASSERT_GE(j["constraints"].size(), 5u);  // toggle, Xi', and D_min <= 1 at each pivot
  Rules rules;
  rules.pcf_min = 95.0;
  rules.orientation = "I";
  expect_rules_met(j, rules);
  // A design on its Xi' bound (sub-class lpp-a90's problem: max Psi trades constant force down
  // to the bound, Xi' = 90.00 against 99.7 at the max-Xi' optimum).
  const json on_bound = run_json("design cfm --config lpp --d 16 --objective max-psi --pcf-min 90");
  EXPECT_NEAR(on_bound["percent_constant_force"].get<double>(), 90.0, 0.01);
  expect_rules_met(on_bound, Rules{90.0, ""});
}

// A thesis sub-class whose printed point breaks its own rule, re-derived with that one limit
// loosened to the printed point's value (docs/errata.md: ssp-b90o has D_equal1 = 10.35 under 'o').
TEST(CliDesign, RuleLimitsLoosenOneBound) {
  const json j = run_json(
      "design cfm --config ssp --d 40 --objective max-psi --pcf-min 90 --orientation o "
      "--rule-limits 'o:D_equal<=10.351'");
  EXPECT_TRUE(j["converged"].get<bool>());
  EXPECT_GE(j["Psi_raw"].get<double>(), 0.0053413 * 0.995);  // printed point's Psi_raw 0.0053413
  Rules rules;
  rules.pcf_min = 90.0;
  rules.orientation = "o";
  rules.o_D_equal_hi = 10.351;
  expect_rules_met(j, rules);
  bool seen = false;
  for (const json& c : j["constraints"]) seen |= c["name"] == "pivot 1 o: D_equal <= 10.351";
  EXPECT_TRUE(seen);
  EXPECT_GT(j["seconds"].get<double>(), 0.0);
  EXPECT_GT(j["full_sampling_evaluations"].get<int>(), 0);
  EXPECT_LE(j["full_sampling_evaluations"].get<int>(), j["evaluations"].get<int>());
}

TEST(CliDesign, BadInputIsExitTwoWithAReason) {
  const struct {
    const char* args;
    const char* says;  // key words of the reason
  } cases[] = {
      {"design cfm --config lpp --d 16 --objective max-psi", "give --pcf-min"},
      {"design cfm --config lpp --d 16 --objective fastest", "objective 'fastest' is unknown"},
      {"design cfm --config xyz --d 16 --objective min-xi", "configuration 'xyz' is unknown"},
      {"design cfm --config lpp --d 100 --objective min-xi", "d = 100 % must lie in (0, 100)"},
      {"design cfm --config lpp --d 16 --objective min-xi --K1 1",
       "K1 is not a variable of configuration lpp"},
      {"design cfm --config lpp --d nan --objective min-xi", "--d (stroke, % of r2 + r3) = nan"},
      {"design cfm --config ssp --d 16 --objective max-pcf --rule-limits 'C>=1'",
       "--rule-limits item 'C>=1'"},
      {"design cfm --config ssp --d 16 --objective max-pcf --rule-limits 'O:C>=x'",
       "'O:C>=x': the value is not a number"},
      {"design cfm --config ssp --d 16 --objective max-pcf --coarse-stride 0",
       "coarse_stride = 0 must be >= 1"},
  };
  for (const auto& c : cases) {
    const CommandResult r = run_flexure(std::string(c.args) + " --json");
    EXPECT_EQ(r.exit_code, 2) << c.args << ": " << r.err;
    const json e = json::parse(r.out);
    EXPECT_EQ(e["exit_code"], 2) << c.args;
    EXPECT_NE(e["error"].get<std::string>().find(c.says), std::string::npos)
        << c.args << ": " << e["error"];
  }
}

}  // namespace
}  // namespace flexure::test
