#include "flexure/elements/prbm_tables.h"

#include <fmt/format.h>

#include <algorithm>

#include "flexure/solver/common/errors.h"

namespace flexure {

const std::vector<FixedPinnedTableRow>& table_5_1() {
  // Howell Table 5.1 (= Table E.1), book digest section 3.2, copied as printed.
  static const std::vector<FixedPinnedTableRow> rows = {
      {0.0, 90.0, 0.8517, 64.3, 1.2385, 2.67617, 58.5},
      {0.5, 116.6, 0.8430, 81.8, 1.2430, 2.63744, 64.1},
      {1.0, 135.0, 0.8360, 94.8, 1.2467, 2.61259, 67.5},
      {1.5, 146.3, 0.8311, 103.8, 1.2492, 2.59289, 65.8},
      {2.0, 153.4, 0.8276, 108.9, 1.2511, 2.59707, 69.0},
      {3.0, 161.6, 0.8232, 115.4, 1.2534, 2.56737, 64.6},
      {4.0, 166.0, 0.8207, 119.1, 1.2548, 2.56506, 66.4},
      {5.0, 168.7, 0.8192, 121.4, 1.2557, 2.56251, 67.5},
      {7.5, 172.4, 0.8168, 124.5, 1.2570, 2.55984, 69.0},
      {10.0, 174.3, 0.8156, 126.1, 1.2578, 2.56597, 69.7},
      {-0.5, 63.4, 0.8612, 47.7, 1.2348, 2.69320, 44.4},
      {-1.0, 45.0, 0.8707, 36.3, 1.2323, 2.72816, 31.5},
      {-1.5, 33.7, 0.8796, 28.7, 1.2322, 2.78081, 23.6},
      {-2.0, 26.6, 0.8813, 23.2, 1.2293, 2.80162, 18.6},
      {-3.0, 18.4, 0.8669, 16.0, 1.2119, 2.68893, 12.9},
      {-4.0, 14.0, 0.8522, 11.9, 1.1971, 2.58991, 9.8},
      {-5.0, 11.3, 0.8391, 9.7, 1.1788, 2.49874, 7.9},
  };
  return rows;
}

const FixedPinnedTableRow* table_5_1_row(double load_ratio_n) {
  for (const auto& row : table_5_1()) {
    if (row.load_ratio_n == load_ratio_n) return &row;
  }
  return nullptr;
}

FixedPinnedTableRow table_5_1_interpolated(double load_ratio_n) {
  if (!(load_ratio_n >= -5.0 && load_ratio_n <= 10.0)) {
    throw InvalidInput(fmt::format(
        "load ratio n = {} is outside Table 5.1, which covers -5 <= n <= 10", load_ratio_n));
  }
  std::vector<FixedPinnedTableRow> sorted = table_5_1();
  std::sort(sorted.begin(), sorted.end(), [](const auto& x, const auto& y) {
    return x.load_ratio_n < y.load_ratio_n;
  });
  for (std::size_t i = 1; i < sorted.size(); ++i) {
    const auto& lo = sorted[i - 1];
    const auto& hi = sorted[i];
    if (load_ratio_n > hi.load_ratio_n) continue;
    const double f = (load_ratio_n - lo.load_ratio_n) / (hi.load_ratio_n - lo.load_ratio_n);
    const auto mix = [f](double x, double y) { return x + f * (y - x); };
    return {load_ratio_n,
            mix(lo.phi_deg, hi.phi_deg),
            mix(lo.gamma, hi.gamma),
            mix(lo.theta_max_gamma_deg, hi.theta_max_gamma_deg),
            mix(lo.c_theta, hi.c_theta),
            mix(lo.K_theta, hi.K_theta),
            mix(lo.theta_max_K_deg, hi.theta_max_K_deg)};
  }
  return sorted.back();
}

const std::vector<CurvedCantileverTableRow>& table_5_2() {
  // Howell Table 5.2 (= Table E.2), book digest section 3.5.
  static const std::vector<CurvedCantileverTableRow> rows = {
      {0.00, 0.85, 0.850, 2.65},
      {0.10, 0.84, 0.840, 2.64},
      {0.25, 0.83, 0.829, 2.56},
      {0.50, 0.81, 0.807, 2.52},
      {1.00, 0.81, 0.797, 2.60},
      {1.50, 0.80, 0.775, 2.80},
      {2.00, 0.79, 0.749, 2.99},
  };
  return rows;
}

const std::vector<CurvedPinnedPinnedTableRow>& table_5_3() {
  // Howell Table 5.3 (= Table E.3), book digest section 3.6. Known not to agree fully with its
  // own equations 5.137-5.139 (gamma up to 0.008 off, rho up to 0.012 off).
  static const std::vector<CurvedPinnedPinnedTableRow> rows = {
      {0.50, 0.793, 0.791, 1.677, 2.59, 0.99},
      {0.75, 0.787, 0.783, 1.456, 2.62, 0.86},
      {1.00, 0.783, 0.775, 1.327, 2.68, 0.79},
      {1.25, 0.779, 0.768, 1.203, 2.75, 0.71},
      {1.50, 0.775, 0.760, 1.070, 2.83, 0.63},
  };
  return rows;
}

}  // namespace flexure
