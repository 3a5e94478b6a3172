// What is checked against what: the accuracy map of `--method auto`, now the data file
// data/method_auto_error_map.csv compiled into the library. The embedded copy is the file, byte
// for byte, and bench::prbm_measured_error returns the margin 1.5 times the largest measured
// value around the load, for measured values written out here from the file's rows.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "flexure/beam/beam_problem.h"
#include "flexure/beam/data_files.h"
#include "tests/support/data_file_support.h"

namespace flexure {
namespace {

constexpr double kMargin = 1.5;

TEST(MethodAutoErrorMap, EmbeddedCopyEqualsTheFile) {
  test::expect_embedded_equals_file(data::method_auto_error_map());
}

TEST(MethodAutoErrorMap, MeasuredValues) {
  EXPECT_EQ(prbm_measured_error(0.0, 3.0), kMargin * 0.0045);   // n = 0, alpha2 = 3
  EXPECT_EQ(prbm_measured_error(-2.0, 0.5), kMargin * 0.027);   // first row
  EXPECT_EQ(prbm_measured_error(3.0, 20.0), kMargin * 0.099);   // last row
  EXPECT_EQ(prbm_measured_error(0.5, 3.5), kMargin * 0.042);    // max of n = 0, 1 x alpha2 = 3, 4
  EXPECT_EQ(prbm_measured_error(-1.5, 6.0), kMargin * 0.0073);  // max of n = -2, -1 x 5, 7.5
  EXPECT_TRUE(std::isnan(prbm_measured_error(-2.5, 3.0)));
  EXPECT_TRUE(std::isnan(prbm_measured_error(0.0, 0.25)));
  EXPECT_TRUE(std::isnan(prbm_measured_error(0.0, 21.0)));
}

TEST(MethodAutoErrorMap, ReasonNamesTheMeasuredRange) {
  AutoMethodRequest request;
  request.load_ratio_n = 5.0;  // in Table 5.1, outside the map
  request.alpha2 = 0.6;
  request.tolerance = 1.0;
  const AutoMethodChoice choice = choose_beam_method(request);
  EXPECT_EQ(choice.method, BeamMethod::kElliptic);
  EXPECT_NE(choice.reason.find(
                "no measured PRBM accuracy at this load (map covers -2 <= n <= 3, 0.5 <= alpha2 "
                "<= 20)"),
            std::string::npos)
      << choice.reason;
}

}  // namespace
}  // namespace flexure
