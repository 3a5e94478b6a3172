#include "flexure/solver/shooting/continuation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "flexure/solver/common/scalar_root.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {

const char* to_string(PathStatus status) {
  switch (status) {
    case PathStatus::kStart:
      return "start";
    case PathStatus::kAccepted:
      return "accepted";
    case PathStatus::kLimitPoint:
      return "limit point";
    case PathStatus::kEnd:
      return "end";
    case PathStatus::kBifurcation:
      return "bifurcation";
  }
  return "unknown";
}

const char* to_string(SpecialPointKind kind) {
  return kind == SpecialPointKind::kLimitPoint ? "limit_point" : "bifurcation";
}

namespace {

// Unit tangent of the solution curve in scaled variables: [J S, g_lambda] t = 0 (Keller's
// pseudo-arclength; the bordered system is regular at limit points). Its sign is fixed by the
// orientation of the path, the sign of det [J S, g_lambda; t^T], which is constant along one
// smooth branch and does not depend on the step: orienting t by the previous tangent instead would
// silently accept a corrector that landed on another branch (or on the same curve travelled
// backwards), which is how a continuation jumps branches near an imperfect bifurcation.
// With orientation 0 the sign is taken by continuity (t . previous > 0).
//
// The orientation is sign(det J) * sign(t_lambda) (eliminate t_z = -t_lambda (J S)^-1 g_lambda
// from the bordered determinant: det = det(J S) t_lambda (1 + |(J S)^-1 g_lambda|^2)), so along
// a branch det J changes sign exactly where t_lambda does (a fold) or where the orientation does
// (a bifurcation point crossed, lambda keeping its direction).
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
  } else if (orientation == 0 && out.t.dot(previous) < 0.0) {
    out.t = -out.t;
    out.orientation = -out.orientation;
  }
  return out;
}

Reaction tip_load_of(const ShootingProblem& problem,
                     const Eigen::VectorXd& z,
                     double lambda,
                     const TipState& tip) {
  // The integrated N at the tip: with distributed loads N varies along the last segment.
  (void)problem;
  (void)z;
  (void)lambda;
  return Reaction{tip.N.x(), tip.N.y(), tip.m};
}

// A corrected point of the path and its evaluation (with dg/dz and dg/dlambda).
struct Corrected {
  bool ok = false;
  Eigen::VectorXd z;
  double lambda = 0.0;
  NewtonOutcome nw;
  double moved = 0.0;  // distance from the predictor (scaled)
};

// Follows one path (continue_load_path) and locates its special points.
class PathTracer {
 public:
  PathTracer(const ShootingProblem& problem,
             ElasticaIntegrator& integrator,
             const ContinuationOptions& options,
             const NewtonOptions& newton)
      : problem_(problem),
        integrator_(integrator),
        o_(options),
        newton_(newton),
        nz_(problem.size()) {}

  LoadPath run(const Eigen::VectorXd* start);

 private:
  Eigen::VectorXd scaled(const Eigen::VectorXd& z, double lambda) const {
    Eigen::VectorXd u(nz_ + 1);
    u.head(nz_) = z.cwiseQuotient(scale_);
    u[nz_] = lambda;
    return u;
  }
  // Corrector onto the path from the predictor u + h t (Keller's constraint with tangent `t`), or
  // from `guess` (scaled) on the same constraint.
  Corrected correct(const Eigen::VectorXd& u,
                    const Eigen::VectorXd& t,
                    double h,
                    const Eigen::VectorXd* guess = nullptr) {
    Corrected c;
    const Eigen::VectorXd pred = u + h * t;
    ArclengthConstraint constraint{t, pred, scale_};
    const Eigen::VectorXd& start = guess != nullptr ? *guess : pred;
    c.z = start.head(nz_).cwiseProduct(scale_);
    c.lambda = start[nz_];
    c.nw = newton_solve(problem_, integrator_, newton_, c.z, c.lambda, &constraint);
    path_.newton_iterations += c.nw.iterations;
    c.moved = (scaled(c.z, c.lambda) - pred).norm();
    c.ok = c.nw.converged();
    return c;
  }

  PathPoint make_point(const ShootingEvaluation& eval,
                       const Eigen::VectorXd& z,
                       double lambda,
                       double step,
                       int iterations,
                       PathStatus status);
  SpecialPoint make_special(SpecialPointKind kind, const Corrected& c, bool located);
  // Appends a point to the recorded path; special points waiting for their index_after get it.
  void record(PathPoint point, double arclength);
  // Records a special point located at arclength `at` (as a path point of its own when located).
  void record_special(SpecialPoint special, const Corrected& c, double at, double step);

  // Brent's method on h in [0, ds], the position along the step from (u_, t_) to `end` (the
  // point on the path on the hyperplane t_ . (u - u_) = h), for a root of f(point); f(current
  // point) and f(end) have opposite signs. Returns the point at the root (and its h), or nothing
  // when a corrector fails. Each corrector starts from the cubic through the nearest points found
  // so far, so it needs about one Newton iteration; within min_gap of a point already found the
  // interpolant itself is taken (one evaluation, no Newton: right next to a bifurcation the
  // corrector's matrix is nearly singular and its iterations would amplify the residual).
  template <typename F>
  std::optional<std::pair<double, Corrected>> locate(double ds,
                                                     const Corrected& end,
                                                     double tolerance,
                                                     F&& f);
  Corrected current_as_corrected() const {
    Corrected c;
    c.ok = true;
    c.z = z_;
    c.lambda = lambda_;
    c.nw.last = eval_;
    c.nw.set_converged(true);
    return c;
  }

