#include "flexure/solver/elliptic/elliptic_solver.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <string>

#include "flexure/solver/common/status.h"
#include "flexure/solver/elliptic/elastica_closed_form.h"
#include "flexure/solver/elliptic/howell_branch.h"
#include "flexure/solver/elliptic/load_continuation.h"
#include "flexure/solver/elliptic/tabulated_predictor.h"

namespace flexure {
namespace {

constexpr double kPi = std::numbers::pi;
// Loads beyond kMaxForce (in units of EI/l^2) put the separatrix closer than double precision can
// resolve (k' ~ e^{-sqrt F}); no physical cantilever is loaded that far.
constexpr double kMaxForce = EllipticSolver::kMaxForce;
constexpr double kMaxMoment = EllipticSolver::kMaxMoment;
// Below this force the closed form would divide by numbers near underflow; linear theory is
// exact to round-off there.
constexpr double kNegligibleForce = 1e-200;

// The loads the shooting method is measured to converge at, for the refusals below (measured on
// Howell's cantilever: |F| l^2/EI = 3.5e4 with a tip force across the beam, 4e4 failed;
// benchmarks/studies/failure_advice.h keeps the measurements of every method).
constexpr double kShootingMeasuredReach = 3.5e4;

// What the other methods offer at a force the elliptic solver refuses: only what they are
// measured to do.
std::string beyond_range_hint(double force) {
  if (force <= kShootingMeasuredReach) {
    return "the shooting method is measured to converge up to |F| l^2/EI of about 3.5e4";
  }
  return "no method of flexure is measured to reach it (the shooting method converged up to about "
         "3.5e4, the chain algorithm up to about 3e4)";
}

void validate_load(const EndLoad& load) {
  require_finite(load.Fx, "horizontal force Fx l^2/EI");
  require_finite(load.Fy, "vertical force Fy l^2/EI (alpha2)");
  require_finite(load.mu, "end moment mu = M l/EI");
  const double force = std::hypot(load.Fx, load.Fy);
  if (force > kMaxForce) {
    throw OutsideMethodDomain(fmt::format(
        "end force |F| l^2/EI = {:.6g} is outside the elliptic solver's range (at most {:.0e}); "
        "{}",
        force,
        kMaxForce,
        beyond_range_hint(force)));
  }
  if (std::fabs(load.mu) > kMaxMoment) {
    throw OutsideMethodDomain(fmt::format(
        "end moment |mu| = {:.6g} is outside the elliptic solver's range (at most {:.0e}); the "
        "shooting method has no such limit on the moment (measured: mu = 2e4 with a tip force "
        "up to alpha2 = 1 converged; a larger tip force with a large moment can stop its "
        "continuation)",
        std::fabs(load.mu),
        kMaxMoment));
  }
}

// Mirrors a solution computed for (Fx, |Fy|, +-mu) back to the original sign of Fy.
void unmirror(EllipticResult& r) {
  if (!r.parameters.mirrored) return;
  r.tip.b_over_l = -r.tip.b_over_l;
  r.tip.theta0 = -r.tip.theta0;
  r.root_moment = -r.root_moment;
}

void fill_from_parameters(EllipticResult& r) {
  const elliptic::EndSummary ends = elliptic::end_summary(r.parameters);
  r.tip = {ends.tip.x, ends.tip.y, ends.tip.theta};
  r.root_moment = ends.root_moment;
  r.inflection_points = ends.inflection_points;
}

}  // namespace

EllipticResult EllipticSolver::solve(const EndLoad& load) const {
  validate_load(load);
  EllipticResult r;
  r.load = load;
  ElasticaParameters& p = r.parameters;
  p.mirrored = load.Fy < 0.0;
  const double Fy = std::fabs(load.Fy);
  const double mu = p.mirrored ? -load.mu : load.mu;
  const double force = std::hypot(load.Fx, Fy);
  p.mu = mu;

  if (force == 0.0 || (force < kNegligibleForce && mu != 0.0)) {
    // Pure end moment: a circular arc (Howell eqs. 2.53-2.64).
    p.family = mu == 0.0 ? ElasticaFamily::kStraight : ElasticaFamily::kCircularArc;
    fill_from_parameters(r);
    r.set_converged(true);
    r.branch_kind = EllipticBranch::kPureMoment;
    r.branch = "unique (pure end moment: circular arc)";
  } else if (mu == 0.0 && (Fy == 0.0 || force < kNegligibleForce)) {
    p.family = ElasticaFamily::kStraight;
    p.force = force;
    p.psi = std::atan2(Fy, load.Fx);
    if (Fy == 0.0) {
      fill_from_parameters(r);
      r.branch_kind = EllipticBranch::kStraight;
      r.branch = load.Fx < -kPi * kPi / 4.0
                     ? "straight (proportional loading along the axis; above the Euler load "
                       "pi^2/4 the straight shape is unstable and buckled equilibria exist)"
                     : "straight (axial load only)";
    } else {
      // Linear theory, exact to round-off at this load: theta0 = Fy/2, b = Fy/3.
      r.tip = {1.0, Fy / 3.0, Fy / 2.0};
      r.root_moment = Fy;
      r.branch_kind = EllipticBranch::kLinearTheory;
      r.branch = "linear theory (negligible load)";
    }
    r.set_converged(true);
  } else if (mu == 0.0) {
    const double psi = std::atan2(Fy, load.Fx);
    const elliptic::HowellBranchSolution h =
        elliptic::solve_howell_branch(force, psi, options_.tolerance);
    r.iterations = h.iterations;
    r.residual = std::fabs(h.residual);
    if (h.converged()) {
      p = h.parameters;
      p.mirrored = load.Fy < 0.0;
      r.tip = h.tip;
      r.root_moment = h.root_moment;
      r.inflection_points = 0;
      r.set_converged(true);
      r.branch_kind = EllipticBranch::kProportionalUnique;
      r.branch = "proportional loading (unique for mu = 0: 0 < theta0 < force angle)";
    } else {
      r.message = fmt::format(
          "elliptic solve for n-branch did not converge (force {:.6g}, angle {:.6g} rad)",
          force,
          psi);
    }
  } else {
    // With an end moment: the equilibrium reached by proportional loading, from the tabulated path
    // where its guard accepts, by the continuation everywhere else.
    const double psi = std::atan2(Fy, load.Fx);
    const elliptic::PendulumProblem problem = elliptic::make_pendulum_problem(force, psi, mu);
    elliptic::GuardedNewton fast;
    if (options_.tabulated_predictor) {
      fast = elliptic::solve_with_predictor(
          elliptic::predictor_table(), load.Fx, Fy, mu, problem, options_.tolerance);
    }
    r.iterations = fast.evaluations;
    if (fast.accepted) {
      p = fast.parameters;
      p.mirrored = load.Fy < 0.0;
      fill_from_parameters(r);
      r.residual = fast.residual;
      r.set_converged(true);
      r.branch_kind = EllipticBranch::kProportionalTabulated;
      r.branch = fmt::format(
          "proportional loading (Newton from the tabulated continuation path, {} residuals)",
          fast.evaluations);
    } else {
      elliptic::ContinuationOptions copts;
      copts.x_tolerance = options_.tolerance;
      copts.max_steps = options_.max_continuation_steps;
      const elliptic::ContinuationSolution c =
          elliptic::solve_by_continuation(force, psi, mu, copts);
      r.iterations += c.iterations;
      r.continuation_steps = c.steps;
      r.residual = std::fabs(c.residual);
      r.limit_points = c.limit_points;
      r.first_limit_load_factor = c.first_limit_load_factor;
      if (c.converged()) {
        p = elliptic::integrate_from_tip(problem, c.tip).parameters;
        p.mirrored = load.Fy < 0.0;
        fill_from_parameters(r);
        r.set_converged(true);
        r.branch_kind = EllipticBranch::kProportionalContinued;
        r.branch =
            fmt::format("proportional loading (pseudo-arclength continuation, {} steps)", c.steps);
        r.branch += limit_points_note(c.limit_points, c.first_limit_load_factor);
      } else {
        r.message = c.message;
      }
    }
  }
  if (r.converged()) {
    unmirror(r);
    if (!(std::isfinite(r.tip.a_over_l) && std::isfinite(r.tip.b_over_l) &&
          std::isfinite(r.tip.theta0))) {
      r.set_converged(false);
      r.message = "elliptic solution evaluated to a non-finite tip (internal error)";
    } else {
      r.message = "converged";
    }
  }
  return r;
}

void EllipticSolver::Options::validate() const {
  if (!(tolerance > 0.0 && tolerance < 1e-2)) {
    throw InvalidInput(
        fmt::format("EllipticSolver::Options::tolerance must be in (0, 1e-2) (got {})", tolerance));
  }
  if (max_iterations < 1) {
    throw InvalidInput(fmt::format("EllipticSolver::Options::max_iterations must be >= 1 (got {})",
                                   max_iterations));
  }
  if (max_continuation_steps < 1) {
    throw InvalidInput(
        fmt::format("EllipticSolver::Options::max_continuation_steps must be >= 1 (got {})",
                    max_continuation_steps));
  }
}

EllipticSolver::EllipticSolver(Options options) : options_(options) { options_.validate(); }

std::vector<ShapePoint> EllipticSolver::shape(const EllipticResult& result, int count) const {
  if (count < 2) {
    throw InvalidInput(fmt::format("shape point count must be at least 2 (got {})", count));
  }
  std::vector<double> s(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) s[static_cast<std::size_t>(i)] = double(i) / (count - 1);
  return shape_at(result, s);
}

std::vector<ShapePoint> EllipticSolver::shape_at(const EllipticResult& result,
                                                 const std::vector<double>& s) const {
  if (!result.converged()) throw InvalidInput("cannot evaluate the shape of an unconverged result");
  std::vector<ShapePoint> points;
  points.reserve(s.size());
  const elliptic::ShapeEvaluator evaluator(result.parameters);
  for (double si : s) {
    if (!(si >= 0.0 && si <= 1.0)) {
      throw InvalidInput(fmt::format("arc length s = {} is outside [0, 1]", si));
    }
    ShapePoint p;
    if (result.branch_kind == EllipticBranch::kLinearTheory) {
      // theta = Fy (s - s^2/2), y = Fy (s^2/2 - s^3/6) for a negligible load.
      const double Fy = result.load.Fy;
      p = {si, si, Fy * (0.5 * si * si - si * si * si / 6.0), Fy * (si - 0.5 * si * si)};
    } else {
      p = evaluator.at(si);
      if (result.parameters.mirrored) {
        p.y = -p.y;
        p.theta = -p.theta;
      }
    }
    points.push_back(p);
  }
  return points;
}

}  // namespace flexure
