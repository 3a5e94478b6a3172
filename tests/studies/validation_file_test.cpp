// The results file of `flexure validate` written by the library (validation_file.h), read back
// with the plain HDF5 C API: every row equals the check it came from (text, numbers bit for bit,
// passed), status is 1 exactly where computed is NaN, the root attributes count and all_passed
// equal the report's. A path that cannot be written fails in the constructor, before any check
// runs, and a writer dropped before write() leaves no file. run_validation() summarises
// run_validation_checks(): all_passed and converged() hold exactly when every row passed.
#include "flexure/benchmarks/studies/validation_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "flexure/solver/common/status.h"
#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

ValidationReport three_rows() {
  ValidationReport r;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  r.checks = {
      {"howell-example", "elliptic", "alpha", 1.7569869, 1.7569869, 1.1e-9, 1e-7, true, 2e-6, ""},
      {"fixed-guided", "chain", "theta0", 0.25, 0.2500001, 4e-7, 1e-6, true, 3e-5, ""},
      {"end moment", "shooting", "a_over_l", nan, 0.0, nan, 1e-7, false, 1e-4, "not converged"},
  };
  r.all_passed = false;
  return r;
}

TEST(ValidationFile, RowsEqualTheChecksAndStatusFlagsNaN) {
  ScratchDir dir;
  const auto path = dir / "v.h5";
  const ValidationReport report = three_rows();
  {
    ValidationFile file(path.string());
    file.write(report);
  }
  ASSERT_EQ(dir.entries(), std::vector<std::string>{"v.h5"});
  const hid_t f = open_read_only(path);
  ASSERT_GE(f, 0);
  const std::vector<std::string> problem = read_strings(f, "problem");
  const std::vector<std::string> method = read_strings(f, "method");
  const std::vector<std::string> quantity = read_strings(f, "quantity");
  const std::vector<std::string> message = read_strings(f, "message");
  const std::vector<std::string> units = read_strings(f, "quantity_units");
  const std::vector<double> computed = read_doubles(f, "computed");
  const std::vector<double> reference = read_doubles(f, "reference");
  const std::vector<double> rel_error = read_doubles(f, "rel_error");
  const std::vector<double> tolerance = read_doubles(f, "tolerance");
  const std::vector<double> seconds = read_doubles(f, "seconds_per_solve");
  const std::vector<int> passed = read_ints(f, "passed");
  const std::vector<int> status = read_ints(f, "status");
  ASSERT_EQ(problem.size(), report.checks.size());
  for (std::size_t i = 0; i < report.checks.size(); ++i) {
    const ValidationCheck& c = report.checks[i];
    EXPECT_EQ(problem[i], c.problem);
    EXPECT_EQ(method[i], c.method);
    EXPECT_EQ(quantity[i], c.quantity);
    EXPECT_EQ(message[i], c.message);
    EXPECT_EQ(units[i], c.quantity == "theta0" ? "rad" : "1");
    EXPECT_EQ(std::isnan(computed[i]), std::isnan(c.computed));
    if (!std::isnan(c.computed)) EXPECT_EQ(computed[i], c.computed);
    EXPECT_EQ(reference[i], c.reference);
    if (!std::isnan(c.rel_error)) EXPECT_EQ(rel_error[i], c.rel_error);
    EXPECT_EQ(tolerance[i], c.tolerance);
    EXPECT_EQ(seconds[i], c.seconds_per_solve);
    EXPECT_EQ(passed[i], c.passed ? 1 : 0);
    EXPECT_EQ(status[i], std::isnan(c.computed) ? 1 : 0) << i;
  }
  EXPECT_EQ(read_int_attribute(f, "/", "count"), 3);
  EXPECT_EQ(read_int_attribute(f, "/", "all_passed"), 0);
  H5Fclose(f);
}

TEST(ValidationFile, UnwritablePathFailsInTheConstructorAndNothingIsLeft) {
  try {
    ValidationFile file("/nonexistent/dir/v.h5");
    FAIL() << "no exception";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir"), std::string::npos) << e.what();
  }
  ScratchDir dir;
  { ValidationFile dropped((dir / "v.h5").string()); }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(ValidationFile, RunValidationPassesExactlyWhenEveryCheckPasses) {
  const ValidationReport r = run_validation();
  ASSERT_GE(r.checks.size(), 20u);
  bool every = true;
  for (const ValidationCheck& c : r.checks) every = every && c.passed;
  EXPECT_EQ(r.all_passed, every);
  EXPECT_EQ(r.converged(), every);
  EXPECT_TRUE(r.all_passed) << r.message;
}

}  // namespace
}  // namespace flexure::test
