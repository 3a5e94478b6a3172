// What is checked against what: io::run_beam_sweep and io::write_beam_sweep with a point solver
// defined here (linear cantilever theory, b/l = alpha2/3 and theta0 = alpha2/2, declared
// "not converged" above a threshold) so every stored value is known in advance: each dataset read
// back with the C API equals the formula or NaN with status 1; serial and 2-thread sweeps agree
// exactly; the attributes carry the metadata and flexure/version.h; an InvalidInput from the
// point solver aborts the sweep naming the load.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

#include "flexure/io/beam_sweep.h"
#include "flexure/solver/common/status.h"
#include "flexure/version.h"
#include "tests/support/cli_test_support.h"

namespace flexure::io {
namespace {

constexpr double kFailAbove = 2.0;  // the fake method "does not converge" for alpha2 > 2

BeamSweepPoint linear_point(double alpha2) {
  BeamSweepPoint point;
  if (alpha2 > kFailAbove) {
    point.message = "fake divergence";
    return point;
  }
  point.set_converged(true);
  point.tip = TipPose{1.0, alpha2 / 3.0, alpha2 / 2.0};
  return point;
}

std::vector<double> loads(long count) {
  std::vector<double> values(count);
  for (long i = 0; i < count; ++i) values[i] = 3.0 * i / (count - 1);  // 0 .. 3
  return values;
}

TEST(BeamSweep, StoresValuesAndFlagsFailuresWithStatusAndNaN) {
  const std::vector<double> alpha2 = loads(301);
  BeamSweepOptions options;
  options.threads = 2;
  options.chunk = 7;  // many chunks, so both threads take part
  const BeamSweepTable table = run_beam_sweep(alpha2, linear_point, options);
  long expected_converged = 0;
  for (std::size_t i = 0; i < alpha2.size(); ++i) {
    if (alpha2[i] <= kFailAbove) {
      ++expected_converged;
      EXPECT_EQ(table.status[i], kSweepConverged);
      EXPECT_EQ(table.b_over_l[i], alpha2[i] / 3.0);
      EXPECT_EQ(table.theta0[i], alpha2[i] / 2.0);
    } else {
      EXPECT_EQ(table.status[i], kSweepNotConverged);
      EXPECT_TRUE(std::isnan(table.a_over_l[i]) && std::isnan(table.b_over_l[i]) &&
                  std::isnan(table.theta0[i]));
    }
  }
  EXPECT_EQ(table.converged_count, expected_converged);
  ASSERT_GE(table.first_failure, 0);
  EXPECT_GT(alpha2[table.first_failure], kFailAbove);
  EXPECT_LE(alpha2[table.first_failure - 1], kFailAbove);
  EXPECT_EQ(table.first_failure_message, "fake divergence");
}

TEST(BeamSweep, TwoThreadsGiveTheSameTableAsOne) {
  const std::vector<double> alpha2 = loads(5000);
  BeamSweepOptions serial;
  serial.threads = 1;
  BeamSweepOptions parallel;
  parallel.threads = 2;
  parallel.chunk = 64;
  const BeamSweepTable a = run_beam_sweep(alpha2, linear_point, serial);
  const BeamSweepTable b = run_beam_sweep(alpha2, linear_point, parallel);
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.converged_count, b.converged_count);
  for (std::size_t i = 0; i < alpha2.size(); ++i) {
    if (a.status[i] == kSweepConverged) EXPECT_EQ(a.b_over_l[i], b.b_over_l[i]);
  }
}

TEST(BeamSweep, ProgressIsReportedUpToTheTotal) {
  const std::vector<double> alpha2 = loads(1000);
  std::atomic<long> last{-1};
  BeamSweepOptions options;
  options.progress = [&](long done, long total) {
    EXPECT_EQ(total, 1000);
    EXPECT_GE(done, last.load());
    last = done;
  };
  run_beam_sweep(alpha2, linear_point, options);
  EXPECT_EQ(last.load(), 1000);
}

TEST(BeamSweep, InvalidInputAbortsTheSweepNamingTheLoad) {
  const std::vector<double> alpha2 = {0.0, 0.5, -1.0, 1.0};
  const BeamPointSolver reject_negative = [](double a) {
    if (a < 0) throw InvalidInput("alpha2 must be >= 0");
    return linear_point(a);
  };
  try {
    run_beam_sweep(alpha2, reject_negative);
    FAIL() << "no exception";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("alpha2 = -1"), std::string::npos) << e.what();
  }
}

