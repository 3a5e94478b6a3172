// The sweep grid (beam/beam_sweep_grid.h): row-major order with the second axis
// fastest, axis ends exact, each point's problem carries its coordinates in the right field, and
// invalid grids are refused naming the flag.
#include "flexure/beam/beam_sweep_grid.h"

#include <gtest/gtest.h>

#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

TEST(BeamSweepGrid, RowMajorSecondAxisFastest) {
  BeamSweepGrid grid;
  grid.axes = {{SweepParameter::kAlpha2, 0.5, 2.5, 3}, {SweepParameter::kLoadRatioN, -1, 1, 5}};
  grid.base.mu = 0.25;
  grid.validate(1000);
  EXPECT_EQ(grid.size(), 15);
  EXPECT_EQ(grid.shape(), (std::vector<long>{3, 5}));
  EXPECT_EQ(grid.axis_names(), "alpha2,load_ratio_n");
  for (long i = 0; i < 3; ++i) {
    for (long j = 0; j < 5; ++j) {
      const BeamProblem p = grid.at(i * 5 + j);
      EXPECT_EQ(p.value, 0.5 + i * 1.0);
      EXPECT_DOUBLE_EQ(p.load_ratio_n, -1.0 + 0.5 * j);
      EXPECT_EQ(p.mu, 0.25);
      EXPECT_EQ(p.given, BeamProblem::Given::kAlpha2);
    }
  }
  EXPECT_EQ(grid.at(14).load_ratio_n, 1.0);  // the end is exact
}

TEST(BeamSweepGrid, InverseTargetsAndMoments) {
  BeamSweepGrid grid;
  grid.base.given = BeamProblem::Given::kTheta0;
  grid.axes = {{SweepParameter::kTheta0, 0.1, 1.0, 10}, {SweepParameter::kMu, 0, 1, 2}};
  grid.validate(100);
  const BeamProblem p = grid.at(19);
  EXPECT_EQ(p.value, 1.0);
  EXPECT_EQ(p.mu, 1.0);
}

TEST(BeamSweepGrid, InvalidGridsNameTheFlag) {
  auto message = [](const BeamSweepGrid& g, long max) -> std::string {
    try {
      g.validate(max);
    } catch (const InvalidInput& e) {
      return e.what();
    }
    return "";
  };
  BeamSweepGrid grid;
  EXPECT_NE(message(grid, 10).find("one or two"), std::string::npos);
  grid.axes = {{SweepParameter::kMu, 0, 1, 2}, {SweepParameter::kMu, 0, 1, 2}};
  EXPECT_NE(message(grid, 10).find("--mu is given as a range twice"), std::string::npos);
  grid.axes = {{SweepParameter::kTheta0, 0, 1, 2}};  // base.given is alpha2
  EXPECT_NE(message(grid, 10).find("--theta0"), std::string::npos);
  grid.base.given = BeamProblem::Given::kBOverL;
  grid.axes = {{SweepParameter::kBOverL, 0, 1.5, 2}};
  EXPECT_NE(message(grid, 10).find("[-1, 1]"), std::string::npos);
  grid.base.given = BeamProblem::Given::kAlpha2;
  grid.axes = {{SweepParameter::kAlpha2, 0, 1, 100000}, {SweepParameter::kLoadRatioN, 0, 1, 200}};
  EXPECT_NE(message(grid, 10'000'000).find("more than 10000000 points"), std::string::npos);
}

}  // namespace
}  // namespace flexure
