// What is checked against what:
//  * the error function (eqs. 5.42, 5.44-5.47) against independently computed n = 0 values
//    (exact tips of eqs. 2.90-2.98 and Theta for gamma = 0.8517; path errors at 40, 70, 77, 80 deg
//    computed from the elliptic solver's tips);
//  * the end-moment derivation (closed-form circular path) against Howell's gamma = 0.7346 (4
//  digits)
//    and theta0_max = 124.4 deg (eqs. 5.107-5.108);
//  * the fixed-pinned derivation from the elliptic solver against Table 5.1, with the issue's
//    acceptance tolerances for the rows n >= -1 (gamma 0.001, c_theta 0.01, K_theta 0.01,
//    Theta_max(gamma) 1 deg); for the tension rows n <= -1.5 the derived Theta_max must be at least
//    the table's (the table's gamma is not the optimum of its own criterion), and at n = -5 the
//    derived gamma differs from the table by about 0.05 (docs/prbm.md, "The tension rows");
//  * K_theta is the least-squares slope of eqs. 5.56-5.59 over Table 5.1's Theta_max(K_theta) (an
//    input: Howell states no criterion for it), recomputed by the test from exact tips;
//  * the derived gamma is a maximiser: Theta_max at gamma +- 0.002 is not larger.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "flexure/elements/prbm_element.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/elliptic/elliptic_solver.h"

