// The pseudo-arclength path shared by the general mechanism's models (mechanisms/general/
// arclength_path.h) on the cubic fold F(x, lambda) = x^3 - x - lambda = 0, whose limit points
// (lambda = +-2 / (3 sqrt 3) at x = -+1 / sqrt 3), grid crossings and zeros are known in closed
// form.
#include "flexure/mechanisms/general/arclength_path.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace flexure::mechanism::general {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

constexpr int kX = 0;
constexpr int kLambda = 1;

ArclengthPath cubic_path(double max_step, int max_steps) {
  ArclengthCurve c;
  c.size = 2;
  c.residual = [](const VectorXd& y, VectorXd& F) {
    F.resize(1);
    F[0] = y[kX] * y[kX] * y[kX] - y[kX] - y[kLambda];
    return true;
  };
  c.jacobian = [](const VectorXd& y, MatrixXd& J) {
    J.resize(1, 2);
    J(0, kX) = 3.0 * y[kX] * y[kX] - 1.0;
    J(0, kLambda) = -1.0;
    return true;
  };
  c.weight = VectorXd::Ones(2);
  return ArclengthPath(c, {1e-12, 30, max_step, max_steps});
}

TEST(ArclengthPath, FollowsTheLoadThroughBothFoldsOfTheCubic) {
  ArclengthPath path = cubic_path(0.05, 10000);
  VectorXd y(2);
  y << -1.5, -1.875;  // on the curve: (-1.5)^3 + 1.5
  std::vector<double> grid;
  for (int i = 0; i < 7; ++i) grid.push_back(-1.5 + 0.5 * i);  // lambda -1.5 .. 1.5
  std::vector<VectorXd> recorded, limits;
  ArclengthPath::Follow how;
  how.controlled = kLambda;
  how.grid = &grid;
  how.record = [&](const VectorXd& p) { recorded.push_back(p); };
  how.limit = [&](const VectorXd& p) { limits.push_back(p); };
  ASSERT_EQ(path.follow(y, 1.875, how), Termination::kConverged);
  EXPECT_NEAR(y[kX], 1.5, 1e-11);  // the upper branch at the target

  // Two folds, in the order met: lambda_max at x = -1/sqrt3, then lambda_min at +1/sqrt3. The
  // bisection stops at 1e-13 of arclength; the fold's lambda is quadratic in it.
  const double xf = 1.0 / std::sqrt(3.0);
  const double lf = 2.0 / (3.0 * std::sqrt(3.0));
  ASSERT_EQ(limits.size(), 2u);
  EXPECT_NEAR(limits[0][kX], -xf, 1e-6);
  EXPECT_NEAR(limits[0][kLambda], lf, 1e-11);
  EXPECT_NEAR(limits[1][kX], xf, 1e-6);
  EXPECT_NEAR(limits[1][kLambda], -lf, 1e-11);

  // The grid values inside the folds' band (|lambda| < 0.385: only 0) are crossed three times
  // (x = -1, 0, 1), the others once: 9 points, each on the curve.
  ASSERT_EQ(recorded.size(), 9u);
  for (const VectorXd& p : recorded) {
    EXPECT_NEAR(p[kX] * p[kX] * p[kX] - p[kX], p[kLambda], 1e-12);
  }
  EXPECT_NEAR(recorded[3][kX], -1.0, 1e-12);
  EXPECT_NEAR(recorded[4][kX], 0.0, 1e-12);
  EXPECT_NEAR(recorded[5][kX], 1.0, 1e-12);

  // The zeros of lambda along the dense path: the same three roots of x^3 - x.
  std::vector<VectorXd> failed;
  const std::vector<VectorXd> zeros = path.zeros_along(kLambda, &failed);
  EXPECT_TRUE(failed.empty());
  ASSERT_EQ(zeros.size(), 3u);
  EXPECT_NEAR(zeros[0][kX], -1.0, 1e-12);
  EXPECT_NEAR(zeros[1][kX], 0.0, 1e-12);
  EXPECT_NEAR(zeros[2][kX], 1.0, 1e-12);
}

TEST(ArclengthPath, RunsOutOfStepsAsALimitPoint) {
  // Ten steps of at most 0.05 cannot reach lambda = 1.875 from -1.875 (about 4.6 of arclength).
  ArclengthPath short_path = cubic_path(0.05, 10);
  VectorXd y(2);
  y << -1.5, -1.875;
  ArclengthPath::Follow how;
  how.controlled = kLambda;
  EXPECT_EQ(short_path.follow(y, 1.875, how), Termination::kLimitPoint);
  EXPECT_EQ(short_path.steps(), 10);
}

}  // namespace
}  // namespace flexure::mechanism::general
