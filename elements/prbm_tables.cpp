#include <fmt/format.h>

#include <algorithm>

#include "flexure/elements/data_files.h"
#include "flexure/elements/prbm_element.h"
#include "flexure/solver/common/csv_table.h"
#include "flexure/solver/common/status.h"

namespace flexure {

const std::vector<FixedPinnedTableRow>& table_5_1() {
  // Howell Table 5.1 (= Table E.1), data/howell_table_5_1.csv, as printed.
  static const std::vector<FixedPinnedTableRow> rows = [] {
    const CsvTable t = CsvTable::parse(data::howell_table_5_1());
    std::vector<FixedPinnedTableRow> list;
    for (std::size_t i = 0; i < t.row_count(); ++i) {
      list.push_back({t.number(i, "n"),
                      t.number(i, "phi"),
                      t.number(i, "gamma"),
                      t.number(i, "Theta_max_gamma"),
                      t.number(i, "c_theta"),
                      t.number(i, "K_theta"),
                      t.number(i, "Theta_max_K_theta")});
    }
    return list;
  }();
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
  // Howell Table 5.2 (= Table E.2), data/howell_table_5_2.csv.
  static const std::vector<CurvedCantileverTableRow> rows = [] {
    const CsvTable t = CsvTable::parse(data::howell_table_5_2());
    std::vector<CurvedCantileverTableRow> list;
    for (std::size_t i = 0; i < t.row_count(); ++i) {
      list.push_back({t.number(i, "kappa0"),
                      t.number(i, "gamma"),
                      t.number(i, "rho"),
                      t.number(i, "K_theta")});
    }
    return list;
  }();
  return rows;
}

const std::vector<CurvedPinnedPinnedTableRow>& table_5_3() {
  // Howell Table 5.3 (= Table E.3), data/howell_table_5_3.csv. Known not to agree fully with its
  // own equations 5.137-5.139 (gamma up to 0.008 off, rho up to 0.012 off).
  static const std::vector<CurvedPinnedPinnedTableRow> rows = [] {
    const CsvTable t = CsvTable::parse(data::howell_table_5_3());
    std::vector<CurvedPinnedPinnedTableRow> list;
    for (std::size_t i = 0; i < t.row_count(); ++i) {
      list.push_back({t.number(i, "kappa0"),
                      t.number(i, "gamma"),
                      t.number(i, "rho"),
                      t.number(i, "Delta_Theta_max_gamma"),
                      t.number(i, "K_theta"),
                      t.number(i, "Delta_Theta_max_K_theta")});
    }
    return list;
  }();
  return rows;
}

}  // namespace flexure
