// What is checked against what: `flexure bench --quick` (the ctest smoke test of the benchmark
// runner).
//  * The HDF5 file, read back with the plain HDF5 C API, follows docs/hdf5-schema.md: root
//    attributes, one group per problem and method, every dataset with one entry per load.
//  * Every error is recomputed here from the stored tips against a reference the test solves
//    itself, independently of the bench: the elliptic solver for the free cantilevers, and for the
//    fixed-guided beam the elliptic cantilever of half the length under a quarter of the load
//    (the guided beam is two such halves, point-symmetric about the inflection point at its
//    middle, Howell §5.3). The bench's own reference group must equal it.
//  * Shooting (the bench's rk8pd, CVODES and Dormand-Prince at rtol 1e-8) against that reference.
//  * The chain algorithm: its order between N = 10 and N = 50, measured on every load where both
//    converge, is 3 +- 0.3 (the corrected variant, docs/theory-chain.md §3), and at N = 50 each
//    error is within what that order allows from the N = 10 error. Howell's second-order variant
//    (order 2.01-2.03 here) fails both.
//  * The PRBM inside its validity limits within the 5 % that docs/benchmarks.md claims; outside
//    Table 5.1 (the post-buckled column's n = 50) it refuses, saying so.
//  * cfm_stroke (mechanism 1A-lpp): its groups carry displacement, force and error_force; the
//    PRBM slider force is within the 5.1 % worst error that docs/benchmarks.md reports for this
//    design against the exact force (the PRBM and the shooting-based exact model share no code
//    path). A determinism check, not an accuracy check: the exact group re-runs the reference's
//    solver on the same stroke and must give the same forces bit for bit.
//  * --stop-after leaves a checkpoint (complete = 0) and no results file; a rerun without --resume
//    is refused and keeps it; --resume reuses the finished groups bit for bit and removes the
//    checkpoint; bad names exit 2 and name what is wrong.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "flexure/benchmarks/studies/bench_run.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/elliptic/elliptic_solver.h"
#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

// Shooting at rtol 1e-8 vs an exact reference: integration error of order rtol times the
// condition of the shooting problem (measured up to 1e-8 near buckling); 1e-6 leaves margin.
constexpr double kShootingRelativeTolerance = 1e-6;
// The chain algorithm's order in 1/N (corrected variant): 3, asserted to +-0.3 as in
// tests/solver/chain_cantilever_test.cpp. Measured here 2.86-3.06 on the 8 loads where N = 10
// converges (Howell's variant: 2.01-2.03).
constexpr double kChainOrder = 3.0;
constexpr double kChainOrderTolerance = 0.3;
// At N = 50 on a load where N = 10 does not converge (it is run without refinement) there is no
// order to bound it by; there a regression bound, labelled as such: the largest third-order error
// on this set is 3.9e-5 (n = 1, alpha2 = 20), Howell's second-order variant gives 1.6e-4 to
// 3.9e-4 on those loads.
constexpr double kChainN50RegressionBound = 1e-4;
// PRBM inside Theta_max: docs/benchmarks.md, "0.4-5 % inside its validity limits" (measured here
// at most 3.3 %).
constexpr double kPrbmRelativeTolerance = 0.05;
// PRBM slider force of the constant-force mechanism vs its exact model: docs/benchmarks.md reports
// a worst error of 5.115e-2 over the 50-point stroke of 1A-lpp (at its first point; the quick
// stroke's first point is further out, measured 4.18e-2).
constexpr double kCfmPrbmForceTolerance = 0.052;
// Reference tips of the test and of the bench: the same elliptic solver (or the guided beam's
// halves) at round-off, up to the continuation's convergence; 1e-9 of l.
constexpr double kReferenceTolerance = 1e-9;

const std::vector<std::string> kProblems = {
    "cantilever_force", "tip_moment", "force_and_moment", "fixed_guided", "post_buckled_column"};