TEST(BeamSweep, WithThreadsTheFirstInvalidLoadIsTheOneReported) {
  // Load 700 is found invalid only after 50 ms, while every later load is refused at once: another
  // thread meets those first. The error must still name load 700, as a single thread would (and
  // as every rank count of an MPI run does: docs/scaling.md).
  std::vector<double> alpha2(2000);
  for (std::size_t i = 0; i < alpha2.size(); ++i) alpha2[i] = static_cast<double>(i);
  const BeamPointSolver reject = [](double a) {
    if (a == 700.0) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    if (a >= 700.0) throw InvalidInput("refused");
    return linear_point(a);
  };
  BeamSweepOptions options;
  options.threads = 2;
  options.chunk = 1;
  for (int run = 0; run < 3; ++run) {
    try {
      run_beam_sweep(alpha2, reject, options);
      FAIL() << "no exception";
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find("alpha2 = 700:"), std::string::npos) << e.what();
    }
  }
}

TEST(BeamSweep, NoConvergenceThrownByTheMethodIsStoredAsStatusOne) {
  const std::vector<double> alpha2 = {0.0, 1.0};
  const BeamPointSolver throwing = [](double a) {
    if (a > 0.5) throw NoConvergence("gave up after 3 steps");
    return linear_point(a);
  };
  const BeamSweepTable table = run_beam_sweep(alpha2, throwing);
  EXPECT_EQ(table.status, (std::vector<int>{kSweepConverged, kSweepNotConverged}));
  EXPECT_EQ(table.first_failure, 1);
  EXPECT_EQ(table.first_failure_message, "gave up after 3 steps");
}

TEST(BeamSweep, FileLayoutReadsBackWithTheCApi) {
  test::ScratchDir dir;
  const auto path = dir / "sweep.h5";
  const std::vector<double> alpha2 = loads(31);
  const BeamSweepTable table = run_beam_sweep(alpha2, linear_point);
  {
    AtomicHdf5File file(path.string());
    write_beam_sweep(file.root(), table, BeamSweepMetadata{BeamMethod::kLinear, 0.5, -0.25, 1e-14});
    file.commit();
  }
  hid_t file = test::open_read_only(path);
  ASSERT_GE(file, 0);
  EXPECT_EQ(test::read_doubles(file, "alpha2"), alpha2);
  const std::vector<double> b = test::read_doubles(file, "b_over_l");
  const std::vector<double> theta0 = test::read_doubles(file, "theta0");
  const std::vector<double> a = test::read_doubles(file, "a_over_l");
  const std::vector<int> status = test::read_ints(file, "status");
  ASSERT_EQ(b.size(), alpha2.size());
  ASSERT_EQ(status.size(), alpha2.size());
  for (std::size_t i = 0; i < alpha2.size(); ++i) {
    if (alpha2[i] <= kFailAbove) {
      EXPECT_EQ(status[i], 0);
      EXPECT_EQ(b[i], alpha2[i] / 3.0);
      EXPECT_EQ(theta0[i], alpha2[i] / 2.0);
      EXPECT_EQ(a[i], 1.0);
    } else {
      EXPECT_EQ(status[i], 1);
      EXPECT_TRUE(std::isnan(b[i]));
    }
  }
  EXPECT_EQ(test::read_string_attribute(file, "/", "method"), "linear");
  EXPECT_EQ(test::read_double_attribute(file, "/", "load_ratio_n"), 0.5);
  EXPECT_EQ(test::read_double_attribute(file, "/", "mu"), -0.25);
  EXPECT_EQ(test::read_double_attribute(file, "/", "tolerance"), 1e-14);
  EXPECT_EQ(test::read_int_attribute(file, "/", "count"), 31);
  EXPECT_EQ(test::read_int_attribute(file, "/", "converged_count"), table.converged_count);
  EXPECT_EQ(test::read_string_attribute(file, "/", "tool_version"), kVersion);
  EXPECT_EQ(test::read_string_attribute(file, "/", "git_commit"), kGitCommit);
  H5Fclose(file);
}

}  // namespace
}  // namespace flexure::io
