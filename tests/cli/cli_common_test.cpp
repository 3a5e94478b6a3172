// What is checked against what: the shared CLI plumbing (cli/cli_common.cpp, linked from the
// tool's flexure_cli library). START:STOP:COUNT parsing against the arithmetic
// of equally spaced values (exact ends, descending ranges, COUNT = 1), rejection of malformed
// ranges with InvalidInput naming the flag, and print_json refusing NaN/Inf anywhere in an object
// with NoConvergence (the contract: a result is never printed as NaN).
#include "cli/cli_common.h"

#include <gtest/gtest.h>

#include <limits>

#include "flexure/solver/common/status.h"

namespace flexure::cli {
namespace {

TEST(ParseRange, EquallySpacedWithExactEnds) {
  const Range r = parse_range("0.1:0.7:7", "--alpha2");
  EXPECT_EQ(r.count, 7);
  EXPECT_EQ(r.at(0), 0.1);
  EXPECT_EQ(r.at(6), 0.7);
  for (long i = 0; i < 7; ++i) EXPECT_NEAR(r.at(i), 0.1 + 0.1 * i, 1e-15);
}

TEST(ParseRange, DescendingAndSingleAndExponents) {
  const Range down = parse_range("2:-2:5", "--alpha2");
  EXPECT_EQ(down.at(1), 1.0);
  EXPECT_EQ(down.at(4), -2.0);
  const Range one = parse_range("3:100:1", "--alpha2");
  EXPECT_EQ(one.count, 1);
  EXPECT_EQ(one.at(0), 3.0);
  const Range exp = parse_range("1e-4:1e1:2", "--alpha2");
  EXPECT_EQ(exp.start, 1e-4);
  EXPECT_EQ(exp.stop, 10.0);
}

TEST(ParseRange, MalformedRangesNameTheFlag) {
  for (const char* bad : {"",
                          "1",
                          "1:2",
                          "1:2:3:4",
                          "a:2:3",
                          "1:b:3",
                          "1:2:c",
                          "1:2:0",
                          "1:2:-3",
                          "1:2:2.5",
                          "nan:2:3",
                          "1:inf:3",
                          "1 :2:3",
                          "1:2:99999999999"}) {
    try {
      parse_range(bad, "--alpha2", 1000);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find("--alpha2"), std::string::npos) << e.what();
    }
  }
}

TEST(PrintJson, RefusesNaNAndInfAnywhere) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(print_json(Json{{"alpha2", nan}}), NoConvergence);
  EXPECT_THROW(print_json(Json{{"shape", Json::array({Json{{"x", 0.0}}, Json{{"x", inf}}})}}),
               NoConvergence);
  try {
    print_json(Json{{"a", 1.0}, {"nested", Json{{"b_over_l", -inf}}}});
    ADD_FAILURE() << "Inf accepted";
  } catch (const NoConvergence& e) {
    EXPECT_NE(std::string(e.what()).find("/nested/b_over_l"), std::string::npos) << e.what();
  }
}

TEST(RequireInRange, MessageNamesTheQuantityAndTheRange) {
  try {
    require_in_range(5.0, "--shape", 2, 4);
    ADD_FAILURE();
  } catch (const InvalidInput& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("--shape"), std::string::npos) << m;
    EXPECT_NE(m.find("[2, 4]"), std::string::npos) << m;
  }
  EXPECT_NO_THROW(require_in_range(4.0, "--shape", 2, 4));
  EXPECT_THROW(require_finite_input(std::numeric_limits<double>::quiet_NaN(), "--n"), InvalidInput);
  EXPECT_THROW(require_finite_result(std::numeric_limits<double>::infinity(), "b/l"),
               NoConvergence);
}

}  // namespace
}  // namespace flexure::cli