  struct Bifurcation {
    bool verified = false;
    double h = 0.0;
    Corrected at;
    Eigen::VectorXd t_along;  // path tangent through the point (in the 2-d null space)
    Eigen::VectorXd t_other;  // the other branch's tangent (orthogonal to t_along)
  };
  Bifurcation locate_bifurcation(double ds, const Corrected& end);
  // One or two more fixed-lambda Newton iterations to the integration noise floor, for points
  // near a bifurcation, whose error is the residual divided by a small singular value of dg/dz
  // (the corrector stops at 1e-10). Returns the point with both derivatives evaluated.
  Corrected polish(const Corrected& c);
  // The path through the point `best` found next to a bifurcation, where no corrector is well
  // conditioned: the cubic Hermite interpolant between polished corrected points a distance
  // delta on either side (their error stays small, the interpolant's is O(delta^4)), evaluated.
  std::optional<Corrected> bridge(const Corrected& best, double ds);
  std::optional<std::pair<double, Corrected>> locate_fold(double ds, const Corrected& end);
  // The other branch's tangent at the bifurcation `b` from the algebraic bifurcation equation
  // (b.t_other when it cannot be formed).
  Eigen::VectorXd branch_tangent(const Bifurcation& b, double local_step);
  // Leaves the bifurcation `b` onto its other branch; false when no corrector lands there.
  // `local_step`: the step that passed it (the path's own scale there).
  bool switch_branch(const Bifurcation& b, int index_of_special, double local_step);

  const ShootingProblem& problem_;
  ElasticaIntegrator& integrator_;
  const ContinuationOptions& o_;
  const NewtonOptions& newton_;
  const int nz_;
  LoadPath path_;
  Eigen::VectorXd scale_;
  // The current point: unknowns, load factor, evaluation (with both derivatives), tangent,
  // orientation and normalized det(dg/dz).
  Eigen::VectorXd z_;
  double lambda_ = 0.0;
  ShootingEvaluation eval_;
  Eigen::VectorXd u_, t_;
  int orientation_ = 0;
  double det_ = 0.0;
  int branch_ = 0;
  double min_step_ = 0.0;             // o_.min_step, lowered after a branch switch (run())
  double switch_distance_ = 0.0;      // distance of the first point on a switched branch from the
                                      // bifurcation (scaled)
  double arclength_ = 0.0;            // scaled arclength of the current point
  double quiet_until_ = 0.0;          // no ordinary samples recorded before this arclength
  std::vector<double> arclength_of_;  // of each recorded point
  std::vector<std::size_t> waiting_;  // special points whose index_after is not known yet
};

PathPoint PathTracer::make_point(const ShootingEvaluation& eval,
                                 const Eigen::VectorXd& z,
                                 double lambda,
                                 double step,
                                 int iterations,
                                 PathStatus status) {
  PathPoint p;
  p.lambda = lambda;
  p.tip = ChainPose{eval.tip.x, eval.tip.y, eval.tip.theta};
  p.reaction = problem_.reaction(z, lambda);
  p.tip_load = tip_load_of(problem_, z, lambda, eval.tip);
  p.step = step;
  p.iterations = iterations;
  p.status = status;
  p.branch = branch_;
  p.held = problem_.mask();
  p.z = z;
  if (o_.shape_points > 1) {
    const double total = problem_.chain().total_length();
    std::vector<double> s(o_.shape_points);
    for (int i = 0; i < o_.shape_points; ++i) s[i] = total * i / (o_.shape_points - 1);
    std::string error;
    if (!shape_with_moments(problem_, integrator_, z, lambda, s, p.shape, p.moment, error)) {
      p.shape.clear();
      p.moment.clear();
    }
  }
  return p;
}

SpecialPoint PathTracer::make_special(SpecialPointKind kind, const Corrected& c, bool located) {
  SpecialPoint sp;
  sp.kind = kind;
  sp.lambda = c.lambda;
  sp.tip = ChainPose{c.nw.last.tip.x, c.nw.last.tip.y, c.nw.last.tip.theta};
  sp.reaction = problem_.reaction(c.z, c.lambda);
  sp.tip_load = tip_load_of(problem_, c.z, c.lambda, c.nw.last.tip);
  sp.branch = branch_;
  sp.located = located;
  sp.z = c.z;
  return sp;
}

void PathTracer::record(PathPoint point, double arclength) {
  path_.points.push_back(std::move(point));
  arclength_of_.push_back(arclength);
  for (std::size_t k : waiting_) {
    path_.special_points[k].index_after = static_cast<int>(path_.points.size()) - 1;
  }
  waiting_.clear();
}

void PathTracer::record_special(SpecialPoint special, const Corrected& c, double at, double step) {
  if (special.kind == SpecialPointKind::kBifurcation && o_.record_path) {
    // Ordinary samples close to a bifurcation are ill-conditioned (their error is the Newton
    // residual divided by a small singular value of dg/dz): drop the ones recorded on the way in
    // (never the start or another special point) and record none on the way out.
    while (path_.points.size() > 1 && path_.points.back().status == PathStatus::kAccepted &&
           at - arclength_of_.back() < o_.bifurcation_vicinity) {
      path_.points.pop_back();
      arclength_of_.pop_back();
    }
    quiet_until_ = at + o_.bifurcation_vicinity;
  }
  if (o_.record_path && special.located) {
    const PathStatus status = special.kind == SpecialPointKind::kLimitPoint
                                  ? PathStatus::kLimitPoint
                                  : PathStatus::kBifurcation;
    record(make_point(c.nw.last, c.z, c.lambda, step, c.nw.iterations, status), at);
    special.index = static_cast<int>(path_.points.size()) - 1;
  }
  if (special.kind == SpecialPointKind::kLimitPoint) {
    if (path_.limit_points == 0) path_.first_limit_load_factor = special.lambda;
    ++path_.limit_points;
  } else {
    ++path_.bifurcation_points;
  }
  path_.special_points.push_back(std::move(special));
  waiting_.push_back(path_.special_points.size() - 1);
}

// Cubic (or lower) interpolation of the path at h through the (up to) 4 known points nearest to
// it (Lagrange; the points cluster around the root as Brent proceeds).
Eigen::VectorXd interpolate_path(const std::vector<std::pair<double, Eigen::VectorXd>>& known,
                                 double h) {
  std::vector<std::size_t> order(known.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::abs(known[a].first - h) < std::abs(known[b].first - h);
  });
  const std::size_t m = std::min<std::size_t>(4, order.size());
  Eigen::VectorXd u = Eigen::VectorXd::Zero(known.front().second.size());
  for (std::size_t i = 0; i < m; ++i) {
    double w = 1.0;
    for (std::size_t j = 0; j < m; ++j) {
      if (j == i) continue;
      w *= (h - known[order[j]].first) / (known[order[i]].first - known[order[j]].first);
    }
    u += w * known[order[i]].second;
  }
  return u;
}

