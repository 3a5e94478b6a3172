#include "flexure/mechanisms/cfm/power_law_fit.h"

#include <fmt/format.h>

#include <cmath>
#include <vector>

#include "flexure/mechanisms/cfm/slider_crank.h"
#include "flexure/solver/common/status.h"

namespace flexure::cfm {
namespace {

// The rotation of pivot p (1..3) at a stroke point (slider_crank.h: psi1, psi2, psi3).
double rotation(int p, double theta2, double theta3) {
  return p == 1 ? theta2 : (p == 2 ? theta2 - theta3 : -theta3);
}

// Straight line through (ln d, ln alpha): ln alpha = ln M + n ln d.
StressPowerLaw loglog_line(const std::vector<double>& d, const std::vector<double>& alpha) {
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  int m = 0;
  for (std::size_t k = 0; k < d.size(); ++k) {
    if (!(d[k] > 0.0 && alpha[k] > 0.0)) continue;
    const double x = std::log(d[k]), y = std::log(alpha[k]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
    ++m;
  }
  if (m < 2) throw InvalidInput("the power-law fit needs two stroke points with alpha_p > 0");
  StressPowerLaw f;
  f.n = (m * sxy - sx * sy) / (m * sxx - sx * sx);
  f.M = std::exp((sy - f.n * sx) / m);
  f.points = m;
  return f;
}

double rms(const StressPowerLaw& f, const std::vector<double>& d, const std::vector<double>& a) {
  double s = 0.0;
  for (std::size_t k = 0; k < d.size(); ++k) {
    const double r = f.M * std::pow(d[k], f.n) - a[k];
    s += r * r;
  }
  return std::sqrt(s / static_cast<double>(d.size()));
}

}  // namespace

StressPowerLaw fit_stress_power_law(const CfmParameters& parameters, const CfmOptions& options) {
  CfmOptions o = options;
  o.keep_curve = true;
  const CfmResult r = CfmModel(o).evaluate(parameters);
  if (!r.converged()) throw NoConvergence("power-law fit: " + r.message);
  const int p = r.primary_pivot;
  std::vector<double> d, alpha;
  d.reserve(r.curve.size());
  alpha.reserve(r.curve.size());
  for (const CfmCurvePoint& c : r.curve) {
    d.push_back(c.stroke_percent);
    alpha.push_back(r.kappa[p - 1] * rotation(p, c.theta2, c.theta3));
  }
  // Gauss-Newton with Levenberg-Marquardt damping on the residuals M d^n - alpha (what the thesis
  // code's lsqcurvefit minimises), from the log-log line, which is close: the residuals are small
  // and the problem is well conditioned (two columns d^n and M d^n ln d).
  StressPowerLaw f = loglog_line(d, alpha);
  double mu = 1e-3;
  double cost = rms(f, d, alpha);
  bool settled = false;
  for (int it = 0; it < 200 && !settled; ++it) {
    double a11 = 0.0, a12 = 0.0, a22 = 0.0, g1 = 0.0, g2 = 0.0;
    for (std::size_t k = 0; k < d.size(); ++k) {
      const double dn = std::pow(d[k], f.n);
      const double res = f.M * dn - alpha[k];
      const double j1 = dn, j2 = f.M * dn * std::log(d[k]);
      a11 += j1 * j1, a12 += j1 * j2, a22 += j2 * j2;
      g1 += j1 * res, g2 += j2 * res;
    }
    for (int tries = 0; tries < 30; ++tries) {
      const double b11 = a11 * (1.0 + mu), b22 = a22 * (1.0 + mu);
      const double det = b11 * b22 - a12 * a12;
      const double dM = -(b22 * g1 - a12 * g2) / det;
      const double dn = -(b11 * g2 - a12 * g1) / det;
      StressPowerLaw trial = f;
      trial.M += dM;
      trial.n += dn;
      const double c = rms(trial, d, alpha);
      if (std::isfinite(c) && c <= cost) {
        settled = std::abs(dM) <= 1e-13 * std::abs(f.M) && std::abs(dn) <= 1e-13;
        settled = settled || cost - c <= 1e-15 * cost;
        f = trial;
        cost = c;
        mu = std::max(mu * 0.1, 1e-12);
        break;
      }
      mu *= 10.0;
      if (tries == 29) settled = true;  // no descent left: at the minimum to rounding
    }
  }
  if (!settled) {
    throw NoConvergence(fmt::format(
        "power-law fit of {} (R = {}) did not settle in 200 iterations", r.config, r.R));
  }
  f.primary_pivot = p;
  f.rms_residual = cost;
  f.points = static_cast<int>(d.size());
  return f;
}

StressPowerLaw fit_stress_power_law_loglog(const CfmParameters& parameters) {
  const CfmResult end = CfmModel().evaluate(parameters);
  const int p = end.primary_pivot;
  const int last = static_cast<int>(std::floor(end.stroke_percent));
  if (last < 2) {
    throw InvalidInput(
        fmt::format("the log-log power-law fit needs a stroke of at least 2 % (got {:g} %)",
                    end.stroke_percent));
  }
  std::vector<double> d, alpha;
  for (int k = 1; k <= last; ++k) {
    const SliderCrankPose pose = slider_crank_pose(parameters.R, k / 100.0);
    d.push_back(k);
    alpha.push_back(end.kappa[p - 1] * rotation(p, pose.theta2, pose.theta3));
  }
  StressPowerLaw f = loglog_line(d, alpha);
  f.primary_pivot = p;
  f.rms_residual = rms(f, d, alpha);
  return f;
}

}  // namespace flexure::cfm
