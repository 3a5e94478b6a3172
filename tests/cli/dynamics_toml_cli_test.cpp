// What is checked against what (`flexure dynamics --mechanism FILE.toml`, the built binary;
// docs/dynamics.md "Designs from TOML"):
//  - docs/examples/mechanism_lplm_dynamics.toml (the built-in 2B-lplm with Table 5's masses and
//    printed springs in [dynamics]) gives the built-in design's output to 1e-12: every array and
//    scalar of the JSON, with inertia, at three frequencies;
//  - without spring_constants the file's spring rule applies: the same file with pure bending
//    against `--mechanism 2B-lplm --spring-rule pure-bending` (springs from the same strips);
//  - `mechanism analyze` reads the same file and ignores [dynamics] (equal to the built-in
//    2B-lplm);
//  - a file lacking a needed mass exits 2 naming the field (one JSON error object with --json);
//    --zero-inertia needs none; a spring at a pin and --spring-rule together with
//    spring_constants are refused.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/cli_test_support.h"

namespace flexure {
namespace {

using nlohmann::json;
using test::read_text;
using test::run_flexure;
using test::ScratchDir;

// The file's numbers are the built-in's decimal values (0.068 m against 68.0 mm x 1e-3): equal to
// the last bit or one ulp apart, so every output agrees to rounding.
constexpr double kSameDesignTolerance = 1e-12;

const std::string kExample =
    std::string(FLEXURE_SOURCE_DIR) + "/docs/examples/mechanism_lplm_dynamics.toml";

json run_json(const std::string& args) {
  const test::CommandResult r = run_flexure(args + " --json");
  EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
  return json::parse(r.out.empty() ? "{}" : r.out);
}

// Every number of `a` (recursively) against `b` to a relative tolerance.
void expect_same_numbers(const json& a, const json& b, const std::string& where) {
  if (a.is_number()) {
    ASSERT_TRUE(b.is_number()) << where;
    const double x = a.get<double>(), y = b.get<double>();
    EXPECT_NEAR(x, y, kSameDesignTolerance * std::max(1.0, std::abs(y))) << where;
  } else if (a.is_array()) {
    ASSERT_EQ(a.size(), b.size()) << where;
    for (std::size_t i = 0; i < a.size(); ++i) {
      expect_same_numbers(a[i], b[i], fmt::format("{}[{}]", where, i));
    }
  } else if (a.is_object()) {
    for (const auto& [key, value] : a.items())
      expect_same_numbers(value, b[key], where + "." + key);
  }
}

std::string write_variant(const ScratchDir& dir,
                          const std::string& name,
                          const std::string& remove,
                          const std::string& add = {}) {
  std::string text = read_text(kExample);
  if (!remove.empty()) {
    const std::size_t at = text.find(remove);
    EXPECT_NE(at, std::string::npos) << remove;
    text.erase(at, remove.size());
  }
  text += add;
  const std::string path = (dir / name).string();
  std::ofstream(path) << text;
  return path;
}

const std::string kSweep = " --omega 0:40:3 --samples 64 --history 31.416";

TEST(DynamicsTomlCli, ExampleFileReproducesTheBuiltInDesign) {
  const json builtin = run_json("dynamics --mechanism 2B-lplm" + kSweep);
  const json file = run_json("dynamics --mechanism '" + kExample + "'" + kSweep);
  EXPECT_EQ(file["mechanism"], "lplm-dynamics-example");
  EXPECT_EQ(file["spring_rule"], "given");
  EXPECT_EQ(file["force_of"], "whole symmetric mechanism");
  EXPECT_TRUE(file["paper_nominal_force"].is_null());  // a file is no row of Table 6
  for (const char* key : {"omega",
                          "mean_force",
                          "median_force",
                          "min_force",
                          "max_force",
                          "peak_to_peak_force",
                          "percent_constant_force",
                          "static_nominal_force",
                          "natural_frequency",
                          "spring_constants",
                          "stroke",
                          "preload",
                          "history"}) {
    ASSERT_TRUE(file.contains(key)) << key;
    expect_same_numbers(file[key], builtin[key], key);
  }
  // Inertia is in play (the check is not a static one): the mean force rises with omega.
  EXPECT_GT(file["mean_force"][2].get<double>(), file["mean_force"][0].get<double>() + 1.0);
}

TEST(DynamicsTomlCli, WithoutSpringConstantsTheFilesSpringRuleApplies) {
  ScratchDir dir;
  const std::string path =
      write_variant(dir, "rule.toml", "spring_constants = [3.4322, 0.0, 3.4322]");
  const json file = run_json("dynamics --mechanism '" + path + "'" + kSweep);
  const json builtin = run_json("dynamics --mechanism 2B-lplm --spring-rule pure-bending" + kSweep);
  EXPECT_EQ(file["spring_rule"], "pure-bending");
  EXPECT_EQ(builtin["spring_rule"], "pure-bending");
  for (const char* key :
       {"mean_force", "peak_to_peak_force", "static_nominal_force", "spring_constants"}) {
    expect_same_numbers(file[key], builtin[key], key);
  }
  // --spring-rule replaces the file's rule, as in mechanism analyze.
  const json t5 = run_json("dynamics --mechanism '" + path + "' --spring-rule table5" + kSweep);
  const json builtin_t5 = run_json("dynamics --mechanism 2B-lplm --spring-rule table5" + kSweep);
  EXPECT_EQ(t5["spring_rule"], "table5");
  expect_same_numbers(t5["static_nominal_force"], builtin_t5["static_nominal_force"], "table5");
}

TEST(DynamicsTomlCli, MechanismAnalyzeIgnoresTheDynamicsTable) {
  const json file = run_json("mechanism analyze '" + kExample + "' --method prbm");
  const json builtin = run_json("mechanism analyze 2B-lplm --method prbm");
  expect_same_numbers(file["force_prbm"], builtin["force_prbm"], "force_prbm");
}

TEST(DynamicsTomlCli, MissingMassIsNamedWithExitTwo) {
  ScratchDir dir;
  const std::string path = write_variant(dir, "no_slider.toml", "m_slider = 0.1167138");
  const test::CommandResult r = run_flexure("dynamics --mechanism '" + path + "'" + kSweep);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_NE(r.err.find("no_slider.toml:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("[dynamics] lacks m_slider"), std::string::npos) << r.err;
  const test::CommandResult j =
      run_flexure("dynamics --mechanism '" + path + "'" + kSweep + " --json");
  EXPECT_EQ(j.exit_code, 2);
  ASSERT_TRUE(test::no_result_on_stdout(j)) << j.out;
  EXPECT_NE(json::parse(j.out)["error"].get<std::string>().find("m_slider"), std::string::npos);
  // Not needed without slider mass.
  EXPECT_EQ(
      run_flexure("dynamics --mechanism '" + path + "'" + kSweep + " --zero-slider-mass").exit_code,
      0);

  // A file without [dynamics] (the analyze example): the first mass it needs is named.
  const std::string plain = std::string(FLEXURE_SOURCE_DIR) + "/docs/examples/mechanism_lplm.toml";
  const test::CommandResult p = run_flexure("dynamics --mechanism '" + plain + "'" + kSweep);
  EXPECT_EQ(p.exit_code, 2);
  EXPECT_NE(p.err.find("needs [dynamics] m2"), std::string::npos) << p.err;
  // Without inertia no mass is needed: the quasi-static force of the file's own springs.
  const json z = run_json("dynamics --mechanism '" + plain + "' --zero-inertia" + kSweep);
  const json zb =
      run_json("dynamics --mechanism 2B-lplm --spring-rule pure-bending --zero-inertia" + kSweep);
  expect_same_numbers(z["mean_force"], zb["mean_force"], "mean_force");
}

TEST(DynamicsTomlCli, InconsistentSpringsAreRefused) {
  ScratchDir dir;
  const std::string bad = write_variant(dir,
                                        "bad.toml",
                                        "spring_constants = [3.4322, 0.0, 3.4322]",
                                        "spring_constants = [3.4322, 1.0, 3.4322]\n");
  const test::CommandResult r = run_flexure("dynamics --mechanism '" + bad + "'" + kSweep);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("spring_constants[1] = 1 for pivot 2, a pin"), std::string::npos) << r.err;
  const test::CommandResult both =
      run_flexure("dynamics --mechanism '" + kExample + "' --spring-rule table5" + kSweep);
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_NE(both.err.find("--spring-rule contradicts [dynamics] spring_constants"),
            std::string::npos)
      << both.err;
  const std::string unknown = write_variant(dir, "unknown.toml", "", "inertia = 1.0\n");
  const test::CommandResult u = run_flexure("dynamics --mechanism '" + unknown + "'" + kSweep);
  EXPECT_EQ(u.exit_code, 2);
  EXPECT_NE(u.err.find("inertia"), std::string::npos) << u.err;
}

}  // namespace
}  // namespace flexure