// Signed test function of the singularity of A = dg/dz S: the last component g of the solution of
// the bordered system [A b; c^T 0] [v; g] = [0; 1], with b and c the left and right singular
// vectors of the smallest singular value of A at one end of the step. g = det A / det M is smooth,
// about the smallest singular value in size, and changes sign with det A (Govaerts, "Numerical
// Methods for Bifurcations of Dynamical Equilibria", SIAM 2000, §3.2); det A itself is a product
// of all singular values and falls to 1e-18 and below on multiple-shooting Jacobians.
struct BorderedTest {
  Eigen::VectorXd b, c;
  explicit BorderedTest(const Eigen::MatrixXd& A) {
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullU | Eigen::ComputeFullV);
    b = svd.matrixU().col(A.cols() - 1);
    c = svd.matrixV().col(A.cols() - 1);
  }
  double operator()(const Eigen::MatrixXd& A) const {
    const Eigen::Index n = A.rows();
    Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n + 1, n + 1);
    M.topLeftCorner(n, n) = A;
    M.topRightCorner(n, 1) = b;
    M.bottomLeftCorner(1, n) = c.transpose();
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + 1);
    rhs[n] = 1.0;
    return M.partialPivLu().solve(rhs)[n];
  }
};

template <typename F>
std::optional<std::pair<double, Corrected>> PathTracer::locate(double ds,
                                                               const Corrected& end,
                                                               double tolerance,
                                                               F&& f) {
  std::vector<std::pair<double, Eigen::VectorXd>> known = {{0.0, u_},
                                                           {ds, scaled(end.z, end.lambda)}};
  std::vector<std::pair<double, Corrected>> seen = {{0.0, current_as_corrected()}, {ds, end}};
  const double f0 = f(seen[0].second), f1 = f(seen[1].second);
  const double min_gap = 1e-6 * ds;
  bool failed = false;
  auto g = [&](double h) {
    if (failed) return f0;  // keeps Brent finite; the result is discarded
    const Eigen::VectorXd guess = interpolate_path(known, h);
    double gap = ds;
    for (const auto& k : known) gap = std::min(gap, std::abs(k.first - h));
    Corrected c;
    ++path_.location_corrections;
    if (gap < min_gap) {
      c.z = guess.head(nz_).cwiseProduct(scale_);
      c.lambda = guess[nz_];
      c.ok = problem_.evaluate(c.z, c.lambda, true, true, integrator_, c.nw.last);
      c.nw.set_converged(c.ok);
    } else {
      c = correct(u_, t_, h, &guess);
      if (c.ok) c.ok = (scaled(c.z, c.lambda) - guess).norm() <= o_.max_predictor_distance * ds;
    }
    if (!c.ok) {
      failed = true;
      return f0;
    }
    const double value = f(c);
    known.emplace_back(h, scaled(c.z, c.lambda));
    seen.emplace_back(h, std::move(c));
    return value;
  };
  ScalarRootOptions ro;
  ro.x_tolerance = tolerance;
  ro.max_iterations = 100;
  const ScalarRootResult r = brent_root(g, 0.0, ds, f0, f1, ro);
  if (failed || !r.converged()) return std::nullopt;
  for (auto& [h, c] : seen) {
    if (h == r.x) return std::make_pair(h, std::move(c));
  }
  return std::nullopt;
}

std::optional<std::pair<double, Corrected>> PathTracer::locate_fold(double ds,
                                                                    const Corrected& end) {
  // lambda is stationary at the fold, so its error is quadratic in the bracket: 1e-8 of the step
  // gives it to about 1e-16 times the curvature.
  auto t_lambda = [&](const Corrected& c) {
    return tangent_at(c.nw.last, scale_, t_, orientation_).t[nz_];
  };
  return locate(ds, end, std::max(o_.location_tolerance, 1e-8 * ds), t_lambda);
}