const std::vector<std::string> kDoubleDatasets = {"load_ratio_n",
                                                  "alpha2",
                                                  "mu",
                                                  "a_over_l",
                                                  "b_over_l",
                                                  "theta0",
                                                  "error_position",
                                                  "error_relative",
                                                  "error_theta0",
                                                  "seconds"};
const std::vector<std::string> kIntDatasets = {
    "status", "repeats", "iterations", "within_validity"};

std::vector<std::string> group_members(hid_t file, const std::string& path) {
  std::vector<std::string> names;
  hid_t group = H5Gopen2(file, path.c_str(), H5P_DEFAULT);
  if (group < 0) return names;
  H5G_info_t info;
  H5Gget_info(group, &info);
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    char name[256];
    H5Lget_name_by_idx(group, ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof name, H5P_DEFAULT);
    names.emplace_back(name);
  }
  H5Gclose(group);
  return names;
}

struct Tip {
  double a = 0.0, b = 0.0;
};

// The test's own reference tip of one load (see the header comment).
Tip independent_reference(const std::string& problem, double n, double alpha2, double mu) {
  if (problem == "fixed_guided") {
    // Each half (length l/2) is a cantilever under the same force with no moment at the
    // inflection point: alpha2 of the half is F (l/2)^2/EI = alpha2/4, and the two halves add
    // twice its tip in units of l/2, i.e. its a/l, b/l in units of l.
    const EllipticResult half = EllipticSolver().solve(EndLoad::howell(0.0, alpha2 / 4.0, 0.0));
    EXPECT_TRUE(half.converged()) << half.message;
    return {half.tip.a_over_l, half.tip.b_over_l};
  }
  const EllipticResult r = EllipticSolver().solve(EndLoad::howell(n, alpha2, mu));
  EXPECT_TRUE(r.converged()) << problem << ": " << r.message;
  return {r.tip.a_over_l, r.tip.b_over_l};
}

// |tip - reference| / |reference - unloaded tip (1, 0)|: Howell's relative position error
// (eq. 5.47), as docs/hdf5-schema.md defines error_relative.
double relative_error(double a, double b, const Tip& ref) {
  return std::hypot(a - ref.a, b - ref.b) / std::hypot(ref.a - 1.0, ref.b);
}

class BenchQuickTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new ScratchDir();
    result_ = new CommandResult(run_flexure("bench --quick --out q.h5", dir_->path()));
  }
  static void TearDownTestSuite() {
    delete result_;
    delete dir_;
  }
  static ScratchDir* dir_;
  static CommandResult* result_;
};
ScratchDir* BenchQuickTest::dir_ = nullptr;
CommandResult* BenchQuickTest::result_ = nullptr;

TEST_F(BenchQuickTest, RunsAndPrintsProgress) {
  ASSERT_EQ(result_->exit_code, 0) << result_->err;
  EXPECT_NE(result_->err.find("cantilever_force/reference"), std::string::npos) << result_->err;
  EXPECT_FALSE(std::filesystem::exists(*dir_ / "q.h5.partial"));
}

