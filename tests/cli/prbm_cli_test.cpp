// What is checked against what: the `flexure prbm` subcommands run as a user would run them.
//  * `derive --json` prints one JSON object with the documented keys, and its gamma/c_theta/K_theta
//    agree with Table 5.1 (n = 1) within the acceptance tolerances;
//  * `table` prints every Table 5.1 row (17 data lines) and the end-moment table; Table 5.2 is
//    re-derived with the book's value beside it (kappa0 = 0.1 row: gamma 0.84 to 2 decimals);
//  * `compare --json` reports the exact tip of Howell's §5.2 example (n = 0, alpha2 = 2.046504
//    gives b/l = 0.5) and a path error below 0.5 % inside the validity range;
//  * `compare --range` gives one row per load and flags the point beyond Theta_max(gamma), with the
//    exact Theta of the n = 0 solution (eqs. 2.90-2.98 and 5.42);
//  * `derive --segment initially-curved --kappa0 0` gives Table 5.1's n = 0 row;
//  * invalid input exits with code 2 and one line on stderr.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/support/cli_test_support.h"

namespace flexure {
namespace {

using test::run_flexure;

TEST(PrbmCli, DeriveJsonHasTheDocumentedKeysAndTable51Values) {
  const auto r = run_flexure("prbm derive --segment fixed-pinned --n 1 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_EQ(test::count_lines(r.out), 1);
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key :
       {"gamma", "theta_max_gamma_deg", "c_theta", "K_theta", "theta_max_K_deg"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_NEAR(j["gamma"].get<double>(), 0.8360, 0.001);
  EXPECT_NEAR(j["theta_max_gamma_deg"].get<double>(), 94.8, 1.0);
  EXPECT_NEAR(j["c_theta"].get<double>(), 1.2467, 0.01);
  EXPECT_NEAR(j["K_theta"].get<double>(), 2.61259, 0.01);
  EXPECT_DOUBLE_EQ(j["theta_max_K_deg"].get<double>(), 67.5);
}

TEST(PrbmCli, TablesPrintEveryRow) {
  const auto fp = run_flexure("prbm table --segment fixed-pinned");
  ASSERT_EQ(fp.exit_code, 0) << fp.err;
  EXPECT_EQ(test::count_lines(fp.out), 17 + 3);  // title, header, 17 rows, footnote
  const auto em = run_flexure("prbm table --segment end-moment --json");
  ASSERT_EQ(em.exit_code, 0) << em.err;
  EXPECT_NEAR(nlohmann::json::parse(em.out)["gamma"].get<double>(), 0.7346, 0.5e-4);
  // Table 5.2 re-derived (coarse 0.5 deg samples for speed): every row, book and derived side by
  // side; kappa0 = 0.1 gives the book's gamma = 0.84 to its printed 2 decimals.
  const auto ic = run_flexure("prbm table --segment initially-curved --step 0.5 --json");
  ASSERT_EQ(ic.exit_code, 0) << ic.err;
  const auto rows = nlohmann::json::parse(ic.out)["rows"];
  ASSERT_EQ(rows.size(), 7u);
  EXPECT_DOUBLE_EQ(rows[1]["book"]["gamma"].get<double>(), 0.84);
  EXPECT_NEAR(rows[1]["gamma"].get<double>(), 0.84, 0.005);
  EXPECT_EQ(rows[1]["per_n"].size(), 7u);
}

TEST(PrbmCli, DeriveInitiallyCurvedAtZeroCurvatureGivesTheStraightBeam) {
  // kappa0 = 0 is the straight beam: Table 5.1's n = 0 row (gamma 0.8517, Theta_max 64.3 deg)
  // within the acceptance tolerances.
  const auto r =
      run_flexure("prbm derive --segment initially-curved --kappa0 0 --n 0 --step 0.25 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["gamma"].get<double>(), 0.8517, 0.001);
  EXPECT_NEAR(j["theta_max_gamma_deg"].get<double>(), 64.3, 1.0);
  EXPECT_DOUBLE_EQ(j["theta_i_deg"].get<double>(), 0.0);
  test::expect_refused("prbm derive --segment initially-curved --kappa0 5",
                       {"--kappa0", "= 5 is outside the allowed range [0, 3]"});
}

TEST(PrbmCli, CompareReportsExactTipAndValidity) {
  const auto r = run_flexure("prbm compare --segment fixed-pinned --n 0 --alpha2 2.046504 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["exact"]["b_over_l"].get<double>(), 0.5, 1e-6);  // exact, eqs. 2.90-2.98
  EXPECT_LT(j["path_error_rel"].get<double>(), 0.005);
  EXPECT_TRUE(j["inside_position_range"].get<bool>());
  EXPECT_TRUE(j["inside_force_range"].get<bool>());
}

TEST(PrbmCli, CompareRangeGivesOneRowPerLoadAndFlagsTheValidityLimit) {
  // Exact n = 0 solution (eqs. 2.90-2.98, 5.42): alpha2 = 3.0870030 and 8.8064153 give
  // Theta = 0.802320 and 1.183640 rad for gamma = 0.8517; the second is beyond
  // Theta_max(gamma) = 64.3 deg.
  const auto r =
      run_flexure("prbm compare --segment fixed-pinned --n 0 --range 3.0870030:8.8064153:2 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["points"].size(), 2u);
  EXPECT_NEAR(j["points"][0]["Theta_exact"].get<double>(), 0.802320, 5e-6);
  EXPECT_NEAR(j["points"][1]["Theta_exact"].get<double>(), 1.183640, 5e-6);
  EXPECT_TRUE(j["points"][0]["inside_position_range"].get<bool>());
  EXPECT_FALSE(j["points"][1]["inside_position_range"].get<bool>());
  const auto text = run_flexure("prbm compare --segment end-moment --range 0.5:3:6");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_EQ(test::count_lines(text.out), 2 + 6);  // title, header, one row per load
}

TEST(PrbmCli, InvalidInputExitsWithCode2) {
  const auto r = run_flexure("prbm derive --segment fixed-pinned --n 99");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(test::count_lines(r.err), 1);
  EXPECT_NE(r.err.find("--n (load ratio) = 99 is outside the allowed range [-20, 20]"),
            std::string::npos)
      << r.err;
  test::expect_refused("prbm table --segment nonsense",
                       {"--segment = 'nonsense' has no table", "fixed-pinned"});
  test::expect_refused("prbm compare --segment fixed-pinned --alpha2 -1",
                       {"--alpha2", "= -1 is outside"});
  test::expect_refused("prbm compare --segment fixed-pinned --range 1:2:0",
                       {"--range = '1:2:0' is not a valid range", "COUNT"});
  test::expect_refused("prbm compare --segment fixed-guided",
                       {"'fixed-guided' cannot be compared", "allowed: fixed-pinned, end-moment"});
}

}  // namespace
}  // namespace flexure