PathTracer::Bifurcation PathTracer::locate_bifurcation(double ds, const Corrected& end) {
  Bifurcation b;
  const BorderedTest test(end.nw.last.jacobian * scale_.asDiagonal());
  auto bordered = [&](const Corrected& c) {
    return test(c.nw.last.jacobian * scale_.asDiagonal());
  };
  auto determinant = [&](const Corrected& c) {
    return normalized_determinant(c.nw.last.jacobian, scale_);
  };
  auto brackets = [](double g0, double g1) {
    return std::isfinite(g0) && std::isfinite(g1) && g0 != 0.0 && (g0 > 0.0) != (g1 > 0.0);
  };
  // The bordered function is the better scaled, but its border comes from one end of the step:
  // where the smallest singular vectors turn much within the step, det M may change sign too and
  // g = det A / det M then keeps its sign (the clamped-clamped beam at the start of its second
  // stage). The normalized determinant always changes sign with det J.
  const bool use_bordered = brackets(bordered(current_as_corrected()), bordered(end));
  if (!use_bordered && !brackets(determinant(current_as_corrected()), determinant(end))) {
    return b;
  }
  auto singularity = [&](const Corrected& c) {
    return use_bordered ? bordered(c) : determinant(c);
  };
  auto found = locate(ds, end, o_.location_tolerance, singularity);
  if (!found) return b;
  b.h = found->first;
  std::optional<Corrected> at = bridge(found->second, ds);
  if (!at) return b;
  b.at = std::move(*at);
  // At a simple bifurcation point [J S, g_lambda] has a 2-d null space holding both branches'
  // tangents; a jump to another branch shows up as a located "root" where the corrector changes
  // branch, with no singular value near zero.
  Eigen::MatrixXd A(nz_, nz_ + 1);
  A.leftCols(nz_) = b.at.nw.last.jacobian * scale_.asDiagonal();
  A.col(nz_) = b.at.nw.last.d_lambda;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
  const Eigen::VectorXd& sigma = svd.singularValues();
  // Relative to the size of [J S, g_lambda] over the step (with one unknown, sigma_max is
  // sigma_min itself).
  auto size_at = [&](const ShootingEvaluation& e) {
    Eigen::MatrixXd B(nz_, nz_ + 1);
    B.leftCols(nz_) = e.jacobian * scale_.asDiagonal();
    B.col(nz_) = e.d_lambda;
    return B.norm();
  };
  const double reference = std::max({sigma[0], size_at(eval_), size_at(end.nw.last)});
  if (!(reference > 0.0) || sigma[nz_ - 1] > o_.singular_tolerance * reference) return b;
  const Eigen::MatrixXd null = svd.matrixV().rightCols(2);
  // The path's own tangent through the point: the incoming chord's direction in the null space.
  const Eigen::VectorXd u_star = scaled(b.at.z, b.at.lambda);
  Eigen::VectorXd in = u_star - u_;
  if (in.norm() < 1e-12) in = t_;
  Eigen::VectorXd along = null * (null.transpose() * in);
  if (along.norm() == 0.0) return b;
  along.normalize();
  // Gram-Schmidt in the 2-d null space: the other tangent is the null vector orthogonal to `along`.
  const Eigen::VectorXd n0 = null.col(0), n1 = null.col(1);
  const double a0 = along.dot(n0), a1 = along.dot(n1);
  Eigen::VectorXd other = -a1 * n0 + a0 * n1;
  other.normalize();
  // The step's end must lie on the continuation of this path, not on the other branch.
  const Eigen::VectorXd out = scaled(end.z, end.lambda) - u_star;
  if (std::abs(out.dot(other)) > std::abs(out.dot(along))) return b;
  b.t_along = along;
  b.t_other = other;
  b.verified = true;
  return b;
}

Corrected PathTracer::polish(const Corrected& c) {
  NewtonOptions tight = newton_;
  tight.residual_tolerance = 1e-14;
  tight.max_iterations = 2;
  Corrected out = c;
  double lambda = c.lambda;
  const NewtonOutcome nw = newton_solve(problem_, integrator_, tight, out.z, lambda, nullptr);
  path_.newton_iterations += nw.iterations;
  if (!(nw.residual <= c.nw.residual)) out.z = c.z;  // no improvement: keep the point
  ShootingEvaluation e;
  if (!problem_.evaluate(out.z, c.lambda, true, true, integrator_, e)) return c;
  out.nw.last = std::move(e);
  out.nw.residual = std::min(nw.residual, c.nw.residual);
  return out;
}

std::optional<Corrected> PathTracer::bridge(const Corrected& best, double ds) {
  // The path's own direction through the point: in the 2-d null space of [J S, g_lambda] (both
  // branches' tangents), the part along the chord from the step's start.
  const Eigen::VectorXd u_best = scaled(best.z, best.lambda);
  Eigen::MatrixXd A(nz_, nz_ + 1);
  A.leftCols(nz_) = best.nw.last.jacobian * scale_.asDiagonal();
  A.col(nz_) = best.nw.last.d_lambda;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
  const Eigen::MatrixXd null = svd.matrixV().rightCols(2);
  Eigen::VectorXd along = null * (null.transpose() * (u_best - u_));
  if (!(along.norm() > 0.0)) along = t_;
  along.normalize();
  if (along.dot(t_) < 0.0) along = -along;
  // Correctors on hyperplanes normal to `along`: the corrector's nearly singular direction is
  // then the other branch's tangent, orthogonal to the path, so the points stay on the path up to
  // an offset towards the other branch, which the polish removes.
  const double delta = std::max(1e-3 * ds, 1e-7);
  struct Side {
    Eigen::VectorXd u, du;  // point and du/ds (s = along . (u - u_best))
  };
  std::vector<Side> sides;
  for (const double s : {-delta, delta}) {
    Corrected c = correct(u_best, along, s);
    ++path_.location_corrections;
    if (!c.ok) return std::nullopt;
    c = polish(c);
    const Eigen::VectorXd tau = tangent_at(c.nw.last, scale_, along, 0).t;
    if (!(tau.dot(along) > 0.0)) return std::nullopt;
    sides.push_back({scaled(c.z, c.lambda), tau / tau.dot(along)});
  }
  // Cubic Hermite at the midpoint s = 0.
  const double w = 2.0 * delta;
  const Eigen::VectorXd u =
      0.5 * (sides[0].u + sides[1].u) + 0.125 * w * (sides[0].du - sides[1].du);
  Corrected out;
  out.z = u.head(nz_).cwiseProduct(scale_);
  out.lambda = u[nz_];
  out.ok = problem_.evaluate(out.z, out.lambda, true, true, integrator_, out.nw.last);
  if (!out.ok) return std::nullopt;
  out.nw.set_converged(true);
  out.nw.residual = out.nw.last.residual.lpNorm<Eigen::Infinity>();
  return out;
}

