// What is checked against what: `flexure sweep beam` run as a process. The endpoints of the
// range are rows of the exact n = 0 table (Howell eqs. 2.90-2.98, computed to 8 digits), so the
// stored a/l, b/l, theta0 are compared with that table; spacing and order of alpha2 with
// START:STOP:COUNT arithmetic; the attributes with the command line and flexure/version.h. The
// file must be complete and alone in its directory (no temporary left), and bad input must fail
// with exit 2 before any file appears.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "flexure/version.h"
#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

using nlohmann::json;

// The n = 0 table has 8 significant digits.
constexpr double kEightDigits = 1e-7;

void expect_relative(double computed, double reference, double tolerance, const char* what) {
  EXPECT_LE(std::abs(computed - reference), tolerance * std::abs(reference))
      << what << ": computed " << computed << ", reference " << reference;
}

TEST(CliSweep, EndpointsMatchTheNZeroTableAndTheFileIsComplete) {
  ScratchDir dir;
  const auto out = dir / "sweep.h5";
  const CommandResult r =
      run_flexure("sweep beam --alpha2 0.51169274:8.8064153:5 --out '" + out.string() + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count_lines(r.out), 1);
  const json j = json::parse(r.out);
  EXPECT_EQ(j["out"], out.string());
  EXPECT_EQ(j["count"], 5);
  EXPECT_EQ(j["converged_count"], 5);
  EXPECT_GE(j["seconds"].get<double>(), 0.0);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"sweep.h5"}) << "temporary file left behind";

  hid_t file = open_read_only(out);
  ASSERT_GE(file, 0) << "sweep file not readable";
  const std::vector<double> alpha2 = read_doubles(file, "alpha2");
  const std::vector<double> a = read_doubles(file, "a_over_l");
  const std::vector<double> b = read_doubles(file, "b_over_l");
  const std::vector<double> theta0 = read_doubles(file, "theta0");
  const std::vector<int> status = read_ints(file, "status");
  ASSERT_EQ(alpha2.size(), 5u);
  ASSERT_EQ(a.size(), 5u);
  ASSERT_EQ(b.size(), 5u);
  ASSERT_EQ(theta0.size(), 5u);
  EXPECT_EQ(status, std::vector<int>(5, 0));
  EXPECT_EQ(alpha2.front(), 0.51169274);
  EXPECT_EQ(alpha2.back(), 8.8064153);
  for (int i = 1; i < 4; ++i) {
    EXPECT_NEAR(alpha2[i], 0.51169274 + i * (8.8064153 - 0.51169274) / 4, 1e-14) << i;
  }
  expect_relative(theta0.front(), 0.25, kEightDigits, "theta0 at the first load");
  expect_relative(a.front(), 0.98336262, kEightDigits, "a/l at the first load");
  expect_relative(b.front(), 0.16572770, kEightDigits, "b/l at the first load");
  expect_relative(theta0.back(), 1.40, kEightDigits, "theta0 at the last load");
  expect_relative(a.back(), 0.47307789, kEightDigits, "a/l at the last load");
  expect_relative(b.back(), 0.79655336, kEightDigits, "b/l at the last load");
  for (int i = 1; i < 5; ++i) EXPECT_GT(theta0[i], theta0[i - 1]) << "stiffer load, larger angle";

  EXPECT_EQ(read_string_attribute(file, "/", "method"), "elliptic");
  EXPECT_EQ(read_double_attribute(file, "/", "load_ratio_n"), 0.0);
  EXPECT_EQ(read_double_attribute(file, "/", "mu"), 0.0);
  EXPECT_GT(read_double_attribute(file, "/", "tolerance"), 0.0);
  EXPECT_EQ(read_string_attribute(file, "/", "tool_version"), kVersion);
  EXPECT_EQ(read_string_attribute(file, "/", "git_commit"), kGitCommit);
  H5Fclose(file);
}

