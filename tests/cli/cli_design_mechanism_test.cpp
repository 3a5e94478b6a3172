// `flexure design mechanism` (docs/cli.md, docs/design.md): thesis design examples 1 and 2 through
// the tool with the designer's units, the JSON contract, the TOML file that `mechanism analyze`
// reads unchanged, and bad input.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

using nlohmann::json;

constexpr double kInch = 0.0254;
constexpr double kKsi = 1e3 * 4.4482216152605 / (kInch * kInch);

// Thesis example 1 by the thesis's own stress rule (eq. 8.5), as printed; the tool's default rule
// is tested in cli_design_rules_test.cpp.
const std::string kExample1 =
    "design mechanism --force 25lbf --stroke 4in --E 30Msi --safety-factor 1.2 "
    "--length-range 12in:15in --width-range 3in:5in --thickness-range 0.04in:0.07in --config lpp "
    "--stress-rule thesis";

TEST(CliDesignMechanism, ExampleOneGivesLppBAndATomlFileThatAnalyses) {
  ScratchDir dir;
  const std::string toml = (dir / "design.toml").string();
  const CommandResult r = run_flexure(kExample1 + " --json --out " + toml);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  ASSERT_FALSE(j["designs"].empty());
  const json& d = j["designs"][0];
  EXPECT_EQ(d["subclass"], "lpp-b");
  EXPECT_NEAR(d["thicknesses"][0].get<double>() / kInch, 0.049, 0.0005);
  EXPECT_NEAR(d["width"].get<double>() / kInch, 5.0, 1e-12);
  EXPECT_NEAR(d["required_yield_strength"].get<double>() / kKsi, 167.0, 1.0);
  EXPECT_NEAR(d["subclass_percent_constant_force"].get<double>(), 97.6, 0.05);
  for (const char* key : {"r2",
                          "r3",
                          "segment_lengths",
                          "percent_constant_force_prbm",
                          "percent_constant_force_exact",
                          "force_prbm",
                          "force_exact",
                          "safety_factor_prbm",
                          "safety_factor_exact"}) {
    EXPECT_TRUE(d.contains(key)) << key;
  }
  // The file is the design: `mechanism analyze` gives the same PRBM and exact forces.
  const CommandResult a = run_flexure("mechanism analyze " + toml + " --json");
  ASSERT_EQ(a.exit_code, 0) << a.err;
  const json m = json::parse(a.out);
  EXPECT_NEAR(m["mean_force_prbm"].get<double>(),
              d["force_prbm"].get<double>(),
              1e-9 * d["force_prbm"].get<double>());
  EXPECT_NEAR(m["mean_force_exact"].get<double>(),
              d["force_exact"].get<double>(),
              1e-9 * d["force_exact"].get<double>());
}

// --model exact: the best design refined against the exact model makes the specified force in
// the exact model (measured: Xi' 93.6 -> 98.5 % exact for example 1), and --out writes it.
TEST(CliDesignMechanism, ModelExactRefinesTheBestDesign) {
  ScratchDir dir;
  const std::string toml = (dir / "refined.toml").string();
  const CommandResult r = run_flexure(kExample1 + " --model exact --json --out " + toml);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  const json& prbm = j["designs"][0];
  const json& refined = j["refined"];
  ASSERT_TRUE(refined["feasible"].get<bool>()) << refined.dump();
  EXPECT_EQ(refined["subclass"], "lpp-b");
  EXPECT_GT(refined["percent_constant_force_exact"].get<double>(),
            prbm["percent_constant_force_exact"].get<double>() + 1.0);
  EXPECT_NEAR(refined["force_exact"].get<double>(), 25.0 * 4.4482216152605, 1e-4 * 111.2);
  // The file holds the refined design: an independent analysis gives its exact force and Xi'.
  const json m = json::parse(run_flexure("mechanism analyze " + toml + " --json").out);
  EXPECT_NEAR(
      m["mean_force_exact"].get<double>(), refined["force_exact"].get<double>(), 1e-9 * 111.2);
  EXPECT_NEAR(m["percent_constant_force_exact"].get<double>(),
              refined["percent_constant_force_exact"].get<double>(),
              1e-9);
}

