// Inverse problems of the elliptic solver: the load alpha2 for a given tip angle or deflection.
#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <optional>

#include "flexure/solver/common/load_search.h"
#include "flexure/solver/common/scalar_root.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/elliptic/elliptic_solver.h"
#include "flexure/solver/elliptic/howell_branch.h"
#include "flexure/solver/elliptic/howell_deflection.h"

namespace flexure {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = 180.0 / kPi;

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
  r.set_converged(h.converged());
  r.message = h.converged() ? "converged" : "tip angle inverse failed";
  r.branch_kind = EllipticBranch::kProportionalUnique;
  r.branch = "proportional loading (unique for mu = 0: 0 < theta0 < force angle)";
  return r;
}

double target_tolerance(double target) {
  return EllipticSolver::kInverseTolerance * std::max(1.0, std::fabs(target));
}

// Checks an explicit or bracketed mu = 0 inverse against its target: converged only if it hits.
EllipticResult verified(EllipticResult r, double reached, double target, const char* what) {
  r.residual = std::fabs(reached - target);
  if (r.converged() && !(r.residual <= target_tolerance(target))) {
    r.set_converged(false);
    r.message =
        fmt::format("the inverse solve reached {} = {:.12g} instead of {:.12g} (miss {:.2e})",
                    what,
                    reached,
                    target,
                    r.residual);
  }
  return r;
}

// The smallest |alpha2| with quantity(solve(alpha2)) = value (solver/common/load_search.h), both
// signs of alpha2, every root verified.
EllipticResult search_alpha2(const EllipticSolver& solver,
                             double load_ratio_n,
                             double mu,
                             const std::function<double(const EllipticResult&)>& quantity,
                             double value,
                             const char* what) {
  bool beyond_range = false;
  auto q = [&](double alpha2) -> std::optional<double> {
    try {
      const EllipticResult r = solver.solve(EndLoad::howell(load_ratio_n, alpha2, mu));
      if (!r.converged()) return std::nullopt;
      return quantity(r);
    } catch (const OutsideMethodDomain&) {
      beyond_range = true;
      return std::nullopt;
    }
  };
  LoadSearchOptions options;
  // Every |alpha2| the force range admits for this load ratio.
  options.max_alpha2 = EllipticSolver::kMaxForce / eta_of(load_ratio_n);
  options.target_tolerance = target_tolerance(value);
  const double at_zero = quantity(solver.solve(EndLoad::howell(load_ratio_n, 0.0, mu)));
  const LoadSearchResult found = find_load_for_target(q, value, at_zero, options);
  if (found.found()) {
    EllipticResult r = solver.solve(EndLoad::howell(load_ratio_n, found.alpha2, mu));
    r.iterations += found.solves;
    r.residual = found.residual;
    return r;
  }
  if (found.status == LoadSearchStatus::kUnreachable && (beyond_range || found.scanned_to_max)) {
    throw OutsideMethodDomain(fmt::format(
        "{} = {:.6g} is not reached by any |alpha2| <= {:.6g} with load ratio n = {:.6g} and end "
        "moment mu = {:.6g}, where the elliptic solver's range ends (|F| l^2/EI <= {:.0e}; the "
        "closest was {} = {:.9g} at alpha2 = {:.9g}); the shooting method searches larger "
        "loads, up to |F| l^2/EI of about 3.5e4 where it is measured to converge",
        what,
        value,
        found.reached_alpha2_max,
        load_ratio_n,
        mu,
        EllipticSolver::kMaxForce,
        what,
        found.reached,
        found.alpha2));
  }
  if (found.status == LoadSearchStatus::kUnreachable) {
    throw InvalidInput(
        fmt::format("{} = {:.6g} cannot be reached with load ratio n = {:.6g} and "
                    "end moment mu = {:.6g}: {}",
                    what,
                    value,
                    load_ratio_n,
                    mu,
                    found.message));
  }
  // Brackets but no root: report what was reached (exit code 3 in the CLI), never a wrong load.
  EllipticResult missed = solver.solve(EndLoad::howell(load_ratio_n, found.alpha2, mu));
  // The quantity jumps across the target between two loads: a fold (limit point) of the path.
  missed.termination = Termination::kLimitPoint;
  missed.iterations += found.solves;
  missed.residual = found.residual;
  missed.message = fmt::format("{} = {:.6g} not reached: {}", what, value, found.message);
  return missed;
}

// mu = 0: the smallest load reaching b/l is the first tip angle on the branch where b(theta0)
// reaches it (howell_deflection.h); b/l has the sign of alpha2 there (the tip angle stays between
// 0 and the force angle), so alpha2 < 0 is the mirror image with n -> -n. Empty when the fast
// search cannot settle the target (beyond the peak of b, beyond the force range, near the
// separatrix): the caller then scans the load as for any other inverse problem, and reports
// unreachable targets.
std::optional<EllipticResult> deflection_on_the_branch(double load_ratio_n, double b_over_l) {
  const bool negative = b_over_l < 0.0;
  const double psi = negative ? force_angle(-load_ratio_n) : force_angle(load_ratio_n);
  const elliptic::DeflectionInverse found =
      elliptic::first_tip_angle_for_deflection(psi, std::fabs(b_over_l), EllipticSolver::kMaxForce);
  if (!found.found) return std::nullopt;
  EllipticResult r = result_from_tip_angle(load_ratio_n, negative ? -found.theta0 : found.theta0);
  if (!(r.converged() && r.parameters.force <= EllipticSolver::kMaxForce)) return std::nullopt;
  r.iterations = found.evaluations;
  const double reached = r.tip.b_over_l;
  r = verified(std::move(r), reached, b_over_l, "tip deflection b/l");
  if (!r.converged()) return std::nullopt;
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
    EllipticResult r = result_from_tip_angle(load_ratio_n, theta0);
    const double reached = r.tip.theta0;
    return verified(std::move(r), reached, theta0, "theta0");
  }
  // With an end moment the tip angle at alpha2 = 0 is mu; the search moves it to theta0.
  auto tip_angle = [](const EllipticResult& r) { return r.tip.theta0; };
  return search_alpha2(*this, load_ratio_n, mu, tip_angle, theta0, "tip angle theta0");
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
  if (mu == 0.0 && b_over_l != 0.0) {
    std::optional<EllipticResult> fast = deflection_on_the_branch(load_ratio_n, b_over_l);
    if (fast) return std::move(*fast);
  }
  auto deflection = [](const EllipticResult& r) { return r.tip.b_over_l; };
  // b/l is not monotonic in the load (for compressive n the tip curls past the top), and under
  // tension it creeps toward its limit over loads from about 10 to infinity: the verified search
  // over alpha2 (both signs, smallest |alpha2| first) covers both, with or without a moment.
  return search_alpha2(*this, load_ratio_n, mu, deflection, b_over_l, "tip deflection b/l");
}

}  // namespace flexure