TEST(CliSweep, PrbmSweepsStateTheirValidityPerPoint) {
  // Table 5.1, n = 0: Theta_max = min(64.3, 58.5) deg. The PRBM equilibrium K_theta Theta =
  // alpha2 cos Theta (Howell eq. 5.35, transverse force; K_theta = 2.676) reaches 58.5 deg at
  // alpha2 = 5.23: alpha2 = 2 (35.1 deg) and 5 (57.5 deg) are within it, 8 (67.0 deg) is not.
  ScratchDir dir;
  const auto out = dir / "prbm.h5";
  ASSERT_EQ(
      run_flexure("sweep beam --method prbm --alpha2 2:8:3 --out '" + out.string() + "'").exit_code,
      0);
  hid_t file = open_read_only(out);
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_ints(file, "within_validity"), (std::vector<int>{1, 1, 0}));
  H5Fclose(file);
  // Exact methods have no validity limit: -1.
  const auto exact = dir / "exact.h5";
  ASSERT_EQ(run_flexure("sweep beam --alpha2 2:8:3 --out '" + exact.string() + "'").exit_code, 0);
  file = open_read_only(exact);
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_ints(file, "within_validity"), (std::vector<int>{-1, -1, -1}));
  H5Fclose(file);
}

TEST(CliSweep, LongSweepsShowProgressOnATerminalOnly) {
  // A shooting sweep of 8000 end moments takes seconds (about 0.2 ms each: with an end moment
  // every point is solved from zero load, beam_sweep_solver.h): on a terminal (a pseudo-terminal
  // from util-linux `script`) a progress line appears after the first second; redirected, stderr
  // stays empty.
  if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "no `script`";
  ScratchDir dir;
  const std::string sweep = std::string("'") + FLEXURE_BINARY +
                            "' sweep beam --method shooting --alpha2 3 --n 1 --mu 0.5:4:8000 "
                            "--threads 1 --out s.h5";
  const std::string command =
      "cd '" + dir.path().string() + "' && script -qec \"" + sweep + "\" /dev/null > tty.txt 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0);
  EXPECT_NE(read_text(dir / "tty.txt").find("sweep beam: "), std::string::npos);
  const CommandResult redirected = run_flexure(
      "sweep beam --method shooting --alpha2 3 --n 1 --mu 0.5:4:8000 --threads 1 --out r.h5",
      dir.path());
  ASSERT_EQ(redirected.exit_code, 0) << redirected.err;
  EXPECT_TRUE(redirected.err.empty()) << redirected.err;
}

TEST(CliSweep, DescendingRangeAndSingleLoad) {
  ScratchDir dir;
  const auto out = dir / "down.h5";
  CommandResult r =
      run_flexure("sweep beam --n 1 --mu 0.1 --alpha2 2:-2:9 --out '" + out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("9"), std::string::npos) << "readable summary: " << r.out;
  hid_t file = open_read_only(out);
  ASSERT_GE(file, 0);
  const std::vector<double> alpha2 = read_doubles(file, "alpha2");
  ASSERT_EQ(alpha2.size(), 9u);
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(alpha2[i], 2.0 - 0.5 * i, 1e-15) << i;
  EXPECT_EQ(read_double_attribute(file, "/", "load_ratio_n"), 1.0);
  EXPECT_EQ(read_double_attribute(file, "/", "mu"), 0.1);
  H5Fclose(file);

  const auto single = dir / "one.h5";
  r = run_flexure("sweep beam --alpha2 3.0870030:99:1 --out '" + single.string() + "' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  file = open_read_only(single);
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_doubles(file, "alpha2"), std::vector<double>{3.0870030}) << "COUNT 1 = START";
  const std::vector<double> b = read_doubles(file, "b_over_l");
  ASSERT_EQ(b.size(), 1u);
  expect_relative(b[0], 0.6103718, kEightDigits, "Howell example b/l");
  H5Fclose(file);
}

TEST(CliSweep, ExistingOutputIsReplacedWhole) {
  ScratchDir dir;
  const auto out = dir / "old.h5";
  std::ofstream(out) << "stale";
  const CommandResult r = run_flexure("sweep beam --alpha2 0:1:3 --out '" + out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  hid_t file = open_read_only(out);
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_ints(file, "status").size(), 3u);
  H5Fclose(file);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"old.h5"});
}