Eigen::VectorXd PathTracer::branch_tangent(const Bifurcation& b, double local_step) {
  // At a simple bifurcation point u* the tangents of both branches lie in the 2-d null space of
  // A = [J S, g_lambda], spanned here by the path's own tangent p (b.t_along) and q (b.t_other,
  // orthogonal to p). A branch through u* with tangent t = alpha p + beta q satisfies, at second
  // order, the algebraic bifurcation equation psi^T D2G[t, t] = 0 with psi the left null vector
  // of A (Keller, "Numerical solution of bifurcation and nonlinear eigenvalue problems", 1977,
  // §5; Govaerts 2000, §5.2): a quadratic form Q = [[a, b], [b, c]] in (alpha, beta) whose two
  // isotropic directions are the two tangents. q itself is a tangent only when the branches
  // cross at right angles in the scaled variables; on the clamped-clamped beam's second stage
  // they meet at 70 deg, so a step along -q leaves the other half-branch at an angle, lands with
  // lambda the wrong way, and the path stopped there (issue 27). D2G[v, w] = d/de A(u* + e v) w by
  // central differences of the sensitivity Jacobian.
  const Eigen::VectorXd& p = b.t_along;
  const Eigen::VectorXd& q = b.t_other;
  Eigen::MatrixXd A(nz_, nz_ + 1);
  A.leftCols(nz_) = b.at.nw.last.jacobian * scale_.asDiagonal();
  A.col(nz_) = b.at.nw.last.d_lambda;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullU);
  const Eigen::VectorXd psi = svd.matrixU().col(nz_ - 1);
  const Eigen::VectorXd u_star = scaled(b.at.z, b.at.lambda);
  // The step: small against the unknowns' own scale (1 in scaled variables), large against the
  // integration noise (rtol 1e-12) of the Jacobian it differences.
  const double e = std::clamp(1e-3 * local_step, 1e-10, 1e-5);
  auto jacobian_at = [&](const Eigen::VectorXd& u, Eigen::MatrixXd& out) {
    ShootingEvaluation ev;
    if (!problem_.evaluate(u.head(nz_).cwiseProduct(scale_), u[nz_], true, true, integrator_, ev)) {
      return false;
    }
    out.resize(nz_, nz_ + 1);
    out.leftCols(nz_) = ev.jacobian * scale_.asDiagonal();
    out.col(nz_) = ev.d_lambda;
    return true;
  };
  Eigen::MatrixXd pp, pm, qp, qm;
  if (!jacobian_at(u_star + e * p, pp) || !jacobian_at(u_star - e * p, pm) ||
      !jacobian_at(u_star + e * q, qp) || !jacobian_at(u_star - e * q, qm)) {
    return q;
  }
  const Eigen::MatrixXd Dp = (pp - pm) / (2.0 * e), Dq = (qp - qm) / (2.0 * e);
  Eigen::Matrix2d Q;
  Q(0, 0) = psi.dot(Dp * p);
  Q(0, 1) = Q(1, 0) = 0.5 * (psi.dot(Dp * q) + psi.dot(Dq * p));
  Q(1, 1) = psi.dot(Dq * q);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(Q);
  const double lo = eig.eigenvalues()[0], hi = eig.eigenvalues()[1];
  // A simple bifurcation has an indefinite Q (two real tangents); anything else: keep q.
  if (!(lo < 0.0 && hi > 0.0) || !(std::min(-lo, hi) > 1e-6 * std::max(-lo, hi))) return q;
  const Eigen::Vector2d e0 = eig.eigenvectors().col(0), e1 = eig.eigenvectors().col(1);
  // The two isotropic directions; the path's own is the one nearer (1, 0).
  Eigen::Vector2d r1 = std::sqrt(hi) * e0 + std::sqrt(-lo) * e1;
  Eigen::Vector2d r2 = std::sqrt(hi) * e0 - std::sqrt(-lo) * e1;
  r1.normalize();
  r2.normalize();
  const bool first_is_own = std::abs(r1[0]) >= std::abs(r2[0]);
  const Eigen::Vector2d& own = first_is_own ? r1 : r2;
  const Eigen::Vector2d& r = first_is_own ? r2 : r1;
  // Self-check: the path's own tangent p must solve the equation too (within 0.2 rad here);
  // otherwise the differences did not resolve D2G (keep q).
  if (std::abs(own[1]) > 0.2 * std::abs(own[0])) return q;
  Eigen::VectorXd t = r[0] * p + r[1] * q;
  t.normalize();
  return t;
}

bool PathTracer::switch_branch(const Bifurcation& b, int index_of_special, double local_step) {
  const Eigen::VectorXd u_star = scaled(b.at.z, b.at.lambda);
  // Which way the new branch goes: the tip's y, or its angle when the end holds y, or the clamp's
  // bending moment m(0) when the end holds both. The half-branch asked for is the one on which
  // that quantity increases (branch_side +1) or decreases.
  const PrescribedMask& held = problem_.mask();
  auto side_of = [&](const Corrected& c) {
    if (!held.y) return c.nw.last.tip.y - b.at.nw.last.tip.y;
    if (!held.theta) return c.nw.last.tip.theta - b.at.nw.last.tip.theta;
    return c.z[0] - b.at.z[0];
  };
  // The first step is branch_switch_step, or four times the step that passed the point where the
  // path's own scale is smaller (a clamped-clamped beam at the start of its second stage passes
  // its bifurcation in steps of 1e-6); a step that lands nowhere is retried a quarter as long.
  std::optional<Corrected> chosen;
  Eigen::VectorXd direction;
  const Eigen::VectorXd other = branch_tangent(b, local_step);
  double h = std::min(o_.branch_switch_step, 4.0 * local_step);
  for (int attempt = 0; attempt < 12 && !chosen; ++attempt, h *= 0.25) {
    for (const double sign : {1.0, -1.0}) {
      const Eigen::VectorXd d = sign * other;
      Corrected c = correct(u_star, d, h);
      if (!c.ok || c.moved > o_.max_predictor_distance * h) continue;
      if ((side_of(c) > 0.0) == (o_.branch_side > 0)) {
        chosen = std::move(c);
        direction = d;
        break;
      }
    }
  }
  if (!chosen) return false;
  // Still next to the bifurcation, where the residual is divided by a small singular value (and
  // the tangent with it): to the noise floor first.
  chosen = polish(*chosen);
  h = (scaled(chosen->z, chosen->lambda) - u_star).norm();
  switch_distance_ = h;
  // Now on the other branch: continue away from the bifurcation, oriented by continuity.
  ++branch_;
  const Tangent tn = tangent_at(chosen->nw.last, scale_, direction, 0);
  z_ = chosen->z;
  lambda_ = chosen->lambda;
  eval_ = chosen->nw.last;
  t_ = tn.t;
  orientation_ = tn.orientation;
  det_ = normalized_determinant(eval_.jacobian, scale_);
  arclength_ += h;
  quiet_until_ = 0.0;
  path_.switched_branch = true;
  path_.special_points[index_of_special].switched = true;
  path_.lambda_reached = std::max(path_.lambda_reached, lambda_);
  if (o_.record_path) {
    record(make_point(eval_, z_, lambda_, h, chosen->nw.iterations, PathStatus::kAccepted),
           arclength_);
  }
  return true;
}

