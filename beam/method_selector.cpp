#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "flexure/beam/beam_problem.h"
#include "flexure/beam/data_files.h"
#include "flexure/elements/prbm_cantilever.h"
#include "flexure/solver/common/csv_table.h"
#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

// The accuracy map, data/method_auto_error_map.csv: relative tip-position error (|tip - exact
// tip| / |exact tip displacement|) of the fixed-pinned PRBM with Table 5.1 constants, measured by
// `flexure bench` (group cantilever_force/prbm, docs/benchmarks.md), rounded UP to two
// significant digits, on a grid of loads (n, alpha2). Regenerate with scripts/plot_benchmarks.py
// --print-prbm-map FILE.h5 after a change to the PRBM constants.
struct ErrorMap {
  std::vector<double> n;       // ascending
  std::vector<double> alpha2;  // ascending
  std::vector<double> error;   // error[i * alpha2.size() + j] at (n[i], alpha2[j])
};

// The file lists the grid row by row, n and alpha2 ascending, alpha2 varying fastest.
ErrorMap read_error_map() {
  const CsvTable t = CsvTable::parse(data::method_auto_error_map());
  ErrorMap map;
  for (std::size_t i = 0; i < t.row_count(); ++i) {
    const double n = t.number(i, "n");
    if (map.n.empty() || n != map.n.back()) map.n.push_back(n);
    if (map.n.size() == 1) map.alpha2.push_back(t.number(i, "alpha2"));
  }
  const auto ascending = [](const std::vector<double>& v) {
    return std::adjacent_find(v.begin(), v.end(), std::greater_equal<double>()) == v.end();
  };
  if (map.n.empty() || t.row_count() != map.n.size() * map.alpha2.size() || !ascending(map.n) ||
      !ascending(map.alpha2)) {
    throw InvalidInput(fmt::format(
        "{}: the rows must form a full grid of loads, n and alpha2 ascending, alpha2 fastest",
        t.source()));
  }
  for (std::size_t i = 0; i < t.row_count(); ++i) {
    const std::size_t row_n = i / map.alpha2.size();
    const std::size_t row_a = i % map.alpha2.size();
    if (t.number(i, "n") != map.n[row_n]) {
      throw t.cell_error(i, "n", fmt::format("expected {} (grid order)", map.n[row_n]));
    }
    if (t.number(i, "alpha2") != map.alpha2[row_a]) {
      throw t.cell_error(i, "alpha2", fmt::format("expected {} (grid order)", map.alpha2[row_a]));
    }
    const double error = t.number(i, "error");
    if (!(error >= 0.0)) throw t.cell_error(i, "error", "a relative error must be >= 0");
    map.error.push_back(error);
  }
  return map;
}

const ErrorMap& error_map() {
  static const ErrorMap map = read_error_map();
  return map;
}

// Between the measured loads the error is not monotone in n (Table 5.1 is interpolated linearly in
// n): up to 1.27 times the largest neighbour on a 0.25 x 0.25 grid of (n, alpha2)
// (tests/beam/bench_auto_method_test.cpp). The map is multiplied by this margin.
constexpr double kBetweenLoadsMargin = 1.5;

// Index range [lo, hi] of the measured values bracketing x (lo == hi on a measured value).
bool bracket(const std::vector<double>& grid, double x, std::size_t& lo, std::size_t& hi) {
  if (x < grid.front() || x > grid.back()) return false;
  hi = static_cast<std::size_t>(std::lower_bound(grid.begin(), grid.end(), x) - grid.begin());
  lo = grid[hi] == x ? hi : hi - 1;
  return true;
}

// The refusal of a tolerance that `method`, the most accurate method here, cannot meet.
[[noreturn]] void refuse_tolerance(double tolerance,
                                   BeamMethod method,
                                   double bound,
                                   bool inverse) {
  const bool elliptic = method == BeamMethod::kElliptic;
  const std::string how =
      inverse    ? fmt::format("ends its inverse solve within {:.0e} of the target",
                            elliptic ? 1e-10 : 1e-8)
      : elliptic ? std::string(
                       "has a relative tip error of about 1e-13 (its scalar solves converge "
                       "to 1e-14)")
                 : std::string(
                       "has a relative tip error below 1e-9 (measured at rtol 1e-12 on the "
                       "benchmark set, docs/benchmarks.md)");
  throw ToleranceBelowReach(
      fmt::format("the tolerance {:.3g} is below the error of every method that solves this "
                  "problem: the most accurate here, the {} method, {}; ask for a tolerance of at "
                  "least {:.0e}",
                  tolerance,
                  to_string(method),
                  how,
                  bound),
      bound,
      to_string(method));
}

}  // namespace

double exact_method_error_bound(BeamMethod method, bool inverse) {
  switch (method) {
    case BeamMethod::kElliptic:
      return inverse ? kEllipticInverseErrorBound : kEllipticErrorBound;
    case BeamMethod::kShooting:
      return inverse ? kShootingInverseErrorBound : kShootingErrorBound;
    default:
      return std::numeric_limits<double>::quiet_NaN();
  }
}

