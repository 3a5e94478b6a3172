#include "flexure/solver/shooting/continuation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {

const char* to_string(PathStatus status) {
  switch (status) {
    case PathStatus::kStart:
      return "start";
    case PathStatus::kAccepted:
      return "accepted";
    case PathStatus::kLimitPoint:
      return "limit point passed";
    case PathStatus::kEnd:
      return "end";
  }
  return "unknown";
}

namespace {

// Unit tangent of the solution curve in scaled variables: [J S, g_lambda] t = 0 (Keller's
// pseudo-arclength; the bordered system is regular at limit points). Its sign is fixed by the
// orientation of the path, the sign of det [J S, g_lambda; t^T], which is constant along one
// smooth branch and does not depend on the step: orienting t by the previous tangent instead would
// silently accept a corrector that landed on another branch (or on the same curve travelled
// backwards), which is how a continuation jumps branches near an imperfect bifurcation.
struct Tangent {
  Eigen::VectorXd t;
  int orientation = 0;  // sign of det [J S, g_lambda; t^T] before fixing the sign
};
Tangent tangent_at(const ShootingEvaluation& eval,
                   const Eigen::VectorXd& scale,
                   const Eigen::VectorXd& previous,
                   int orientation) {
  const int nz = static_cast<int>(scale.size());
  Eigen::MatrixXd A(nz + 1, nz + 1);
  A.topLeftCorner(nz, nz) = eval.jacobian * scale.asDiagonal();
  A.topRightCorner(nz, 1) = eval.d_lambda;
  A.bottomRows(1) = previous.transpose();
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(nz + 1);
  rhs[nz] = 1.0;
  Tangent out;
  out.t = robust_solve(A, rhs);
  out.t.normalize();
  A.bottomRows(1) = out.t.transpose();
  const double det = A.partialPivLu().determinant();
  out.orientation = det > 0.0 ? 1 : (det < 0.0 ? -1 : 0);
  if (orientation != 0 && out.orientation != 0 && out.orientation != orientation) {
    out.t = -out.t;
  }
  return out;
}

PathPoint make_point(const ShootingProblem& problem,
                     const ShootingEvaluation& eval,
                     const Eigen::VectorXd& z,
                     double lambda,
                     double step,
                     int iterations,
                     PathStatus status) {
  PathPoint p;
  p.lambda = lambda;
  p.tip = ChainPose{eval.tip.x, eval.tip.y, eval.tip.theta};
  p.reaction = problem.reaction(z, lambda);
  p.step = step;
  p.iterations = iterations;
  p.status = status;
  return p;
}

}  // namespace

int jacobian_sign(const ShootingEvaluation& eval) {
  if (eval.jacobian.size() == 0) return 0;
  const double det = eval.jacobian.partialPivLu().determinant();
  return det > 0.0 ? 1 : (det < 0.0 ? -1 : 0);
}

bool singular_jacobian(const ShootingEvaluation& eval) {
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(eval.jacobian);
  qr.setThreshold(1e-10);
  return qr.rank() < eval.jacobian.cols();
}

