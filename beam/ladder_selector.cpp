#include "flexure/beam/ladder_selector.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>

#include "flexure/beam/data_files.h"
#include "flexure/solver/common/csv_table.h"
#include "flexure/solver/common/status.h"

namespace flexure::bench {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The rungs of the file, in its column order; the elliptic solution has a time only.
constexpr std::array<BeamMethod, 6> kRungs = {BeamMethod::kLinear,
                                              BeamMethod::kPrbm,
                                              BeamMethod::kPrbm3r,
                                              BeamMethod::kBcm,
                                              BeamMethod::kCbcm,
                                              BeamMethod::kElliptic};
constexpr std::size_t kModels = kRungs.size() - 1;

// data/ladder_auto_error_map.csv: a full grid of (n, alpha2, mu), mu fastest.
struct LadderMap {
  std::vector<double> n, alpha2, mu;         // ascending; mu: the tip angle of a guided map
  BeamMethod exact = BeamMethod::kElliptic;  // the reference (the last rung): shooting if guided
  // error[r][i] (per length; NaN: no answer) and micros[r][i] of rung r at grid index i.
  std::array<std::vector<double>, kRungs.size()> error, micros;
  std::size_t index(std::size_t i, std::size_t j, std::size_t k) const {
    return (i * alpha2.size() + j) * mu.size() + k;
  }
};

void add_axis_value(std::vector<double>& axis, double x) {
  if (std::find(axis.begin(), axis.end(), x) == axis.end()) axis.push_back(x);
}

// `third`: the third axis's column (mu, or tip_angle for a guided map); `exact`: the reference.
LadderMap read_map(const EmbeddedFile& file,
                   const std::string& third = "mu",
                   BeamMethod exact = BeamMethod::kElliptic) {
  const CsvTable t = CsvTable::parse(file);
  LadderMap map;
  map.exact = exact;
  for (std::size_t r = 0; r < t.row_count(); ++r) {
    add_axis_value(map.n, t.number(r, "n"));
    add_axis_value(map.alpha2, t.number(r, "alpha2"));
    add_axis_value(map.mu, t.number(r, third));
  }
  const auto ascending = [](const std::vector<double>& v) {
    return std::adjacent_find(v.begin(), v.end(), std::greater_equal<double>()) == v.end();
  };
  if (map.n.size() < 2 || map.alpha2.size() < 2 || map.mu.size() < 2 ||
      t.row_count() != map.n.size() * map.alpha2.size() * map.mu.size() || !ascending(map.n) ||
      !ascending(map.alpha2) || !ascending(map.mu)) {
    throw InvalidInput(fmt::format(
        "{}: the rows must form a full grid of loads, n, alpha2 and {} ascending, {} fastest",
        t.source(),
        third,
        third));
  }
  for (auto& v : map.error) v.resize(t.row_count());
  for (auto& v : map.micros) v.resize(t.row_count());
  for (std::size_t r = 0; r < t.row_count(); ++r) {
    const std::size_t i = r / (map.alpha2.size() * map.mu.size());
    const std::size_t j = (r / map.mu.size()) % map.alpha2.size();
    const std::size_t k = r % map.mu.size();
    if (t.number(r, "n") != map.n[i] || t.number(r, "alpha2") != map.alpha2[j] ||
        t.number(r, third) != map.mu[k]) {
      throw t.cell_error(r, "n", "the row is out of the grid's order (n, alpha2, mu; mu fastest)");
    }
    for (std::size_t m = 0; m < kRungs.size(); ++m) {
      const std::string name = to_string(m < kModels ? kRungs[m] : exact);
      const std::string us = name + "_us";
      if (m < kModels) {
        const std::string err = name + "_error";
        const double e = t.number_or(r, err, kNaN);
        if (!(e >= 0.0) && !std::isnan(e)) throw t.cell_error(r, err, "an error must be >= 0");
        map.error[m][r] = e;
      } else {
        map.error[m][r] = 0.0;  // the exact solution
      }
      const double time = t.number_or(r, us, kNaN);
      if (!std::isnan(map.error[m][r]) && !(time > 0.0)) {
        throw t.cell_error(r, us, "a model with an error needs a time per solve > 0");
      }
      map.micros[m][r] = time;
    }
  }
  return map;
}

const LadderMap& ladder_map() {
  static const LadderMap map = read_map(data::ladder_auto_error_map());
  return map;
}

const LadderMap& guided_map() {
  static const LadderMap map =
      read_map(data::ladder_auto_error_map_guided(), "tip_angle", BeamMethod::kShooting);
  return map;
}

const LadderMap& axial_map() {
  static const LadderMap map = read_map(data::ladder_auto_error_map_axial());
  return map;
}

// Index range [lo, hi] of the measured values bracketing x (lo == hi on a measured value).
bool bracket(const std::vector<double>& grid, double x, std::size_t& lo, std::size_t& hi) {
  if (!(x >= grid.front() && x <= grid.back())) return false;
  hi = static_cast<std::size_t>(std::lower_bound(grid.begin(), grid.end(), x) - grid.begin());
  lo = grid[hi] == x ? hi : hi - 1;
  return true;
}

std::size_t rung_index(BeamMethod method) {
  const auto it = std::find(kRungs.begin(), kRungs.end(), method);
  return it == kRungs.end() ? kRungs.size() : static_cast<std::size_t>(it - kRungs.begin());
}

}  // namespace