LoadPath PathTracer::run(const Eigen::VectorXd* start) {
  min_step_ = o_.min_step;
  z_ = start != nullptr ? *start : problem_.unloaded_unknowns();
  lambda_ = 0.0;
  path_.z = z_;
  path_.tip = problem_.chain().unloaded_tip();
  path_.tip_state.x = path_.tip.x;
  path_.tip_state.y = path_.tip.y;
  path_.tip_state.theta = path_.tip.theta;

  if (!problem_.evaluate(z_, lambda_, true, true, integrator_, eval_)) {
    path_.message = "integration of the unloaded chain failed: " + eval_.error;
    return path_;
  }
  path_.tip_state = eval_.tip;
  path_.tip = ChainPose{eval_.tip.x, eval_.tip.y, eval_.tip.theta};
  if (singular_jacobian(eval_)) {
    path_.singular_start = true;
    path_.message =
        "the linearised problem is singular at zero load (a bifurcation: e.g. a prescribed change "
        "of the end-to-end distance of a straight inextensible chain needs buckling); the path "
        "cannot start";
    return path_;
  }
  // Scale the unknowns by their linear-theory rate so that one unit of scaled arclength is about
  // one unit of load factor at the start.
  const Eigen::VectorXd z_rate = robust_solve(eval_.jacobian, -eval_.d_lambda);
  scale_ = z_rate.cwiseAbs().cwiseMax(1.0);
  Eigen::VectorXd along_lambda = Eigen::VectorXd::Zero(nz_ + 1);
  along_lambda[nz_] = 1.0;
  const Tangent start_tangent = tangent_at(eval_, scale_, along_lambda, 0);
  t_ = start_tangent.t;
  // The path keeps this orientation (see tangent_at); lambda increases at the start.
  orientation_ = start_tangent.orientation;
  det_ = normalized_determinant(eval_.jacobian, scale_);
  if (o_.record_path) {
    record(make_point(eval_, z_, lambda_, 0.0, 0, PathStatus::kStart), 0.0);
  }

  // Under a large load the linear-theory tangent is a poor predictor beyond a load factor of about
  // 1/sqrt(F) (the boundary layer of the elastica has width 1/sqrt(F)); a first step of that size
  // lets the step control grow from there instead of burning the budget on failed correctors.
  double ds = std::min(o_.initial_step, o_.max_step);
  const double contraction = unique_equilibrium_bound(problem_.chain());
  if (std::isfinite(contraction) && contraction > 1.0) {
    ds = std::min(ds, 1.5 / std::sqrt(contraction));
  }
  int attempts = 0;
  int bifurcations_seen = 0;  // located bifurcations, for switch_at_bifurcation
  const long integrator_start = integrator_.steps_taken();
  // The work of one evaluation grows with the multiple-shooting intervals (about sqrt(F)/2.5 of
  // them): the budget grows with them, so that large loads can be reached while a failure still
  // comes within seconds (about 8 s at |F| l^2/EI = 1e4, 41 intervals).
  const long integrator_budget =
      o_.max_integrator_steps * std::max(1L, static_cast<long>(problem_.interval_count()) / 16);
  bool out_of_budget = false;
  auto reject = [&](double shorter) {
    ++path_.rejected_steps;
    ds = shorter;
    return ds >= min_step_;
  };
  while (attempts < o_.max_steps) {
    ++attempts;
    if (integrator_.steps_taken() - integrator_start > integrator_budget) {
      out_of_budget = true;
      break;
    }
    // Point density: no step changes the load factor by more than max_load_step.
    if (o_.max_load_step > 0.0 && std::abs(t_[nz_]) > 0.0) {
      ds = std::min(ds, o_.max_load_step / std::abs(t_[nz_]));
    }
    u_ = scaled(z_, lambda_);
    const Eigen::VectorXd pred = u_ + ds * t_;

    // Landing on lambda = 1 when the predictor crosses it (or stops just short of it: a step
    // capped by max_load_step lands on 1 up to rounding).
    if (pred[nz_] >= 1.0 - 1e-9 && t_[nz_] > 0.0) {
      const double h = (1.0 - lambda_) / t_[nz_];
      const Eigen::VectorXd start_end = u_ + h * t_;
      Eigen::VectorXd z_end = start_end.head(nz_).cwiseProduct(scale_);
      double lambda_end = 1.0;
      NewtonOutcome nw = newton_solve(problem_, integrator_, newton_, z_end, lambda_end, nullptr);
      path_.newton_iterations += nw.iterations;
      const double moved = (scaled(z_end, 1.0) - start_end).norm();
      // The landing point must lie on this branch, reached with lambda still increasing (the
      // fixed-lambda corrector does not compute dg/dlambda, so evaluate once more). A fold or a
      // bifurcation inside the landing step flips the tangent: then the step is shortened until
      // an ordinary step passes it, where it is located.
      ShootingEvaluation at_end;
      const bool same_branch =
          nw.converged() && problem_.evaluate(z_end, 1.0, true, true, integrator_, at_end) &&
          tangent_at(at_end, scale_, t_, orientation_).t.dot(t_) >= std::cos(o_.max_turn);
      if (same_branch && moved <= o_.max_predictor_distance * std::max(h, o_.min_step)) {
        z_ = z_end;
        lambda_ = 1.0;
        ++path_.steps;
        path_.z = z_;
        path_.lambda = 1.0;
        path_.lambda_reached = 1.0;
        path_.residual = nw.residual;
        path_.tip = ChainPose{nw.last.tip.x, nw.last.tip.y, nw.last.tip.theta};
        path_.tip_state = nw.last.tip;
        path_.set_converged(true);
        path_.jacobian_sign = jacobian_sign(at_end);
        if (o_.record_path) {
          record(make_point(nw.last, z_, 1.0, h, nw.iterations, PathStatus::kEnd), arclength_ + h);
        }
        path_.message =
            fmt::format("reached load factor 1 in {} steps ({} rejected, {} limit points{} passed)",
                        path_.steps,
                        path_.rejected_steps,
                        path_.limit_points,
                        path_.bifurcation_points > 0
                            ? fmt::format(", {} bifurcation points", path_.bifurcation_points)
                            : std::string());
        return path_;
      }
      if (!reject(0.5 * std::min(ds, h))) break;
      continue;
    }

    Corrected c = correct(u_, t_, ds);
    if (!c.ok || c.moved > o_.max_predictor_distance * ds) {
      if (!reject(0.5 * ds)) break;
      continue;
    }
    if (c.lambda > 1.0) {
      // Overshot lambda = 1 during the correction: shorten so that the predictor lands before it.
      if (!reject(0.5 * ds)) break;
      continue;
    }
    if (o_.max_load_step > 0.0 && std::abs(c.lambda - lambda_) > o_.max_load_step) {
      // The corrector moved lambda past the cap (the predictor keeps to it): shorten in
      // proportion, with a margin.
      if (!reject(0.95 * ds * o_.max_load_step / std::abs(c.lambda - lambda_))) break;
      continue;
    }
    // The tangent by continuity: a turn beyond max_turn is a corrector on another branch.
    const Tangent tn = tangent_at(c.nw.last, scale_, t_, 0);
    if (tn.t.dot(t_) < std::cos(o_.max_turn)) {
      if (!reject(0.5 * ds)) break;
      continue;
    }
    const bool fold = tn.t[nz_] * t_[nz_] < 0.0;
    const bool flipped = tn.orientation != 0 && orientation_ != 0 && tn.orientation != orientation_;
    if (fold && flipped) {
      // Two special points (or a landing on another branch) in one step: separate them.
      if (!reject(0.5 * ds)) break;
      continue;
    }
    std::optional<Bifurcation> bifurcation;
    if (flipped) {
      // The orientation flipped while lambda kept its direction: det(dg/dz) changed sign, so
      // either the path crossed a bifurcation point or the corrector landed on another branch.
      // A located singular point through which this step's end continues the path is a
      // crossing; anything else is a jump, retried with a shorter step.
      Bifurcation b;
      if (o_.locate_special_points) b = locate_bifurcation(ds, c);
      if (!b.verified && ds > o_.bifurcation_step) {
        if (!reject(0.5 * ds)) break;
        continue;
      }
      bifurcation = std::move(b);
    }
    // Accepted.
    const double step_start = arclength_;
    if (bifurcation && bifurcation->verified) {
      // The points on either side of a bifurcation: to the noise floor (see polish()).
      c = polish(c);
      if (o_.record_path && !path_.points.empty() && arclength_of_.back() == step_start &&
          path_.points.back().status == PathStatus::kAccepted) {
        const Corrected before = polish(current_as_corrected());
        PathPoint& p = path_.points.back();
        p = make_point(before.nw.last, before.z, lambda_, p.step, p.iterations, p.status);
      }
    }
    if (bifurcation) {
      ++bifurcations_seen;
      const bool located = bifurcation->verified;
      if (located) {
        SpecialPoint sp = make_special(SpecialPointKind::kBifurcation, bifurcation->at, true);
        record_special(std::move(sp), bifurcation->at, step_start + bifurcation->h, bifurcation->h);
      } else {
        // A persistent flip at a step too short to locate: a crossing somewhere in this step.
        SpecialPoint sp = make_special(SpecialPointKind::kBifurcation, c, false);
        record_special(std::move(sp), c, step_start + ds, ds);
      }
      if (located && o_.switch_at_bifurcation == bifurcations_seen) {
        arclength_ = step_start + bifurcation->h;
        if (switch_branch(*bifurcation, static_cast<int>(path_.special_points.size()) - 1, ds)) {
          ++path_.steps;
          path_.z = z_;
          path_.lambda = lambda_;
          path_.tip = ChainPose{eval_.tip.x, eval_.tip.y, eval_.tip.theta};
          path_.tip_state = eval_.tip;
          // The new branch's own scale is the distance of its first point: the first step on it
          // is at most a few times that, and the path gives up only at steps 1e-3 of it (a
          // pitchfork on the clamped-clamped beam's second stage bends to the load factor within
          // 1e-7 of the bifurcation, where min_step = 1e-7 stopped it: issue 27).
          ds = std::min({ds, 2.0 * o_.branch_switch_step, 4.0 * switch_distance_});
          min_step_ = std::min(min_step_, 1e-3 * switch_distance_);
          continue;
        }
        path_.message = fmt::format(
            "no corrector landed on the other branch at the bifurcation at load factor {:.9g}",
            bifurcation->at.lambda);
        path_.z = bifurcation->at.z;
        path_.lambda = bifurcation->at.lambda;
        return path_;
      }
      orientation_ = tn.orientation;
    }
    PathStatus status = PathStatus::kAccepted;
    if (fold) {
      std::optional<std::pair<double, Corrected>> at;
      if (o_.locate_special_points) at = locate_fold(ds, c);
      if (at) {
        SpecialPoint sp = make_special(SpecialPointKind::kLimitPoint, at->second, true);
        record_special(std::move(sp), at->second, step_start + at->first, at->first);
      } else {
        // Not located: the point after the fold is marked, lambda is the larger end.
        SpecialPoint sp = make_special(SpecialPointKind::kLimitPoint, c, false);
        sp.lambda = t_[nz_] > 0.0 ? std::max(lambda_, c.lambda) : std::min(lambda_, c.lambda);
        record_special(std::move(sp), c, step_start + ds, ds);
        status = PathStatus::kLimitPoint;
        if (o_.record_path) {
          path_.special_points.back().index = static_cast<int>(path_.points.size());
        }
      }
    }
    const double t_before_lambda = t_[nz_];
    const double step_length = ds;
    arclength_ = step_start + ds;
    z_ = c.z;
    lambda_ = c.lambda;
    eval_ = c.nw.last;
    t_ = tn.t;
    det_ = normalized_determinant(eval_.jacobian, scale_);
    ++path_.steps;
    path_.z = z_;
    path_.lambda = lambda_;
    path_.residual = c.nw.residual;
    path_.tip = ChainPose{eval_.tip.x, eval_.tip.y, eval_.tip.theta};
    path_.tip_state = eval_.tip;
    path_.lambda_reached = std::max(path_.lambda_reached, lambda_);
    if (o_.record_path && (arclength_ >= quiet_until_ || status != PathStatus::kAccepted)) {
      record(make_point(eval_, z_, lambda_, ds, c.nw.iterations, status), arclength_);
    }
    if (lambda_ < -1e-12 && t_[nz_] < 0.0) {
      path_.message = fmt::format(
          "the load path turned back below zero load (lambda = {:.6g}) after reaching {:.6g}",
          lambda_,
          path_.lambda_reached);
      return path_;
    }
    if (c.nw.iterations <= o_.easy_iterations) {
      ds = std::min(ds * o_.growth, o_.max_step);
    } else if (c.nw.iterations > 2 * o_.easy_iterations) {
      ds *= 0.7;
    }
    const double level_rate = (t_[nz_] - t_before_lambda) / step_length;
    if (t_[nz_] * level_rate < 0.0) {
      ds = std::min(
          ds, std::max(o_.level_fraction * std::abs(t_[nz_] / level_rate), o_.level_min_step));
    }
  }
  path_.message = fmt::format(
      "continuation stopped at load factor {:.9g} (largest reached {:.9g}) after {} accepted and "
      "{} "
      "rejected steps: {}",
      lambda_,
      path_.lambda_reached,
      path_.steps,
      path_.rejected_steps,
      out_of_budget ? "integration budget exhausted (the reactions grow without bound?)"
      : attempts >= o_.max_steps ? "step budget exhausted (the path approaches an asymptote?)"
                                 : "step size fell below min_step");
  return path_;
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

double normalized_determinant(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& scale) {
  Eigen::MatrixXd A = jacobian * scale.asDiagonal();
  for (Eigen::Index i = 0; i < A.rows(); ++i) {
    const double norm = A.row(i).norm();
    if (!(norm > 0.0)) return 0.0;
    A.row(i) /= norm;
  }
  return A.partialPivLu().determinant();
}

bool shape_with_moments(const ShootingProblem& problem,
                        ElasticaIntegrator& integrator,
                        const Eigen::VectorXd& z,
                        double lambda,
                        const std::vector<double>& s,
                        std::vector<ShapePoint>& shape,
                        std::vector<double>& moment,
                        std::string& error) {
  const SegmentChain& chain = problem.chain();
  if (chain.has_distributed_loads()) {
    // N varies along the segments: the moment is the integrated state (docs/distributed-loads.md).
    TipState tip;
    std::vector<double> moments;
    shape.clear();
    integrator.set_shape_moments(&moments);
    const bool ok = problem.integrate_solution(z, lambda, integrator, tip, error, &s, &shape);
    integrator.set_shape_moments(nullptr);
    if (!ok) return false;
    if (shape.size() != s.size() || moments.size() != s.size()) {
      error = "the shape integration returned fewer points than asked for";
      return false;
    }
    moment = std::move(moments);
    return true;
  }
  const ChainForces f = problem.forces(z, lambda);
  const int n = chain.segment_count();
  // Arc length of every node 1..n-1 where the internal force or the moment changes.
  std::vector<double> node_s(n + 1, 0.0);
  for (int j = 0; j < n; ++j) {
    node_s[j + 1] =
        node_s[j] + std::visit([](const auto& seg) { return seg.length; }, chain.segments[j]);
  }
  std::vector<int> jumps;  // nodes with a force or moment change
  for (int k = 1; k < n; ++k) {
    if ((f.N[k] - f.N[k - 1]).norm() > 0.0 || f.moment_drop[k] != 0.0) jumps.push_back(k);
  }
  // Sample the requested points and the nodes with a force change in one integration.
  std::vector<double> all = s;
  for (int k : jumps) all.push_back(node_s[k]);
  std::sort(all.begin(), all.end());
  TipState tip;
  std::vector<ShapePoint> sampled;
  if (!problem.integrate_solution(z, lambda, integrator, tip, error, &all, &sampled)) return false;
  if (sampled.size() != all.size()) {
    error = "the shape integration returned fewer points than asked for";
    return false;
  }
  auto position_at = [&](double arc) {
    const auto it = std::lower_bound(all.begin(), all.end(), arc);
    return sampled[static_cast<std::size_t>(it - all.begin())];
  };
  std::vector<ShapePoint> node_pose;
  for (int k : jumps) node_pose.push_back(position_at(node_s[k]));
  shape.clear();
  moment.clear();
  for (double arc : s) {
    const ShapePoint p = position_at(arc);
    // m(s) = m(0) + integral of (N_x sin theta - N_y cos theta): N(0) x r(s) from the root, and
    // for every node k before s the change of N (and the moment drop) from there on.
    double m = f.m0 + f.N[0].x() * p.y - f.N[0].y() * p.x;
    for (std::size_t i = 0; i < jumps.size(); ++i) {
      const int k = jumps[i];
      if (!(node_s[k] < arc)) continue;
      const Eigen::Vector2d dN = f.N[k] - f.N[k - 1];
      m += dN.x() * (p.y - node_pose[i].y) - dN.y() * (p.x - node_pose[i].x) - f.moment_drop[k];
    }
    shape.push_back(p);
    moment.push_back(m);
  }
  return true;
}

LoadPath continue_load_path(const ShootingProblem& problem,
                            ElasticaIntegrator& integrator,
                            const ContinuationOptions& options,
                            const NewtonOptions& newton,
                            const Eigen::VectorXd* start) {
  const long before = integrator.steps_taken();
  PathTracer tracer(problem, integrator, options, newton);
  LoadPath path = tracer.run(start);
  path.integrator_steps = integrator.steps_taken() - before;
  return path;
}

}  // namespace flexure