TEST(CliDesignMechanism, WholeMechanismForcesAreTwiceTheHalf) {
  const json half = json::parse(run_flexure(kExample1 + " --json --no-exact").out);
  const json whole = json::parse(
      run_flexure("design mechanism --force 50lbf --stroke 4in --E 30Msi --safety-factor 1.2 "
                  "--length-range 12in:15in --width-range 3in:5in --thickness-range 0.04in:0.07in "
                  "--config lpp --force-of whole --json --no-exact")
          .out);
  EXPECT_NEAR(whole["designs"][0]["force_prbm"].get<double>(),
              2.0 * half["designs"][0]["force_prbm"].get<double>(),
              1e-9);
  EXPECT_EQ(whole["designs"][0]["thicknesses"], half["designs"][0]["thicknesses"]);
  EXPECT_TRUE(half["designs"][0]["force_exact"].is_null());
}

TEST(CliDesignMechanism, ExampleTwoIsInfeasibleWithExitThreeNamingM) {
  ScratchDir dir;
  const std::string toml = (dir / "design.toml").string();
  const CommandResult r = run_flexure(
      "design mechanism --force 3mN --stroke 7.5mm --E 110GPa --yield-strength 552MPa "
      "--safety-factor 1.1 --length-range 150mm --thickness-range 1.5mm:2mm "
      "--pcf-min 90 --in-plane --config sss --stress-rule thesis --json --out " +
      toml);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  const json j = json::parse(r.out);
  const std::string error = j["error"];
  EXPECT_NE(error.find("sss-a95I"), std::string::npos) << error;
  EXPECT_NE(error.find("M = 1.7796"), std::string::npos) << error;
  EXPECT_NEAR(j["screens"]["M_max"].get<double>(), 0.3792, 0.00005);
  EXPECT_FALSE(j["rejected"].empty());
  EXPECT_TRUE(dir.entries().empty());  // nothing written
  // Table 8.5 gives no width and, here, no thickness: for 3 mN the thickest flexure the stress
  // allows would be narrower than it is thick (eq. 8.19: b = 0.0148 mm at h = 0.326 mm), which
  // the slender-beam limit b/h >= 1 refuses; the section is then the thickest with b >= h, and
  // every design stays within the safety factor by both models.
  const CommandResult any = run_flexure(
      "design mechanism --force 3mN --stroke 7.5mm --E 110GPa --yield-strength 552MPa "
      "--safety-factor 1.1 --length-range 150mm --pcf-min 90 --in-plane --json");
  ASSERT_EQ(any.exit_code, 0) << any.err;
  const json designs = json::parse(any.out)["designs"];
  ASSERT_FALSE(designs.empty());
  for (const json& d : designs) {
    for (std::size_t i = 0; i < d["widths"].size(); ++i) {
      EXPECT_GE(d["widths"][i].get<double>(), d["thicknesses"][i].get<double>() * (1.0 - 1e-9))
          << d["subclass"];
    }
    EXPECT_GE(d["safety_factor_prbm"].get<double>(), 1.1 * (1.0 - 1e-9)) << d["subclass"];
    EXPECT_GE(d["safety_factor_exact"].get<double>(), 1.1 * (1.0 - 1e-9)) << d["subclass"];
  }
}

TEST(CliDesignMechanism, BadInputIsExitTwoWithAReason) {
  const std::string base =
      "design mechanism --force 25lbf --stroke 4in --E 30Msi --safety-factor 1.2 "
      "--width-range 3in:5in --thickness-range 0.04in:0.07in ";
  for (const std::string& args :
       {base + "--length-range 15in:12in",
        base + "--length-range 12in:15in --config xyz",
        base + "--length-range 12in:15in --in-plane --out-of-plane",
        base + "--length-range 12in:15in --rank best",
        base + "--length-range 12in:15in --model fem",
        std::string("design mechanism --force 25lbf --stroke 4in --E 30Msi --safety-factor 1.2 "
                    "--length-range 12in:15in"),
        base + "--length-range 12in:15in --model exact --no-exact",
        base + "--length-range 12in:15xy",
        base + "--length-range 12in:15in --force-of both",
        std::string("design mechanism --force nan --stroke 4in --E 30Msi --safety-factor 1.2 "
                    "--length-range 12in --width-range 3in --thickness-range 0.04in"),
        std::string("design mechanism --force 25lbf --stroke 4in --E 30Msi --safety-factor -1 "
                    "--length-range 12in --width-range 3in --thickness-range 0.04in")}) {
    const CommandResult r = run_flexure(args + " --json");
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_FALSE(r.err.empty()) << args;
  }
  // A stroke no sub-class reaches: exit 3 naming the stroke.
  const CommandResult r = run_flexure(
      "design mechanism --force 25lbf --stroke 15in --E 30Msi --safety-factor 1.2 --width-range "
      "3in:5in --thickness-range 0.04in:0.07in --length-range 12in:15in --json");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("stroke"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace flexure::test
