// What is checked against what: the `flexure mechanism` commands as a user runs them -- the JSON
// keys and array lengths the issue specifies, exit codes for bad input (2), the toggle refusal,
// the yield warning, the HDF5 file (read back with the plain HDF5 C API), and that the JSON error
// equals the error recomputed from the printed force arrays.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

using nlohmann::json;

// "NAME = VALUE" as the refusal messages print a ratio ({:.4g}).
std::string fmt_ratio(const std::string& name, double value) {
  return name + " = " + fmt::format("{:.4g}", value);
}

std::string fmt_stroke(double stroke) {
  std::ostringstream out;
  out.precision(17);
  out << "\nstroke = " << stroke;
  return out.str();
}

TEST(MechanismCli, AnalyzeBuiltinJson) {
  const CommandResult r = run_flexure("mechanism analyze 1A-lpp --points 20 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  for (const std::string& key : mechanism_analyze_contract_keys()) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  ASSERT_EQ(j["displacement"].size(), 20u);
  ASSERT_EQ(j["force_exact"].size(), 20u);
  double worst = 0.0;
  for (int k = 0; k < 20; ++k) {
    const double fp = j["force_prbm"][k], fe = j["force_exact"][k];
    worst = std::max(worst, std::abs(fp - fe) / std::abs(fe));
  }
  EXPECT_NEAR(j["max_force_error"].get<double>(), worst, 1e-12);
}

TEST(MechanismCli, PrbmOnlyFlagSkipsTheExactCurve) {
  const CommandResult r = run_flexure("mechanism analyze 1B-plp --prbm-only --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_TRUE(j["force_exact"].is_null());
  EXPECT_TRUE(j["max_force_error"].is_null());
}

TEST(MechanismCli, BadInputExitsTwo) {
  expect_refused("mechanism analyze 9Z-abc", {"unknown mechanism '9Z-abc'", "1A-lpp"});
  expect_refused("mechanism analyze 1A-lpp --points 1", {"--points = 1 is outside"});
  // At the toggle position the R = 1 designs fold flat: refused up front (it ran for a minute
  // and failed with a NaN shooting guess).
  const CommandResult toggle = run_flexure("mechanism validate --toggle-fraction 1");
  EXPECT_EQ(toggle.exit_code, 2);
  EXPECT_NE(toggle.err.find("[1e-06, 1)"), std::string::npos) << toggle.err;
  // Options that were silently ignored beside others.
  expect_refused("mechanism validate --markdown --json --points 4", {"--markdown excludes --json"});
  expect_refused("mechanism validate --spring-rules --designs thesis",
                 {"--spring-rules excludes --designs"});
  // Contradictory method flags were resolved silently in favour of --prbm-only.
  const CommandResult both = run_flexure("mechanism analyze 1A-lpp --prbm-only --method exact");
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_NE(both.err.find("contradicts --method exact"), std::string::npos) << both.err;
  ScratchDir dir;
  std::ofstream(dir / "neg.toml") << "config = \"lpp\"\nr2 = 0.05\nr3 = 0.04\nstroke = 0.01\n"
                                     "[material]\nE = 1e9\nyield_strength = 3e7\n[ground]\n"
                                     "thickness = 1e-3\nwidth = -0.01\n";
  const CommandResult neg = run_flexure("mechanism analyze neg.toml", dir.path());
  EXPECT_EQ(neg.exit_code, 2);
  EXPECT_NE(neg.err.find("neg.toml:10: ground.width must be finite and > 0"), std::string::npos)
      << neg.err;
  std::ofstream(dir / "nan.toml") << "config = \"lpp\"\nr2 = nan\n";
  const CommandResult nan = run_flexure("mechanism analyze nan.toml", dir.path());
  EXPECT_EQ(nan.exit_code, 2);
  EXPECT_NE(nan.err.find("nan.toml:2: r2 must be finite and > 0"), std::string::npos) << nan.err;
  std::filesystem::create_directory(dir / "folder.toml");
  const CommandResult folder = run_flexure("mechanism analyze folder.toml", dir.path());
  EXPECT_EQ(folder.exit_code, 2);
  EXPECT_NE(folder.err.find("it is a directory"), std::string::npos) << folder.err;
  std::ofstream(dir / "far.toml") << "config = \"lpp\"\nr2 = 0.05\nr3 = 0.04\nstroke = 0.08\n"
                                     "[material]\nE = 1e9\nyield_strength = 3e7\n[ground]\n"
                                     "thickness = 1e-3\nwidth = 0.01\n";
  const CommandResult far = run_flexure("mechanism analyze far.toml", dir.path());
  EXPECT_EQ(far.exit_code, 2);
  EXPECT_NE(far.err.find("toggle"), std::string::npos) << far.err;
}

TEST(MechanismCli, YieldingSegmentIsReported) {
  ScratchDir dir;
  // 1 mm polypropylene crank strained far past yield over a 20 mm stroke.
  std::ofstream(dir / "thick.toml") << "config = \"lpp\"\nr2 = 0.05\nr3 = 0.0443\nstroke = 0.02\n"
                                       "[material]\nE = 1.4e9\nyield_strength = 1e6\n[ground]\n"
                                       "thickness = 1e-3\nwidth = 0.01\n";
  const CommandResult r = run_flexure("mechanism analyze thick.toml --json", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("yields"), std::string::npos) << r.err;
  const json j = json::parse(r.out);
  EXPECT_LT(j["safety_factor"].get<double>(), 1.0);
  EXPECT_EQ(j["yielding_pivots"].size(), 1u);
}

TEST(MechanismCli, Hdf5OutputAndList) {
  ScratchDir dir;
  const CommandResult r =
      run_flexure("mechanism analyze 3A-sss --points 12 --out sss.h5", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const hid_t file = H5Fopen((dir / "sss.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_doubles(file, "displacement").size(), 12u);
  EXPECT_EQ(read_doubles(file, "force_exact").size(), 12u);
  H5Fclose(file);
  EXPECT_EQ(dir.entries().size(), 1u);  // no temporary left behind
  const CommandResult list = run_flexure("mechanism list");
  EXPECT_EQ(list.exit_code, 0);
  // The nine thesis designs, the eleven modified ones of paper 004, nine Howell designs (Table
  // 10.1 without 2B, and example 2), and the inversions of the 6 + 5 thesis and Howell designs
  // with a type-asymmetric configuration.
  EXPECT_EQ(count_lines(list.out), 9 + 11 + 9 + 11);
  const CommandResult table = run_flexure("mechanism validate --markdown --points 10");
  EXPECT_EQ(table.exit_code, 0) << table.err;
  EXPECT_EQ(count_lines(table.out), 2 + 9 + 11);  // header, rule, nine + eleven mechanisms
}

// The example lpp driven to 0.99999 of its toggle stroke: at the toggle the class 1A
// PRBM force is zero (the crank spring's moment has no lever along the slider), and the exact
// force, whose own zero lies a little earlier, turns negative. The exact percent constant force
// was printed as 100 min/max = -5.45 % with exit 0 and no warning. Expected: the sign change is
// flagged (read off the printed force array, independently of the flag), the exact percentage is
// 0 with a warning, and the PRBM percentage, whose force stays positive, is still 100 min/max of
// its printed array.
TEST(MechanismCli, ForceChangingSignHasNoPercentConstantForce) {
  const std::string text =
      read_text(std::string(FLEXURE_SOURCE_DIR) + "/docs/examples/mechanism_lpp.toml");
  auto value_of = [&](const std::string& key) {
    std::smatch m;
    const std::regex re("\\n" + key + " = ([0-9.e+-]+)");
    EXPECT_TRUE(std::regex_search(text, m, re)) << key;
    return std::stod(m[1]);
  };
  const double r2 = value_of("r2"), r3 = value_of("r3"), R = r3 / r2;
  // Toggle position of the slider-crank (docs/cfm.md §1.3): crank and coupler in line.
  const double toggle = (1.0 - std::sqrt(std::abs(1.0 - R) / (1.0 + R))) * (r2 + r3);
  ScratchDir dir;
  std::ofstream(dir / "toggle.toml") << std::regex_replace(
      text, std::regex("\\nstroke = [0-9.e+-]+"), fmt_stroke(0.99999 * toggle));
  const CommandResult r = run_flexure("mechanism analyze toggle.toml --json", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  const std::vector<double> fe = j["force_exact"], fp = j["force_prbm"];
  ASSERT_LT(*std::min_element(fe.begin(), fe.end()), 0.0);
  ASSERT_GT(*std::max_element(fe.begin(), fe.end()), 0.0);
  EXPECT_EQ(j["percent_constant_force_exact"].get<double>(), 0.0);
  EXPECT_TRUE(j["force_changes_sign_exact"].get<bool>());
  EXPECT_TRUE(j["force_vanishes_exact"].get<bool>());
  EXPECT_TRUE(j["force_vanishes"].get<bool>());
  EXPECT_TRUE(j["force_changes_sign"].get<bool>());
  EXPECT_NE(r.err.find("exact force changes sign"), std::string::npos) << r.err;
  // The PRBM force is small but positive at the last point: a genuine (tiny) ratio, not flagged.
  const double pmin = *std::min_element(fp.begin(), fp.end());
  const double pmax = *std::max_element(fp.begin(), fp.end());
  ASSERT_GT(pmin, 0.0);
  EXPECT_FALSE(j["force_vanishes_prbm"].get<bool>());
  EXPECT_FALSE(j["force_changes_sign_prbm"].get<bool>());
  EXPECT_NEAR(j["percent_constant_force_prbm"].get<double>(), 100.0 * pmin / pmax, 1e-12);
  EXPECT_EQ(r.err.find("PRBM force"), std::string::npos) << r.err;
  // The text report says why the exact value is 0.
  const CommandResult text_run = run_flexure("mechanism analyze toggle.toml", dir.path());
  ASSERT_EQ(text_run.exit_code, 0) << text_run.err;
  EXPECT_NE(text_run.out.find("exact 0.00 % (force changes sign)"), std::string::npos)
      << text_run.out;
  // The example at its own stroke: nothing flagged, 100 min/max of the printed exact force.
  const CommandResult ok = run_flexure("mechanism analyze " + std::string(FLEXURE_SOURCE_DIR) +
                                       "/docs/examples/mechanism_lpp.toml --json");
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  const json k = json::parse(ok.out);
  const std::vector<double> fk = k["force_exact"];
  EXPECT_FALSE(k["force_vanishes"].get<bool>());
  EXPECT_FALSE(k["force_changes_sign_exact"].get<bool>());
  EXPECT_NEAR(
      k["percent_constant_force_exact"].get<double>(),
      100.0 * *std::min_element(fk.begin(), fk.end()) / *std::max_element(fk.begin(), fk.end()),
      1e-12);
}

// The example designs with an absurd ground flexure -- 1 m thick (24 mm and 2.73 mm
// long), or 1e-9 m thick or wide -- ran 50-230 s of CPU without an answer. They are outside
// slender-beam theory (docs/mechanisms.md "Geometry limits") and must be refused at once (exit 2),
// naming the segment and the ratio, whose value is recomputed here from the file's numbers.
TEST(MechanismCli, AbsurdFlexureGeometryIsRefusedAtOnce) {
  struct Case {
    std::string example, from, to, expect;
  };
  const std::string lplm = "mechanism_lplm.toml", sss = "mechanism_sss.toml";
  // Lengths: lplm's ground strip 24 mm; sss's ground flexure 2.73 mm. Thicknesses 0.5181 mm, 0.1
  // mm.
  const std::vector<Case> cases = {
      {lplm,
       "thickness = 0.5181e-3",
       "thickness = 1.0",
       fmt_ratio("thickness/length", 1.0 / 0.024)},
      {lplm, "width = 25.4e-3", "width = 1e-9", fmt_ratio("width/thickness", 1e-9 / 0.5181e-3)},
      {lplm, "thickness = 0.5181e-3", "thickness = 1e-9", "load parameter |P| L^2/(EI) = "},
      {sss, "thickness = 0.1e-3", "thickness = 1.0", fmt_ratio("thickness/length", 1.0 / 2.73e-3)},
      {sss, "width = 5e-3", "width = 1e-9", fmt_ratio("width/thickness", 1e-9 / 0.1e-3)},
      {sss, "thickness = 0.1e-3", "thickness = 1e-9", "load parameter |P| L^2/(EI) = "}};
  ScratchDir dir;
  for (const Case& c : cases) {
    std::string text = read_text(std::string(FLEXURE_SOURCE_DIR) + "/docs/examples/" + c.example);
    const std::size_t at = text.find(c.from);  // the first occurrence is in [ground]
    ASSERT_NE(at, std::string::npos) << c.example << ": " << c.from;
    ASSERT_LT(
        at,
        text.find("[middle]") == std::string::npos ? text.find("[slider]") : text.find("[middle]"));
    text.replace(at, c.from.size(), c.to);
    std::ofstream(dir / "absurd.toml") << text;
    const auto start = std::chrono::steady_clock::now();
    const CommandResult r = run_flexure("mechanism analyze absurd.toml --json", dir.path());
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(r.exit_code, 2) << c.example << " " << c.to << ": " << r.err;
    EXPECT_LT(seconds, 5.0) << c.example << " " << c.to;
    EXPECT_NE(r.err.find("ground pivot 1 segment [ground]: " + c.expect), std::string::npos)
        << c.example << " " << c.to << ": " << r.err;
    EXPECT_TRUE(test::no_result_on_stdout(r)) << r.out;
  }
}

// `validate` marks the cells it reports as 0 for that reason and leaves out their difference.
TEST(MechanismCli, ValidateMarksAForceChangingSign) {
  const CommandResult r = run_flexure(
      "mechanism validate --designs thesis --toggle-fraction 0.99999 --points 10 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  bool found = false;
  const json j = json::parse(r.out);
  for (const json& row : j["mechanisms"]) {
    if (row["design"]["name"] != "1A-lpp") continue;
    found = true;
    EXPECT_TRUE(row["force_changes_sign_exact"].get<bool>());
    EXPECT_EQ(row["percent_constant_force_exact"].get<double>(), 0.0);
  }
  EXPECT_TRUE(found);
  EXPECT_NE(r.err.find("1A-lpp: the exact force changes sign"), std::string::npos) << r.err;
  const CommandResult md = run_flexure(
      "mechanism validate --designs thesis --toggle-fraction 0.99999 --points 10 --markdown");
  ASSERT_EQ(md.exit_code, 0) << md.err;
  EXPECT_NE(md.out.find("| 0.00 (force changes sign) | - |"), std::string::npos) << md.out;
}

// `validate` skips the exact stresses; its JSON said 0 Pa for them (an unstressed flexure), which a
// reader cannot tell from a computed value. `analyze` computes them (non-zero: the 1A-spp flexure
// bends through the whole stroke).
TEST(MechanismCli, ExactStressesNotComputedAreNull) {
  const CommandResult v = run_flexure("mechanism validate --json --points 6");
  ASSERT_EQ(v.exit_code, 0) << v.err;
  const json first = json::parse(v.out)["mechanisms"][0];
  ASSERT_EQ(first["design"]["name"], "1A-spp");
  EXPECT_TRUE(first["max_stress_exact"][0].is_null()) << first["max_stress_exact"];
  const CommandResult a = run_flexure("mechanism analyze 1A-spp --points 6 --json");
  ASSERT_EQ(a.exit_code, 0) << a.err;
  EXPECT_GT(json::parse(a.out)["max_stress_exact"][0].get<double>(), 0.0);
}

}  // namespace
}  // namespace flexure::test
