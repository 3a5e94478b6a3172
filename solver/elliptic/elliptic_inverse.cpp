// Inverse problems of the elliptic solver: the load alpha2 for a given tip angle or deflection.
#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <optional>

#include "solver/common/errors.h"
#include "solver/common/load_search.h"
#include "solver/common/scalar_root.h"
#include "solver/elliptic/elliptic_solver.h"
#include "solver/elliptic/howell_branch.h"

namespace flexure {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = 180.0 / kPi;
// Largest |alpha2| searched when the inverse problem has an end moment (no closed form in theta0).
constexpr double kMaxAlpha2Search = 1e4;

// Force angle of Howell's load (P, nP) for P > 0 (eq. 2.87 corrected: phi = atan2(1, -n)).
double force_angle(double load_ratio_n) { return std::atan2(1.0, -load_ratio_n); }

double eta_of(double load_ratio_n) { return std::hypot(1.0, load_ratio_n); }

// The mu = 0 branch from an explicit tip angle: sign of theta0 picks the sign of alpha2.
EllipticResult result_from_tip_angle(double load_ratio_n, double theta0) {
  const bool negative = theta0 < 0.0;
  // With P < 0 the force (P, nP) mirrors to (|P|, -n|P|)... i.e. force angle atan2(1, n).
  const double psi = negative ? force_angle(-load_ratio_n) : force_angle(load_ratio_n);
  const elliptic::HowellBranchSolution h =
      elliptic::howell_branch_from_tip_angle(psi, std::fabs(theta0));
  EllipticResult r;
  const double force = h.parameters.force;
  const double alpha2 = (negative ? -1.0 : 1.0) * force / eta_of(load_ratio_n);
  r.load = EndLoad::howell(load_ratio_n, alpha2, 0.0);
  r.parameters = h.parameters;
  r.parameters.mirrored = negative;
  r.tip = h.tip;
  r.root_moment = h.root_moment;
  if (negative) {
    r.tip.b_over_l = -r.tip.b_over_l;
    r.tip.theta0 = -r.tip.theta0;
    r.root_moment = -r.root_moment;
  }
  r.converged = h.converged;
  r.message = h.converged ? "converged" : "tip angle inverse failed";
  r.branch = "proportional loading (unique for mu = 0: 0 < theta0 < force angle)";
  return r;
}

// Finds the smallest |alpha2| with quantity(solve(alpha2)) = value (solver/common/load_search.h).
EllipticResult search_alpha2(const EllipticSolver& solver,
                             double load_ratio_n,
                             double mu,
                             const std::function<double(const EllipticResult&)>& quantity,
                             double value) {
  auto solve_at = [&](double alpha2) {
    return solver.solve(EndLoad::howell(load_ratio_n, alpha2, mu));
  };
  auto q = [&](double alpha2) -> std::optional<double> {
    const EllipticResult r = solve_at(alpha2);
    if (!r.converged) return std::nullopt;
    return quantity(r);
  };
  LoadSearchOptions options;
  options.max_alpha2 = kMaxAlpha2Search;
  const LoadSearchResult found = find_load_for_target(q, value, quantity(solve_at(0.0)), options);
  if (!found.found) {
    EllipticResult failed;
    failed.message = found.message;
    return failed;
  }
  EllipticResult r = solve_at(found.alpha2);
  r.iterations += found.solves;
  return r;
}

}  // namespace

