// What is checked against what: `flexure beam` run as a process. JSON values are compared with
// independent references: Howell eqs. 2.90-2.98 evaluated to 7-8 digits (§2.9.2 worked example,
// n = 0 table, and n = 1, -1, 2.5 at theta0 = 0.6 rad), Howell's closed form for a pure end
// moment (eqs. 2.53, 2.59, 2.64) and geometry (the shape starts at the clamp and ends at the
// tip). Bad input must give exit code 2 with one line on stderr naming the input, and nothing on
// stdout.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "flexure/version.h"
#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

using nlohmann::json;

// The reference values carry 8 significant digits: 1e-7 relative only fails on a real error.
constexpr double kEightDigits = 1e-7;
// The theta0 = 0.6 rad rows have 7 decimals: half a unit is up to 1.3e-7 of b/l = 0.3767408.
constexpr double kSevenDecimals = 2e-7;
// Closed forms: the solver's tolerance is 1e-14; allow rounding in trigonometric functions.
constexpr double kClosedForm = 1e-10;

json run_json(const std::string& args) {
  const CommandResult r = run_flexure(args + " --json");
  EXPECT_EQ(r.exit_code, 0) << args << "\nstderr: " << r.err;
  EXPECT_EQ(count_lines(r.out), 1) << "exactly one JSON object on one line: " << r.out;
  EXPECT_TRUE(r.err.empty()) << r.err;
  return json::parse(r.out);
}

void expect_relative(double computed, double reference, double tolerance, const char* what) {
  EXPECT_LE(std::abs(computed - reference), tolerance * std::abs(reference))
      << what << ": computed " << computed << ", reference " << reference;
}

void expect_invalid(const std::string& args, const std::string& must_mention) {
  const CommandResult r = run_flexure(args);
  EXPECT_EQ(r.exit_code, 2) << args << "\nstderr: " << r.err;
  EXPECT_TRUE(test::no_result_on_stdout(r)) << args << " printed on stdout: " << r.out;
  EXPECT_EQ(count_lines(r.err), 1) << "one-line error expected for " << args << ": " << r.err;
  EXPECT_NE(r.err.find(must_mention), std::string::npos)
      << args << ": message should mention '" << must_mention << "': " << r.err;
}

TEST(CliBeam, HowellExampleByTipAngleHasAllKeysAndTheBookValues) {
  const json j = run_json("beam --theta0 1");
  for (const char* key : {"method",
                          "n",
                          "alpha2",
                          "mu",
                          "a_over_l",
                          "b_over_l",
                          "theta0",
                          "iterations",
                          "converged",
                          "branch",
                          "inflection_points",
                          "root_moment",
                          "family",
                          "message"}) {
    EXPECT_TRUE(j.contains(key)) << "missing key " << key;
  }
  EXPECT_FALSE(j.contains("shape")) << "shape only with --shape";
  EXPECT_EQ(j["method"], "elliptic");
  EXPECT_EQ(j["converged"], true);
  EXPECT_EQ(j["n"].get<double>(), 0.0);
  EXPECT_EQ(j["mu"].get<double>(), 0.0);
  expect_relative(std::sqrt(j["alpha2"].get<double>()), 1.7569869, kEightDigits, "alpha");
  expect_relative(j["a_over_l"].get<double>(), 0.7383564, kEightDigits, "a/l");
  expect_relative(j["b_over_l"].get<double>(), 0.6103718, kEightDigits, "b/l");
  expect_relative(j["theta0"].get<double>(), 1.0, kEightDigits, "theta0");
  EXPECT_EQ(j["inflection_points"].get<int>(), 0) << "n = 0 tip load: curvature keeps its sign";
}

TEST(CliBeam, ForwardLoadReproducesTheNZeroTable) {
  const json j = run_json("beam --alpha2 5.4691778 --n 0");
  expect_relative(j["theta0"].get<double>(), 1.25, kEightDigits, "theta0");
  expect_relative(j["a_over_l"].get<double>(), 0.58909259, kEightDigits, "a/l");
  expect_relative(j["b_over_l"].get<double>(), 0.72947569, kEightDigits, "b/l");
  expect_relative(j["alpha2"].get<double>(), 5.4691778, 1e-15, "alpha2 echoes the input");
}

TEST(CliBeam, LoadRatiosAtTipAngleZeroPointSix) {
  struct Row {
    const char* n;
    double alpha, a_over_l, b_over_l;
  };
  for (const Row& row : {Row{"1", 0.9439966, 0.9071300, 0.3809919},
                         Row{"-1", 1.7993680, 0.8975785, 0.4067666},
                         Row{"2.5", 0.7647424, 0.9086205, 0.3767408}}) {
    SCOPED_TRACE(row.n);
    const json j = run_json(std::string("beam --theta0 0.6 --n ") + row.n);
    expect_relative(std::sqrt(j["alpha2"].get<double>()), row.alpha, kSevenDecimals, "alpha");
    expect_relative(j["a_over_l"].get<double>(), row.a_over_l, kSevenDecimals, "a/l");
    expect_relative(j["b_over_l"].get<double>(), row.b_over_l, kSevenDecimals, "b/l");
  }
}

TEST(CliBeam, InverseByDeflectionFindsTheHowellExample) {
  const json j = run_json("beam --b-over-l 0.6103718");
  // b/l has 7 digits; d(theta0)/d(b/l) is about 2 here, so theta0 is good to about 2e-7.
  expect_relative(j["theta0"].get<double>(), 1.0, 1e-6, "theta0");
  expect_relative(j["a_over_l"].get<double>(), 0.7383564, 1e-6, "a/l");
}

