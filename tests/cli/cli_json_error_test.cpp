// What is checked against what, through the built tool:
//  * with --json every failure prints exactly one JSON object on stdout, {"error", "exit_code",
//    ...}, with the exit code the process returns (2 invalid input, including parse errors; 3 no
//    converged solution, with what was reached: method, termination, load factor); without --json
//    stdout stays empty and the message goes to stderr;
//  * a PRBM result states its validity: within_validity, the PRB angle Theta and the limit used
//    (Howell Table 5.1, n = 0: Theta_max = min(64.3, 58.5) deg), with a warning on stderr outside
//    it; Theta solves the PRBM's equilibrium K_theta Theta = alpha2 cos Theta (Howell eq. 5.35
//    for a transverse force, n = 0) with the Table 5.1 K_theta;
//  * auto that meets a fold tries the shooting method too and says so.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "flexure/elements/prbm_element.h"
#include "tests/support/cli_test_support.h"

namespace flexure {
namespace {

using test::run_flexure;
using Json = nlohmann::json;

// The fold case of tests/solver/inverse_random_test.cpp: theta0 jumps across the target between
// alpha2 = 2.2 and 3.3, so no load reaches it.
const std::string kFoldInverse =
    "beam --n 14.174796494879462 --theta0 1.0053858735474077 --mu -1.527731579147511";

Json only_json_line(const test::CommandResult& r) {
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  return Json::parse(r.out);
}

TEST(CliJsonError, InvalidInputAndParseErrorsPrintOneErrorObject) {
  for (const char* args : {"beam --alpha2 nan --json",
                           "beam --alpha 2 --json",
                           "beam --alpha2 1 --method fem --json"}) {
    const test::CommandResult r = run_flexure(args);
    ASSERT_EQ(r.exit_code, 2) << args;
    const Json j = only_json_line(r);
    EXPECT_EQ(j["exit_code"], 2) << args;
    EXPECT_FALSE(j["error"].get<std::string>().empty()) << args;
    EXPECT_NE(r.err.find("flexure: "), std::string::npos) << "stderr keeps the message";
  }
  EXPECT_NE(
      only_json_line(run_flexure("beam --alpha2 nan --json"))["error"].get<std::string>().find(
          "alpha2"),
      std::string::npos);
}

TEST(CliJsonError, NoConvergenceSaysWhatWasReached) {
  const test::CommandResult r = run_flexure(kFoldInverse + " --method elliptic --json");
  ASSERT_EQ(r.exit_code, 3) << r.err;
  const Json j = only_json_line(r);
  EXPECT_EQ(j["exit_code"], 3);
  EXPECT_EQ(j["method"], "elliptic");
  EXPECT_EQ(j["termination"], "limit_point");
  EXPECT_TRUE(j.contains("load_factor"));
  EXPECT_NE(j["error"].get<std::string>().find("jumps across the target"), std::string::npos);
}

TEST(CliJsonError, WithoutJsonStdoutStaysEmpty) {
  const test::CommandResult r = run_flexure(kFoldInverse + " --method elliptic");
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_NE(r.err.find("jumps across the target"), std::string::npos) << r.err;
}

TEST(CliJsonError, AutoTriesShootingAfterTheEllipticMethodFails) {
  const test::CommandResult r = run_flexure(kFoldInverse + " --json");
  ASSERT_EQ(r.exit_code, 3) << r.err;
  const Json j = only_json_line(r);
  EXPECT_EQ(j["method"], "shooting");
  EXPECT_EQ(j["termination"], "limit_point");
  const std::string reason = j["method_reason"].get<std::string>();
  EXPECT_NE(reason.find("the elliptic method did not converge"), std::string::npos) << reason;
  EXPECT_NE(reason.find("did not converge either"), std::string::npos) << reason;
}

TEST(CliPrbmValidity, EveryPrbmResultStatesItsValidity) {
  constexpr double kDeg = std::numbers::pi / 180.0;
  const double K_theta = FixedPinnedConstants::from_table(0.0).K_theta;
  for (double alpha2 : {3.0, 30.0}) {
    const test::CommandResult r =
        run_flexure("beam --method prbm --json --alpha2 " + std::to_string(alpha2));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Json j = Json::parse(r.out);
    const double Theta = j["Theta"].get<double>();
    EXPECT_NEAR(K_theta * Theta, alpha2 * std::cos(Theta), 1e-9) << "alpha2 = " << alpha2;
    // Table 5.1, n = 0: Theta_max(gamma) = 64.3 deg, Theta_max(K_theta) = 58.5 deg.
    EXPECT_NEAR(j["theta_max"].get<double>(), 58.5 * kDeg, 1e-9);
    const bool inside = Theta <= 58.5 * kDeg;
    EXPECT_EQ(j["within_validity"].get<bool>(), inside) << "alpha2 = " << alpha2;
    EXPECT_EQ(inside, alpha2 == 3.0);
    EXPECT_EQ(r.err.find("warning") != std::string::npos, !inside) << r.err;
  }
}

}  // namespace
}  // namespace flexure
