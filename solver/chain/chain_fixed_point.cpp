#include "flexure/solver/chain/chain_fixed_point.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "flexure/solver/chain/anderson_mixing.h"

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

  // Anderson acceleration (anderson_mixing.h) of the passes.
  const double l = options.length_scale;
  FixedPointReport report;
  ChainGeometry image;
  Eigen::VectorXd x, g, f;
  pack(geometry, l, x);
  AndersonMixing mixing(x.size(), options.anderson_depth);
  double best = INFINITY;
  while (report.passes < options.max_passes) {
    const ChainPassReport r = chain_pass(d, loads, geometry, options.pass, image);
    ++report.passes;
    if (!r.ok) {
      if (!mixing.has_previous()) {
        report.failed_element = r.failed_element;
        return report;
      }
      // The extrapolated geometry buckled an element: restart from the last plain image.
      x = mixing.previous_image();
      unpack(x, l, geometry);
      mixing.restart();
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
    if (report.change > kRestartGrowth * best) mixing.restart();
    best = std::min(best, report.change);
    x = mixing.next(g, f);
    unpack(x, l, geometry);
  }
  // Out of passes: return the last plain image, which is a consistent chain geometry.
  if (mixing.has_previous()) unpack(mixing.previous_image(), l, geometry);
  return report;
}

}  // namespace flexure