TEST(CliBeam, PureEndMomentIsTheCircularArc) {
  const double mu = std::numbers::pi / 2;
  const json j = run_json("beam --alpha2 0 --mu 1.5707963267948966");
  expect_relative(j["theta0"].get<double>(), mu, kClosedForm, "theta0 = mu (eq. 2.53)");
  expect_relative(j["a_over_l"].get<double>(), std::sin(mu) / mu, kClosedForm, "eq. 2.64");
  expect_relative(j["b_over_l"].get<double>(), (1 - std::cos(mu)) / mu, kClosedForm, "eq. 2.59");
  expect_relative(j["root_moment"].get<double>(), mu, kClosedForm, "constant moment");
}

TEST(CliBeam, ShapeStartsAtTheClampAndEndsAtTheTip) {
  const json j = run_json("beam --theta0 1 --shape 11");
  ASSERT_TRUE(j["shape"].is_array());
  ASSERT_EQ(j["shape"].size(), 11u);
  const json& first = j["shape"].front();
  const json& last = j["shape"].back();
  EXPECT_EQ(first["s"].get<double>(), 0.0);
  EXPECT_NEAR(first["x"].get<double>(), 0.0, 1e-14);
  EXPECT_NEAR(first["y"].get<double>(), 0.0, 1e-14);
  EXPECT_NEAR(first["theta"].get<double>(), 0.0, 1e-14);
  EXPECT_NEAR(last["s"].get<double>(), 1.0, 1e-14);
  expect_relative(last["x"].get<double>(), 0.7383564, kEightDigits, "tip x = a/l");
  expect_relative(last["y"].get<double>(), 0.6103718, kEightDigits, "tip y = b/l");
  expect_relative(last["theta"].get<double>(), 1.0, kEightDigits, "tip angle");
  for (std::size_t i = 0; i < 11; ++i) {
    EXPECT_NEAR(j["shape"][i]["s"].get<double>(), i / 10.0, 1e-14) << "equally spaced s";
  }
}

TEST(CliBeam, ReadableReportWithoutJson) {
  const CommandResult r = run_flexure("beam --theta0 1");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("a/l"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("0.73835"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find('{'), std::string::npos) << "not JSON: " << r.out;
}

TEST(CliBeam, NonFiniteInputIsExitTwo) {
  expect_invalid("beam --alpha2 nan", "--alpha2");
  expect_invalid("beam --alpha2 inf", "--alpha2");
  expect_invalid("beam --alpha2 -inf --json", "--alpha2");
  expect_invalid("beam --theta0 nan", "--theta0");
  expect_invalid("beam --alpha2 1 --n nan", "--n");
  expect_invalid("beam --alpha2 1 --mu inf", "--mu");
}

TEST(CliBeam, MissingConflictingAndNonNumericArgumentsAreExitTwo) {
  expect_invalid("beam --alpha2 1 --theta0 1", "--theta0");
  expect_invalid("beam --alpha2 1 --b-over-l 0.5 --json", "--b-over-l");
  expect_invalid("beam --n 1", "--alpha2");
  expect_invalid("beam --alpha2 abc", "abc");
  expect_invalid("beam --alpha2 1 --bogus", "--bogus");
  expect_invalid("", "subcommand");
}

TEST(CliBeam, UnreachableTipAngleIsExitTwo) {
  // n = 0, mu = 0: the tip angle stays below the force angle pi/2 (Howell eq. 2.90, theta0 < phi1).
  expect_invalid("beam --n 0 --theta0 2.0", "theta0");
  expect_invalid("beam --n 0 --theta0 2.0 --json", "theta0");
}

TEST(CliBeam, UnknownOrUnavailableMethodIsExitTwo) {
  expect_invalid("beam --alpha2 1 --method foo", "foo");
  // The elliptic method solves only the free cantilever with dead loads.
  expect_invalid("beam --alpha2 1 --method elliptic --follower 1", "shooting or chain method");
}

TEST(CliBeam, ExplicitEllipticMethodEqualsAuto) {
  const json a = run_json("beam --theta0 0.5 --method auto");
  const json e = run_json("beam --theta0 0.5 --method elliptic");
  EXPECT_EQ(a["method"], "elliptic");
  EXPECT_EQ(a["alpha2"], e["alpha2"]);
}

TEST(CliBeam, NoConvergedSolutionIsExitThreeWithAOneLineReason) {
  // n = 1 with a large end moment and a reversed load: the beam rolls up more than four turns and
  // the path passes eight limit points (elliptic and shooting agree on the end state), which the
  // chain algorithm's load increments cannot follow.
  for (const char* json_flag : {"", " --json"}) {
    const CommandResult r =
        run_flexure(std::string("beam --method chain --n 1 --alpha2 -50 --mu 30") + json_flag);
    EXPECT_EQ(r.exit_code, 3) << r.err;
    EXPECT_TRUE(test::no_result_on_stdout(r)) << "no result may be printed: " << r.out;
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("chain"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("no converged solution"), std::string::npos) << r.err;
  }
}

TEST(CliBeam, ShapeCountOutOfRangeIsExitTwo) {
  expect_invalid("beam --alpha2 1 --shape 1", "--shape");
  expect_invalid("beam --alpha2 1 --shape -5", "--shape");
}

TEST(CliBeam, VersionNamesVersionAndCommit) {
  const CommandResult r = run_flexure("--version");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find(kVersion), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(kGitCommit), std::string::npos) << r.out;
}

}  // namespace
}  // namespace flexure::test
