// What is checked against what: `flexure beam --method auto --tol` through the built tool.
//  * With --tol 1e-2 inside the PRBM validity range the JSON says method "prbm" and a reason; the
//    tip it prints agrees with the exact elliptic tip (`--method elliptic`, an independent
//    solver) within that tolerance relative to the deflection.
//  * With the default tolerance auto gives the elliptic tip; off the free cantilever, shooting.
//  * --tol 0 and --tol with a named method are refused (exit 2) saying why.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

constexpr double kLooseTolerance = 1e-2;  // the --tol given to auto

nlohmann::json beam_json(const std::string& args) {
  const CommandResult r = run_flexure("beam " + args + " --json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return nlohmann::json::parse(r.out.empty() ? "{}" : r.out);
}

TEST(AutoMethodCli, LooseToleranceInsideValidityPicksPrbm) {
  const nlohmann::json prbm = beam_json("--alpha2 3 --method auto --tol 1e-2");
  const nlohmann::json exact = beam_json("--alpha2 3 --method elliptic");
  ASSERT_EQ(prbm.value("method", ""), "prbm") << prbm.dump();
  EXPECT_NE(prbm.value("method_reason", "").find("Theta_max"), std::string::npos);
  const double deflection =
      std::hypot(exact["a_over_l"].get<double>() - 1.0, exact["b_over_l"].get<double>());
  const double error = std::hypot(prbm["a_over_l"].get<double>() - exact["a_over_l"].get<double>(),
                                  prbm["b_over_l"].get<double>() - exact["b_over_l"].get<double>());
  EXPECT_LE(error / deflection, kLooseTolerance);
}

TEST(AutoMethodCli, DefaultToleranceAndOtherBoundariesPickExactMethods) {
  EXPECT_EQ(beam_json("--alpha2 3").value("method", ""), "elliptic");
  EXPECT_EQ(beam_json("--alpha2 3 --tol 1e-2 --boundary guided").value("method", ""), "shooting");
  const CommandResult zero = run_flexure("beam --alpha2 3 --tol 0");
  EXPECT_EQ(zero.exit_code, 2);
  EXPECT_NE(zero.err.find("--tol must be a finite relative error > 0"), std::string::npos)
      << zero.err;
  // --tol means one thing (the error auto allows); with a named method it is refused, saying why.
  const CommandResult named = run_flexure("beam --alpha2 3 --method elliptic --tol 1e-3");
  EXPECT_EQ(named.exit_code, 2);
  EXPECT_NE(named.err.find("--method elliptic works to its own tolerance"), std::string::npos)
      << named.err;
  EXPECT_NE(named.err.find("--method auto"), std::string::npos) << named.err;
  const CommandResult mechanism = run_flexure("mechanism analyze 1A-lpp --method exact --tol 0.1");
  EXPECT_EQ(mechanism.exit_code, 2);
  EXPECT_NE(mechanism.err.find("--method exact works to its own tolerance"), std::string::npos)
      << mechanism.err;
}

}  // namespace
}  // namespace flexure::test
