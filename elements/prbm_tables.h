#pragma once
// The published PRB constants, copied exactly as printed (Howell, Compliant Mechanisms, Tables 5.1,
// 5.2, 5.3 = App. E Tables E.1, E.2, E.3: data/howell_table_5_{1,2,3}.csv, compiled into the
// library and read at the first call; eqs. 5.107-5.110 below). Angles in degrees as printed.
// These are data to compare against, not the constants the elements must use: the elements accept
// constants from these tables, from the curve fits (prbm_curve_fits.h) or from the derivation
// (prbm_derivation.h).
#include <vector>

namespace flexure {

// One row of Table 5.1: fixed-pinned segment with a tip force at angle phi = atan2(1, -n).
struct FixedPinnedTableRow {
  double load_ratio_n = 0.0;
  double phi_deg = 90.0;             // force angle
  double gamma = 0.0;                // characteristic radius factor
  double theta_max_gamma_deg = 0.0;  // Theta_max(gamma), position error <= 0.5 %
  double c_theta = 0.0;              // parametric angle coefficient, theta0 = c_theta Theta
  double K_theta = 0.0;              // stiffness coefficient, (alpha^2)_t = K_theta Theta
  double theta_max_K_deg = 0.0;      // Theta_max(K_theta)
};
// The 17 rows in the book's order (n = 0 ... 10, then -0.5 ... -5).
const std::vector<FixedPinnedTableRow>& table_5_1();
// The row with exactly this n, or nullptr.
const FixedPinnedTableRow* table_5_1_row(double load_ratio_n);
// All columns linearly interpolated in n between rows (-5 <= n <= 10); throws InvalidInput outside.
FixedPinnedTableRow table_5_1_interpolated(double load_ratio_n);

// One row of Table 5.2: initially curved cantilever.
struct CurvedCantileverTableRow {
  double kappa0 = 0.0;  // l / R_i (eq. 5.114)
  double gamma = 0.0;
  double rho = 0.0;  // PRB link length / l (eq. 5.116)
  double K_theta = 0.0;
};
const std::vector<CurvedCantileverTableRow>& table_5_2();

// One row of Table 5.3: initially curved pinned-pinned segment. Delta Theta in radians.
struct CurvedPinnedPinnedTableRow {
  double kappa0 = 0.0;
  double gamma = 0.0;
  double rho = 0.0;
  double delta_theta_max_gamma = 0.0;
  double K_theta = 0.0;
  double delta_theta_max_K = 0.0;
};
const std::vector<CurvedPinnedPinnedTableRow>& table_5_3();

// End-moment segment (eqs. 5.107-5.110).
struct EndMomentConstants {
  double gamma = 0.7346;          // eq. 5.107
  double theta0_max_deg = 124.4;  // tip angle up to which error < 0.5 % (eq. 5.108)
  double c_theta = 1.5164;        // eq. 5.109
  double K_theta = 2.0643;        // eq. 5.110
};
inline constexpr EndMomentConstants kEndMomentBook{};

}  // namespace flexure