void require_tolerance_within_reach(double tolerance, BeamMethod method, bool inverse) {
  const double bound = exact_method_error_bound(method, inverse);
  if (std::isfinite(bound) && tolerance < bound) {
    refuse_tolerance(tolerance, method, bound, inverse);
  }
}

double prbm_measured_error(double load_ratio_n, double alpha2) {
  const ErrorMap& map = error_map();
  std::size_t n_lo = 0, n_hi = 0, a_lo = 0, a_hi = 0;
  if (!bracket(map.n, load_ratio_n, n_lo, n_hi)) return std::numeric_limits<double>::quiet_NaN();
  // Below alpha2 = 0.5 the relative error keeps growing toward the PRBM's small-angle stiffness
  // error (3.9 % at alpha2 = 0.25, n = 0): not measured, so not used.
  if (!bracket(map.alpha2, alpha2, a_lo, a_hi)) return std::numeric_limits<double>::quiet_NaN();
  const auto at = [&](std::size_t i, std::size_t j) {
    return map.error[i * map.alpha2.size() + j];
  };
  // Conservative: the largest error at the measured loads around (n, alpha2), with a margin.
  return kBetweenLoadsMargin *
         std::max({at(n_lo, a_lo), at(n_lo, a_hi), at(n_hi, a_lo), at(n_hi, a_hi)});
}

AutoMethodChoice choose_beam_method(const AutoMethodRequest& r) {
  if (!std::isfinite(r.tolerance) || r.tolerance <= 0.0) {
    throw InvalidInput(
        fmt::format("the tolerance must be a finite relative error > 0 (got {})", r.tolerance));
  }
  const bool inverse = !std::isfinite(r.alpha2);
  if (!r.plain_cantilever) {
    const double bound = exact_method_error_bound(BeamMethod::kShooting, inverse);
    if (r.tolerance < bound) refuse_tolerance(r.tolerance, BeamMethod::kShooting, bound, inverse);
    return {BeamMethod::kShooting,
            fmt::format("not a free uniform cantilever with dead loads: the shooting solver "
                        "(rtol 1e-12, measured error < {:.0e}) is the only exact method here",
                        bound),
            bound};
  }
  std::string why_not_prbm;
  if (!r.ladder_verdict.empty()) {
    why_not_prbm = r.ladder_verdict;
  } else if (!std::isfinite(r.alpha2)) {
    why_not_prbm = "the load is not given (inverse problem)";
  } else if (r.mu != 0.0) {
    why_not_prbm = "the fixed-pinned PRBM carries no tip moment";
  } else if (r.load_ratio_n < -5.0 || r.load_ratio_n > 10.0) {
    why_not_prbm = fmt::format("n = {:g} is outside Table 5.1 (-5 <= n <= 10)", r.load_ratio_n);
  } else {
    const PrbmCantileverSolution eq =
        solve_prbm_cantilever(EndCondition::kFree, r.load_ratio_n, r.alpha2, 0.0);
    const double theta_max = eq.limits.theta_max();
    const double measured = prbm_measured_error(r.load_ratio_n, r.alpha2);
    constexpr double kDeg = 180.0 / 3.14159265358979323846;
    if (!eq.converged()) {
      why_not_prbm = "the PRBM has no equilibrium at this load";
    } else if (!eq.inside_validity) {
      why_not_prbm = fmt::format(
          "the PRB angle {:.1f} deg exceeds the validity limit Theta_max = {:.1f} deg (Howell "
          "eqs. 5.47, 5.63)",
          std::fabs(eq.Theta) * kDeg,
          theta_max * kDeg);
    } else if (!std::isfinite(measured)) {
      const ErrorMap& map = error_map();
      why_not_prbm = fmt::format(
          "no measured PRBM accuracy at this load (map covers {:g} <= n <= {:g}, {:g} <= alpha2 "
          "<= {:g})",
          map.n.front(),
          map.n.back(),
          map.alpha2.front(),
          map.alpha2.back());
    } else if (measured > r.tolerance) {
      why_not_prbm = fmt::format(
          "the PRBM is inside its validity limits but its measured error {:.2g} exceeds the "
          "tolerance {:.2g}",
          measured,
          r.tolerance);
    } else {
      return {BeamMethod::kPrbm,
              fmt::format("PRBM {} ({}): Theta = {:.1f} deg is inside Theta_max = {:.1f} deg and "
                          "its measured error {:.2g} is within the tolerance {:.2g}",
                          eq.element,
                          eq.constants_source,
                          std::fabs(eq.Theta) * kDeg,
                          theta_max * kDeg,
                          measured,
                          r.tolerance),
              measured};
    }
  }
  const double bound = exact_method_error_bound(BeamMethod::kElliptic, inverse);
  if (r.tolerance < bound) refuse_tolerance(r.tolerance, BeamMethod::kElliptic, bound, inverse);
  return {BeamMethod::kElliptic,
          fmt::format("{}; the exact elliptic solution (error ~{:.0e}) is the next cheapest",
                      why_not_prbm,
                      bound),
          bound};
}

}  // namespace flexure
