#include "flexure/mechanisms/general/arclength_path.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace flexure::mechanism::general {

using Eigen::MatrixXd;
using Eigen::VectorXd;

ArclengthPath::ArclengthPath(ArclengthCurve curve, ArclengthSettings settings)
    : c_(std::move(curve)), o_(settings) {}

bool ArclengthPath::newton_fixed(VectorXd& y, int fixed) {
  const int n = c_.size - 1;
  for (int it = 0; it <= o_.max_newton_iterations; ++it) {
    VectorXd F;
    if (!c_.residual(y, F)) return false;
    const double r = F.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(r)) return false;
    if (r < o_.tolerance) {
      worst_ = std::max(worst_, r);
      return true;
    }
    MatrixXd J;
    if (!c_.jacobian(y, J)) return false;
    ++iterations_;
    MatrixXd Js(n, n);
    Js << J.leftCols(fixed), J.rightCols(n - fixed);
    const VectorXd dx = Js.fullPivLu().solve(-F);
    if (!dx.allFinite()) return false;
    for (int i = 0, k = 0; i <= n; ++i) {
      if (i != fixed) y[i] += dx[k++];
    }
  }
  return false;
}

bool ArclengthPath::tangent(const VectorXd& y, const VectorXd& orient, VectorXd& t) {
  const int n = c_.size - 1;
  MatrixXd J;
  if (!c_.jacobian(y, J)) return false;
  MatrixXd M(n + 1, n + 1);
  M.topRows(n) = J;
  M.row(n) = orient.cwiseProduct(c_.weight).transpose();
  VectorXd rhs = VectorXd::Zero(n + 1);
  rhs[n] = 1.0;
  t = M.fullPivLu().solve(rhs);
  const double norm = t.cwiseProduct(c_.weight).norm();
  if (!t.allFinite() || !(norm > 0.0)) return false;
  t /= norm;
  if (t.cwiseProduct(c_.weight).dot(orient) < 0.0) t = -t;
  return true;
}

int ArclengthPath::corrector(VectorXd& y, const VectorXd& base, const VectorXd& t, double h) {
  const int n = c_.size - 1;
  const VectorXd tw = t.cwiseProduct(c_.weight);
  for (int it = 0; it <= o_.max_newton_iterations; ++it) {
    VectorXd F;
    if (!c_.residual(y, F)) return -1;
    VectorXd f(n + 1);
    f.head(n) = F;
    f[n] = tw.dot(y - base) - h;
    const double r = f.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(r)) return -1;
    if (r < o_.tolerance) return it;
    MatrixXd J;
    if (!c_.jacobian(y, J)) return -1;
    ++iterations_;
    MatrixXd M(n + 1, n + 1);
    M.topRows(n) = J;
    M.row(n) = tw.transpose();
    const VectorXd dx = M.fullPivLu().solve(-f);
    if (!dx.allFinite()) return -1;
    y += dx;
  }
  return -1;
}

Termination ArclengthPath::follow(VectorXd& yc, double target, const Follow& how) {
  const int p = how.controlled;
  const bool recording = how.grid != nullptr;
  VectorXd orient = VectorXd::Zero(c_.size);
  orient[p] = target >= yc[p] ? 1.0 : -1.0;
  VectorXd t;
  if (!tangent(yc, orient, t)) return Termination::kNoConvergence;
  double h = o_.max_step;
  if (recording) dense_.push_back(yc);
  while (steps_ < o_.max_steps) {
    VectorXd yn = yc + h * t;
    const int its = corrector(yn, yc, t, h);
    VectorXd tn;
    const bool ok = its >= 0 && tangent(yn, t, tn) &&
                    t.cwiseProduct(c_.weight).dot(tn.cwiseProduct(c_.weight)) > 0.9;
    if (!ok) {
      h *= 0.5;
      if (h < 1e-10) return Termination::kNoConvergence;
      continue;
    }
    ++steps_;
    if (t[p] * tn[p] < 0.0) {
      // A limit point of the controlled component inside this step: bisect the arclength on the
      // sign of the tangent's component along it.
      double lo = 0.0, hi = h;
      VectorXd yl = yn;
      for (int k = 0; k < 60 && hi - lo > 1e-13; ++k) {
        const double mid = 0.5 * (lo + hi);
        VectorXd ym = yc + mid * t;
        VectorXd tm;
        if (corrector(ym, yc, t, mid) < 0 || !tangent(ym, t, tm)) break;
        (tm[p] * t[p] > 0.0 ? lo : hi) = mid;
        yl = ym;
      }
      if (how.limit) how.limit(yl);
    }
    // Grid values (and the target) crossed by this step, in the order of travel.
    const double from = yc[p], to = yn[p];
    auto crossed = [&](double v) { return (v - from) * (v - to) <= 0.0 && v != from; };
    auto solve_at = [&](double v, VectorXd& out) {
      out = yc + ((v - from) / (to - from)) * (yn - yc);
      out[p] = v;
      return newton_fixed(out, p);
    };
    if (recording) {
      std::vector<double> hits;
      for (double v : *how.grid) {
        if (crossed(v)) hits.push_back(v);
      }
      std::sort(
          hits.begin(), hits.end(), [&](double a, double b) { return to > from ? a < b : a > b; });
      for (double v : hits) {
        VectorXd yg;
        if (!solve_at(v, yg)) return Termination::kNoConvergence;
        how.record(yg);
      }
      dense_.push_back(yn);
      if (how.give_up && how.give_up()) return Termination::kLimitPoint;
    }
    if (crossed(target)) {
      VectorXd yt;
      if (!solve_at(target, yt)) return Termination::kNoConvergence;
      yc = yt;
      return Termination::kConverged;
    }
    yc = yn;
    t = tn;
    if (its <= 3) h = std::min(1.5 * h, o_.max_step);
  }
  return Termination::kLimitPoint;
}

std::vector<VectorXd> ArclengthPath::zeros_along(int index, std::vector<VectorXd>* failed) {
  std::vector<VectorXd> zeros;
  for (std::size_t i = 0; i + 1 < dense_.size(); ++i) {
    const double l0 = dense_[i][index], l1 = dense_[i + 1][index];
    if (!(l0 * l1 <= 0.0)) continue;
    VectorXd y =
        l0 == l1 ? dense_[i] : VectorXd(dense_[i] + (l0 / (l0 - l1)) * (dense_[i + 1] - dense_[i]));
    y[index] = 0.0;
    if (newton_fixed(y, index)) {
      zeros.push_back(std::move(y));
    } else if (failed != nullptr) {
      failed->push_back(dense_[i]);
    }
  }
  return zeros;
}

}  // namespace flexure::mechanism::general
