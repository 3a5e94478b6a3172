#include "flexure/solver/chain/chain_fixed_point.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace flexure {

namespace {

// Geometry <-> scaled state vector (x/l, y/l, theta at nodes 1..E) for the least-squares step.
void pack(const ChainGeometry& g, double l, Eigen::VectorXd& v) {
  const int E = static_cast<int>(g.x.size()) - 1;
  v.resize(3 * E);
  for (int i = 0; i < E; ++i) {
    v[3 * i] = g.x[i + 1] / l;
    v[3 * i + 1] = g.y[i + 1] / l;
    v[3 * i + 2] = g.theta[i + 1];
  }
}

void unpack(const Eigen::VectorXd& v, double l, ChainGeometry& g) {
  const int E = static_cast<int>(v.size()) / 3;
  g.x.assign(E + 1, 0.0);
  g.y.assign(E + 1, 0.0);
  g.theta.assign(E + 1, 0.0);
  for (int i = 0; i < E; ++i) {
    g.x[i + 1] = v[3 * i] * l;
    g.y[i + 1] = v[3 * i + 1] * l;
    g.theta[i + 1] = v[3 * i + 2];
  }
}

double scaled_change(const ChainPassReport& r, double l) {
  return std::max(r.position_change / l, r.angle_change);
}

FixedPointReport plain_passes(const ChainDiscretisation& d,
                              const ChainNodeLoads& loads,
                              ChainGeometry& geometry,
                              const FixedPointOptions& options) {
  FixedPointReport report;
  ChainGeometry next;
  while (report.passes < options.max_passes) {
    const ChainPassReport r = chain_pass(d, loads, geometry, options.pass, next);
    ++report.passes;
    if (!r.ok) {
      report.failed_element = r.failed_element;
      return report;
    }
    report.change = scaled_change(r, options.length_scale);
    std::swap(geometry, next);
    if (!std::isfinite(report.change)) return report;
    if (report.change < options.tolerance) {
      report.set_converged(true);
      return report;
    }
  }
  return report;
}

}  // namespace

FixedPointReport converge_chain(const ChainDiscretisation& d,
                                const ChainNodeLoads& loads,
                                ChainGeometry& geometry,
                                const FixedPointOptions& options) {
  if (options.anderson_depth <= 0) return plain_passes(d, loads, geometry, options);

  // Anderson acceleration, type II (Walker & Ni 2011): x+ = G(x) - dG * gamma with gamma the
  // least-squares fit of the residual f = G(x) - x by the last m residual differences dF.
  const double l = options.length_scale;
  const int m = options.anderson_depth;
  FixedPointReport report;
  ChainGeometry image;
  Eigen::VectorXd x, g, f, f_prev, g_prev;
  pack(geometry, l, x);
  const int n = static_cast<int>(x.size());
  Eigen::MatrixXd dF(n, m), dG(n, m);
  int stored = 0;  // columns in use
  int head = 0;    // next column to overwrite
  bool have_prev = false;
  double best = INFINITY;
  while (report.passes < options.max_passes) {
    const ChainPassReport r = chain_pass(d, loads, geometry, options.pass, image);
    ++report.passes;
    if (!r.ok) {
      if (!have_prev) {
        report.failed_element = r.failed_element;
        return report;
      }
      // The extrapolated geometry buckled an element: restart from the last plain image.
      unpack(g_prev, l, geometry);
      x = g_prev;
      stored = 0;
      head = 0;
      have_prev = false;
      continue;
    }
    pack(image, l, g);
    f = g - x;
    report.change = f.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(report.change)) return report;
    if (report.change < options.tolerance) {
      geometry = image;
      report.set_converged(true);
      return report;
    }
    // Restart the history when the residual grows a lot: the extrapolation has lost its way.
    const double kRestartGrowth = 1e3;
    if (report.change > kRestartGrowth * best) {
      stored = 0;
      head = 0;
      have_prev = false;
    }
    best = std::min(best, report.change);
    if (have_prev) {
      dF.col(head) = f - f_prev;
      dG.col(head) = g - g_prev;
      head = (head + 1) % m;
      stored = std::min(stored + 1, m);
    }
    f_prev = f;
    g_prev = g;
    have_prev = true;
    x = g;
    if (stored > 0) {
      // Normal equations of the m-column fit (m <= 50, so m x m is cheap); a relative Tikhonov
      // term keeps them solvable when the columns become nearly dependent close to convergence.
      Eigen::MatrixXd gram = dF.leftCols(stored).transpose() * dF.leftCols(stored);
      const double kRidge = 1e-12;
      gram.diagonal().array() += kRidge * gram.diagonal().maxCoeff() + 1e-300;
      const Eigen::VectorXd gamma = gram.ldlt().solve(dF.leftCols(stored).transpose() * f);
      if (gamma.allFinite()) x.noalias() -= dG.leftCols(stored) * gamma;
    }
    unpack(x, l, geometry);
  }
  // Out of passes: return the last plain image, which is a consistent chain geometry.
  if (have_prev) unpack(g_prev, l, geometry);
  return report;
}

}  // namespace flexure
