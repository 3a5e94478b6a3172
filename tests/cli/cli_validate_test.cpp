// What is checked against what: `flexure validate` run as a process. Its JSON must report every
// check passed, and independently of its own reference list the Howell worked example (§2.9.2,
// recomputed: alpha = 1.7569869, a/l = 0.7383564, b/l = 0.6103718) must appear among the computed
// values; the results file must hold one row per JSON check. The default output is
// validation.h5 in the working directory, and an unwritable --out is exit 2.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

using nlohmann::json;

constexpr double kEightDigits = 1e-7;  // the reference values' 8 significant digits

TEST(CliValidate, AllChecksPassAndTheHowellExampleIsAmongThem) {
  ScratchDir dir;
  const auto out = dir / "v.h5";
  const CommandResult r = run_flexure("validate --json --out '" + out.string() + "'");
  EXPECT_EQ(r.exit_code, 0) << r.err << r.out;
  ASSERT_EQ(count_lines(r.out), 1) << r.out;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["out"], out.string());
  EXPECT_EQ(j["all_passed"], true);
  ASSERT_TRUE(j["checks"].is_array());
  ASSERT_GE(j["checks"].size(), 20u);
  bool saw_alpha = false, saw_a = false, saw_b = false;
  std::set<std::string> methods;
  for (const json& c : j["checks"]) {
    for (const char* key : {"problem",
                            "method",
                            "quantity",
                            "computed",
                            "reference",
                            "rel_error",
                            "tolerance",
                            "passed"}) {
      ASSERT_TRUE(c.contains(key)) << key << " missing in " << c.dump();
    }
    EXPECT_EQ(c["passed"], true) << c.dump();
    methods.insert(c["method"].get<std::string>());
    const double computed = c["computed"].get<double>();
    if (c["problem"] == "howell-example theta0=1 inverse" && c["method"] == "elliptic") {
      const std::string q = c["quantity"];
      if (q == "alpha") {
        saw_alpha = std::abs(computed - 1.7569869) <= kEightDigits * 1.7569869;
      } else if (q == "a_over_l") {
        saw_a = std::abs(computed - 0.7383564) <= kEightDigits * 0.7383564;
      } else if (q == "b_over_l") {
        saw_b = std::abs(computed - 0.6103718) <= kEightDigits * 0.6103718;
      }
    }
  }
  EXPECT_TRUE(saw_alpha && saw_a && saw_b) << "Howell example missing or wrong";
  // Every available method is validated.
  EXPECT_EQ(methods, (std::set<std::string>{"elliptic", "shooting", "chain"}));

  hid_t file = open_read_only(out);
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_strings(file, "problem").size(), j["checks"].size());
  EXPECT_EQ(read_doubles(file, "computed").size(), j["checks"].size());
  EXPECT_EQ(read_ints(file, "passed"), std::vector<int>(j["checks"].size(), 1));
  EXPECT_EQ(read_int_attribute(file, "/", "all_passed"), 1);
  H5Fclose(file);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"v.h5"});
}

TEST(CliValidate, DefaultOutputInTheWorkingDirectoryAndReadableTable) {
  ScratchDir dir;
  const CommandResult r = run_flexure("validate", dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("reference"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("checks passed"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("FAIL"), std::string::npos) << r.out;
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"validation.h5"});
}

TEST(CliValidate, UnwritableOutputIsExitTwo) {
  const CommandResult r = run_flexure("validate --out /nonexistent/dir/v.h5 --json");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(test::no_result_on_stdout(r)) << r.out;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("/nonexistent/dir"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace flexure::test