LadderMapRange ladder_map_range() {
  const LadderMap& m = ladder_map();
  return {m.n.front(), m.n.back(), m.alpha2.front(), m.alpha2.back(), m.mu.front(), m.mu.back()};
}

namespace {

std::optional<std::vector<LadderEstimate>> estimates_in(const LadderMap& map,
                                                        double load_ratio_n,
                                                        double alpha2,
                                                        double mu) {
  std::array<std::size_t, 2> ni{}, ai{}, mi{};
  if (!bracket(map.n, load_ratio_n, ni[0], ni[1]) || !bracket(map.alpha2, alpha2, ai[0], ai[1]) ||
      !bracket(map.mu, mu, mi[0], mi[1])) {
    return std::nullopt;
  }
  std::vector<LadderEstimate> out;
  for (std::size_t r = 0; r < kRungs.size(); ++r) {
    double largest = 0.0, time = 0.0;
    int corners = 0;
    for (std::size_t i : ni) {
      for (std::size_t j : ai) {
        for (std::size_t k : mi) {
          const std::size_t at = map.index(i, j, k);
          largest = std::max(largest, map.error[r][at]);  // NaN propagates below
          if (std::isnan(map.error[r][at])) largest = kNaN;
          time += map.micros[r][at];
          ++corners;
        }
      }
    }
    if (std::isnan(largest)) continue;  // no answer at a corner: not mapped here
    out.push_back(
        {r < kModels ? kRungs[r] : map.exact, kBetweenNodesMargin * largest, time / corners});
  }
  std::stable_sort(out.begin(), out.end(), [](const LadderEstimate& a, const LadderEstimate& b) {
    return a.microseconds < b.microseconds;
  });
  return out;
}

}  // namespace

std::optional<std::vector<LadderEstimate>> ladder_estimates(double load_ratio_n,
                                                            double alpha2,
                                                            double mu) {
  return estimates_in(ladder_map(), load_ratio_n, alpha2, mu);
}

double ladder_mapped_error(BeamMethod method, double load_ratio_n, double alpha2, double mu) {
  if (rung_index(method) >= kModels) return kNaN;
  const auto all = ladder_estimates(load_ratio_n, alpha2, mu);
  if (!all) return kNaN;
  for (const LadderEstimate& e : *all) {
    if (e.method == method) return e.error_per_length;
  }
  return kNaN;
}

LadderMapRange ladder_guided_map_range() {
  const LadderMap& m = guided_map();
  return {m.n.front(), m.n.back(), m.alpha2.front(), m.alpha2.back(), m.mu.front(), m.mu.back()};
}

std::optional<std::vector<LadderEstimate>> ladder_estimates_guided(double load_ratio_n,
                                                                   double alpha2,
                                                                   double tip_angle) {
  return estimates_in(guided_map(), load_ratio_n, alpha2, tip_angle);
}

double ladder_mapped_error_guided(BeamMethod method,
                                  double load_ratio_n,
                                  double alpha2,
                                  double tip_angle) {
  if (rung_index(method) >= kModels) return kNaN;
  const auto all = ladder_estimates_guided(load_ratio_n, alpha2, tip_angle);
  if (!all) return kNaN;
  for (const LadderEstimate& e : *all) {
    if (e.method == method) return e.error_per_length;
  }
  return kNaN;
}

double ladder_mapped_error_any_n(BeamMethod method, double load_ratio_n, double alpha2, double mu) {
  if (rung_index(method) >= kModels) return kNaN;
  const LadderMap& main = ladder_map();
  const bool in_main = load_ratio_n >= main.n.front() && load_ratio_n <= main.n.back();
  const auto all = estimates_in(in_main ? main : axial_map(), load_ratio_n, alpha2, mu);
  if (!all) return kNaN;
  for (const LadderEstimate& e : *all) {
    if (e.method == method) return e.error_per_length;
  }
  return kNaN;
}

double relative_error_bound(double error_per_length, double model_displacement) {
  if (!(error_per_length >= 0.0) || !(model_displacement > error_per_length)) {
    return std::numeric_limits<double>::infinity();
  }
  return error_per_length / (model_displacement - error_per_length);
}

}  // namespace flexure::bench
