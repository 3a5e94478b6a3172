#include "elements/prbm_derivation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "elements/prbm_tables.h"
#include "solver/common/errors.h"
#include "solver/elliptic/elliptic_solver.h"

namespace flexure {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Eq. 5.47 in a cheaper form: the PRB tip lies on the ray from the pivot through the exact tip
// (that is how Theta is defined, eq. 5.42), so the error is the radial distance |r - gamma|.
double fast_relative_error(const PathSample& s, double gamma) {
  return std::abs(std::hypot(s.a - (1.0 - gamma), s.b) - gamma) / std::hypot(1.0 - s.a, s.b);
}

// Theta_max(gamma) from the samples, with the crossing interpolated linearly in Theta between the
// last sample inside the limit and the first outside (the path starts at Theta = 0, error = 0).
struct ThetaMaxOnSamples {
  double theta_max = 0.0;
  int first_violation = -1;  // index of the first sample above the limit, -1 if none
};

ThetaMaxOnSamples theta_max_on_samples(const std::vector<PathSample>& samples,
                                       double gamma,
                                       double limit) {
  ThetaMaxOnSamples out;
  double prev_error = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double error = fast_relative_error(samples[i], gamma);
    if (error > limit) {
      const double prev_theta = i > 0 ? prb_angle(samples[i - 1], gamma) : 0.0;
      const double theta = prb_angle(samples[i], gamma);
      const double f = (limit - prev_error) / (error - prev_error);
      out.theta_max = prev_theta + f * (theta - prev_theta);
      out.first_violation = static_cast<int>(i);
      return out;
    }
    prev_error = error;
  }
  out.theta_max = samples.empty() ? 0.0 : prb_angle(samples.back(), gamma);
  return out;
}

// Grid search of Theta_max(gamma) over [lo, hi]; returns the best gamma (the largest on ties, which
// keeps it on the stable side of a jump found later by bisection).
double best_gamma_on_grid(
    const std::vector<PathSample>& samples, double lo, double hi, double step, double limit) {
  const int count = static_cast<int>(std::ceil((hi - lo) / step));
  double best_gamma = lo;
  double best_theta = -1.0;
  for (int i = 0; i <= count; ++i) {
    const double gamma = std::min(hi, lo + i * step);
    const double theta = theta_max_on_samples(samples, gamma, limit).theta_max;
    if (theta >= best_theta) {
      best_theta = theta;
      best_gamma = gamma;
    }
  }
  return best_gamma;
}

// Least squares through the origin, y = k x, over samples with 0 < Theta <= theta_max.
struct OriginFit {
  double slope = 0.0;
  int count = 0;
};

template <typename Y>
OriginFit fit_through_origin(const std::vector<PathSample>& samples,
                             double gamma,
                             double theta_max,
                             Y y_of) {
  double sxy = 0.0;
  double sxx = 0.0;
  OriginFit fit;
  for (const auto& s : samples) {
    if (!s.in_fit) continue;
    const double theta = prb_angle(s, gamma);
    if (!(theta > 0.0 && theta <= theta_max)) {
      if (theta > theta_max) break;  // Theta grows with theta0 along the sampled path
      continue;
    }
    sxy += theta * y_of(s, theta);
    sxx += theta * theta;
    ++fit.count;
  }
  fit.slope = fit.count > 0 ? sxy / sxx : 0.0;
  return fit;
}

}  // namespace

double prb_angle(const PathSample& s, double gamma) {
  return std::atan2(s.b, s.a - (1.0 - gamma));  // eq. 5.42, atan2 so that Theta may pass 90 deg
}

double relative_position_error(const PathSample& s, double gamma) {
  const double theta = prb_angle(s, gamma);
  const double dx = s.a - (1.0 - gamma * (1.0 - std::cos(theta)));  // eq. 5.46
  const double dy = s.b - gamma * std::sin(theta);
  const double deflection = std::hypot(1.0 - s.a, s.b);  // eq. 5.44
  return std::hypot(dx, dy) / deflection;                // eq. 5.47
}

void PrbmDerivationOptions::validate() const {
  const auto check = [](double value, double lo, double hi, const char* what) {
    if (!std::isfinite(value) || value < lo || value > hi) {
      throw InvalidInput(
          fmt::format("PrbmDerivationOptions::{} = {} is outside the allowed range [{}, {}]",
                      what,
                      value,
                      lo,
                      hi));
    }
  };
  check(theta0_step_deg, 1e-4, 5.0, "theta0_step_deg");
  check(error_limit, 1e-6, 0.5, "error_limit");
  check(gamma_min, 0.05, 1.0, "gamma_min");
  check(gamma_max, gamma_min + 1e-6, 1.0, "gamma_max");
  check(gamma_coarse_step, 1e-5, 0.1, "gamma_coarse_step");
  check(gamma_fine_step, 1e-8, gamma_coarse_step, "gamma_fine_step");
  check(theta_max_K_deg, -1e300, 180.0, "theta_max_K_deg");
  check(end_moment_theta0_max_deg, 1.0, 359.0, "end_moment_theta0_max_deg");
  check(tail_samples, 0, 60, "tail_samples");
}

