// Distributed loads and extensible beams through the tool (docs/cli.md, docs/distributed-loads.md,
// docs/extensible.md):
//   * the self-weight example file: small-load limit of a short strip against q L^4/(8 EI) and
//     q L^2/2, and the flags (--density) against the equivalent TOML file (two input paths);
//   * an extensible bar under an axial force: tip x = L + F L/EA, strain F/EA, stress F/A;
//   * the chain method on the self-weight example converges to the shooting answer (lumped loads);
//   * methods that cannot model them are refused (exit 2).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/cli_test_support.h"

namespace flexure {
namespace {

using test::run_flexure;
using Json = nlohmann::json;

Json run_json(const std::string& args) {
  const test::CommandResult r = run_flexure(args + " --json");
  EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err << r.out;
  return r.exit_code == 0 ? Json::parse(r.out) : Json::object();
}

const std::string kExample =
    std::string(FLEXURE_SOURCE_DIR) + "/docs/examples/self_weight_cantilever.toml";

TEST(CliDistributed, SelfWeightSmallLoadLimitAndFlagsMatchTheFile) {
  // 50 mm of the example's strip: w = q L^3/EI = 2.3e-3, linear theory to ~w^2.
  const double L = 0.05, b = 0.02, h = 0.0005, E = 200e9, rho = 7850.0, g = 9.80665;
  const double EI = E * b * h * h * h / 12.0, q = rho * b * h * g;
  const Json flags =
      run_json("beam --length 50mm --E 200GPa --width 20mm --thickness 0.5mm --density 7850");
  ASSERT_FALSE(flags.empty());
  EXPECT_NEAR(flags["tip_y"].get<double>() / (-q * L * L * L * L / (8.0 * EI)), 1.0, 1e-4);
  EXPECT_NEAR(flags["root_moment_Nm"].get<double>() / (-q * L * L / 2.0), 1.0, 1e-4);
  EXPECT_NEAR(flags["qy_N_per_m"].get<double>(), -q, 1e-12);
  EXPECT_TRUE(flags["alpha2"].is_null());
  // The same beam from a TOML file.
  test::ScratchDir dir;
  const std::string file = (dir / "strip.toml").string();
  std::ofstream(file) << "units = \"SI\"\n[[segment]]\ntype = \"flexible\"\nlength = \"50 mm\"\n"
                         "E = \"200 GPa\"\nwidth = \"20 mm\"\nthickness = \"0.5 mm\"\n"
                         "density = 7850\n";
  const Json toml = run_json("beam --chain " + file);
  ASSERT_FALSE(toml.empty());
  EXPECT_NEAR(toml["tip_y"].get<double>(), flags["tip_y"].get<double>(), 1e-15);
  EXPECT_NEAR(toml["max_stress"].get<double>(),
              flags["max_stress"].get<double>(),
              1e-9 * flags["max_stress"].get<double>());
}

TEST(CliDistributed, ExtensibleBarStretchesByFLOverEA) {
  const double L = 0.01, A = 4e-6, E = 200e9, F = 1000.0;
  const Json j = run_json(
      "beam --length 10mm --E 200GPa --width 2mm --thickness 2mm --Fx 1000N --extensible --nu 0.3");
  ASSERT_FALSE(j.empty());
  EXPECT_NEAR(j["tip_x"].get<double>(), L + F * L / (E * A), 1e-15);
  EXPECT_NEAR(j["max_axial_strain"].get<double>(), F / (E * A), 1e-12);
  EXPECT_NEAR(j["max_axial_force_N"].get<double>(), F, 1e-8);
  EXPECT_NEAR(j["max_stress"].get<double>(), F / A, 1e-6 * F / A);
  EXPECT_NEAR(j["EA_N"].get<double>(), E * A, 1e-3);
}

TEST(CliDistributed, ChainMethodLumpsTheSelfWeight) {
  const Json shooting = run_json("beam --chain " + kExample);
  const Json chain = run_json("beam --chain " + kExample + " --method chain --elements 400");
  ASSERT_FALSE(shooting.empty());
  ASSERT_FALSE(chain.empty());
  // Second order in N: ~(1/400)^2 of the deflection.
  EXPECT_NEAR(chain["tip_y"].get<double>(), shooting["tip_y"].get<double>(), 1e-5 * 0.5);
  EXPECT_LT(shooting["tip_y"].get<double>(), -0.1);  // a large deflection (~0.33 L)
}

TEST(CliDistributed, UnsupportedMethodsAreRefused) {
  for (const std::string args :
       {"beam --chain " + kExample + " --method elliptic",
        "beam --chain " + kExample + " --method prbm",
        std::string("beam --length 50mm --E 200GPa --width 20mm --thickness 0.5mm --q-follower 1 "
                    "--method chain"),
        std::string("beam --length 50mm --E 200GPa --I 1e-12 --density 7850"),
        std::string("beam --length 50mm --E 200GPa --width 20mm --thickness 0.5mm --extensible")}) {
    const test::CommandResult r = run_flexure(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
  }
}

}  // namespace
}  // namespace flexure
