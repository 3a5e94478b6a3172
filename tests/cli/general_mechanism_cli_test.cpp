// `flexure mechanism analyze FILE.toml` for the general form (docs/mechanisms.md "General
// mechanisms"): the shipped bistable switch through the tool, its JSON keys, and the refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <regex>
#include <set>
#include <sstream>

#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
const std::string kSwitch =
    std::string("'") + FLEXURE_SOURCE_DIR + "/docs/examples/howell_bistable_switch.toml'";

TEST(GeneralMechanismCli, BistableSwitchJsonReportsTable11_2Equilibria) {
  const CommandResult r = run_flexure("mechanism analyze " + kSwitch + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["form"], "general");
  EXPECT_EQ(j["model"], "prbm");
  EXPECT_EQ(j["input_unit"], "rad");
  EXPECT_EQ(j["input_load_unit"], "N m");
  ASSERT_EQ(j["input"].size(), 77u);
  ASSERT_EQ(j["input_load"].size(), 77u);
  ASSERT_EQ(j["stability"]["force_control"].size(), 77u);
  ASSERT_EQ(j["equilibria"].size(), 3u);
  // Howell Table 11.2: 0, 18.7, 32 deg (stable, unstable, stable).
  EXPECT_NEAR(j["equilibria"][0]["input"].get<double>() / kDeg, 0.0, 0.5);
  EXPECT_NEAR(j["equilibria"][1]["input"].get<double>() / kDeg, 18.7, 0.05);
  EXPECT_NEAR(j["equilibria"][2]["input"].get<double>() / kDeg, 32.0, 0.5);
  EXPECT_EQ(j["equilibria"][0]["stability"], "stable");
  EXPECT_EQ(j["equilibria"][1]["stability"], "unstable");
  EXPECT_EQ(j["equilibria"][2]["stability"], "stable");
  EXPECT_EQ(j["models"]["prbm"]["input"], j["input"]);
  // The flexure is thicker than half its length: said once on stderr.
  EXPECT_NE(r.err.find("warning: flexure 'pivot4': thickness/length = 0.547619"),
            std::string::npos);
}