PrbmDerivation derive_from_path(
    const std::vector<PathSample>& samples,
    const std::function<PathSample(double)>& exact,
    const std::function<double(const PathSample&, double, double)>& tangential_load,
    double theta_max_K,
    const PrbmDerivationOptions& options) {
  options.validate();
  PrbmDerivation d;
  d.samples = static_cast<int>(samples.size());
  d.iterations = d.samples;
  if (samples.size() < 3) {
    d.message =
        fmt::format("only {} exact tips on the path; at least 3 are needed", samples.size());
    return d;
  }
  const double limit = options.error_limit;

  // Step 3: coarse grid, finer grids, then bisection on the upper edge of the best plateau.
  double gamma = best_gamma_on_grid(
      samples, options.gamma_min, options.gamma_max, options.gamma_coarse_step, limit);
  for (double step = options.gamma_coarse_step; step > options.gamma_fine_step;) {
    const double half_width = 2.0 * step;
    step = std::max(options.gamma_fine_step, step / 10.0);
    gamma = best_gamma_on_grid(samples,
                               std::max(options.gamma_min, gamma - half_width),
                               std::min(options.gamma_max, gamma + half_width),
                               step,
                               limit);
  }
  {
    // If Theta_max drops sharply just above gamma, a hump of the error curve touches the limit
    // between gamma and gamma + fine_step: locate that edge to 1e-10.
    const double here = theta_max_on_samples(samples, gamma, limit).theta_max;
    double lo = gamma;
    double hi = std::min(options.gamma_max, gamma + options.gamma_fine_step);
    const double there = theta_max_on_samples(samples, hi, limit).theta_max;
    if (hi > lo && here - there > 0.1 * kDeg) {
      while (hi - lo > 1e-10) {
        const double mid = 0.5 * (lo + hi);
        const double t = theta_max_on_samples(samples, mid, limit).theta_max;
        if (here - t > 0.1 * kDeg) {
          hi = mid;
        } else {
          lo = mid;
        }
      }
      gamma = lo;
    }
  }
  d.gamma = gamma;

  // Refine Theta_max(gamma) on the exact error function between the bracketing samples.
  const ThetaMaxOnSamples coarse = theta_max_on_samples(samples, gamma, limit);
  if (coarse.first_violation < 0) {
    d.theta_max_gamma = coarse.theta_max;
    d.theta0_at_theta_max = samples.back().theta0;
    d.theta_max_at_path_end = true;
    d.residual = 0.0;
  } else {
    const int i = coarse.first_violation;
    double lo = i > 0 ? samples[i - 1].theta0 : 0.0;
    double hi = samples[i].theta0;
    double e_lo = i > 0 ? relative_position_error(samples[i - 1], gamma) - limit : -limit;
    double e_hi = relative_position_error(samples[i], gamma) - limit;
    PathSample best = samples[i];
    // Illinois (modified regula falsi): bracketed, superlinear, ~10 exact tips.
    int side = 0;
    for (int it = 0; it < 60 && hi - lo > 1e-12; ++it) {
      const double x = (lo * e_hi - hi * e_lo) / (e_hi - e_lo);
      const PathSample s = exact(x);
      ++d.iterations;
      const double e = relative_position_error(s, gamma) - limit;
      best = s;
      if (e == 0.0) break;
      if (e > 0.0) {
        hi = x;
        e_hi = e;
        if (side == 1) e_lo /= 2.0;
        side = 1;
      } else {
        lo = x;
        e_lo = e;
        if (side == -1) e_hi /= 2.0;
        side = -1;
      }
      if (std::abs(e) < 1e-14) break;
    }
    d.theta0_at_theta_max = best.theta0;
    d.theta_max_gamma = prb_angle(best, gamma);
    d.residual = std::abs(relative_position_error(best, gamma) - limit);
  }

  // Step 4: c_theta.
  const OriginFit c_fit = fit_through_origin(
      samples, gamma, d.theta_max_gamma, [](const PathSample& s, double) { return s.theta0; });
  d.c_theta = c_fit.slope;
  d.samples_c_theta_fit = c_fit.count;

  // Step 5: K_theta.
  d.theta_max_K = theta_max_K > 0.0 ? theta_max_K : d.theta_max_gamma;
  const OriginFit k_fit =
      fit_through_origin(samples, gamma, d.theta_max_K, [&](const PathSample& s, double theta) {
        return tangential_load(s, theta, gamma);
      });
  d.K_theta = k_fit.slope;
  d.samples_K_theta_fit = k_fit.count;

  d.converged = c_fit.count >= 2 && k_fit.count >= 2 && std::isfinite(d.c_theta) &&
                std::isfinite(d.K_theta) && d.theta_max_gamma > 0.0;
  if (!d.converged) {
    d.message = fmt::format(
        "too few samples inside the fitted ranges ({} for c_theta, {} for K_theta); use a smaller "
        "theta0 step",
        c_fit.count,
        k_fit.count);
  } else {
    d.message = fmt::format(
        "gamma maximises Theta_max = {:.4f} deg; {} exact tips, {} in the c_theta fit, {} in the "
        "K_theta fit{}",
        d.theta_max_gamma / kDeg,
        d.iterations,
        c_fit.count,
        k_fit.count,
        d.theta_max_at_path_end ? "; the error stayed below the limit up to the end of the path "
                                  "(theta0 -> phi), which bounds Theta_max"
                                : "");
  }
  return d;
}