TEST_F(BenchQuickTest, FileFollowsTheSchema) {
  ASSERT_EQ(result_->exit_code, 0) << result_->err;
  const hid_t file = open_read_only(*dir_ / "q.h5");
  ASSERT_GE(file, 0);
  for (const char* attr :
       {"tool_version", "git_commit", "machine", "creation_time", "command_line", "reference"}) {
    const std::string value = read_string_attribute(file, "/", attr);
    EXPECT_NE(value, "<missing>") << attr;
    EXPECT_FALSE(value.empty()) << attr;
  }
  EXPECT_EQ(read_int_attribute(file, "/", "quick"), 1);
  EXPECT_EQ(read_int_attribute(file, "/", "complete"), 1);
  EXPECT_EQ(group_members(file, "/"),
            std::vector<std::string>({"cantilever_force",
                                      "cfm_stroke",
                                      "fixed_guided",
                                      "force_and_moment",
                                      "post_buckled_column",
                                      "tip_moment"}));
  for (const std::string& problem : kProblems) {
    const std::vector<std::string> methods = group_members(file, "/" + problem);
    ASSERT_GE(methods.size(), 4u) << problem;
    EXPECT_EQ(std::count(methods.begin(), methods.end(), "reference"), 1) << problem;
    for (const std::string& method : methods) {
      const std::string g = "/" + problem + "/" + method;
      const std::size_t n = read_doubles(file, (g + "/alpha2").c_str()).size();
      ASSERT_GT(n, 0u) << g;
      for (const std::string& d : kDoubleDatasets) {
        EXPECT_EQ(read_doubles(file, (g + "/" + d).c_str()).size(), n) << g << "/" << d;
      }
      for (const std::string& d : kIntDatasets) {
        EXPECT_EQ(read_ints(file, (g + "/" + d).c_str()).size(), n) << g << "/" << d;
      }
      EXPECT_EQ(read_strings(file, (g + "/message").c_str()).size(), n) << g;
      for (int s : read_ints(file, (g + "/status").c_str())) {
        EXPECT_TRUE(s >= 0 && s <= 3) << g;
      }
      for (double t : read_doubles(file, (g + "/seconds").c_str())) {
        EXPECT_TRUE(std::isfinite(t) && t > 0.0) << g;
      }
      EXPECT_NE(read_string_attribute(file, g.c_str(), "family"), "<missing>") << g;
    }
  }
  H5Fclose(file);
}