TEST(GeneralMechanismCli, InputRangeFromTheCommandLine) {
  const CommandResult r =
      run_flexure("mechanism analyze " + kSwitch + " --input '10deg:20deg:3' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["input"].size(), 3u);
  EXPECT_NEAR(j["input"][0].get<double>(), 10 * kDeg, 1e-12);
  EXPECT_NEAR(j["input"][2].get<double>(), 20 * kDeg, 1e-12);
  ASSERT_EQ(j["equilibria"].size(), 1u);  // only the toggle lies in 10..20 deg
}

// Driven past the end of its travel (35 deg; the coupler and rocker align at 33.376 deg in the
// rigid four-bar), the exact model does not answer: exit 3, and the message says where the input
// turned back so that the range can end before it.
TEST(GeneralMechanismCli, InputPastTheTravelNamesTheLimit) {
  const CommandResult r =
      run_flexure("mechanism analyze " + kSwitch + " --model exact --input -5deg:35deg:21 --json");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  const std::string key = "turned back at a limit point at input ";
  const std::size_t at = r.err.find(key);
  ASSERT_NE(at, std::string::npos) << r.err;
  const std::size_t deg = r.err.find("rad (", at);
  ASSERT_NE(deg, std::string::npos) << r.err;
  const double travel = std::stod(r.err.substr(deg + 5));
  const double r1 = 36.1, r2 = 20.0, r3 = 10.0, r4 = 12.3;  // mm, Howell Table 11.1
  const double rigid = std::acos((r2 * r2 + r1 * r1 - (r3 + r4) * (r3 + r4)) / (2 * r1 * r2)) *
                       180 / std::numbers::pi;
  EXPECT_NEAR(travel, rigid, 0.02) << r.err;
  // The PRBM's rigid linkage creeps towards the dead point while the torque grows without bound:
  // its message names how far it came.
  const CommandResult p =
      run_flexure("mechanism analyze " + kSwitch + " --model prbm --input -5deg:35deg:21 --json");
  EXPECT_EQ(p.exit_code, 3) << p.err;
  const std::size_t came = p.err.find("came no further than input ");
  ASSERT_NE(came, std::string::npos) << p.err;
  const std::size_t pdeg = p.err.find("rad (", came);
  ASSERT_NE(pdeg, std::string::npos) << p.err;
  EXPECT_NEAR(std::stod(p.err.substr(pdeg + 5)), rigid, 0.02) << p.err;
  EXPECT_NE(p.err.find(" N m (the end of the linkage's travel"), std::string::npos) << p.err;
}

TEST(GeneralMechanismCli, ThePrbmOfAnExtensibleBeamBetweenFixedPointsNamesTheStretch) {
  // The inclined beam between a clamp and a guided shuttle moves only by stretching: its PRB
  // linkage (rigid links) has no freedom, and the message says why and what solves it.
  const std::string beam =
      std::string("'") + FLEXURE_SOURCE_DIR + "/docs/examples/inclined_bistable_beam.toml'";
  const CommandResult r = run_flexure("mechanism analyze " + beam + " --model prbm --json");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("flexure 'beam' is extensible"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--model exact"), std::string::npos) << r.err;
  EXPECT_EQ(run_flexure("mechanism analyze " + beam + " --model exact --json").exit_code, 0);
}

TEST(GeneralMechanismCli, Refusals) {
  expect_refused("mechanism analyze " + kSwitch + " --prbm-only", {"--prbm-only", "general"});
  expect_refused("mechanism analyze " + kSwitch + " --input '0deg:10mm:3'", {"--input STOP"});
  expect_refused("mechanism analyze 1A-lpp --model prbm", {"--model applies to general"});
  // The constant-force designs' material and fatigue options are refused, not ignored.
  expect_refused("mechanism analyze " + kSwitch + " --material polypropylene",
                 {"--material", "general"});
  expect_refused("mechanism analyze " + kSwitch + " --Kf 1.2", {"--Kf", "general"});
  const CommandResult r =
      run_flexure("mechanism analyze " + kSwitch + " --model exact --input '0Nm:1Nm:3' --json");
  EXPECT_EQ(r.exit_code, 2);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["exit_code"], 2);
}

// Every option of `mechanism analyze` other than those a general file takes is refused by name
// (exit 2), read from the command's own help so that an option added later is covered too.
TEST(GeneralMechanismCli, EveryConstantForceOptionIsRefusedByName) {
  const CommandResult help = run_flexure("mechanism analyze --help");
  ASSERT_EQ(help.exit_code, 0) << help.err;
  const std::set<std::string> general = {"--help",
                                         "--points",
                                         "--json",
                                         "--model",
                                         "--input",
                                         "--out",
                                         "--csv",
                                         "--flexure-model",
                                         "--flexure-tol",
                                         "--check-flexures",
                                         "--stable"};
  // A valid value for the options whose values are checked before the form is known.
  const std::map<std::string, std::string> value = {{"--method", "prbm"},
                                                    {"--spring-rule", "table2"},
                                                    {"--force-of", "whole"},
                                                    {"--surface-finish", "ground"},
                                                    {"--material", "polypropylene"},
                                                    {"--ultimate-strength", "900MPa"},
                                                    {"--endurance-limit", "400MPa"},
                                                    {"--reliability", "0.9"},
                                                    {"--fatigue-factor", "0.9"},
                                                    {"--Kf", "1.2"},
                                                    {"--tol", "1e-3"},
                                                    {"--plate", "on"},
                                                    {"--nu", "0.3"}};
  const std::regex line(R"(^\s+(?:-\w,)?(--[A-Za-z-]+)( \S+)?)");
  std::istringstream in(help.out);
  std::string text;
  int checked = 0;
  while (std::getline(in, text)) {
    std::smatch m;
    if (!std::regex_search(text, m, line) || general.count(m[1]) > 0) continue;
    const std::string name = m[1];
    const bool takes_value = m[2].matched;
    const auto given = value.find(name);
    const std::string arg =
        name + (takes_value ? " " + (given != value.end() ? given->second : "1") : "");
    expect_refused("mechanism analyze " + kSwitch + " " + arg,
                   {name + " belongs to the constant-force designs"});
    ++checked;
  }
  // --prbm-only, --method, --tol, --spring-rule, --force-of, --material, --plate, --nu and the six
  // fatigue options today.
  EXPECT_GE(checked, 12);
}

// --stable (docs/mechanisms.md "Stable equilibria (--stable)"): the switch's crank path is stable
// held (nothing to do, exit 0); the inclined beam's exact path is unstable held between its
// bifurcations with no stable branch traced there (exit 3, JSON error naming where); a
// constant-force design in its general form refuses it (exit 2).
TEST(GeneralMechanismCli, StableFlag) {
  const CommandResult r =
      run_flexure("mechanism analyze " + kSwitch + " --model both --stable --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["stable"], true);
  EXPECT_NE(j["stable_search"].get<std::string>().find("prbm: not needed"), std::string::npos)
      << j["stable_search"];
  EXPECT_EQ(j["input"].size(), 77u);
  const CommandResult plain = run_flexure("mechanism analyze " + kSwitch + " --json");
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_TRUE(nlohmann::json::parse(plain.out)["stable_search"].is_null());
  const std::string beam =
      std::string("'") + FLEXURE_SOURCE_DIR + "/docs/examples/inclined_bistable_beam.toml'";
  const CommandResult b =
      run_flexure("mechanism analyze " + beam + " --model exact --stable --json");
  EXPECT_EQ(b.exit_code, 3) << b.err;
  const auto e = nlohmann::json::parse(b.out);
  EXPECT_EQ(e["exit_code"], 3);
  EXPECT_NE(e["error"].get<std::string>().find("no stable equilibrium found under displacement "
                                               "control at 64 of 121"),
            std::string::npos)
      << e["error"];
  expect_refused("mechanism analyze 3A-sss --model mixed --stable", {"--stable"});
}

TEST(GeneralMechanismCli, BothModels) {
  const CommandResult r =
      run_flexure("mechanism analyze " + kSwitch + " --model both --input '-5deg:33deg:39' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["model"], "both");
  EXPECT_EQ(j["input"], j["models"]["prbm"]["input"]);
  const auto& exact = j["models"]["exact"];
  ASSERT_EQ(exact["input_load"].size(), 39u);
  ASSERT_EQ(exact["equilibria"].size(), 3u);
  // The stable positions are where the flexure is unstressed: the same for both models.
  for (int i : {0, 2}) {
    EXPECT_NEAR(exact["equilibria"][i]["input"].get<double>(),
                j["models"]["prbm"]["equilibria"][i]["input"].get<double>(),
                1e-8);
  }
  // The exact model's own verdicts (exact_stability.h): the PRBM's classification of the
  // equilibria (Table 11.2), and its verdicts at the points where both models' torques slope the
  // same way (before 8.6 deg both rise: stable under a dead torque).
  for (int i : {0, 1, 2}) {
    EXPECT_EQ(exact["equilibria"][i]["stability"],
              j["models"]["prbm"]["equilibria"][i]["stability"]);
  }
  EXPECT_EQ(exact["equilibria"][1]["stability"], "unstable");
  EXPECT_EQ(exact["equilibria"][1]["index"], 1);
  EXPECT_EQ(exact["stability"]["force_control"][0], "stable");
  EXPECT_EQ(exact["stability"]["displacement_control"][20], "stable");
}

// --model mixed on a built-in design (its general form): every flexure exact gives the catalogue's
// exact force; auto within its tolerance; each flexure's report (docs/mechanisms.md "A model per
// flexure").
TEST(GeneralMechanismCli, MixedModelOnABuiltInDesign) {
  const CommandResult catalogue =
      run_flexure("mechanism analyze 3A-sss --method exact --points 10 --json");
  ASSERT_EQ(catalogue.exit_code, 0) << catalogue.err;
  const auto c = nlohmann::json::parse(catalogue.out);
  std::vector<double> exact = c["force_exact"].get<std::vector<double>>();
  double largest = 0.0;
  for (double f : exact) largest = std::max(largest, std::fabs(f));

  const CommandResult all_exact = run_flexure(
      "mechanism analyze 3A-sss --model mixed --flexure-model exact --points 10 --json");
  ASSERT_EQ(all_exact.exit_code, 0) << all_exact.err;
  const auto e = nlohmann::json::parse(all_exact.out);
  ASSERT_EQ(e["force"].size(), 10u);
  for (std::size_t i = 0; i < exact.size(); ++i) {
    EXPECT_NEAR(e["force"][i].get<double>(), exact[i], 1e-8 * largest) << i;
    EXPECT_NEAR(e["displacement"][i].get<double>(),
                c["displacement"][i].get<double>(),
                1e-15 + 1e-12 * c["displacement"][i].get<double>());
  }
  ASSERT_EQ(e["flexure_models"].size(), 3u);
  EXPECT_EQ(e["flexure_models"][0]["model"], "exact");
  EXPECT_EQ(e["flexure_models"][0]["expected_error_per_length"], 0.0);

  const CommandResult automatic = run_flexure(
      "mechanism analyze 3A-sss --model mixed --flexure-model auto --flexure-tol 1e-3 "
      "--check-flexures --points 10 --json");
  ASSERT_EQ(automatic.exit_code, 0) << automatic.err;
  const auto a = nlohmann::json::parse(automatic.out);
  for (std::size_t i = 0; i < exact.size(); ++i) {
    EXPECT_NEAR(a["force"][i].get<double>(), exact[i], 1e-3 * largest) << i;
  }
  int cheaper = 0;
  for (const auto& f : a["flexure_models"]) {
    EXPECT_EQ(f["requested"], "auto");
    EXPECT_EQ(f["tolerance"], 1e-3);
    EXPECT_FALSE(f["method_reason"].get<std::string>().empty());
    EXPECT_LE(f["expected_error_per_length"].get<double>(), 1e-3);
    // Exact flexures: 0 expected, 1e-13 measured (the shooting integrator against the elliptic
    // solution).
    EXPECT_LE(f["measured_error_per_length"].get<double>(),
              f["expected_error_per_length"].get<double>() + 1e-9);
    if (f["model"] != "exact") ++cheaper;
  }
  EXPECT_GE(cheaper, 1);  // measured: f3 takes the CBCM at 1e-3
}

TEST(GeneralMechanismCli, MixedModelKeysAndRefusals) {
  ScratchDir dir;
  std::string text =
      read_text(std::string(FLEXURE_SOURCE_DIR) + "/docs/examples/howell_bistable_switch.toml");
  const std::string key = "prbm = \"small-length\"";
  const auto at = text.find(key);
  ASSERT_NE(at, std::string::npos);
  auto with = [&](const std::string& extra) {
    std::string t = text;
    t.insert(at + key.size(), "\n" + extra);
    const auto path = dir / "switch.toml";
    std::ofstream(path) << t;
    return "'" + path.string() + "'";
  };
  expect_refused("mechanism analyze " + with("model = \"auto\"") + " --model mixed",
                 {"switch.toml:", "needs a tolerance"});
  expect_refused(
      "mechanism analyze " + with("model = \"fem\"") + " --model mixed",
      {"switch.toml:", "not one of prbm, exact, linear, bcm, prbm3r, cbcm, chain, auto"});
  expect_refused("mechanism analyze " + with("model = \"bcm\"\nelements = 4") + " --model mixed",
                 {"elements belongs to model = \"cbcm\""});
  const CommandResult r =
      run_flexure("mechanism analyze " + with("model = \"cbcm\"\nelements = 12") +
                  " --model mixed --input '-5deg:33deg:39' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["flexure_models"][0]["model"], "cbcm");
  EXPECT_EQ(j["flexure_models"][0]["elements"], 12);
  // A CBCM of 12 elements is not on the map: no expected error, said so.
  EXPECT_TRUE(j["flexure_models"][0]["expected_error_per_length"].is_null());
  // The stable positions are where the flexure is unstressed: those of the exact model.
  const CommandResult ex = run_flexure("mechanism analyze " + kSwitch +
                                       " --model exact --input '-5deg:33deg:39' --json");
  const auto x = nlohmann::json::parse(ex.out);
  ASSERT_EQ(j["equilibria"].size(), 3u);
  for (int i : {0, 2}) {
    EXPECT_NEAR(
        j["equilibria"][i]["input"].get<double>(), x["equilibria"][i]["input"].get<double>(), 1e-8);
  }
  // The chain algorithm per flexure: its default 100 elements, a bad count refused with the line.
  expect_refused("mechanism analyze " + with("model = \"chain\"\nelements = 0") + " --model mixed",
                 {"switch.toml:", "flexure", "elements must be a whole number in [1, 2000]"});
  const CommandResult chain = run_flexure("mechanism analyze " + kSwitch +
                                          " --model mixed --flexure-model chain "
                                          "--input '-5deg:33deg:39' --json");
  ASSERT_EQ(chain.exit_code, 0) << chain.err;
  const auto c = nlohmann::json::parse(chain.out);
  EXPECT_EQ(c["flexure_models"][0]["model"], "chain");
  EXPECT_EQ(c["flexure_models"][0]["elements"], 100);
  EXPECT_TRUE(c["flexure_models"][0]["expected_error_per_length"].is_null());
  // Its stable positions, where the flexure is unstressed, are the exact model's.
  ASSERT_EQ(c["equilibria"].size(), 3u);
  for (int i : {0, 2}) {
    EXPECT_NEAR(
        c["equilibria"][i]["input"].get<double>(), x["equilibria"][i]["input"].get<double>(), 1e-8);
  }
  expect_refused("mechanism analyze 3A-sss --model mixed --flexure-model f7=bcm",
                 {"f7", "f1, f2, f3"});
  expect_refused("mechanism analyze 3A-sss --model mixed --flexure-model auto", {"--flexure-tol"});
  expect_refused("mechanism analyze 3A-sss --flexure-model bcm", {"--model mixed"});
  expect_refused("mechanism analyze 3A-sss --model mixed --material polypropylene",
                 {"--material", "--model mixed"});
  // A long segment at pivot 2 (plp: link 2 a fixed-pinned beam pinned at the ground) has a
  // general form too (catalogue_general.h): every flexure exact gives the catalogue's exact force.
  const CommandResult plp =
      run_flexure("mechanism analyze 1B-plp --model mixed --flexure-model exact --points 5 --json");
  ASSERT_EQ(plp.exit_code, 0) << plp.err;
  const CommandResult plp_catalogue = run_flexure("mechanism analyze 1B-plp --points 5 --json");
  ASSERT_EQ(plp_catalogue.exit_code, 0) << plp_catalogue.err;
  const auto pj = nlohmann::json::parse(plp.out);
  const auto pc = nlohmann::json::parse(plp_catalogue.out);
  ASSERT_EQ(pj["force"].size(), 5u);
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_NEAR(pj["force"][k].get<double>(),
                pc["force_exact"][k].get<double>(),
                2e-9 * std::fabs(pc["force_exact"][k].get<double>()));
  }
}

// The inclined bistable beam example: an extensible flexure (TOML `extensible = true`) between the
// ground and a guided shuttle; the exact model crosses the straight position and the force changes
// sign twice, the last zero the beam path's second stable position 9.696183 mm
// (tests/mechanisms/general_exact_stability_test.cpp compares the numbers).
TEST(GeneralMechanismCli, InclinedBistableBeamExample) {
  const std::string file =
      std::string("'") + FLEXURE_SOURCE_DIR + "/docs/examples/inclined_bistable_beam.toml'";
  const CommandResult r = run_flexure("mechanism analyze " + file + " --model exact --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const std::vector<double> load = j["input_load"].get<std::vector<double>>();
  ASSERT_EQ(load.size(), 121u);
  int changes = 0;
  for (std::size_t i = 2; i < load.size(); ++i) changes += load[i] * load[i - 1] < 0.0 ? 1 : 0;
  EXPECT_EQ(changes, 2);
  EXPECT_NEAR(6.709203e-3 - j["equilibria"].back()["input"].get<double>(), 9.696183e-3, 1e-9);
  // Held at the shuttle, the unbuckled beam turns unstable where the antisymmetric mode branches
  // off: the beam path locates that bifurcation at 1.289366 mm of travel (docs/paths.md, another
  // method: the shooting path's test functions). The flexure is judged with its ends held by the
  // extensible second variation; the margin's zero, interpolated between grid points 0.1 mm
  // apart, lies within 2e-3 mm of it (measured 3.1e-4 mm).
  const std::vector<double> input = j["input"].get<std::vector<double>>();
  const std::vector<double> margin =
      j["stability"]["displacement_control_margin"].get<std::vector<double>>();
  const std::vector<std::string> kind =
      j["stability"]["displacement_control"].get<std::vector<std::string>>();
  double flip = -1.0;
  for (std::size_t i = 1; i < margin.size() && flip < 0.0; ++i) {
    if (margin[i - 1] > 0.0 && margin[i] <= 0.0) {
      const double t = margin[i - 1] / (margin[i - 1] - margin[i]);
      flip = input[0] - (input[i - 1] + t * (input[i] - input[i - 1]));
      EXPECT_EQ(kind[i - 1], "stable");
      EXPECT_EQ(kind[i], "unstable");
    }
  }
  EXPECT_NEAR(flip, 1.289366e-3, 2e-6);
}

// The same file with --model mixed --flexure-model cbcm (6 elements, extensible). The
// force zeros within the CBCM's measured error of the exact model's (6.068895 and 9.696183 mm;
// measured +5.6e-4 and +5.4e-4 mm, tests/mechanisms/general_cbcm_test.cpp), and the held
// shuttle's verdict turns unstable at the beam path's bifurcation 1.289366 mm (the margin's zero
// interpolated on the 0.1 mm grid: measured 3.2e-4 mm off, as the exact model's 3.1e-4).
TEST(GeneralMechanismCli, InclinedBistableBeamWithTheCbcm) {
  const std::string file =
      std::string("'") + FLEXURE_SOURCE_DIR + "/docs/examples/inclined_bistable_beam.toml'";
  const CommandResult r =
      run_flexure("mechanism analyze " + file + " --model mixed --flexure-model cbcm --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["flexure_models"][0]["model"], "cbcm");
  EXPECT_EQ(j["flexure_models"][0]["elements"], 6);
  ASSERT_EQ(j["equilibria"].size(), 3u);
  const double y0 = 6.709203e-3;
  EXPECT_NEAR(y0 - j["equilibria"][1]["input"].get<double>(), 6.068895e-3, 6e-7);
  EXPECT_NEAR(y0 - j["equilibria"][2]["input"].get<double>(), 9.696183e-3, 6e-7);
  EXPECT_EQ(j["equilibria"][1]["stability"], "unstable");
  EXPECT_EQ(j["equilibria"][2]["stability"], "stable");
  const std::vector<double> input = j["input"].get<std::vector<double>>();
  const std::vector<double> margin =
      j["stability"]["displacement_control_margin"].get<std::vector<double>>();
  double flip = -1.0;
  for (std::size_t i = 1; i < margin.size() && flip < 0.0; ++i) {
    if (margin[i - 1] > 0.0 && margin[i] <= 0.0) {
      const double t = margin[i - 1] / (margin[i - 1] - margin[i]);
      flip = input[0] - (input[i - 1] + t * (input[i] - input[i - 1]));
    }
  }
  EXPECT_NEAR(flip, 1.289366e-3, 2e-6);
}

}  // namespace
}  // namespace flexure::test