namespace flexure {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Acceptance tolerances for Table 5.1 (docs/prbm.md), rows n >= -1.
constexpr double kGammaTolerance = 0.001;
constexpr double kCThetaTolerance = 0.01;
constexpr double kKThetaTolerance = 0.01;
constexpr double kThetaMaxToleranceDeg = 1.0;
// The same samples and the same sums in another order: rounding only.
constexpr double kKThetaRecomputedTolerance = 1e-9;

TEST(PrbErrorFunction, MatchesIndependentValuesForVerticalLoad) {
  // n = 0 exact tips (eqs. 2.90-2.98, 8 digits) and Theta (eq. 5.42) for gamma = 0.8517 (6 digits).
  struct Row {
    double theta0, a, b, Theta;
  };
  const Row rows[] = {{0.25, 0.98336262, 0.16572770, 0.195916},
                      {0.50, 0.93377750, 0.32590739, 0.393299},
                      {1.00, 0.73835640, 0.61037180, 0.802320},
                      {1.40, 0.47307789, 0.79655336, 1.183640}};
  for (const Row& r : rows) {
    EXPECT_NEAR(prb_angle({r.theta0, r.a, r.b, 0.0}, 0.8517), r.Theta, 5e-6) << r.theta0;  // 6 s.f.
  }
  // Path error (eq. 5.47, n = 0, gamma = 0.8517, computed to 2-3 digits): the error crosses 0.5 %
  // at theta0 = 77 deg, Theta = 64.27 deg (Howell §5.2.2: 77 deg; Table 5.1: 64.3 deg), after a
  // hump of 0.48 % at 40 deg.
  const EllipticSolver solver;
  const auto error_at = [&](double theta0_deg) {
    const EllipticResult r = solver.solve_for_tip_angle(0.0, theta0_deg * kDeg);
    EXPECT_TRUE(r.converged()) << r.message;
    return relative_position_error({theta0_deg * kDeg, r.tip.a_over_l, r.tip.b_over_l, 0.0},
                                   0.8517);
  };
  EXPECT_NEAR(error_at(40.0), 0.0048, 0.00005);
  EXPECT_NEAR(error_at(70.0), 0.0002, 0.00005);
  EXPECT_NEAR(error_at(77.0), 0.00501, 0.000005);
  EXPECT_NEAR(error_at(80.0), 0.0086, 0.00005);
}

TEST(EndMomentDerivation, ReproducesHowellGammaToFourDigits) {
  const PrbmDerivation d = derive_end_moment();
  ASSERT_TRUE(d.converged()) << d.message;
  EXPECT_EQ(d.segment, PrbmSegment::kEndMoment);
  EXPECT_NEAR(d.gamma, kEndMomentBook.gamma, 0.5e-4);  // 0.7346, 4 digits
  EXPECT_NEAR(d.theta0_at_theta_max / kDeg, kEndMomentBook.theta0_max_deg, 0.1);  // 124.4 deg
  // The error at Theta_max is the 0.5 % limit (root found on the closed form).
  EXPECT_LT(d.residual, 1e-10);
  // c_theta by least squares differs from the book's 1.5164 by 0.006 (docs/prbm.md); K = c_theta.
  EXPECT_NEAR(d.c_theta, kEndMomentBook.c_theta, 0.01);
  EXPECT_NEAR(d.K_theta * d.gamma, d.c_theta, 1e-12);
}

// K_theta recomputed by the test from its definition: the least-squares slope through the origin
// of the tangential load (alpha2)_t = alpha2 sqrt(1 + n^2) sin(phi - Theta) against the PRB angle
// Theta = atan2(b, a - (1 - gamma)) (Howell eqs. 5.42, 5.56-5.59), on exact tips of the elliptic
// solver's explicit inverse at theta0 = 0.1, 0.2, ... deg, over 0 < Theta <= theta_max_K.
double k_theta_by_least_squares(double n, double gamma, double theta_max_K) {
  const double phi = std::atan2(1.0, -n), eta = std::sqrt(1.0 + n * n);
  const EllipticSolver solver;
  double sum_xy = 0.0, sum_xx = 0.0;
  for (int i = 1; i * 0.1 * kDeg < phi; ++i) {
    const EllipticResult r = solver.solve_for_tip_angle(n, i * 0.1 * kDeg);
    EXPECT_TRUE(r.converged()) << r.message;
    const double theta = std::atan2(r.tip.b_over_l, r.tip.a_over_l - (1.0 - gamma));
    if (theta > theta_max_K) break;  // Theta rises with theta0 on this path
    const double tangential = r.load.Fy * eta * std::sin(phi - theta);
    sum_xy += theta * tangential;
    sum_xx += theta * theta;
  }
  return sum_xy / sum_xx;
}

TEST(FixedPinnedDerivation, ReproducesTable51ForRowsNAtLeastMinusOne) {
  for (const FixedPinnedTableRow& row : table_5_1()) {
    if (row.load_ratio_n < -1.0) continue;
    const PrbmDerivation d = derive_fixed_pinned(row.load_ratio_n);
    ASSERT_TRUE(d.converged()) << "n = " << row.load_ratio_n << ": " << d.message;
    EXPECT_EQ(d.segment, PrbmSegment::kFixedPinned);
    EXPECT_NEAR(d.gamma, row.gamma, kGammaTolerance) << "n = " << row.load_ratio_n;
    EXPECT_NEAR(d.theta_max_gamma / kDeg, row.theta_max_gamma_deg, kThetaMaxToleranceDeg)
        << "n = " << row.load_ratio_n;
    EXPECT_NEAR(d.c_theta, row.c_theta, kCThetaTolerance) << "n = " << row.load_ratio_n;
    EXPECT_NEAR(d.K_theta, row.K_theta, kKThetaTolerance) << "n = " << row.load_ratio_n;
    // Theta_max(K_theta) is an input (Howell states no criterion for it, docs/prbm.md step 5):
    // the fit must be the least-squares slope over Table 5.1's range, recomputed here.
    EXPECT_NE(d.theta_max_K_source.find("Table 5.1"), std::string::npos) << d.theta_max_K_source;
    EXPECT_NEAR(d.K_theta,
                k_theta_by_least_squares(row.load_ratio_n, d.gamma, row.theta_max_K_deg * kDeg),
                kKThetaRecomputedTolerance)
        << "n = " << row.load_ratio_n;
    EXPECT_FALSE(d.theta_max_at_path_end);
  }
}

TEST(FixedPinnedDerivation, TensionRowsReachAtLeastTheTablesThetaMax) {
  for (const FixedPinnedTableRow& row : table_5_1()) {
    if (row.load_ratio_n > -1.5) continue;
    const PrbmDerivation d = derive_fixed_pinned(row.load_ratio_n);
    ASSERT_TRUE(d.converged()) << "n = " << row.load_ratio_n << ": " << d.message;
    // Theta_max is quoted to 0.1 deg in the table.
    EXPECT_GE(d.theta_max_gamma / kDeg, row.theta_max_gamma_deg - 0.05)
        << "n = " << row.load_ratio_n;
  }
  const PrbmDerivation d5 = derive_fixed_pinned(-5.0);
  EXPECT_NEAR(d5.gamma - table_5_1_row(-5.0)->gamma, 0.05, 0.01);  // docs/prbm.md: +0.052
}

TEST(FixedPinnedDerivation, DerivedGammaIsALocalMaximiserOfThetaMax) {
  // Re-run with gamma confined to one side of the optimum: Theta_max cannot grow.
  const PrbmDerivation best = derive_fixed_pinned(1.0);
  ASSERT_TRUE(best.converged()) << best.message;
  PrbmDerivationOptions below;
  below.gamma_max = best.gamma - 0.002;
  PrbmDerivationOptions above;
  above.gamma_min = best.gamma + 0.002;
  EXPECT_LE(derive_fixed_pinned(1.0, below).theta_max_gamma, best.theta_max_gamma);
  EXPECT_LE(derive_fixed_pinned(1.0, above).theta_max_gamma, best.theta_max_gamma);
}

TEST(PrbmSegment, NamesRoundTripAndAnUnknownNameListsTheAllowedOnes) {
  EXPECT_EQ(to_string(PrbmSegment::kFixedPinned), "fixed-pinned");
  EXPECT_EQ(to_string(PrbmSegment::kEndMoment), "end-moment");
  EXPECT_EQ(to_string(PrbmSegment::kInitiallyCurved), "initially-curved");
  for (PrbmSegment s :
       {PrbmSegment::kFixedPinned, PrbmSegment::kEndMoment, PrbmSegment::kInitiallyCurved}) {
    EXPECT_EQ(prbm_segment_from_string(to_string(s)), s);
  }
  try {
    prbm_segment_from_string("fixed-guided");
    ADD_FAILURE() << "no exception";
  } catch (const InvalidInput& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'fixed-guided'"), std::string::npos) << what;
    EXPECT_NE(what.find("fixed-pinned, end-moment, initially-curved"), std::string::npos) << what;
  }
}

TEST(FixedPinnedDerivation, RejectsInvalidInput) {
  EXPECT_THROW(derive_fixed_pinned(50.0), InvalidInput);
  EXPECT_THROW(derive_fixed_pinned(std::nan("")), InvalidInput);
  PrbmDerivationOptions bad;
  bad.theta0_step_deg = 0.0;
  EXPECT_THROW(derive_fixed_pinned(0.0, bad), InvalidInput);
}

}  // namespace
}  // namespace flexure
