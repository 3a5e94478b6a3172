#include "flexure/benchmarks/studies/method_selector.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "flexure/elements/fixed_pinned_segment.h"
#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/errors.h"

namespace flexure::bench {
namespace {

// The accuracy map: relative tip-position error (|tip - exact tip| / |exact tip displacement|) of
// the fixed-pinned PRBM with Table 5.1 constants, measured by `flexure bench` (group
// cantilever_force/prbm, git commit 8de2adb3d613, docs/benchmarks.md), rounded UP to two
// significant digits. Rows: n; columns: alpha2. Regenerate with scripts/plot_benchmarks.py
// --print-prbm-map FILE.h5 after a change to the PRBM constants.
constexpr std::array<double, 5> kMapN = {-2.0, -1.0, 0.0, 1.0, 3.0};
constexpr std::array<double, 12> kMapAlpha2 = {0.5, 1, 2, 3, 4, 5, 7.5, 10, 12.5, 15, 17.5, 20};
constexpr double kMapError[5][12] = {
    {0.027,
     0.011,
     0.005,
     0.0078,
     0.0078,
     0.0067,
     0.0043,
     0.0077,
     0.013,
     0.018,
     0.022,
     0.025},  // n = -2
    {0.028,
     0.016,
     0.0051,
     0.0058,
     0.0071,
     0.0073,
     0.0065,
     0.0078,
     0.011,
     0.015,
     0.019,
     0.022},  // n = -1
    {0.042, 0.033, 0.015, 0.0045, 0.0065, 0.0099, 0.015, 0.018, 0.021, 0.024, 0.027, 0.031},  // n =
                                                                                              // 0
    {0.045, 0.033, 0.013, 0.033, 0.042, 0.045, 0.048, 0.05, 0.052, 0.055, 0.058, 0.061},   // n = 1
    {0.051, 0.036, 0.074, 0.077, 0.077, 0.077, 0.079, 0.084, 0.088, 0.092, 0.096, 0.099},  // n = 3
};

// Between the measured loads the error is not monotone in n (Table 5.1 is interpolated linearly in
// n): up to 1.27 times the largest neighbour on a 0.25 x 0.25 grid of (n, alpha2)
// (tests/studies/bench_auto_method_test.cpp). The map is multiplied by this margin.
constexpr double kBetweenLoadsMargin = 1.5;

// Index range [lo, hi] of the measured values bracketing x (lo == hi on a measured value).
template <std::size_t N>
bool bracket(const std::array<double, N>& grid, double x, std::size_t& lo, std::size_t& hi) {
  if (x < grid.front() || x > grid.back()) return false;
  hi = static_cast<std::size_t>(std::lower_bound(grid.begin(), grid.end(), x) - grid.begin());
  lo = grid[hi] == x ? hi : hi - 1;
  return true;
}

// Measured shooting accuracy at rtol 1e-12 (docs/benchmarks.md): below 1e-9.
constexpr double kShootingMeasuredError = 1e-9;
// The elliptic solver's scalar solves converge to 1e-14 relative.
constexpr double kEllipticError = 1e-13;

}  // namespace

double prbm_measured_error(double load_ratio_n, double alpha2) {
  std::size_t n_lo = 0, n_hi = 0, a_lo = 0, a_hi = 0;
  if (!bracket(kMapN, load_ratio_n, n_lo, n_hi)) return std::numeric_limits<double>::quiet_NaN();
  // Below alpha2 = 0.5 the relative error keeps growing toward the PRBM's small-angle stiffness
  // error (3.9 % at alpha2 = 0.25, n = 0): not measured, so not used.
  if (!bracket(kMapAlpha2, alpha2, a_lo, a_hi)) return std::numeric_limits<double>::quiet_NaN();
  // Conservative: the largest error at the measured loads around (n, alpha2), with a margin.
  return kBetweenLoadsMargin * std::max({kMapError[n_lo][a_lo],
                                         kMapError[n_lo][a_hi],
                                         kMapError[n_hi][a_lo],
                                         kMapError[n_hi][a_hi]});
}

AutoMethodChoice choose_beam_method(const AutoMethodRequest& r) {
  if (!std::isfinite(r.tolerance) || r.tolerance <= 0.0) {
    throw InvalidInput(
        fmt::format("--tol must be a finite relative error > 0 (got {})", r.tolerance));
  }
  if (!r.plain_cantilever) {
    return {"shooting",
            fmt::format("not a free uniform cantilever with dead loads: the shooting solver "
                        "(rtol 1e-12, measured error < {:.0e}) is the only exact method here",
                        kShootingMeasuredError)};
  }
  std::string why_not_prbm;
  if (!std::isfinite(r.alpha2)) {
    why_not_prbm = "the load is not given (inverse problem)";
  } else if (r.mu != 0.0) {
    why_not_prbm = "the fixed-pinned PRBM carries no tip moment";
  } else if (r.load_ratio_n < -5.0 || r.load_ratio_n > 10.0) {
    why_not_prbm = fmt::format("n = {:g} is outside Table 5.1 (-5 <= n <= 10)", r.load_ratio_n);
  } else {
    const FixedPinnedSegment element(FixedPinnedConstants::from_table(r.load_ratio_n));
    const PrbEquilibrium eq = element.solve(EndLoad::howell(r.load_ratio_n, r.alpha2, 0.0));
    const ValidityLimits limits = element.limits();
    const double theta_max = limits.theta_max();
    const double measured = prbm_measured_error(r.load_ratio_n, r.alpha2);
    constexpr double kDeg = 180.0 / 3.14159265358979323846;
    if (!eq.converged) {
      why_not_prbm = "the PRBM has no equilibrium at this load";
    } else if (!limits.contains(eq.Theta)) {
      why_not_prbm = fmt::format(
          "the PRB angle {:.1f} deg exceeds the validity limit Theta_max = {:.1f} deg (Howell "
          "eqs. 5.47, 5.63)",
          std::fabs(eq.Theta) * kDeg,
          theta_max * kDeg);
    } else if (!std::isfinite(measured)) {
      why_not_prbm =
          "no measured PRBM accuracy at this load (map covers -2 <= n <= 3, 0.5 <= alpha2 <= "
          "20)";
    } else if (measured > r.tolerance) {
      why_not_prbm = fmt::format(
          "the PRBM is inside its validity limits but its measured error {:.2g} exceeds --tol "
          "{:.2g}",
          measured,
          r.tolerance);
    } else {
      return {"prbm",
              fmt::format("PRBM fixed-pinned segment ({}): Theta = {:.1f} deg is inside "
                          "Theta_max = {:.1f} deg and its measured error {:.2g} is within --tol "
                          "{:.2g}",
                          element.constants().source,
                          std::fabs(eq.Theta) * kDeg,
                          theta_max * kDeg,
                          measured,
                          r.tolerance)};
    }
  }
  return {"elliptic",
          fmt::format("{}; the exact elliptic solution (error ~{:.0e}) is the next cheapest",
                      why_not_prbm,
                      kEllipticError)};
}

}  // namespace flexure::bench
