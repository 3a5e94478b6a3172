// `flexure beam --method linear|prbm3r|bcm|cbcm` (docs/models.md, docs/cli.md):
// - every method prints the keys of the exact methods (reactions included) and its own;
// - at a small load each gives linear theory's b/l = alpha2/3 + mu/2 (PR-3R: its own 0.34066);
// - `--chain FILE --method cbcm|bcm` against the shooting method on the same file (tip and
//   reactions), for the example chains of docs/examples;
// - --elements, --constants, --slenderness change what they should and are refused elsewhere;
// - a load a model cannot represent exits 2 with the reason and the model that can.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/support/cli_test_support.h"

namespace flexure {
namespace {

using test::expect_refused;
using test::run_flexure;
using Json = nlohmann::json;

Json run_json(const std::string& args) {
  const test::CommandResult r = run_flexure(args + " --json");
  EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
  return r.exit_code == 0 ? Json::parse(r.out) : Json::object();
}

const std::string kExamples = std::string(FLEXURE_SOURCE_DIR) + "/docs/examples/";

TEST(CliLadder, EveryModelPrintsTheKeysOfTheExactMethods) {
  const Json shooting = run_json("beam --alpha2 1.5 --mu 0.3 --method shooting");
  for (const char* method : {"linear", "prbm3r", "bcm", "cbcm"}) {
    SCOPED_TRACE(method);
    const Json j = run_json(fmt::format("beam --alpha2 1.5 --mu 0.3 --method {}", method));
    EXPECT_EQ(j["method"], method);
    EXPECT_EQ(j["method_reason"], fmt::format("requested: {}", method));
    EXPECT_EQ(j["termination"], "converged");
    for (const auto& [key, value] : shooting.items()) {
      EXPECT_TRUE(j.contains(key)) << key;
    }
    for (const char* r : {"Fx", "Fy", "M"}) EXPECT_TRUE(j["reactions"][r].is_number()) << r;
    // Statics of the whole beam: the clamp holds the tip force.
    EXPECT_NEAR(j["reactions"]["Fy"].get<double>(), -1.5, 1e-12);
  }
  EXPECT_EQ(run_json("beam --alpha2 1 --method prbm3r")["constants"], "su");
  const Json c = run_json("beam --alpha2 1 --method cbcm");
  EXPECT_EQ(c["elements"], 6);
  EXPECT_TRUE(c["within_validity"].is_boolean());
  EXPECT_TRUE(c["max_element_deflection"].is_number());
  EXPECT_TRUE(c["slenderness"].is_null());
  EXPECT_EQ(run_json("beam --alpha2 1 --method bcm")["elements"], 1);
}

TEST(CliLadder, SmallLoadsGiveLinearTheory) {
  const double a = 1e-5, mu = 2e-5;
  for (const char* method : {"linear", "bcm", "cbcm", "elliptic"}) {
    const Json j = run_json(fmt::format("beam --alpha2 {} --mu {} --method {}", a, mu, method));
    EXPECT_NEAR(j["b_over_l"].get<double>(), a / 3.0 + mu / 2.0, 1e-9) << method;
    EXPECT_NEAR(j["theta0"].get<double>(), a / 2.0 + mu, 1e-9) << method;
  }
  // PR-3R with Su's constants: b = 0.34066 alpha2 (2.2 % soft); with flexure's own, alpha2/3
  // within 0.2 %.
  const Json su = run_json(fmt::format("beam --alpha2 {} --method prbm3r", a));
  EXPECT_NEAR(su["b_over_l"].get<double>() / a, 0.34066, 1e-5);
  const Json own = run_json(fmt::format("beam --alpha2 {} --method prbm3r --constants flexure", a));
  EXPECT_EQ(own["constants"], "flexure");
  EXPECT_NEAR(own["b_over_l"].get<double>() / a * 3.0, 1.0, 2e-3);
}

TEST(CliLadder, ChainFilesAgreeWithTheShootingMethod) {
  for (const char* file : {"fixed_guided_beam.toml", "inclined_flexure_links.toml"}) {
    SCOPED_TRACE(file);
    const std::string chain = "beam --chain " + kExamples + file;
    const Json exact = run_json(chain + " --method shooting");
    const Json cbcm = run_json(chain + " --method cbcm --elements 32");
    for (const char* key : {"a_over_l", "b_over_l", "theta0"}) {
      EXPECT_NEAR(cbcm[key].get<double>(), exact[key].get<double>(), 1e-5) << key;
    }
    for (const char* r : {"Fx", "Fy", "M"}) {
      const double e = exact["reactions_chain_units"][r].get<double>();
      EXPECT_NEAR(
          cbcm["reactions_chain_units"][r].get<double>(), e, 1e-4 * std::max(1.0, std::fabs(e)))
          << r;
    }
    // Six elements (the default) and one (the BCM) are further off, in that order.
    const Json six = run_json(chain + " --method cbcm");
    const Json one = run_json(chain + " --method bcm");
    const double e32 = std::fabs(cbcm["theta0"].get<double>() - exact["theta0"].get<double>()) +
                       std::fabs(cbcm["b_over_l"].get<double>() - exact["b_over_l"].get<double>());
    const double e6 = std::fabs(six["theta0"].get<double>() - exact["theta0"].get<double>()) +
                      std::fabs(six["b_over_l"].get<double>() - exact["b_over_l"].get<double>());
    const double e1 = std::fabs(one["theta0"].get<double>() - exact["theta0"].get<double>()) +
                      std::fabs(one["b_over_l"].get<double>() - exact["b_over_l"].get<double>());
    EXPECT_LT(e32, e6);
    EXPECT_LT(e6, e1);
  }
}

TEST(CliLadder, GuidedAndPrescribedEnds) {
  // Fixed-guided beam b = alpha2/12 at small loads, and the guide's moment alpha2/2.
  for (const char* method : {"linear", "bcm", "cbcm"}) {
    const Json j =
        run_json(fmt::format("beam --boundary guided --alpha2 1e-5 --method {}", method));
    EXPECT_NEAR(j["b_over_l"].get<double>(), 1e-5 / 12.0, 1e-11) << method;
    EXPECT_NEAR(j["theta0"].get<double>(), 0.0, 1e-14) << method;
    EXPECT_NEAR(-j["reactions"]["M"].get<double>(), 0.5e-5, 1e-10) << method;
  }
  // A fixed end under displacement control: the tip is where prescribed; the reactions, set by the
  // axial force, converge more slowly than the tip (6 elements: 2.6 % off in M; 16: 0.2 %).
  const Json fixed = run_json(
      "beam --boundary fixed --alpha2 0 --tip-x 0.95 --tip-y 0.3 --tip-angle 0.2 --method cbcm "
      "--elements 16");
  EXPECT_NEAR(fixed["a_over_l"].get<double>(), 0.95, 1e-10);
  EXPECT_NEAR(fixed["b_over_l"].get<double>(), 0.3, 1e-10);
  const Json exact = run_json(
      "beam --boundary fixed --alpha2 0 --tip-x 0.95 --tip-y 0.3 --tip-angle 0.2 --method "
      "shooting");
  EXPECT_NEAR(fixed["reactions"]["M"].get<double>(),
              exact["reactions"]["M"].get<double>(),
              0.005 * std::fabs(exact["reactions"]["M"].get<double>()));
}

TEST(CliLadder, InverseProblemsReachTheirTarget) {
  for (const char* method : {"linear", "prbm3r", "bcm", "cbcm"}) {
    const Json j = run_json(fmt::format("beam --theta0 0.3 --method {}", method));
    EXPECT_NEAR(j["theta0"].get<double>(), 0.3, 1e-9) << method;
    EXPECT_LT(j["target_residual"].get<double>(), 1e-9) << method;
  }
  // Linear theory: theta0 = alpha2/2.
  EXPECT_NEAR(run_json("beam --theta0 0.3 --method linear")["alpha2"].get<double>(), 0.6, 1e-9);
}

TEST(CliLadder, SlendernessMakesTheBcmExtensible) {
  // An axial pull alone (as a chain: no Howell n): a = 1 + p/d, d = 12 (L/t)^2 = 1200 at L/t = 10.
  const Json j = run_json(fmt::format("beam --chain {}steel_strip.toml --method bcm", kExamples));
  EXPECT_TRUE(j["slenderness"].is_null());
  const Json pulled = run_json(
      "beam --boundary guided --alpha2 1e-9 --n -1e9 --method bcm "
      "--slenderness 10");
  EXPECT_NEAR(pulled["a_over_l"].get<double>(), 1.0 + 1.0 / 1200.0, 1e-9);
  EXPECT_EQ(pulled["slenderness"], 10.0);
}

TEST(CliLadder, ChainSegmentsEAMakesTheChainedBcmExtensible) {
  // docs/examples/inclined_bistable_path.toml (EA given) with its shuttle moved from 6.709 mm to
  // 2 mm, past the beam's buckling: the CBCM (24 elements) against the shooting method's
  // extensible beam; the reactions converge as the elements' h^2 or faster (ladder_models_test).
  std::string text = test::read_text(kExamples + "inclined_bistable_path.toml");
  text += "\n[tip]\ny = \"2 mm\"\n";
  const test::ScratchDir dir;
  const std::string file = (dir / "inclined_2mm.toml").string();
  {
    std::ofstream out(file);
    out << text;
  }
  const std::string chain = "beam --chain " + file;
  const Json exact = run_json(chain + " --method shooting");
  const Json cbcm = run_json(chain + " --method cbcm --elements 24");
  EXPECT_EQ(cbcm["termination"], "converged");
  // d = EA L^2/EI with the file's EA = E b h = 25959.675 N and EI = E b h^3/12.
  const double EI = 1.379e9 * 12.55e-3 * std::pow(1.5e-3, 3) / 12.0;
  EXPECT_NEAR(cbcm["axial_stiffness_d"].get<double>(), 25959.675 * 0.07 * 0.07 / EI, 1e-8);
  EXPECT_TRUE(cbcm["slenderness"].is_null());
  for (const char* r : {"Fx", "Fy"}) {
    const double e = exact["reactions_chain_units"][r].get<double>();
    EXPECT_NEAR(cbcm["reactions_chain_units"][r].get<double>(), e, 2e-4 * 52.66) << r;
  }
  // EA and --slenderness both set d: refused, naming both.
  expect_refused(chain + " --method cbcm --slenderness 46.667", {"EA = 25959.7", "slenderness"});
  // An inextensible chain's JSON says so.
  EXPECT_TRUE(run_json("beam --chain " + kExamples +
                       "fixed_guided_beam.toml --method cbcm")["axial_stiffness_d"]
                  .is_null());
}

TEST(CliLadder, RefusalsNameTheReasonAndTheModelThatCan) {
  expect_refused("beam --method prbm --alpha2 2 --mu 1", {"not both", "prbm3r", "cbcm"});
  expect_refused("beam --method linear --boundary pinned --tip-y 0.1 --alpha2 0",
                 {"pinned", "cbcm", "shooting"});
  expect_refused("beam --method prbm3r --boundary fixed --tip-y 0.1 --alpha2 0", {"fixed", "cbcm"});
  expect_refused("beam --method bcm --alpha2 3 --n 1", {"buckling", "cbcm"});
  expect_refused("beam --method cbcm --alpha2 1 --follower 1", {"dead loads", "shooting"});
  expect_refused("beam --method linear --chain " + kExamples + "fixed_guided_beam.toml",
                 {"segment chain", "cbcm"});
  expect_refused("beam --method cbcm --chain " + kExamples + "two_flexures_rigid_link.toml",
                 {"2 flexible segments", "shooting"});
  // A distributed load (self-weight) is not an end load: refused, not dropped.
  expect_refused("beam --method cbcm --chain " + kExamples + "self_weight_cantilever.toml",
                 {"distributed", "shooting"});
  expect_refused("beam --method bcm --alpha2 1 --elements 4", {"--elements", "cbcm"});
  expect_refused("beam --method cbcm --alpha2 1 --elements 0", {"--elements"});
  expect_refused("beam --method cbcm --alpha2 1 --constants flexure", {"--constants", "PR-3R"});
  expect_refused("beam --method linear --alpha2 1 --slenderness 20", {"--slenderness"});
  expect_refused("beam --method cbcm --alpha2 1 --slenderness -3", {"--slenderness"});
  expect_refused("beam --method prbm3r --alpha2 1 --boundary guided --mu 1", {"guided", "mu"});
  // With --json the refusal is a JSON error object.
  const test::CommandResult r = run_flexure("beam --method bcm --alpha2 3 --n 1 --json");
  EXPECT_EQ(r.exit_code, 2);
  const Json e = Json::parse(r.out);
  EXPECT_EQ(e["exit_code"], 2);
  EXPECT_NE(e["error"].get<std::string>().find("buckling"), std::string::npos);
}

}  // namespace
}  // namespace flexure
