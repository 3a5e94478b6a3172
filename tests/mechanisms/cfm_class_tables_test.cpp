// What is checked against what: the class-level rows of Howell's Table 10.1 (§10.1.3) and of
// thesis Table 2.1 (§2.4), recomputed with 50 equally spaced stroke points and the spring
// rotations of the principal-angle convention (the printed "2 pi" dropped), against the printed
// Xi = max F/min F and mean Phi.
//  * Howell 1A, 2A, 3A: within 1e-4 (the lead's acceptance figure) plus the change caused by
//    rounding the printed R, K1, K2 to 4 decimals (2A-a: dPhi/dK1 = 3.75, so K1's rounding alone
//    is worth 1.9e-4; the computed Phi is 1.5e-4 off).
//  * Class 1B: within 2e-3; the 1B force rises steeply from Delta x = 0, so its mean depends on the
//    sampling at ~1e-3 (with/without the Delta x -> 0 point brackets the printed value).
//  * Howell 2B is NOT reproducible: its Xi and Phi belong to K2 ~ 1 (the Ch. 7 set, K2 = 1.0029)
//    while K2 = 0.1208 is printed. Checked both ways: far from K2 = 0.1208, near K2 = 1.0029.
//  * Thesis Table 2.1's 2B row (K2 = 0.1208 with Xi 1.0029, Phi 0.5230) IS self-consistent.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/cfm_comparison.h"
#include "tests/support/cfm_test_support.h"

namespace flexure::cfm {
namespace {

constexpr double kHowellTolerance = 1e-4;    // acceptance for 1A, 2A, 3A
constexpr double kClass1BTolerance = 2e-3;   // sampling sensitivity of class 1B
constexpr double kPrintedHalfUnit = 0.5e-4;  // Table 2.1 prints 4 decimals
constexpr double kRepresentation = 1e-12;
// Howell 2B printed Xi/Phi vs the K2 ~ 1 model: "approximately" (no single K2 gives 4 digits,
// docs/cfm.md §3 item 3); 50 points give 8e-4/5e-4 (a) and 9e-4/5e-4 (b).
constexpr double kBook2BNearOne = 1.5e-3;

CfmModel fifty_points() {
  CfmOptions options;
  options.sampling = StrokeSampling::kUniform;
  options.points = 50;  // Howell §10.1: "average of Phi for 50 equally spaced points"
  return CfmModel(options);
}

void expect_row(const CfmClassRow& row, double tolerance) {
  const CfmParameters p = parameters_of(row);
  const CfmResult r = fifty_points().evaluate(p);
  ASSERT_TRUE(r.converged()) << row.name;
  const auto xi = [](const CfmResult& x) { return x.Xi; };
  const auto phi = [](const CfmResult& x) { return x.Phi; };
  EXPECT_NEAR(
      r.Xi, row.Xi, tolerance + testing::input_band(fifty_points(), p, xi) + kRepresentation)
      << row.name;
  EXPECT_NEAR(
      r.Phi, row.Phi, tolerance + testing::input_band(fifty_points(), p, phi) + kRepresentation)
      << row.name;
}

TEST(CfmHowellTable10_1, Classes1A2A3AWithinOneInTenThousand) {
  for (const CfmClassRow& row : howell_table_10_1()) {
    const std::string c = row.class_name;
    if (c == "1A" || c == "2A" || c == "3A") expect_row(row, kHowellTolerance);
  }
}

TEST(CfmHowellTable10_1, Class1BWithinSamplingSensitivity) {
  for (const CfmClassRow& row : howell_table_10_1()) {
    if (std::string(row.class_name) == "1B") expect_row(row, kClass1BTolerance);
  }
}

TEST(CfmHowellTable10_1, Class2BPrintedValuesBelongToK2NearOneNotToPrintedK2) {
  const CfmModel model = fifty_points();
  for (const CfmClassRow& row : howell_table_10_1()) {
    if (std::string(row.class_name) != "2B") continue;
    EXPECT_FALSE(row.reproducible);
    const CfmResult printed_inputs = model.evaluate(parameters_of(row));
    EXPECT_GT(std::abs(printed_inputs.Phi - row.Phi), 0.5) << row.name;  // 0.523 vs 1.2259
    // The Ch. 7 originals (lps/sps-a: K2 = 1.0029; sps-b: 1.0235) land within 1e-3 of the book.
    CfmParameters p = parameters_of(row);
    p.K2 = row.stroke_percent == 16.0 ? 1.0029 : 1.0235;
    const CfmResult near_one = model.evaluate(p);
    EXPECT_NEAR(near_one.Phi, row.Phi, kBook2BNearOne) << row.name;
    EXPECT_NEAR(near_one.Xi, row.Xi, kBook2BNearOne) << row.name;
  }
}

TEST(CfmThesisTable2_1, EveryRowIncluding2BWithPrintedK2) {
  for (const CfmClassRow& row : thesis_table_2_1()) {
    const bool class_1B = std::string(row.class_name) == "1B";
    expect_row(row, class_1B ? kClass1BTolerance : kPrintedHalfUnit);
  }
}

TEST(CfmThesisTable2_1, Class2AbRowReproducesOnlyAtTheToggleClampedStroke) {
  const CfmClassRow* row = find_class_row("table2.1-2A-b");
  ASSERT_NE(row, nullptr);
  const CfmResult r = fifty_points().evaluate(parameters_of(*row));
  EXPECT_TRUE(r.stroke_clamped);
  EXPECT_NEAR(r.stroke_percent, 37.04, 0.005);  // docs/cfm.md §1.3
}

}  // namespace
}  // namespace flexure::cfm
