// What is checked against what: the command-line side of the robustness reproducers (wrong
// branches, inverse misses, ranges; docs/theory-elliptic.md), run as a process. Values are compared
// with another method's answer (elliptic against shooting or chain), with the target of an inverse
// problem, or with the documented exit code and a message that names what went wrong:
//  * inverse problems: a converged answer reaches its target (target_residual within 1e-10 /
//    1e-8); a miss is exit 3 naming what was reached, an unreachable target exit 2;
//  * a load beyond the elliptic solver's range: `--method elliptic` says which method reaches
//    further (exit 2), `auto` uses it;
//  * strong tension and a chain whose shape point coincides with a shooting cut (CV_TOO_CLOSE)
//    are solved and agree with the exact or chain answer;
//  * an unreachable pinned target is exit 2 before any solve;
//  * limit points passed by the elliptic solver are in the JSON.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

using nlohmann::json;

json run_json(const std::string& args) {
  const CommandResult r = run_flexure(args + " --json");
  EXPECT_EQ(r.exit_code, 0) << args << "\nstderr: " << r.err;
  return r.exit_code == 0 ? json::parse(r.out) : json::object();
}

TEST(CliBeamRobustness, InverseAnswersCarryTheirResidual) {
  for (const char* method : {"elliptic", "shooting", "chain"}) {
    const json j = run_json(std::string("beam --method ") + method + " --n 1 --theta0 0.6");
    ASSERT_TRUE(j.contains("target_residual")) << method;
    EXPECT_LE(j["target_residual"].get<double>(), 1e-8) << method;
    EXPECT_NEAR(j["theta0"].get<double>(), 0.6, 1e-8) << method;
  }
  // A forward solve has no target.
  EXPECT_TRUE(run_json("beam --n 1 --alpha2 2")["target_residual"].is_null());
}

TEST(CliBeamRobustness, AnInverseMissIsExitThreeNamingWhatWasReached) {
  const CommandResult r = run_flexure(
      "beam --method elliptic --n 14.174796494879462 --theta0 1.0053858735474077 --mu "
      "-1.527731579147511 --json");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_TRUE(test::no_result_on_stdout(r)) << r.out;
  const std::string all = r.out + r.err;
  EXPECT_NE(all.find("jumps across the target"), std::string::npos) << all;
}

TEST(CliBeamRobustness, UnreachableTargetsAreExitTwo) {
  for (const char* args : {"beam --method chain --n 13.981339484676916 --theta0 -1.691380594686975",
                           "beam --method shooting --n -1 --theta0 2.026156500895776"}) {
    const CommandResult r = run_flexure(args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find("cannot be reached"), std::string::npos) << r.err;
  }
}

TEST(CliBeamRobustness, BeyondTheEllipticRangeAutoUsesShooting) {
  // |F| l^2/EI = 1.05e4 > 1e4, the elliptic solver's range.
  const CommandResult elliptic = run_flexure("beam --method elliptic --n -1 --alpha2 7425");
  EXPECT_EQ(elliptic.exit_code, 2) << elliptic.err;
  EXPECT_NE(elliptic.err.find("shooting"), std::string::npos) << elliptic.err;
  const json automatic = run_json("beam --n -1 --alpha2 7425");
  EXPECT_EQ(automatic["method"], "shooting");
  EXPECT_NE(automatic["method_reason"].get<std::string>().find("elliptic"), std::string::npos);
  // Strong tension: the tip lines up with the force within a boundary layer of width 1/sqrt(F):
  // theta0 = pi/4 for n = -1 to about 1e-9.
  EXPECT_NEAR(automatic["theta0"].get<double>(), std::atan(1.0), 1e-6);
}

TEST(CliBeamRobustness, StrongTensionIsSolvedByShooting) {
  // Exited 3 "load path turned back below zero load"; the elliptic solver answers too.
  const json s = run_json("beam --method shooting --n -50 --alpha2 10");
  const json e = run_json("beam --method elliptic --n -50 --alpha2 10");
  EXPECT_NEAR(s["a_over_l"].get<double>(), e["a_over_l"].get<double>(), 1e-9);
  EXPECT_NEAR(s["b_over_l"].get<double>(), e["b_over_l"].get<double>(), 1e-9);
  EXPECT_NEAR(s["theta0"].get<double>(), e["theta0"].get<double>(), 1e-9);
}

TEST(CliBeamRobustness, ChainUnderStrongTensionIsSolvedWithAuto) {
  // Fx = 1000 on the two-flexure chain: shooting reached full load, then its shape integration
  // failed with CV_TOO_CLOSE where a shape point met a shooting cut. The chain algorithm is the
  // independent answer.
  ScratchDir dir;
  const auto toml = dir / "tension.toml";
  std::ofstream(toml) << "boundary = \"free\"\n"
                         "[[segment]]\ntype = \"flexible\"\nlength = 0.3\nEI = 1.0\n"
                         "[[segment]]\ntype = \"rigid\"\nlength = 0.4\n"
                         "[[segment]]\ntype = \"flexible\"\nlength = 0.3\nEI = 1.0\n"
                         "[tip_load]\nFx = 1000.0\nFy = 2.0\nM = 0.0\n";
  const json automatic = run_json("beam --chain '" + toml.string() + "'");
  EXPECT_EQ(automatic["method"], "shooting");
  const json chain = run_json("beam --method chain --elements 400 --chain '" + toml.string() + "'");
  EXPECT_NEAR(automatic["b_over_l"].get<double>(), chain["b_over_l"].get<double>(), 1e-6);
}

TEST(CliBeamRobustness, UnreachablePinnedTargetIsExitTwoAtOnce) {
  // (0.6, 0.8) is one length from the clamp, 53 deg off its tangent; it ran 730 iterations.
  for (const char* method : {"shooting", "chain"}) {
    const CommandResult r =
        run_flexure(std::string("beam --boundary pinned --alpha2 0 --tip-x 0.6 --tip-y 0.8 "
                                "--method ") +
                    method);
    EXPECT_EQ(r.exit_code, 2) << method << ": " << r.err;
    EXPECT_NE(r.err.find("cannot be reached"), std::string::npos) << r.err;
  }
}

TEST(CliBeamRobustness, LimitPointsPassedAreReported) {
  // n = -1, alpha2 = 3.9965, mu = 2 pi: an S-shaped fold near lambda = 0.8907; elliptic and
  // shooting pass it and end on the same equilibrium.
  const std::string load = " --n -1 --alpha2 3.996521110664009 --mu 6.283185307179586";
  const json e = run_json("beam --method elliptic" + load);
  const json s = run_json("beam --method shooting" + load);
  EXPECT_EQ(e["limit_points"].get<int>(), 2);
  EXPECT_GE(s["limit_points"].get<int>(), 1);
  EXPECT_NEAR(e["first_limit_load_factor"].get<double>(), 0.8907, 5e-4);
  EXPECT_NEAR(e["theta0"].get<double>(), s["theta0"].get<double>(), 1e-9);
}

}  // namespace
}  // namespace flexure::test
