// The stress power law alpha_p = M d^n (mechanisms/cfm/power_law_fit.h) against the values Weight
// printed: M and n of all 68 Ch. 7 sub-classes (nonlinear least squares over the thesis code's
// stroke sampling) and Table 4.2 (log-log line on the integer grid, Table 2.1's R).
#include "flexure/mechanisms/cfm/power_law_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/cfm_comparison.h"

namespace flexure::cfm {
namespace {

// Ch. 7 prints M and n to 4 decimals. n is reproduced to one unit in the last place (measured at
// most 5.2e-5). M to two units: half a unit of its own rounding plus the effect of the printed R's
// rounding (half a unit of R moves M by 1.2e-4 to 1.3e-4 on the spp rows); measured at most 1.8e-4
// (spp-a95), 1.3e-4 (slp-a90I), 1.2e-4 (spp-a90), all others below 7.6e-5.
constexpr double kMTolerance = 2e-4;
constexpr double kNTolerance = 1e-4;
TEST(PowerLawFit, ReproducesEveryChapterSevenRow) {
  int rows = 0;
  for (const CfmSubclass& row : thesis_subclasses()) {
    const StressPowerLaw f = fit_stress_power_law(parameters_of(row));
    // sps-b86IO (R = 1, K2 = 1) is its own mirror image: pivots 1 and 3 tie (docs/cfm.md §5 of
    // the reproduction notes) and carry the same alpha, so either gives the printed M and n.
    if (std::string(row.name) != "sps-b86IO") {
      EXPECT_EQ(f.primary_pivot, row.primary_pivot) << row.name;
    }
    EXPECT_NEAR(f.M, row.M, kMTolerance) << row.name;
    EXPECT_NEAR(f.n, row.n, kNTolerance) << row.name;
    ++rows;
  }
  EXPECT_EQ(rows, 68);
}

// Table 4.2 (the log-log regression of the class rows of Table 2.1 over d = 1..d_max): printed to
// 3 decimals.
TEST(PowerLawFit, LogLogFitReproducesTableFourTwo) {
  struct Case {
    const char* config;
    double R, K1, K2, d, M, n;
  };
  const Case cases[] = {
      {"lpp", 0.8274, 0.0, 0.0, 16.0, 0.450, 0.500},
      {"lpp", 0.8853, 0.0, 0.0, 40.0, 0.479, 0.503},
      {"spp", 0.8274, 0.0, 0.0, 16.0, 2.351, 0.500},
      {"lps", 0.7591, 0.0, 0.1208, 16.0, 3.743, 0.511},
      {"sss", 2.6633, 1.0, 12.6704, 16.0, 8.356, 0.525},
  };
  for (const Case& c : cases) {
    CfmParameters p{c.config, c.R, std::nullopt, std::nullopt, c.d};
    if (c.K1 > 0.0) p.K1 = c.K1;
    if (c.K2 > 0.0) p.K2 = c.K2;
    const StressPowerLaw f = fit_stress_power_law_loglog(p);
    EXPECT_NEAR(f.M, c.M, 6e-4) << c.config << " d = " << c.d;
    EXPECT_NEAR(f.n, c.n, 6e-4) << c.config << " d = " << c.d;
    EXPECT_EQ(f.points, static_cast<int>(c.d)) << c.config;
  }
}

TEST(PowerLawFit, RefusesAStrokeTooShortForTheGrid) {
  EXPECT_THROW(fit_stress_power_law_loglog({"lpp", 0.8274, std::nullopt, std::nullopt, 1.5}),
               std::exception);
}

}  // namespace
}  // namespace flexure::cfm
