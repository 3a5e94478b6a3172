// Physical beams and units through the tool (docs/units.md):
//  * the steel strip of issue 13 (50 x 10 x 0.5 mm, E = 200 GPa, 5 N at 30 deg from the
//    perpendicular): alpha2 = Fy L^2/EI, n = -Fx/Fy by hand; the stress M c/I and the safety
//    factor from the reported moment by hand; the shape in metres is the nondimensional shape
//    times L;
//  * Howell's fixed-pinned example of sec. 5.2 in inches and pounds (steel, 20 x 1.25 x 1/32 in,
//    E = 30e6 psi): the elliptic solution the book quotes, P = 0.49 lb for b = 10 in, a = 16.7 in,
//    theta0 = 0.79 rad, and sigma = 6 P a/(w h^2) by hand;
//  * unit suffixes equal their SI values; warnings name the likely mistake; unknown units, wrong
//    dimensions and mixed physical and nondimensional input are exit-2 errors;
//  * a chain file in physical units: alpha2 = Fy l^2/EI (0.52, not the raw Fy 4.33), and the same
//    SI keys as the flags.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "tests/support/cli_test_support.h"

namespace flexure {
namespace {

using test::run_flexure;
using Json = nlohmann::json;

constexpr double kInch = 0.0254;
constexpr double kPound = 4.4482216152605;

const char* kStrip =
    "beam --length 50mm --E 200GPa --width 10mm --thickness '0.5 mm' --Fx -2.5N --Fy 4.33N "
    "--yield-strength 1.5GPa";

template <typename... T>
std::string fmt_args(const char* format, T... values) {
  char buffer[1024];
  std::snprintf(buffer, sizeof buffer, format, values...);
  return buffer;
}

Json run_json(const std::string& args) {
  const test::CommandResult r = run_flexure(args + " --json");
  EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err << r.out;
  return r.exit_code == 0 ? Json::parse(r.out) : Json::object();
}

TEST(CliUnits, SteelStripByHand) {
  const Json j = run_json(std::string(kStrip) + " --shape 5");
  const double I = 0.01 * std::pow(0.0005, 3) / 12.0, EI = 200e9 * I, L = 0.05;
  EXPECT_NEAR(j["alpha2"].get<double>(), 4.33 * L * L / EI, 1e-13);
  EXPECT_NEAR(j["n"].get<double>(), 2.5 / 4.33, 1e-14);
  EXPECT_NEAR(j["EI_Nm2"].get<double>(), EI, 1e-15);
  EXPECT_NEAR(j["tip_x"].get<double>(), j["a_over_l"].get<double>() * L, 1e-15);
  EXPECT_NEAR(j["tip_y"].get<double>(), j["b_over_l"].get<double>() * L, 1e-15);
  // Statics of the whole beam: M(0) = Fy a - Fx b.
  const double M0 = 4.33 * j["tip_x"].get<double>() + 2.5 * j["tip_y"].get<double>();
  EXPECT_NEAR(j["root_moment_Nm"].get<double>(), M0, 1e-12);
  EXPECT_NEAR(j["root_moment_Nm"].get<double>(), j["root_moment"].get<double>() * EI / L, 1e-12);
  // No end moment, tip load only: the moment is largest at the clamp.
  EXPECT_NEAR(j["max_moment_Nm"].get<double>(), M0, 1e-12);
  const double sigma = M0 * 0.00025 / I;
  EXPECT_NEAR(j["max_stress"].get<double>(), sigma, 1e-6 * sigma);
  EXPECT_NEAR(j["safety_factor"].get<double>(), 1.5e9 / sigma, 1e-6);
  ASSERT_EQ(j["shape"].size(), 5u);
  for (const Json& p : j["shape"]) {
    EXPECT_NEAR(p["x_m"].get<double>(), p["x"].get<double>() * L, 1e-15);
    EXPECT_NEAR(p["y_m"].get<double>(), p["y"].get<double>() * L, 1e-15);
    EXPECT_NEAR(p["s_m"].get<double>(), p["s"].get<double>() * L, 1e-15);
    // M(s) = M(0) - Fy x + Fx y (the part beyond s carries the tip load).
    const double m = M0 - 4.33 * p["x_m"].get<double>() - 2.5 * p["y_m"].get<double>();
    EXPECT_NEAR(p["moment_Nm"].get<double>(), m, 1e-12);
    EXPECT_NEAR(p["stress_Pa"].get<double>(), std::fabs(m) * 0.00025 / I, 1e-3);
  }
  // The text report says the same in words.
  const test::CommandResult text = run_flexure(kStrip);
  EXPECT_EQ(text.exit_code, 0);
  EXPECT_NE(text.out.find("safety factor against yield"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("tip y = "), std::string::npos);
}

TEST(CliUnits, HowellFixedPinnedExampleInInchesAndPounds) {
  // Howell sec. 5.2 (eqs. 5.81-5.86) quotes the elliptic solution: F = 0.49 lb for b = 10 in, with
  // a = 16.7 in and theta0 = 0.79 rad (two or three figures).
  const Json j = run_json(
      "beam --length 20in --E 30Msi --width 1.25in --thickness 0.03125in --Fy 0.49lbf "
      "--method elliptic");
  EXPECT_NEAR(j["tip_y"].get<double>() / kInch, 10.0, 0.1);
  EXPECT_NEAR(j["tip_x"].get<double>() / kInch, 16.7, 0.05);
  EXPECT_NEAR(j["theta0"].get<double>(), 0.79, 0.01);  // two figures, of a load rounded to 0.49
  // Eq. 5.85's stress, sigma = 6 P a/(w h^2), at the elliptic a.
  const double P = 0.49 * kPound, a = j["tip_x"].get<double>();
  const double sigma = 6 * P * a / (1.25 * kInch * std::pow(0.03125 * kInch, 2));
  EXPECT_NEAR(j["max_stress"].get<double>(), sigma, 1e-9 * sigma);
  // The book's 41,000 psi is at P = 0.50 lb; at 0.49 lb about 2 % less.
  EXPECT_NEAR(j["max_stress"].get<double>() / (kPound / (kInch * kInch)), 40200, 400);
}

TEST(CliUnits, SuffixesEqualTheirSiValues) {
  const Json with = run_json(
      "beam --length 2in --E 30Msi --width 0.5in --thickness 0.02in "
      "--Fy 0.25lbf --M '0.1 lbf in' --yield-strength 167ksi");
  const double psi = kPound / (kInch * kInch);
  const Json plain =
      run_json(fmt_args("beam --length %.17g --E %.17g --width %.17g --thickness "
                        "%.17g --Fy %.17g --M %.17g --yield-strength %.17g",
                        2 * kInch,
                        30e6 * psi,
                        0.5 * kInch,
                        0.02 * kInch,
                        0.25 * kPound,
                        0.1 * kPound * kInch,
                        167e3 * psi));
  for (const char* key : {"alpha2", "mu", "tip_x", "tip_y", "max_stress", "safety_factor"}) {
    EXPECT_NEAR(with[key].get<double>(),
                plain[key].get<double>(),
                1e-14 * std::fabs(plain[key].get<double>()))
        << key;
  }
  const Json degrees = run_json("beam --theta0 30deg");
  const Json radians = run_json("beam --theta0 0.52359877559829882");
  EXPECT_NEAR(degrees["alpha2"].get<double>(), radians["alpha2"].get<double>(), 1e-14);
}

TEST(CliUnits, LikelyMistakesAreWarnedAndNamed) {
  const test::CommandResult deg = run_flexure("beam --theta0 60 --json");
  EXPECT_NE(deg.err.find("warning: --theta0"), std::string::npos) << deg.err;
  EXPECT_NE(deg.err.find("60deg"), std::string::npos) << deg.err;
  const test::CommandResult thick =
      run_flexure("beam --length 50mm --E 200GPa --width 10mm --thickness 6mm --Fy 1 --json");
  EXPECT_EQ(thick.exit_code, 0);
  EXPECT_NE(thick.err.find("Euler-Bernoulli"), std::string::npos) << thick.err;
  const test::CommandResult soft =
      run_flexure("beam --length 0.05 --E 200000 --width 0.01 --thickness 0.0005 --Fy 1e-6");
  EXPECT_NE(soft.err.find("did you mean 200000MPa or 200000GPa"), std::string::npos) << soft.err;
  // None of them for the plausible strip.
  EXPECT_EQ(run_flexure(std::string(kStrip) + " --json").err, "");
}

TEST(CliUnits, BadUnitsAndMixedInputAreExitTwo) {
  const struct {
    const char* args;
    const char* says;
  } cases[] = {
      {"beam --length 50mn --E 200GPa --I 1e-13 --Fy 1", "unknown unit 'mn'"},
      {"beam --length 50mm --E 200Gpa --I 1e-13 --Fy 1", "did you mean 'GPa'"},
      {"beam --length 5N --E 200GPa --I 1e-13 --Fy 1", "is a force, but --length is a length"},
      {"beam --length 50mm --E 200GPa --I 1e-13 --Fy 1 --alpha2 2", "do not combine"},
      {"beam --length 50mm --E 200GPa --I 1e-13 --width 1mm --thickness 1mm --Fy 1", "exactly one"},
      {"beam --length 50mm --E 200GPa --I 1e-13 --Fy 1 --yield-strength 1GPa", "--thickness"},
      {"beam --length -50mm --E 200GPa --I 1e-13 --Fy 1", "--length"},
      {"beam --E 200GPa --I 1e-13 --Fy 1", "--length and --E"},
  };
  for (const auto& c : cases) {
    const test::CommandResult r = run_flexure(std::string(c.args) + " --json");
    EXPECT_EQ(r.exit_code, 2) << c.args;
    const Json error = Json::parse(r.out);
    EXPECT_NE(error["error"].get<std::string>().find(c.says), std::string::npos)
        << c.args << ": " << error.dump();
  }
}

TEST(CliUnits, ChainFileInPhysicalUnits) {
  test::ScratchDir dir;
  // The chain of issue 13: length 0.05 m, EI = 0.02083 N m^2, Fx = -2.5 N, Fy = 4.33 N.
  std::ofstream(dir / "si.toml") << "units = \"SI\"\n[[segment]]\ntype = \"flexible\"\n"
                                    "length = 0.05\nEI = 0.02083\n[tip_load]\nFx = -2.5\n"
                                    "Fy = 4.33\n";
  const Json j = run_json("beam --chain '" + (dir / "si.toml").string() + "'");
  EXPECT_NEAR(j["alpha2"].get<double>(), 4.33 * 0.0025 / 0.02083, 1e-12);
  EXPECT_EQ(j["units"], "SI");
  EXPECT_NEAR(j["tip_y"].get<double>(), j["b_over_l"].get<double>() * 0.05, 1e-15);
  EXPECT_NEAR(j["root_moment_Nm"].get<double>(), j["root_moment_chain_units"].get<double>(), 0);
  EXPECT_TRUE(j["max_stress"].is_null());  // EI only: no section
  // A section needs physical units, and says how to declare them.
  std::ofstream(dir / "plain.toml") << "[[segment]]\ntype = \"flexible\"\nlength = 1\nE = 2\n"
                                       "I = 0.5\n";
  const test::CommandResult r = run_flexure("beam --chain '" + (dir / "plain.toml").string() + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("units = \"SI\""), std::string::npos) << r.err;
  // A modulus in MPa written without its unit.
  std::ofstream(dir / "soft.toml") << "units = \"SI\"\n[[segment]]\ntype = \"flexible\"\n"
                                      "length = 0.05\nE = 200000\nwidth = 0.01\nthickness = "
                                      "0.0005\n[tip_load]\nFy = 1e-6\n";
  const test::CommandResult soft =
      run_flexure("beam --chain '" + (dir / "soft.toml").string() + "'");
  EXPECT_NE(soft.err.find("segment 1.E = 200000 Pa"), std::string::npos) << soft.err;
}

TEST(CliUnits, MechanismFileWithUnitsIsTheSiFile) {
  // docs/examples/mechanism_lpp.toml with every quantity written with a unit.
  test::ScratchDir dir;
  std::ofstream(dir / "lpp.toml") << "config = \"lpp\"\nr2 = \"50 mm\"\nr3 = \"44.3 mm\"\n"
                                     "stroke = \"2 cm\"\n[material]\nE = \"1.4 GPa\"\n"
                                     "yield_strength = \"34.5 MPa\"\n[ground]\n"
                                     "thickness = \"1 mm\"\nwidth = \"10 mm\"\n";
  const std::string si = std::string(FLEXURE_SOURCE_DIR) + "/docs/examples/mechanism_lpp.toml";
  const Json a =
      run_json("mechanism analyze '" + (dir / "lpp.toml").string() + "' --method prbm --points 11");
  const Json b = run_json("mechanism analyze '" + si + "' --method prbm --points 11");
  ASSERT_TRUE(a.contains("force_prbm"));
  for (std::size_t i = 0; i < b["force_prbm"].size(); ++i) {
    EXPECT_NEAR(a["force_prbm"][i].get<double>(), b["force_prbm"][i].get<double>(), 1e-12);
  }
  EXPECT_NEAR(a["max_stress"].get<double>(), b["max_stress"].get<double>(), 1e-3);
  // A modulus in MPa without its unit, a flexure thicker than a tenth of its length: warned.
  std::ofstream(dir / "soft.toml") << "config = \"sss\"\nr2 = 0.0273\nr3 = 0.0727\nstroke = "
                                      "0.016\n[material]\nE = 207000\nyield_strength = 1.2e9\n"
                                      "[ground]\nthickness = 0.5e-3\nwidth = 5e-3\nlength = "
                                      "2.73e-3\n[middle]\nthickness = 0.1e-3\nwidth = 5e-3\n"
                                      "[slider]\nthickness = 0.1e-3\nwidth = 5e-3\n";
  const test::CommandResult soft = run_flexure(
      "mechanism analyze '" + (dir / "soft.toml").string() + "' --method prbm --points 3");
  EXPECT_NE(soft.err.find("material.E = 207000 Pa"), std::string::npos) << soft.err;
  EXPECT_NE(soft.err.find("ground: the thickness 0.0005 m"), std::string::npos) << soft.err;
  EXPECT_EQ(soft.err.find("middle: the thickness"), std::string::npos) << soft.err;
  const test::CommandResult sweep =
      run_flexure("sweep beam --theta0 0.1:45:3 --out '" + (dir / "s.h5").string() + "'");
  EXPECT_NE(sweep.err.find("warning: --theta0 = 45 rad"), std::string::npos) << sweep.err;
  std::ofstream(dir / "bad.toml") << "config = \"lpp\"\nr2 = \"50 N\"\n";
  const test::CommandResult r =
      run_flexure("mechanism analyze '" + (dir / "bad.toml").string() + "'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("r2: '50 N' is a force"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace flexure