LoadPath continue_load_path(const ShootingProblem& problem,
                            ElasticaIntegrator& integrator,
                            const ContinuationOptions& options,
                            const NewtonOptions& newton,
                            const Eigen::VectorXd* start) {
  LoadPath path;
  const int nz = problem.size();
  Eigen::VectorXd z = start != nullptr ? *start : problem.unloaded_unknowns();
  double lambda = 0.0;
  path.z = z;
  path.tip = problem.chain().unloaded_tip();
  path.tip_state.x = path.tip.x;
  path.tip_state.y = path.tip.y;
  path.tip_state.theta = path.tip.theta;

  ShootingEvaluation eval;
  if (!problem.evaluate(z, lambda, true, true, integrator, eval)) {
    path.message = "integration of the unloaded chain failed: " + eval.error;
    return path;
  }
  path.tip_state = eval.tip;
  path.tip = ChainPose{eval.tip.x, eval.tip.y, eval.tip.theta};
  if (singular_jacobian(eval)) {
    path.singular_start = true;
    path.message =
        "the linearised problem is singular at zero load (a bifurcation: e.g. a prescribed change "
        "of the end-to-end distance of a straight inextensible chain needs buckling); the path "
        "cannot start";
    return path;
  }
  // Scale the unknowns by their linear-theory rate so that one unit of scaled arclength is about
  // one unit of load factor at the start.
  const Eigen::VectorXd z_rate = robust_solve(eval.jacobian, -eval.d_lambda);
  Eigen::VectorXd scale = z_rate.cwiseAbs().cwiseMax(1.0);
  Eigen::VectorXd along_lambda = Eigen::VectorXd::Zero(nz + 1);
  along_lambda[nz] = 1.0;
  const Tangent start_tangent = tangent_at(eval, scale, along_lambda, 0);
  Eigen::VectorXd t = start_tangent.t;
  // The path keeps this orientation (see tangent_at); lambda increases at the start.
  int orientation = start_tangent.orientation;
  if (options.record_path) {
    path.points.push_back(make_point(problem, eval, z, lambda, 0.0, 0, PathStatus::kStart));
  }

  auto scaled = [&](const Eigen::VectorXd& zz, double ll) {
    Eigen::VectorXd u(nz + 1);
    u.head(nz) = zz.cwiseQuotient(scale);
    u[nz] = ll;
    return u;
  };

  // Under a large load the linear-theory tangent is a poor predictor beyond a load factor of about
  // 1/sqrt(F) (the boundary layer of the elastica has width 1/sqrt(F)); a first step of that size
  // lets the step control grow from there instead of burning the budget on failed correctors.
  double ds = options.initial_step;
  const double contraction = unique_equilibrium_bound(problem.chain());
  if (std::isfinite(contraction) && contraction > 1.0) {
    ds = std::min(ds, 1.5 / std::sqrt(contraction));
  }
  int attempts = 0;
  double arclength = 0.0;    // scaled arclength of the current point
  double quiet_until = 0.0;  // no samples recorded before this arclength (bifurcations)
  std::vector<double> arclength_of(path.points.size(), 0.0);  // of each recorded point
  const long integrator_start = integrator.steps_taken();
  // The work of one evaluation grows with the multiple-shooting intervals (about sqrt(F)/2.5 of
  // them): the budget grows with them, so that large loads can be reached while a failure still
  // comes within seconds (about 8 s at |F| l^2/EI = 1e4, 41 intervals).
  const long integrator_budget =
      options.max_integrator_steps * std::max(1L, static_cast<long>(problem.interval_count()) / 16);
  bool out_of_budget = false;
  while (attempts < options.max_steps) {
    ++attempts;
    if (integrator.steps_taken() - integrator_start > integrator_budget) {
      out_of_budget = true;
      break;
    }
    const Eigen::VectorXd u = scaled(z, lambda);
    Eigen::VectorXd pred = u + ds * t;

    // Landing on lambda = 1 when the predictor crosses it.
    if (pred[nz] >= 1.0 && t[nz] > 0.0) {
      const double h = (1.0 - lambda) / t[nz];
      const Eigen::VectorXd start = u + h * t;
      Eigen::VectorXd z_end = start.head(nz).cwiseProduct(scale);
      double lambda_end = 1.0;
      NewtonOutcome nw = newton_solve(problem, integrator, newton, z_end, lambda_end, nullptr);
      path.newton_iterations += nw.iterations;
      const double moved = (scaled(z_end, 1.0) - start).norm();
      // The landing point must lie on this branch, reached with lambda still increasing (the
      // fixed-lambda corrector does not compute dg/dlambda, so evaluate once more).
      ShootingEvaluation at_end;
      const bool same_branch =
          nw.converged() && problem.evaluate(z_end, 1.0, true, true, integrator, at_end) &&
          tangent_at(at_end, scale, t, orientation).t.dot(t) >= std::cos(options.max_turn);
      if (same_branch && moved <= options.max_predictor_distance * std::max(h, options.min_step)) {
        z = z_end;
        lambda = 1.0;
        ++path.steps;
        path.z = z;
        path.lambda = 1.0;
        path.lambda_reached = 1.0;
        path.residual = nw.residual;
        path.tip = ChainPose{nw.last.tip.x, nw.last.tip.y, nw.last.tip.theta};
        path.tip_state = nw.last.tip;
        path.set_converged(true);
        path.jacobian_sign = jacobian_sign(at_end);
        if (options.record_path) {
          path.points.push_back(
              make_point(problem, nw.last, z, 1.0, h, nw.iterations, PathStatus::kEnd));
        }
        path.message =
            fmt::format("reached load factor 1 in {} steps ({} rejected, {} limit points passed)",
                        path.steps,
                        path.rejected_steps,
                        path.limit_points);
        return path;
      }
      ++path.rejected_steps;
      ds = 0.5 * std::min(ds, h);
      if (ds < options.min_step) break;
      continue;
    }

    ArclengthConstraint c{t, pred, scale};
    Eigen::VectorXd z_new = pred.head(nz).cwiseProduct(scale);
    double lambda_new = pred[nz];
    NewtonOutcome nw = newton_solve(problem, integrator, newton, z_new, lambda_new, &c);
    path.newton_iterations += nw.iterations;
    const double moved = (scaled(z_new, lambda_new) - pred).norm();
    if (!nw.converged() || moved > options.max_predictor_distance * ds) {
      ++path.rejected_steps;
      ds *= 0.5;
      if (ds < options.min_step) break;
      continue;
    }
    if (lambda_new > 1.0) {
      // Overshot lambda = 1 during the correction: shorten so that the predictor lands before it.
      ++path.rejected_steps;
      ds *= 0.5;
      if (ds < options.min_step) break;
      continue;
    }
    Eigen::VectorXd t_new = tangent_at(nw.last, scale, t, orientation).t;
    if (t_new.dot(t) < std::cos(options.max_turn)) {
      // The orientation flipped: either the corrector landed on another branch (then a shorter
      // step lands on this one again) or the path crossed a bifurcation point, where
      // det [J S, g_lambda; t^T] changes sign on the branch itself (a symmetric arch). Only a flip
      // that persists at a very short step, with the tangent taken by continuity, is a crossing.
      const bool crossing =
          ds <= options.bifurcation_step && -t_new.dot(t) >= std::cos(options.max_turn);
      if (!crossing) {
        ++path.rejected_steps;
        ds *= 0.5;
        if (ds < options.min_step) break;
        continue;
      }
      // Crossed: the branch continues with the opposite orientation. Samples within
      // bifurcation_vicinity of the crossing are ill-conditioned (the Jacobian is nearly singular
      // there, so their error is the Newton residual divided by a small singular value): the
      // ones recorded on the way in are dropped and none are recorded on the way out.
      orientation = -orientation;
      ++path.bifurcation_points;
      t_new = -t_new;
      while (path.points.size() > 1 &&
             arclength - arclength_of.back() < options.bifurcation_vicinity) {
        path.points.pop_back();
        arclength_of.pop_back();
      }
      quiet_until = arclength + ds + options.bifurcation_vicinity;
    }
    arclength += ds;
    PathStatus status = PathStatus::kAccepted;
    if (t_new[nz] * t[nz] < 0.0) {
      status = PathStatus::kLimitPoint;
      if (path.limit_points == 0) {
        path.first_limit_load_factor = std::max(path.lambda_reached, lambda_new);
      }
      ++path.limit_points;
    }
    z = z_new;
    lambda = lambda_new;
    t = t_new;
    ++path.steps;
    path.z = z;
    path.lambda = lambda;
    path.residual = nw.residual;
    path.tip = ChainPose{nw.last.tip.x, nw.last.tip.y, nw.last.tip.theta};
    path.tip_state = nw.last.tip;
    path.lambda_reached = std::max(path.lambda_reached, lambda);
    if (options.record_path && arclength >= quiet_until) {
      path.points.push_back(make_point(problem, nw.last, z, lambda, ds, nw.iterations, status));
      arclength_of.push_back(arclength);
    }
    if (lambda < -1e-12 && t[nz] < 0.0) {
      path.message = fmt::format(
          "the load path turned back below zero load (lambda = {:.6g}) after reaching {:.6g}",
          lambda,
          path.lambda_reached);
      return path;
    }
    if (nw.iterations <= options.easy_iterations) {
      ds = std::min(ds * options.growth, options.max_step);
    } else if (nw.iterations > 2 * options.easy_iterations) {
      ds *= 0.7;
    }
  }
  path.message = fmt::format(
      "continuation stopped at load factor {:.9g} (largest reached {:.9g}) after {} accepted and "
      "{} "
      "rejected steps: {}",
      lambda,
      path.lambda_reached,
      path.steps,
      path.rejected_steps,
      out_of_budget ? "integration budget exhausted (the reactions grow without bound?)"
      : attempts >= options.max_steps ? "step budget exhausted (the path approaches an asymptote?)"
                                      : "step size fell below min_step");
  return path;
}

}  // namespace flexure
