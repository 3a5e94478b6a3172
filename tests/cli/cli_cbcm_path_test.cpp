// `flexure path --method cbcm|bcm --control ...` (elements/cbcm_path.h; docs/models.md "Paths
// under displacement control"): the inclined bistable beam of docs/examples/
// inclined_bistable_path.toml against the shooting method's path (docs/paths.md, measured to 7
// digits), CBCM's convergence as N grows, the BCM stopping where it leaves its stated range, the
// same JSON keys and HDF5 layout as the shooting path.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/cli_test_support.h"

namespace flexure {
namespace {

using test::run_flexure;

// The shooting path (docs/paths.md "Example: the inclined bistable beam"), d = the shuttle's
// travel from y0 = L sin 5.5 deg, force = -tip_Fy.
constexpr double kY0 = 0.0067092027;  // m
constexpr double kBuckle = 1.289366e-3, kPush = 3.045947;
constexpr double kUnstableZero = 6.709203e-3;
constexpr double kPullAt = 8.046628e-3, kPull = -0.562119;
constexpr double kStableZero = 9.696183e-3;

std::string command(const std::string& method) {
  return fmt::format(
      "path --chain {}/docs/examples/inclined_bistable_path.toml --control tip-y --tip-y "
      "-0.0052907973 --branch 1 --one-way --min-points 121 --method {} --json",
      FLEXURE_SOURCE_DIR,
      method);
}

struct Landmarks {
  double buckle = NAN, push = NAN, unstable_zero = NAN, pull_at = NAN, pull = NAN,
         stable_zero = NAN;
};

// The force points in path order: the first minimum of tip_Fy (buckling), the zeros and the
// largest pull (the maximum of tip_Fy of smallest value... the one after the unstable zero).
Landmarks landmarks(const nlohmann::json& j) {
  Landmarks m;
  int zeros = 0;
  for (const auto& p : j["force_points"]) {
    const double d = kY0 - p["coordinate"].get<double>(), f = -p["force"].get<double>();
    const std::string kind = p["kind"];
    if (kind == "force_minimum" && std::isnan(m.buckle)) {
      m.buckle = d;
      m.push = f;
    } else if (kind == "force_zero") {
      (zeros++ == 0 ? m.unstable_zero : m.stable_zero) = d;
    } else if (kind == "force_maximum" && zeros == 1 && (std::isnan(m.pull) || f < m.pull)) {
      m.pull_at = d;
      m.pull = f;
    }
  }
  EXPECT_EQ(zeros, 2) << "the force changes sign twice (bistable)";
  return m;
}

double largest_error(const Landmarks& m) {
  return std::max({std::fabs(m.buckle - kBuckle) / kBuckle,
                   std::fabs(m.push - kPush) / kPush,
                   std::fabs(m.unstable_zero - kUnstableZero) / kUnstableZero,
                   std::fabs(m.pull_at - kPullAt) / kPullAt,
                   std::fabs(m.pull - kPull) / std::fabs(kPull),
                   std::fabs(m.stable_zero - kStableZero) / kStableZero});
}

// Measured (docs/models.md): the largest relative error of the six landmarks (each time the largest
// pull) 9.8e-5 (N = 8), 6.8e-5 (16), 1.9e-5 (32); the buckling travel's alone 2.2e-5, 3.1e-6,
// 7.8e-7 (order 2.8, then 2.0).
TEST(CliCbcmPath, InclinedBistableBeamConvergesToTheShootingPath) {
  test::ScratchDir dir;
  double previous = INFINITY;
  for (int n : {8, 16, 32}) {
    const test::CommandResult r = run_flexure(command(fmt::format("cbcm --elements {}", n)) +
                                              " --out " + (dir / "path.h5").string());
    ASSERT_EQ(r.exit_code, 0) << n << ": " << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["method"], "cbcm");
    EXPECT_EQ(j["elements"], n);
    EXPECT_TRUE(j["completed"].get<bool>());
    EXPECT_TRUE(j["switched_branch"].get<bool>());
    const Landmarks m = landmarks(j);
    const double e = largest_error(m);
    EXPECT_LT(e, 1e-3) << n;
    EXPECT_LT(e, previous) << n << ": the error falls as N grows";
    previous = e;
    // The unstable zero lies at y = 0 exactly (point symmetry of the beam with level ends).
    EXPECT_NEAR(m.unstable_zero, kUnstableZero, 1e-9) << n;
  }
  EXPECT_LT(previous, 3e-5);  // N = 32
}

TEST(CliCbcmPath, BcmStopsWhereItLeavesItsRange) {
  test::ScratchDir dir;
  const test::CommandResult r = run_flexure(command("bcm") + " --out " + (dir / "bcm.h5").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;  // OutsideMethodDomain
  EXPECT_NE(r.err.find("passed 0.1 of its length"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--method cbcm"), std::string::npos) << r.err;
}

TEST(CliCbcmPath, KeysAndRefusals) {
  test::ScratchDir dir;
  const std::string out = (dir / "cbcm.h5").string();
  const test::CommandResult r = run_flexure(command("cbcm --elements 8") + " --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"force_points",
                          "bifurcations",
                          "limit_point_list",
                          "stability",
                          "load_factor_reached",
                          "control",
                          "control_target"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  // The same HDF5 layout as the shooting path: `flexure plot` draws it.
  const test::CommandResult plot =
      run_flexure("plot " + out + " --out " + (dir / "cbcm.png").string());
  EXPECT_EQ(plot.exit_code, 0) << plot.err;

  // Proportional loading, --shapes and --elements with bcm are refused (exit 2).
  const test::CommandResult load = run_flexure(
      fmt::format("path --chain {}/docs/examples/inclined_bistable_path.toml --method cbcm --out "
                  "{}.h5",
                  FLEXURE_SOURCE_DIR,
                  (dir / "x").string()));
  EXPECT_EQ(load.exit_code, 2);
  EXPECT_NE(load.err.find("--control"), std::string::npos) << load.err;
  const test::CommandResult shapes = run_flexure(command("cbcm") + " --shapes 5 --out " + out);
  EXPECT_EQ(shapes.exit_code, 2);
  const test::CommandResult elements = run_flexure(command("bcm --elements 4") + " --out " + out);
  EXPECT_EQ(elements.exit_code, 2);
}

}  // namespace
}  // namespace flexure