PrbmDerivation derive_fixed_pinned(double n, const PrbmDerivationOptions& options) {
  if (!std::isfinite(n) || n < -20.0 || n > 20.0) {
    throw InvalidInput(fmt::format(
        "load ratio n = {} is outside the range [-20, 20] supported by the derivation", n));
  }
  options.validate();
  const double phi = std::atan2(1.0, -n);  // eq. 5.41
  const double eta = std::sqrt(1.0 + n * n);

  // Theta_max(K_theta): Howell does not define it; see the header for the rule.
  double theta_max_K = 0.0;
  std::string source;
  if (options.theta_max_K_deg > 0.0) {
    theta_max_K = options.theta_max_K_deg * kDeg;
    source = "given";
  } else if (const FixedPinnedTableRow* row = table_5_1_row(n)) {
    theta_max_K = row->theta_max_K_deg * kDeg;
    source = "Table 5.1";
  } else if (n < 0.0) {
    theta_max_K = 0.7 * phi;
    source = "0.7 phi (eq. 5.63)";
  } else if (n <= 10.0) {
    theta_max_K = table_5_1_interpolated(n).theta_max_K_deg * kDeg;
    source = "Table 5.1 interpolated in n";
  } else {
    theta_max_K = table_5_1_row(10.0)->theta_max_K_deg * kDeg;
    source = "Table 5.1 at n = 10 (n > 10 is beyond the table)";
  }

  const EllipticSolver solver;
  int failures = 0;
  std::string failure;
  const auto exact = [&](double theta0) {
    const EllipticResult r = solver.solve_for_tip_angle(n, theta0);
    if (!r.converged) throw NoConvergence(r.message);
    return PathSample{theta0, r.tip.a_over_l, r.tip.b_over_l, r.load.Fy};
  };

  // Step 1: uniform samples 0 < theta0 < phi. Near phi the load grows without bound; stop at the
  // first tip the solver cannot deliver and report it.
  std::vector<PathSample> samples;
  const double step = options.theta0_step_deg * kDeg;
  for (int i = 1;; ++i) {
    const double theta0 = i * step;
    if (theta0 >= phi * (1.0 - 1e-9)) break;
    try {
      samples.push_back(exact(theta0));
    } catch (const std::exception& e) {
      ++failures;
      failure = fmt::format(
          "the exact solver failed at theta0 = {:.4f} deg ({})", theta0 / kDeg, e.what());
      break;
    }
  }
  if (failures == 0 && !samples.empty()) {
    const double gap = phi - samples.back().theta0;
    for (int k = 1; k <= options.tail_samples; ++k) {
      try {
        PathSample s = exact(phi - gap * std::ldexp(1.0, -k));
        s.in_fit = false;
        samples.push_back(s);
      } catch (const std::exception&) {
        break;  // the load is unbounded at phi; how close the solver gets is reported as theta0
      }
    }
  }

  const auto tangential = [phi, eta](const PathSample& s, double theta, double) {
    return s.load * eta * std::sin(phi - theta);  // (alpha2)_t, eqs. 5.56-5.57
  };
  PrbmDerivation d;
  try {
    d = derive_from_path(samples, exact, tangential, theta_max_K, options);
  } catch (const NoConvergence& e) {
    d.converged = false;
    d.message = fmt::format("refining Theta_max failed: {}", e.what());
  }
  d.segment = "fixed-pinned";
  d.load_ratio_n = n;
  d.phi = phi;
  d.theta_max_K_source = source;
  if (failures > 0) d.message += "; sampling stopped early: " + failure;
  return d;
}

PrbmDerivation derive_end_moment(const PrbmDerivationOptions& options) {
  options.validate();
  // Pure end moment: theta = mu s, a circular arc (eqs. 2.53, 2.59, 2.64); mu = theta0.
  const auto exact = [](double theta0) {
    return PathSample{theta0, std::sin(theta0) / theta0, (1.0 - std::cos(theta0)) / theta0, theta0};
  };
  std::vector<PathSample> samples;
  const double step = options.theta0_step_deg * kDeg;
  const double end = options.end_moment_theta0_max_deg * kDeg;
  for (int i = 1; i * step <= end * (1.0 + 1e-12); ++i) samples.push_back(exact(i * step));
  // K = gamma K_theta (eq. 5.111) and mu = K Theta, so K_theta Theta is fitted to mu / gamma.
  const auto tangential = [](const PathSample& s, double, double gamma) { return s.load / gamma; };
  PrbmDerivation d = derive_from_path(samples, exact, tangential, 0.0, options);
  d.segment = "end-moment";
  d.phi = std::numbers::pi;
  d.theta_max_K_source = "Theta_max(gamma) (Howell gives one limit for the end moment)";
  return d;
}

}  // namespace flexure
