// What is checked against what: the run of `flexure sweep beam` in the library
// (benchmarks/studies/beam_sweep_run.h).
//  * The scheduling policy against its documented rule (docs/cli.md, docs/scaling.md): 10^7 points
//    and 2 threads outside mpirun; chunks of count/(64 threads) clamped to [1, 2048]; blocks of at
//    least 1024 loads for the microsecond methods (elliptic, PRBM), 1 for the others.
//  * A 2-axis run (alpha2 x n, elliptic; and a 1-axis shooting run), read back with the plain HDF5
//    C API: every point's tip equals solve_beam at that grid point (1e-12: the same solver; the
//    shooting sweep's neighbour starts converge to the same equilibrium within its tolerance),
//    /axes holds the axes' values, the status is 0 everywhere, the counts match.
//  * A path that cannot be written fails when the file is made (InvalidInput naming the caller's
//    option), before any solve; a second run of one file is refused.
#include "flexure/benchmarks/studies/beam_sweep_run.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "flexure/beam/beam_problem.h"
#include "flexure/solver/common/status.h"
#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

TEST(BeamSweepRun, PolicyFollowsItsRule) {
  EXPECT_EQ(max_beam_sweep_points(), 10'000'000L);
  EXPECT_EQ(default_beam_sweep_threads(), 2);
  EXPECT_EQ(beam_sweep_chunk(100'000, 2), 781);  // 100000 / 128
  EXPECT_EQ(beam_sweep_chunk(10, 2), 1);
  EXPECT_EQ(beam_sweep_chunk(1'000'000'000L, 1), 2048);
  EXPECT_EQ(beam_sweep_min_block(BeamMethod::kElliptic), 1024);
  EXPECT_EQ(beam_sweep_min_block(BeamMethod::kPrbm), 1024);
  EXPECT_EQ(beam_sweep_min_block(BeamMethod::kShooting), 1);
  EXPECT_EQ(beam_sweep_min_block(BeamMethod::kChain), 1);
}

BeamSweepGrid grid_alpha2_by_n() {
  BeamSweepGrid grid;
  grid.axes.push_back({SweepParameter::kAlpha2, 0.5, 3.5, 4});
  grid.axes.push_back({SweepParameter::kLoadRatioN, -1.0, 1.0, 3});
  grid.validate(max_beam_sweep_points());
  return grid;
}

TEST(BeamSweepRun, FileHoldsTheSolutionAtEveryGridPoint) {
  ScratchDir dir;
  const std::string path = (dir / "grid.h5").string();
  const BeamSweepGrid grid = grid_alpha2_by_n();
  BeamSweepFile file(path, false);
  const BeamSweepRun run = file.run(grid, BeamMethod::kAuto);
  EXPECT_EQ(run.method, BeamMethod::kElliptic);  // auto over a sweep
  EXPECT_EQ(run.count, 12);
  EXPECT_EQ(run.converged_count, 12);
  EXPECT_EQ(run.first_failure, -1);
  EXPECT_EQ(run.stored_axes, (std::vector<std::string>{"alpha2", "load_ratio_n"}));

  const hid_t h5 = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(h5, 0);
  const std::vector<double> a = read_doubles(h5, "/a_over_l");
  const std::vector<double> b = read_doubles(h5, "/b_over_l");
  const std::vector<int> status = read_ints(h5, "/status");
  const std::vector<double> axis_alpha2 = read_doubles(h5, "/axes/alpha2");
  const std::vector<double> axis_n = read_doubles(h5, "/axes/load_ratio_n");
  H5Fclose(h5);
  ASSERT_EQ(a.size(), 12u);
  ASSERT_EQ(status.size(), 12u);
  // Equally spaced (exact at both ends; the inner values to rounding).
  ASSERT_EQ(axis_alpha2.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(axis_alpha2[k], 0.5 + k, 1e-15);
  EXPECT_EQ(axis_n, (std::vector<double>{-1.0, 0.0, 1.0}));
  for (long i = 0; i < 12; ++i) {
    const BeamSolution s = solve_beam(BeamMethod::kElliptic, grid.at(i));
    ASSERT_TRUE(s.converged());
    EXPECT_EQ(status[i], 0);
    EXPECT_NEAR(a[i], s.tip.a_over_l, 1e-12) << describe_sweep_point(grid, i);
    EXPECT_NEAR(b[i], s.tip.b_over_l, 1e-12) << describe_sweep_point(grid, i);
  }
  EXPECT_EQ(describe_sweep_point(grid, 5),
            fmt::format("alpha2 = {}, load_ratio_n = 1", grid.axes[0].at(1)));
  EXPECT_THROW(file.run(grid, BeamMethod::kElliptic), std::logic_error);
}

TEST(BeamSweepRun, ShootingSweepMatchesSingleSolves) {
  ScratchDir dir;
  const std::string path = (dir / "shooting.h5").string();
  BeamSweepGrid grid;
  grid.base.load_ratio_n = 0.5;
  grid.axes.push_back({SweepParameter::kAlpha2, 0.5, 5.0, 10});
  grid.validate(max_beam_sweep_points());
  BeamSweepFile file(path, false);
  BeamSweepRunOptions options;
  options.threads = 1;
  const BeamSweepRun run = file.run(grid, BeamMethod::kShooting, options);
  EXPECT_EQ(run.converged_count, 10);
  EXPECT_TRUE(run.stored_axes.empty());  // the plain sweep over alpha2: /alpha2 is the axis
  const hid_t h5 = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(h5, 0);
  const std::vector<double> a = read_doubles(h5, "/a_over_l");
  H5Fclose(h5);
  ASSERT_EQ(a.size(), 10u);
  for (long i = 0; i < 10; ++i) {
    // Shooting at rtol 1e-12 from another start: the same equilibrium to well within 1e-8.
    EXPECT_NEAR(a[i], solve_beam(BeamMethod::kElliptic, grid.at(i)).tip.a_over_l, 1e-8);
  }
}

TEST(BeamSweepRun, AnUnwritablePathFailsBeforeSolving) {
  try {
    BeamSweepFile file("/nonexistent-directory/sweep.h5", false, "out");
    FAIL() << "accepted an unwritable path";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()).rfind("out: ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace flexure::test