TEST(CliSweep, PointsWithoutSolutionAreFlaggedAndTheExitCodeIsThree) {
  // Same load family as CliBeam.NoConvergedSolutionIsExitThree: the chain algorithm cannot follow
  // the path through its limit points, so the far end of the range fails.
  ScratchDir dir;
  const auto out = dir / "partial.h5";
  const CommandResult r =
      run_flexure("sweep beam --method chain --n 1 --mu 30 --alpha2 0:-50:6 --out '" +
                  out.string() + "' --json");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("first is alpha2 = "), std::string::npos) << r.err;
  ASSERT_EQ(count_lines(r.out), 1) << "the summary is still printed: " << r.out;
  const json j = json::parse(r.out);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"partial.h5"}) << "written whole";

  hid_t file = open_read_only(out);
  ASSERT_GE(file, 0);
  const std::vector<int> status = read_ints(file, "status");
  const std::vector<double> a = read_doubles(file, "a_over_l");
  const std::vector<double> b = read_doubles(file, "b_over_l");
  const std::vector<double> theta0 = read_doubles(file, "theta0");
  ASSERT_EQ(status.size(), 6u);
  ASSERT_EQ(b.size(), 6u);
  EXPECT_EQ(status.front(), 0) << "alpha2 = 0 is the circular arc, always solvable";
  EXPECT_EQ(status.back(), 1) << "the last load should be past the limit point";
  long converged = 0;
  for (std::size_t i = 0; i < status.size(); ++i) {
    const bool all_nan = std::isnan(a[i]) && std::isnan(b[i]) && std::isnan(theta0[i]);
    const bool all_finite = std::isfinite(a[i]) && std::isfinite(b[i]) && std::isfinite(theta0[i]);
    if (status[i] == 0) {
      ++converged;
      EXPECT_TRUE(all_finite) << i;
    } else {
      EXPECT_EQ(status[i], 1);
      EXPECT_TRUE(all_nan) << "NaN means no solution and is always flagged by status: " << i;
    }
  }
  EXPECT_EQ(j["converged_count"].get<long>(), converged);
  EXPECT_EQ(read_int_attribute(file, "/", "converged_count"), converged);
  H5Fclose(file);
}

void expect_invalid(const std::string& args, const std::string& must_mention) {
  const CommandResult r = run_flexure(args);
  EXPECT_EQ(r.exit_code, 2) << args << "\nstderr: " << r.err;
  EXPECT_TRUE(test::no_result_on_stdout(r)) << r.out;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(must_mention), std::string::npos) << args << ": " << r.err;
}

TEST(CliSweep, UnwritablePathIsExitTwoWithTheNameOfThePath) {
  expect_invalid("sweep beam --alpha2 0:1:3 --out /nonexistent/dir/x.h5", "/nonexistent/dir");
  expect_invalid("sweep beam --alpha2 0:1:3 --out /nonexistent/dir/x.h5 --json", "--out");
}

TEST(CliSweep, BadRangesAndMethodsAreExitTwoAndWriteNothing) {
  ScratchDir dir;
  const std::string out = " --out '" + (dir / "x.h5").string() + "'";
  expect_invalid("sweep beam --alpha2 0:1:0" + out, "COUNT");
  expect_invalid("sweep beam --alpha2 0:1" + out, "START:STOP:COUNT");
  expect_invalid("sweep beam --alpha2 nan:1:3" + out, "START");
  expect_invalid("sweep beam --alpha2 0:inf:3" + out, "STOP");
  expect_invalid("sweep beam --alpha2 0:1:2.5" + out, "COUNT");
  expect_invalid("sweep beam --alpha2 0:1:3 --n nan" + out, "--n");
  expect_invalid("sweep beam --alpha2 0:1:3 --method newton" + out, "--method");
  expect_invalid("sweep beam --alpha2 0:1:3 --method bogus" + out, "bogus");
  expect_invalid("sweep beam --alpha2 0:1:3", "--out");
  expect_invalid("sweep --alpha2 0:1:3" + out, "subcommand");
  EXPECT_TRUE(dir.entries().empty()) << "nothing may be written for invalid input";
}

}  // namespace
}  // namespace flexure::test

namespace flexure::test {
namespace {

// The serial build (FLEXURE_MPI=OFF) started by mpirun with several ranks would run the whole
// sweep in each and write the same file: it refuses, naming the build option (docs/scaling.md).
// The MPI build's behaviour under mpirun is tested in tests/mpi/.
TEST(CliSweep, SerialBuildUnderMpirunWithSeveralRanksIsRefused) {
#ifdef FLEXURE_WITH_MPI
  GTEST_SKIP() << "the MPI build divides the sweep (tests/mpi/)";
#endif
  if (std::system("command -v mpirun >/dev/null 2>&1") != 0) GTEST_SKIP() << "no mpirun";
  ScratchDir dir;
  const CommandResult r = run_flexure(
      "sweep beam --alpha2 0:1:11 --out s.h5",
      dir.path(),
      "env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 timeout 120 mpirun -np 2 "
      "--oversubscribe ");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("built without MPI"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("-DFLEXURE_MPI=ON"), std::string::npos) << r.err;
  EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace flexure::test