TEST_F(BenchQuickTest, ExactMethodsAgreeWithAnIndependentReference) {
  ASSERT_EQ(result_->exit_code, 0) << result_->err;
  const hid_t file = open_read_only(*dir_ / "q.h5");
  ASSERT_GE(file, 0);
  int shooting_checked = 0, orders_measured = 0, chain_bounded = 0, prbm_inside = 0;
  for (const std::string& problem : kProblems) {
    const std::string r = "/" + problem + "/reference";
    const std::vector<double> n = read_doubles(file, (r + "/load_ratio_n").c_str());
    const std::vector<double> alpha2 = read_doubles(file, (r + "/alpha2").c_str());
    const std::vector<double> mu = read_doubles(file, (r + "/mu").c_str());
    const std::vector<double> ref_a = read_doubles(file, (r + "/a_over_l").c_str());
    const std::vector<double> ref_b = read_doubles(file, (r + "/b_over_l").c_str());
    std::vector<Tip> reference;
    for (std::size_t i = 0; i < alpha2.size(); ++i) {
      reference.push_back(independent_reference(problem, n[i], alpha2[i], mu[i]));
      EXPECT_NEAR(ref_a[i], reference[i].a, kReferenceTolerance) << r << " load " << i;
      EXPECT_NEAR(ref_b[i], reference[i].b, kReferenceTolerance) << r << " load " << i;
    }
    struct Run {
      std::vector<int> status, inside;
      std::vector<double> error;  // recomputed; NaN where not converged
      std::vector<std::string> message;
    };
    const auto read_run = [&](const std::string& method) {
      const std::string g = "/" + problem + "/" + method;
      Run run;
      run.status = read_ints(file, (g + "/status").c_str());
      run.inside = read_ints(file, (g + "/within_validity").c_str());
      run.message = read_strings(file, (g + "/message").c_str());
      const std::vector<double> a = read_doubles(file, (g + "/a_over_l").c_str());
      const std::vector<double> b = read_doubles(file, (g + "/b_over_l").c_str());
      const std::vector<double> stored = read_doubles(file, (g + "/error_relative").c_str());
      EXPECT_EQ(a.size(), reference.size()) << g;
      for (std::size_t i = 0; i < a.size() && i < reference.size(); ++i) {
        run.error.push_back(run.status[i] == 0 ? relative_error(a[i], b[i], reference[i])
                                               : std::nan(""));
        // The bench's own error_relative is the same quantity (its reference agrees with ours
        // to kReferenceTolerance, which moves the error by at most that over the deflection).
        if (run.status[i] == 0) {
          const double deflection = std::hypot(reference[i].a - 1.0, reference[i].b);
          EXPECT_NEAR(stored[i], run.error[i], 2.0 * kReferenceTolerance / deflection)
              << g << " load " << i;
        }
      }
      return run;
    };
    for (const std::string& method : group_members(file, "/" + problem)) {
      if (method.rfind("shooting_", 0) != 0) continue;
      const Run run = read_run(method);
      for (std::size_t i = 0; i < run.error.size(); ++i) {
        // Shooting must converge on every problem of the set (it is the reference method).
        ASSERT_EQ(run.status[i], 0) << problem << "/" << method << " load " << i;
        EXPECT_LT(run.error[i], kShootingRelativeTolerance)
            << problem << "/" << method << " load " << i;
        ++shooting_checked;
      }
    }
    const Run n10 = read_run("chain_N010_inc05");
    const Run n50 = read_run("chain_N050_inc05");
    for (std::size_t i = 0; i < n50.error.size(); ++i) {
      if (n50.status[i] != 0) continue;
      const std::string where = problem + " load " + std::to_string(i);
      // The unloaded tip of the full circle (mu = 2 pi) is reached to round-off: no order there.
      if (n10.status[i] == 0 && n50.error[i] > 1e-12) {
        const double order = std::log(n10.error[i] / n50.error[i]) / std::log(5.0);
        EXPECT_NEAR(order, kChainOrder, kChainOrderTolerance)
            << where << ": N = 10 error " << n10.error[i] << ", N = 50 error " << n50.error[i];
        ++orders_measured;
        EXPECT_LE(n50.error[i], n10.error[i] * std::pow(5.0, -(kChainOrder - kChainOrderTolerance)))
            << where;
      } else {
        EXPECT_LT(n50.error[i], kChainN50RegressionBound) << where << " (regression bound)";
      }
      ++chain_bounded;
    }
    if (problem == "force_and_moment") continue;  // no PRBM element takes a force and a moment
    const Run prbm = read_run("prbm");
    for (std::size_t i = 0; i < prbm.error.size(); ++i) {
      const std::string where = problem + "/prbm load " + std::to_string(i);
      if (problem == "post_buckled_column") {
        // n = 50 lies outside Table 5.1 (-5 <= n <= 10): refused with the reason.
        EXPECT_EQ(prbm.status[i], 2) << where;
        EXPECT_NE(prbm.message[i].find("outside Table 5.1"), std::string::npos)
            << where << ": " << prbm.message[i];
        continue;
      }
      if (prbm.status[i] == 0 && prbm.inside[i] == 1) {
        EXPECT_LT(prbm.error[i], kPrbmRelativeTolerance) << where;
        ++prbm_inside;
      }
    }
  }
  EXPECT_GE(shooting_checked, 40);
  EXPECT_GE(orders_measured, 6);  // 8 measured
  EXPECT_GE(chain_bounded, 20);   // 21 of the 24 loads converge at N = 50
  EXPECT_GE(prbm_inside, 6);      // 7 measured
  H5Fclose(file);
}

