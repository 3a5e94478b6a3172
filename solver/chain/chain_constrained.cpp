#include "flexure/solver/chain/chain_constrained.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <deque>

#include "flexure/solver/chain/anderson_mixing.h"

namespace flexure {

namespace {

// Scaled state: x/l, y/l, theta at nodes 1..E, then z_k / scale_k for each unknown.
void pack(const ChainGeometry& g,
          const Eigen::Vector3d& z,
          const ConstrainedTip& tip,
          double l,
          Eigen::VectorXd& v) {
  const int E = static_cast<int>(g.x.size()) - 1;
  const int n = static_cast<int>(tip.unknowns.size());
  v.resize(3 * E + n);
  for (int i = 0; i < E; ++i) {
    v[3 * i] = g.x[i + 1] / l;
    v[3 * i + 1] = g.y[i + 1] / l;
    v[3 * i + 2] = g.theta[i + 1];
  }
  for (int k = 0; k < n; ++k) {
    const int c = tip.unknowns[k];
    v[3 * E + k] = z[c] / tip.unknown_scale[c];
  }
}

void unpack(const Eigen::VectorXd& v,
            const ConstrainedTip& tip,
            double l,
            ChainGeometry& g,
            Eigen::Vector3d& z) {
  const int n = static_cast<int>(tip.unknowns.size());
  const int E = (static_cast<int>(v.size()) - n) / 3;
  g.x.assign(E + 1, 0.0);
  g.y.assign(E + 1, 0.0);
  g.theta.assign(E + 1, 0.0);
  for (int i = 0; i < E; ++i) {
    g.x[i + 1] = v[3 * i] * l;
    g.y[i + 1] = v[3 * i + 1] * l;
    g.theta[i + 1] = v[3 * i + 2];
  }
  for (int k = 0; k < n; ++k) {
    const int c = tip.unknowns[k];
    z[c] = v[3 * E + k] * tip.unknown_scale[c];
  }
}

// Tip coordinate c of a geometry, scaled as the residual (positions over l, angles).
double tip_coordinate(const ChainGeometry& g, int c, double l) {
  const std::size_t E = g.x.size() - 1;
  return c == 0 ? g.x[E] / l : c == 1 ? g.y[E] / l : g.theta[E];
}

double boundary_residual(const ChainGeometry& g, const ConstrainedTip& tip, double l) {
  double r = 0.0;
  for (int c : tip.unknowns) {
    const double wanted = c == 2 ? tip.wanted[2] : tip.wanted[c] / l;
    r = std::max(r, std::fabs(tip_coordinate(g, c, l) - wanted));
  }
  return r;
}

// One constrained iteration (the header's formulas). Returns false when an element buckled.
struct Step {
  ChainGeometry image;                          // x'
  Eigen::Vector3d z = Eigen::Vector3d::Zero();  // z'
  int failed_element = -1;
  int passes = 0;
};
bool constrained_step(const ChainDiscretisation& d,
                      const ChainNodeLoads& loads,
                      const ConstrainedTip& tip,
                      const ChainGeometry& x,
                      const Eigen::Vector3d& z,
                      const ChainPassOptions& pass,
                      double l,
                      Step& out) {
  const int E = d.element_count();
  const int n = static_cast<int>(tip.unknowns.size());
  ChainNodeLoads with = loads;
  with.fx[E] += z[0];
  with.fy[E] += z[1];
  with.m[E] += z[2];
  ChainGeometry y0;
  ChainPassReport r = chain_pass(d, with, x, pass, y0);
  ++out.passes;
  if (!r.ok) {
    out.failed_element = r.failed_element;
    return false;
  }
  std::vector<ChainGeometry> yk(n);
  std::vector<double> h(n);
  Eigen::MatrixXd J(n, n);
  Eigen::VectorXd residual(n);
  for (int k = 0; k < n; ++k) {
    const int c = tip.unknowns[k];
    h[k] = 1e-6 * std::max(std::fabs(z[c]), tip.unknown_scale[c]);
    ChainNodeLoads moved = with;
    (c == 0 ? moved.fx[E] : c == 1 ? moved.fy[E] : moved.m[E]) += h[k];
    r = chain_pass(d, moved, x, pass, yk[k]);
    ++out.passes;
    if (!r.ok) {
      out.failed_element = r.failed_element;
      return false;
    }
  }
  for (int row = 0; row < n; ++row) {
    const int c = tip.unknowns[row];
    const double t0 = tip_coordinate(y0, c, l);
    residual[row] = (c == 2 ? tip.wanted[2] : tip.wanted[c] / l) - t0;
    for (int k = 0; k < n; ++k) J(row, k) = (tip_coordinate(yk[k], c, l) - t0) / h[k];
  }
  // Minimum-norm least squares, as the Newton step of eq. 7.39 (solve_step): at a straight,
  // inextensible chain the axial reaction does not move the tip at first order.
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
  svd.setThreshold(1e-9);
  const Eigen::VectorXd dz = svd.rank() > 0 ? Eigen::VectorXd(svd.solve(residual))
                                            : Eigen::VectorXd(Eigen::VectorXd::Zero(n));
  out.image = y0;
  out.z = z;
  for (int k = 0; k < n; ++k) {
    const double w = dz[k] / h[k];
    for (int i = 1; i <= E; ++i) {
      out.image.x[i] += w * (yk[k].x[i] - y0.x[i]);
      out.image.y[i] += w * (yk[k].y[i] - y0.y[i]);
      out.image.theta[i] += w * (yk[k].theta[i] - y0.theta[i]);
    }
    out.z[tip.unknowns[k]] += dz[k];
  }
  return true;
}

}  // namespace

ConstrainedReport converge_constrained_chain(const ChainDiscretisation& d,
                                             const ChainNodeLoads& loads,
                                             const ConstrainedTip& tip,
                                             Eigen::Vector3d& z,
                                             ChainGeometry& geometry,
                                             const FixedPointOptions& options) {
  const double l = options.length_scale;
  const int n = static_cast<int>(tip.unknowns.size());
  const int m = std::max(0, options.anderson_depth);
  const int per_iteration = 1 + n;
  ConstrainedReport report;
  Eigen::VectorXd x, g, f;
  pack(geometry, z, tip, l, x);
  AndersonMixing mixing(x.size(), m);
  double best = INFINITY;
  // The best change so far after each iteration: the rate of convergence over a window of them.
  std::deque<double> best_history;
  constexpr int kRateWindow = 25;
  ChainGeometry current = geometry;
  Eigen::Vector3d zc = z;
  Step step;
  while (report.passes + per_iteration <= options.max_passes) {
    step = Step{};
    const bool ok = constrained_step(d, loads, tip, current, zc, options.pass, l, step);
    report.passes += step.passes;
    ++report.iterations;
    if (!ok) {
      if (!mixing.has_previous()) {
        report.failed_element = step.failed_element;
        report.failure =
            fmt::format("element {} buckled (eq. 7.30 has no inverse)", step.failed_element);
        return report;
      }
      // The extrapolated state buckled an element: restart from the last plain image.
      x = mixing.previous_image();
      unpack(x, tip, l, current, zc);
      mixing.restart();
      continue;
    }
    pack(step.image, step.z, tip, l, g);
    f = g - x;
    report.change = f.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(report.change)) {
      report.failure = "the passes produced a non-finite geometry";
      return report;
    }
    report.boundary_residual = boundary_residual(step.image, tip, l);
    if (report.change < options.tolerance && report.boundary_residual <= tip.tolerance) {
      geometry = step.image;
      z = step.z;
      report.set_converged(true);
      return report;
    }
    if (report.change > 1e3 * best) mixing.restart();  // the extrapolation has lost its way
    best = std::min(best, report.change);
    best_history.push_back(best);
    // A budget from the measured rate: over the last kRateWindow iterations the best change fell
    // by `rate` per iteration; when the iterations left cannot reach the tolerance at that rate,
    // more passes would only cost time.
    if (static_cast<int>(best_history.size()) > kRateWindow) {
      const double rate = std::pow(best / best_history.front(), 1.0 / kRateWindow);
      best_history.pop_front();
      const int left = (options.max_passes - report.passes) / per_iteration;
      const double needed =
          rate < 1.0 ? std::log(options.tolerance / best) / std::log(rate) : INFINITY;
      if (report.passes >= 4 * kRateWindow * per_iteration && needed > left) {
        report.rate = rate;
        report.failure =
            rate < 1.0
                ? fmt::format(
                      "the passes converge too slowly: the change fell by a factor {:.4g} per "
                      "iteration over the last {} (now {:.3g}), so the {} passes left cannot "
                      "reach {:.3g}",
                      rate,
                      kRateWindow,
                      best,
                      left * per_iteration,
                      options.tolerance)
                : fmt::format(
                      "the passes stopped converging: no decrease of the change over the last {} "
                      "iterations (it stays at {:.3g}; the tolerance is {:.3g})",
                      kRateWindow,
                      best,
                      options.tolerance);
        break;
      }
    }
    x = mixing.next(g, f);
    unpack(x, tip, l, current, zc);
  }
  if (report.failure.empty()) {
    report.failure = fmt::format(
        "the passes did not converge in {} passes (change {:.3g})", report.passes, report.change);
  }
  // Out of passes: the last plain image, a consistent chain geometry.
  if (mixing.has_previous()) unpack(mixing.previous_image(), tip, l, geometry, z);
  return report;
}

}  // namespace flexure
