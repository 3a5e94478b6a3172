// `flexure models map` (docs/cli.md, docs/hdf5-schema.md "flexure models map"): the file's layout
// (axes, the reference, one group per model named by its --method name, the grid shape), the JSON
// summary against the file, the 1R model's refusal of force plus moment as status 2, the guided
// map's reference, and refused input (exit 2). The honesty of the errors themselves is checked
// against independently computed exact solutions in tests/studies/model_map_test.cpp.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

using Json = nlohmann::json;

TEST(CliModelsMap, FileLayoutAndJsonSummary) {
  ScratchDir dir;
  const CommandResult r = run_flexure(
      "models map --n 0:0.5:2 --alpha2 0.5:2:3 --mu 0:0.4:2 --models linear,prbm,cbcm "
      "--elements 4 --min-seconds 0 --out m.h5 --json",
      dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Json j = Json::parse(r.out);
  EXPECT_EQ(j["boundary"], "free");
  EXPECT_EQ(j["reference"], "elliptic");
  EXPECT_EQ(j["points"], 12);
  ASSERT_EQ(j["models"].size(), 3u);
  const hid_t file = open_read_only(dir / "m.h5");
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_doubles(file, "/n").size(), 2u);
  EXPECT_EQ(read_doubles(file, "/alpha2").size(), 3u);
  EXPECT_EQ(read_doubles(file, "/mu").size(), 2u);
  EXPECT_EQ(read_string_attribute(file, "/", "schema"), "flexure-models-map 1");
  EXPECT_EQ(read_string_attribute(file, "/reference", "method"), "elliptic");
  EXPECT_EQ(read_doubles(file, "/reference/theta0").size(), 12u);
  for (const Json& m : j["models"]) {
    const std::string g = "/" + m["method"].get<std::string>();
    SCOPED_TRACE(g);
    const std::vector<double> error = read_doubles(file, (g + "/position_error").c_str());
    const std::vector<int> status = read_ints(file, (g + "/status").c_str());
    ASSERT_EQ(error.size(), 12u);
    double largest = 0.0;
    long converged = 0;
    for (std::size_t i = 0; i < error.size(); ++i) {
      if (status[i] != 0) {
        EXPECT_TRUE(std::isnan(error[i]));
        continue;
      }
      ++converged;
      largest = std::max(largest, error[i]);
    }
    EXPECT_EQ(m["converged_points"], converged);
    EXPECT_DOUBLE_EQ(m["max_position_error"].get<double>(), largest);
    if (m["method"] == "prbm") {
      // mu = 0.4 with a force: the 1R model cannot represent it (grid order: mu fastest).
      for (std::size_t i = 0; i < status.size(); ++i) EXPECT_EQ(status[i], i % 2 == 0 ? 0 : 2);
    }
    if (m["method"] == "cbcm") {
      EXPECT_EQ(read_string_attribute(file, g.c_str(), "settings"), "elements 4");
    }
  }
  // Linear theory's error at one point from its closed form (b = alpha2/3 + mu/2, a = 1) and
  // the reference: point (n 0.5, alpha2 2, mu 0.4) is the last.
  const std::vector<double> a = read_doubles(file, "/reference/a_over_l");
  const std::vector<double> b = read_doubles(file, "/reference/b_over_l");
  const std::vector<double> linear = read_doubles(file, "/linear/position_error");
  EXPECT_NEAR(linear[11], std::hypot(1.0 - a[11], 2.0 / 3.0 + 0.2 - b[11]), 1e-14);
  H5Fclose(file);
}

TEST(CliModelsMap, GuidedMapUsesTheShootingMethodAsItsReference) {
  ScratchDir dir;
  const CommandResult r = run_flexure(
      "models map --boundary guided --n 0 --alpha2 1:2:2 --tip-angle 0:0.2:2 --models linear,bcm "
      "--min-seconds 0 --out g.h5 --json",
      dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Json j = Json::parse(r.out);
  EXPECT_EQ(j["reference"], "shooting");
  const hid_t file = open_read_only(dir / "g.h5");
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_doubles(file, "/tip_angle").size(), 2u);
  // Linear theory of the guided beam: b = alpha2/12 + phi/2, theta0 = phi exactly.
  const std::vector<double> theta = read_doubles(file, "/reference/theta0");
  EXPECT_NEAR(theta[1], 0.2, 1e-9);
  H5Fclose(file);
}

TEST(CliModelsMap, RefusedInput) {
  expect_refused("models map --models linear,nonsense --out x.h5", {"nonsense"});
  expect_refused("models map --models elliptic --out x.h5", {"reference"});
  expect_refused("models map --boundary guided --mu 1 --out x.h5", {"--mu", "--tip-angle"});
  expect_refused("models map --boundary pinned --out x.h5", {"free or a guided"});
  expect_refused("models map --alpha2 1:nan:3 --out x.h5", {"--alpha2"});
  expect_refused("models map --constants bogus --alpha2 1 --out x.h5", {"bogus"});
  expect_refused("models map --alpha2 1 --out /nonexistent-dir/x.h5", {"nonexistent-dir"});
}

}  // namespace
}  // namespace flexure::test