TEST_F(BenchQuickTest, CfmStrokeComparesPrbmWithTheExactMechanismModel) {
  ASSERT_EQ(result_->exit_code, 0) << result_->err;
  const hid_t file = open_read_only(*dir_ / "q.h5");
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_string_attribute(file, "/cfm_stroke", "mechanism"), "1A-lpp");
  ASSERT_EQ(group_members(file, "/cfm_stroke"),
            std::vector<std::string>({"exact", "prbm", "reference"}));
  const std::vector<double> reference_force = read_doubles(file, "/cfm_stroke/reference/force");
  ASSERT_GE(reference_force.size(), 2u);
  for (const std::string method : {"exact", "prbm", "reference"}) {
    const std::string g = "/cfm_stroke/" + method;
    const std::vector<double> dx = read_doubles(file, (g + "/displacement").c_str());
    const std::vector<double> force = read_doubles(file, (g + "/force").c_str());
    const std::vector<double> error = read_doubles(file, (g + "/error_force").c_str());
    const std::vector<double> error_relative = read_doubles(file, (g + "/error_relative").c_str());
    const std::vector<double> seconds = read_doubles(file, (g + "/seconds").c_str());
    const std::vector<int> status = read_ints(file, (g + "/status").c_str());
    ASSERT_EQ(dx.size(), reference_force.size()) << g;
    ASSERT_EQ(force.size(), dx.size()) << g;
    ASSERT_EQ(error.size(), dx.size()) << g;
    ASSERT_EQ(seconds.size(), dx.size()) << g;
    ASSERT_EQ(status.size(), dx.size()) << g;
    EXPECT_EQ(read_strings(file, (g + "/message").c_str()).size(), dx.size()) << g;
    for (std::size_t i = 0; i < dx.size(); ++i) {
      // The stroke runs outward from the straight position.
      EXPECT_GT(dx[i], i == 0 ? 0.0 : dx[i - 1]) << g;
      ASSERT_EQ(status[i], 0) << g << " point " << i;
      EXPECT_TRUE(std::isfinite(force[i]) && force[i] > 0.0) << g << " point " << i;
      EXPECT_TRUE(std::isfinite(seconds[i]) && seconds[i] > 0.0) << g;
      if (method == "reference") continue;
      ASSERT_TRUE(std::isfinite(error[i])) << g << " point " << i;
      EXPECT_EQ(error_relative[i], error[i]) << g;
      // The error is the one of the stored forces; the bound below is on the recomputed value.
      const double recomputed = std::fabs(force[i] - reference_force[i]) / reference_force[i];
      EXPECT_NEAR(error[i], recomputed, 1e-12) << g;
      if (method == "exact") {
        // Determinism, not accuracy: the same model and continuation as the reference group, so
        // the forces are bit-identical (the accuracy is the PRBM comparison below and the exact
        // model's own tests).
        EXPECT_EQ(force[i], reference_force[i]) << g << " point " << i;
      } else {
        EXPECT_LT(recomputed, kCfmPrbmForceTolerance) << g << " point " << i;
      }
    }
  }
  H5Fclose(file);
}

// Group statistics (issue 27): the attributes agree with the datasets, recomputed here, and a
// statistic over zero points is NaN in the file and "n/a" in the progress line, never 0.
TEST_F(BenchQuickTest, GroupStatisticsCoverOnlyTheirPoints) {
  ASSERT_EQ(result_->exit_code, 0) << result_->err;
  const hid_t file = open_read_only(*dir_ / "q.h5");
  ASSERT_GE(file, 0);
  int without_error = 0;
  for (const std::string& problem : group_members(file, "/")) {
    for (const std::string& method : group_members(file, "/" + problem)) {
      const std::string g = "/" + problem + "/" + method;
      const std::vector<int> status = read_ints(file, (g + "/status").c_str());
      const std::vector<double> error = read_doubles(file, (g + "/error_relative").c_str());
      long long converged = 0, measured = 0;
      double worst = -1.0;
      for (std::size_t i = 0; i < status.size(); ++i) {
        converged += status[i] == 0 || status[i] == 3 ? 1 : 0;
        if (status[i] == 0 && std::isfinite(error[i])) {
          ++measured;
          worst = std::max(worst, error[i]);
        }
      }
      EXPECT_EQ(read_int_attribute(file, g.c_str(), "converged_points"), converged) << g;
      EXPECT_EQ(read_int_attribute(file, g.c_str(), "measured_points"), measured) << g;
      const double stored = read_double_attribute(file, g.c_str(), "max_relative_error");
      // The progress line of this group, as printed on stderr.
      const std::size_t at = result_->err.find("] " + problem + "/" + method + ": ");
      ASSERT_NE(at, std::string::npos) << g;
      const std::string line = result_->err.substr(at, result_->err.find('\n', at) - at);
      if (measured == 0) {
        ++without_error;
        EXPECT_TRUE(std::isnan(stored)) << g << ": " << stored;
        EXPECT_NE(line.find("max relative error n/a"), std::string::npos) << line;
        EXPECT_EQ(line.find("0.00e+00"), std::string::npos) << line;
      } else {
        EXPECT_EQ(stored, worst) << g;
        EXPECT_EQ(line.find("n/a"), std::string::npos) << line;
      }
    }
  }
  // At least the reference groups (no error against themselves).
  EXPECT_GE(without_error, 6);
  H5Fclose(file);
}

