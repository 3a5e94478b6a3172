// What is checked against what: the `flexure mechanism` commands as a user runs them -- the JSON
// keys and array lengths the issue specifies, exit codes for bad input (2), the toggle refusal,
// the yield warning, the HDF5 file (read back with the plain HDF5 C API), and that the JSON error
// equals the error recomputed from the printed force arrays.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/cli_test_support.h"

namespace flexure::test {
namespace {

using nlohmann::json;

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
  EXPECT_EQ(run_flexure("mechanism analyze 9Z-abc").exit_code, 2);
  EXPECT_EQ(run_flexure("mechanism analyze 1A-lpp --points 1").exit_code, 2);
  // At the toggle position the R = 1 designs fold flat: refused up front (it ran for a minute
  // and failed with a NaN shooting guess).
  const CommandResult toggle = run_flexure("mechanism validate --toggle-fraction 1");
  EXPECT_EQ(toggle.exit_code, 2);
  EXPECT_NE(toggle.err.find("[1e-06, 1)"), std::string::npos) << toggle.err;
  // Options that were silently ignored beside others.
  EXPECT_EQ(run_flexure("mechanism validate --markdown --json --points 4").exit_code, 2);
  EXPECT_EQ(run_flexure("mechanism validate --spring-rules --designs thesis").exit_code, 2);
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
