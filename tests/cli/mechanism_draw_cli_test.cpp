// `flexure mechanism draw`, `design mechanism --drawing` and the buildable geometry in the outputs
// of `mechanism analyze` and `design mechanism` (docs/drawings.md), as a user runs them: the JSON
// names the file and its dimensions, which equal the design's own numbers (the built-in design's
// r2, r3, flexure lengths from `mechanism list --json`; the TOML keys the design writes); bad paths
// exit 2 and write nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/cli_test_support.h"

namespace {

using flexure::test::CommandResult;
using flexure::test::run_flexure;
using flexure::test::ScratchDir;
using json = nlohmann::json;
namespace fs = std::filesystem;

json list_entry(const std::string& name) {
  const json all = json::parse(run_flexure("mechanism list --json").out)["mechanisms"];
  for (const auto& d : all) {
    if (d["name"] == name) return d;
  }
  return json();
}

TEST(MechanismDrawCli, JsonNamesTheFileAndTheDesignsDimensions) {
  ScratchDir dir;
  const std::string out = (dir / "sss.svg").string();
  const CommandResult r = run_flexure("mechanism draw 3A-sss --out " + out + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["out"], out);
  EXPECT_EQ(j["format"], "svg");
  EXPECT_TRUE(fs::exists(out));
  const json d = list_entry("3A-sss");
  ASSERT_FALSE(d.is_null());
  std::map<std::string, double> dims;
  for (const auto& x : j["dimensions"]) dims[x["name"]] = x["value"];
  EXPECT_NEAR(dims.at("r2"), d["r2"].get<double>(), 1e-12 * d["r2"].get<double>());
  EXPECT_NEAR(dims.at("r3"), d["r3"].get<double>(), 1e-12 * d["r3"].get<double>());
  EXPECT_NEAR(dims.at("stroke"), d["stroke"].get<double>(), 1e-12 * d["stroke"].get<double>());
  ASSERT_EQ(j["geometry"]["flexures"].size(), 3u);
}

TEST(MechanismDrawCli, DxfAndStrokeEndOff) {
  ScratchDir dir;
  const std::string out = (dir / "lpp.DXF").string();
  const CommandResult r = run_flexure("mechanism draw 1A-lpp --out " + out + " --stroke-end off");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string text = flexure::test::read_text(out);
  EXPECT_NE(text.find("AC1009"), std::string::npos);
  EXPECT_EQ(text.find("DEFORMED\n  0\nPOLYLINE"), std::string::npos);
  EXPECT_EQ(text.find("\n  8\nDEFORMED\n"), std::string::npos);  // no entity on DEFORMED
  EXPECT_NE(r.out.find("flexure 1 (long)"), std::string::npos) << r.out;
}

TEST(MechanismDrawCli, UnknownExtensionExitsTwoAndWritesNothing) {
  ScratchDir dir;
  const std::string out = (dir / "sss.png").string();
  const CommandResult r = run_flexure("mechanism draw 3A-sss --out " + out + " --json");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(".svg or .dxf"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(json::parse(r.out)["exit_code"], 2);
}

TEST(MechanismDrawCli, AnalyzeReportsTheBuildableGeometry) {
  const CommandResult r = run_flexure("mechanism analyze 3A-sss --prbm-only --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  const json& g = j["geometry"];
  ASSERT_EQ(g["flexures"].size(), 3u);
  // The middle flexure's physical length by Table 8.1's default 0.1 (r2 + r3)/2 when the design
  // gives none; 3A-sss's middle length is written in the design (r2, r3 in "design").
  const double r2 = j["design"]["r2"], r3 = j["design"]["r3"];
  double sum = 0.0;  // the parts of the rest line add up to the overall length
  for (const auto& f : g["flexures"]) sum += f["length"].get<double>();
  for (const auto& l : g["links"]) sum += l["length"].get<double>();
  EXPECT_NEAR(sum, g["overall_length"].get<double>(), 1e-12 * (r2 + r3));
  const CommandResult t = run_flexure("mechanism analyze 3A-sss --prbm-only");
  EXPECT_NE(t.out.find("buildable geometry (mm"), std::string::npos) << t.out;
}

// Thesis design example 1 (docs/design.md) with --drawing, and the TOML's [geometry] table.
TEST(MechanismDrawCli, DesignMechanismDrawsTheWrittenDesign) {
  ScratchDir dir;
  const std::string toml = (dir / "d.toml").string();
  const std::string svg = (dir / "d.svg").string();
  const std::string args =
      "design mechanism --force 25lbf --stroke 4in --E 30Msi --safety-factor 1.2 "
      "--length-range 12in:15in --width-range 3in:5in --thickness-range 0.04in:0.07in --config "
      "lpp --stress-rule thesis --no-exact --out " +
      toml + " --drawing " + svg;
  const CommandResult r = run_flexure(args + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["drawing"], svg);
  EXPECT_TRUE(fs::exists(svg));
  const json& best = j["designs"][0];
  ASSERT_TRUE(best["geometry"].is_object());
  EXPECT_NEAR(best["geometry"]["flexures"][0]["thickness"].get<double>(),
              best["thicknesses"][0].get<double>(),
              1e-15);
  // The file with its [geometry] table still reads back as the same design.
  const CommandResult a = run_flexure("mechanism analyze " + toml + " --prbm-only --json");
  ASSERT_EQ(a.exit_code, 0) << a.err;
  EXPECT_NE(flexure::test::read_text(toml).find("[[geometry.flexures]]"), std::string::npos);
  // Text in the user's unit (--stroke 4in).
  const CommandResult t = run_flexure(args);
  ASSERT_EQ(t.exit_code, 0) << t.err;
  EXPECT_NE(t.out.find("buildable geometry (in"), std::string::npos) << t.out;
  // An unknown drawing extension is refused before any design work.
  const CommandResult bad = run_flexure(args + ".txt");
  EXPECT_EQ(bad.exit_code, 2);
}

}  // namespace