// A group in which nothing converged (0 of 3): no error statistic, and the line says why.
TEST(BenchStatisticsTest, NothingConvergedHasNoErrorStatistic) {
  bench::MethodRun run;
  run.problem = "tip_moment";
  run.method = "chain_N010_inc05";
  run.alpha2 = {1.0, 2.0, 3.0};
  run.status = {bench::kStatusNotConverged, bench::kStatusError, bench::kStatusNotConverged};
  run.error_relative.assign(3, std::numeric_limits<double>::quiet_NaN());
  run.seconds = {3e-5, 1e-5, 2e-5};
  const bench::RunStatistics s = bench::run_statistics(run);
  EXPECT_EQ(s.points, 3);
  EXPECT_EQ(s.converged, 0);
  EXPECT_EQ(s.measured, 0);
  EXPECT_TRUE(std::isnan(s.max_relative_error));
  EXPECT_EQ(s.median_seconds, 2e-5);
  const std::string line = bench::summarize(run);
  EXPECT_NE(line.find("0/3 converged, max relative error n/a (no converged load)"),
            std::string::npos)
      << line;
  // One converged load with an error of 0 (an exact method on its own reference) is a real 0.
  run.status[1] = bench::kStatusConverged;
  run.error_relative[1] = 0.0;
  EXPECT_EQ(bench::run_statistics(run).max_relative_error, 0.0);
  EXPECT_NE(bench::summarize(run).find("1/3 converged, max relative error 0.00e+00"),
            std::string::npos)
      << bench::summarize(run);
}

// The summary's counts over every group (the JSON keys solves and failed_solves): a status of 1
// (not converged) or 2 (threw) is a failed solve; 0 and 3 (converged, with or without a
// reference) are not. Counted by hand: 6 solves, 2 failed.
TEST(BenchStatisticsTest, SummaryCountsSolvesAndFailures) {
  bench::BenchSummary summary;
  bench::MethodRun a;
  a.status = {bench::kStatusConverged, bench::kStatusNotConverged, bench::kStatusError, 3};
  bench::MethodRun b;
  b.status = {bench::kStatusConverged, bench::kStatusConverged};
  summary.runs = {a, b};
  EXPECT_EQ(summary.solves(), 6);
  EXPECT_EQ(summary.failed_solves(), 2);
  EXPECT_EQ(bench::BenchSummary{}.solves(), 0);
}

// An output that cannot be written is refused before any solve, naming the caller's option.
TEST(BenchInputTest, OutputsAreCheckedBeforeSolving) {
  bench::BenchOptions options;
  options.out = "/nonexistent-directory/bench.h5";
  try {
    bench::check_bench_outputs(options, "out");
    FAIL() << "accepted an unwritable path";
  } catch (const InvalidInput& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("out '/nonexistent-directory/bench.h5': ", 0), 0u) << message;
    EXPECT_NE(message.find("does not exist"), std::string::npos) << message;
  }
}