EllipticResult EllipticSolver::solve_for_tip_angle(double load_ratio_n,
                                                   double theta0,
                                                   double mu) const {
  require_finite(load_ratio_n, "load ratio n");
  require_finite(theta0, "tip angle theta0");
  require_finite(mu, "end moment mu");
  if (mu == 0.0) {
    if (theta0 == 0.0) return solve(EndLoad::howell(load_ratio_n, 0.0, 0.0));
    const double upper = force_angle(load_ratio_n);
    const double lower = -force_angle(-load_ratio_n);
    if (!(theta0 > lower && theta0 < upper)) {
      throw InvalidInput(fmt::format(
          "tip angle theta0 = {:.6g} rad ({:.4g} deg) cannot be reached with load ratio n = {:.6g} "
          "and no end moment: theta0 must lie strictly between {:.6g} and {:.6g} rad ({:.4g} to "
          "{:.4g} deg), the force angles for alpha2 < 0 and alpha2 > 0 (Howell eq. 2.90)",
          theta0,
          theta0 * kDeg,
          load_ratio_n,
          lower,
          upper,
          lower * kDeg,
          upper * kDeg));
    }
    return result_from_tip_angle(load_ratio_n, theta0);
  }
  // With an end moment the tip angle at alpha2 = 0 is mu; search the side that moves it to theta0.
  auto tip_angle = [](const EllipticResult& r) { return r.tip.theta0; };
  EllipticResult r = search_alpha2(*this, load_ratio_n, mu, tip_angle, theta0);
  if (r.converged) return r;
  throw InvalidInput(fmt::format(
      "tip angle theta0 = {:.6g} rad is not reached by any |alpha2| <= {:.0e} with load ratio "
      "n = {:.6g} and end moment mu = {:.6g}",
      theta0,
      kMaxAlpha2Search,
      load_ratio_n,
      mu));
}

EllipticResult EllipticSolver::solve_for_deflection(double load_ratio_n,
                                                    double b_over_l,
                                                    double mu) const {
  require_finite(load_ratio_n, "load ratio n");
  require_finite(b_over_l, "tip deflection b/l");
  require_finite(mu, "end moment mu");
  if (std::fabs(b_over_l) >= 1.0) {
    throw InvalidInput(fmt::format(
        "tip deflection b/l = {:.6g} is outside (-1, 1): an inextensible beam of length l cannot "
        "reach it",
        b_over_l));
  }
  auto deflection = [](const EllipticResult& r) { return r.tip.b_over_l; };
  if (mu == 0.0) {
    if (b_over_l == 0.0) return solve(EndLoad::howell(load_ratio_n, 0.0, 0.0));
    // b/l is explicit in theta0 on this branch; the sign of b picks the sign of alpha2. Scan theta0
    // up to the force angle for the first crossing (the smallest load), then refine with Brent.
    const double sign = b_over_l > 0.0 ? 1.0 : -1.0;
    const double limit = sign > 0.0 ? force_angle(load_ratio_n) : force_angle(-load_ratio_n);
    auto f = [&](double t) {
      return deflection(result_from_tip_angle(load_ratio_n, sign * t)) - b_over_l;
    };
    constexpr int kScan = 256;
    double a = 0.0;
    double fa = -b_over_l;
    double best = 0.0;
    for (int i = 1; i < kScan; ++i) {
      const double t = limit * i / kScan;
      const double ft = f(t);
      best = sign > 0.0 ? std::max(best, ft + b_over_l) : std::min(best, ft + b_over_l);
      if ((fa > 0.0) != (ft > 0.0) || ft == 0.0) {
        ScalarRootOptions opts;
        opts.x_tolerance = 1e-15;
        const ScalarRootResult root = brent_root(f, a, t, fa, ft, opts);
        if (root.converged) {
          EllipticResult r = result_from_tip_angle(load_ratio_n, sign * root.x);
          r.iterations = i + root.iterations;
          return r;
        }
        break;
      }
      a = t;
      fa = ft;
    }
    throw InvalidInput(fmt::format(
        "tip deflection b/l = {:.6g} cannot be reached with load ratio n = {:.6g} and no end "
        "moment: the largest |b/l| on the proportional-loading branch is about {:.6g}",
        b_over_l,
        load_ratio_n,
        std::fabs(best)));
  }
  EllipticResult r = search_alpha2(*this, load_ratio_n, mu, deflection, b_over_l);
  if (r.converged) return r;
  throw InvalidInput(fmt::format(
      "tip deflection b/l = {:.6g} is not reached by any |alpha2| <= {:.0e} with load ratio "
      "n = {:.6g} and end moment mu = {:.6g}",
      b_over_l,
      kMaxAlpha2Search,
      load_ratio_n,
      mu));
}

}  // namespace flexure