// The JSON summary carries the same statistics per group, null where they cover no point.
TEST(BenchJsonTest, StatisticsOverNoConvergedLoadAreNull) {
  ScratchDir dir;
  const CommandResult r = run_flexure(
      "bench --quick --problems tip_moment --methods elliptic --out j.h5 --json", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json out = nlohmann::json::parse(r.out);
  ASSERT_TRUE(out.contains("groups")) << r.out;
  int seen = 0;
  for (const nlohmann::json& g : out["groups"]) {
    ASSERT_TRUE(g.contains("max_relative_error")) << g.dump();
    if (g["method"] == "reference") {
      EXPECT_TRUE(g["max_relative_error"].is_null()) << g.dump();
      EXPECT_EQ(g["measured_points"], 0) << g.dump();
      ++seen;
    } else if (g["method"] == "elliptic") {
      // The elliptic solver is the reference here: measured at every load, error 0.
      EXPECT_EQ(g["measured_points"], g["points"]) << g.dump();
      EXPECT_EQ(g["max_relative_error"], 0.0) << g.dump();
      ++seen;
    }
    EXPECT_TRUE(g["median_seconds"].is_number()) << g.dump();
  }
  EXPECT_EQ(seen, 2) << r.out;
}

TEST(BenchResumeTest, InterruptedRunResumesFromItsCheckpoint) {
  ScratchDir dir;
  const std::string select = "--quick --problems tip_moment --methods elliptic,prbm --out r.h5";
  const CommandResult first = run_flexure("bench " + select + " --stop-after 2", dir.path());
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "r.h5"));
  ASSERT_TRUE(std::filesystem::exists(dir / "r.h5.partial"));
  hid_t file = open_read_only(dir / "r.h5.partial");
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_int_attribute(file, "/", "complete"), 0);
  const std::vector<double> seconds_before = read_doubles(file, "/tip_moment/elliptic/seconds");
  ASSERT_FALSE(seconds_before.empty());
  EXPECT_TRUE(group_members(file, "/tip_moment") ==
              std::vector<std::string>({"elliptic", "reference"}));
  H5Fclose(file);

  // Without --resume the checkpoint is kept and the run refused (exit 2), saying how to go on.
  const CommandResult again = run_flexure("bench " + select, dir.path());
  EXPECT_EQ(again.exit_code, 2);
  EXPECT_NE(again.err.find("--resume"), std::string::npos) << again.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "r.h5.partial"));

  const CommandResult resumed = run_flexure("bench " + select + " --resume --json", dir.path());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("\"groups_reused\":2"), std::string::npos) << resumed.out;
  EXPECT_NE(resumed.out.find("\"groups_computed\":1"), std::string::npos) << resumed.out;
  EXPECT_FALSE(std::filesystem::exists(dir / "r.h5.partial"));
  file = open_read_only(dir / "r.h5");
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_int_attribute(file, "/", "complete"), 1);
  // Timings differ between runs, so identical values prove the group was reused, not re-run.
  EXPECT_EQ(read_doubles(file, "/tip_moment/elliptic/seconds"), seconds_before);
  EXPECT_EQ(read_ints(file, "/tip_moment/prbm/status").size(), seconds_before.size());
  H5Fclose(file);

  // A checkpoint of a quick run cannot be resumed by a full run.
  const CommandResult mismatch =
      run_flexure("bench --problems tip_moment --methods elliptic --out r.h5 --resume", dir.path());
  EXPECT_EQ(mismatch.exit_code, 2) << mismatch.err;
  EXPECT_NE(mismatch.err.find("written with --quick"), std::string::npos) << mismatch.err;
}

TEST(BenchInputTest, UnknownNamesAndUnwritablePathsExitTwo) {
  ScratchDir dir;
  // Each refusal names its reason: the option, the bad value and what is allowed.
  const struct {
    const char* args;
    std::vector<std::string> reason;
  } cases[] = {
      {"--problems nosuch --out x.h5",
       {"--problems", "unknown problem 'nosuch'", "cantilever_force"}},
      {"--methods nosuch --out x.h5", {"--methods", "unknown method 'nosuch'", "chain_N050_inc05"}},
      {"--out /nonexistent-dir/x.h5", {"--out", "'/nonexistent-dir' does not exist"}},
  };
  for (const auto& c : cases) {
    const std::string args = std::string("bench --quick ") + c.args;
    const CommandResult r = run_flexure(args, dir.path());
    EXPECT_EQ(r.exit_code, 2) << args;
    for (const std::string& word : c.reason) {
      EXPECT_NE(r.err.find(word), std::string::npos) << args << ": " << r.err;
    }
  }
}

}  // namespace
}  // namespace flexure::test
