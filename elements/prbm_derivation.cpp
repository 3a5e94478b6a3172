#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "flexure/elements/prbm_element.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/elliptic/elliptic_solver.h"

namespace flexure {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Eq. 5.47 in a cheaper form: the PRB tip lies on the ray from the pivot through the exact tip
// (that is how Theta is defined, eq. 5.42), so the error is the radial distance |r - rho|.
double fast_relative_error(const PathSample& s, double gamma, double rho, const UnloadedTip& u) {
  return std::abs(std::hypot(s.a - (1.0 - gamma), s.b) - rho) / std::hypot(s.a - u.a, s.b - u.b);
}

// Theta_max(gamma) from the samples, with the crossing interpolated linearly in Theta between the
// last sample inside the limit and the first outside (the path starts at Theta = Theta_i, error =
// 0). Angles are Theta - Theta_i.
struct ThetaMaxOnSamples {
  double theta_max = 0.0;
  int first_violation = -1;  // index of the first sample above the limit, -1 if none
};

ThetaMaxOnSamples theta_max_on_samples(const std::vector<PathSample>& samples,
                                       double gamma,
                                       double limit,
                                       const UnloadedTip& u) {
  ThetaMaxOnSamples out;
  const double rho = prb_link_length(gamma, u);
  const double theta_i = prb_initial_angle(gamma, u);
  double prev_error = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double error = fast_relative_error(samples[i], gamma, rho, u);
    if (error > limit) {
      const double prev_theta = i > 0 ? prb_angle(samples[i - 1], gamma) - theta_i : 0.0;
      const double theta = prb_angle(samples[i], gamma) - theta_i;
      const double f = (limit - prev_error) / (error - prev_error);
      out.theta_max = prev_theta + f * (theta - prev_theta);
      out.first_violation = static_cast<int>(i);
      return out;
    }
    prev_error = error;
  }
  out.theta_max = samples.empty() ? 0.0 : prb_angle(samples.back(), gamma) - theta_i;
  return out;
}

// Grid search of Theta_max(gamma) over [lo, hi]; returns the best gamma (the largest on ties, which
// keeps it on the stable side of a jump found later by bisection).
double best_gamma_on_grid(const std::vector<PathSample>& samples,
                          double lo,
                          double hi,
                          double step,
                          double limit,
                          const UnloadedTip& u) {
  const int count = static_cast<int>(std::ceil((hi - lo) / step));
  double best_gamma = lo;
  double best_theta = -1.0;
  for (int i = 0; i <= count; ++i) {
    const double gamma = std::min(hi, lo + i * step);
    const double theta = theta_max_on_samples(samples, gamma, limit, u).theta_max;
    if (theta >= best_theta) {
      best_theta = theta;
      best_gamma = gamma;
    }
  }
  return best_gamma;
}

// Least squares through the origin, y = k x, over samples with 0 < Theta - Theta_i <= theta_max.
struct OriginFit {
  double slope = 0.0;
  int count = 0;
};

template <typename Y>
OriginFit fit_through_origin(const std::vector<PathSample>& samples,
                             double gamma,
                             double theta_i,
                             double theta_max,
                             Y y_of) {
  double sxy = 0.0;
  double sxx = 0.0;
  OriginFit fit;
  for (const auto& s : samples) {
    if (!s.in_fit) continue;
    const double theta = prb_angle(s, gamma) - theta_i;
    if (!(theta > 0.0 && theta <= theta_max)) {
      if (theta > theta_max) break;  // Theta grows along the sampled path
      continue;
    }
    sxy += theta * y_of(s, theta + theta_i);
    sxx += theta * theta;
    ++fit.count;
  }
  fit.slope = fit.count > 0 ? sxy / sxx : 0.0;
  return fit;
}

// Theta_max(K_theta) of the straight beam for load ratio n: Howell does not define it; see the
// header of derive_fixed_pinned for the rule.
double straight_theta_max_K(double n, const PrbmDerivationOptions& options, std::string& source) {
  const double phi = std::atan2(1.0, -n);  // eq. 5.41
  if (options.theta_max_K_deg > 0.0) {
    source = "given";
    return options.theta_max_K_deg * kDeg;
  }
  if (const FixedPinnedTableRow* row = table_5_1_row(n)) {
    source = "Table 5.1";
    return row->theta_max_K_deg * kDeg;
  }
  if (n < 0.0) {
    source = "0.7 phi (eq. 5.63)";
    return 0.7 * phi;
  }
  if (n <= 10.0) {
    source = "Table 5.1 interpolated in n";
    return table_5_1_interpolated(n).theta_max_K_deg * kDeg;
  }
  source = "Table 5.1 at n = 10 (n > 10 is beyond the table)";
  return table_5_1_row(10.0)->theta_max_K_deg * kDeg;
}

}  // namespace

double prb_angle(const PathSample& s, double gamma) {
  return std::atan2(s.b, s.a - (1.0 - gamma));  // eq. 5.42, atan2 so that Theta may pass 90 deg
}

UnloadedTip UnloadedTip::circular_arc(double kappa0) {
  // Eqs. 5.117-5.118; the series avoids 0/0 for a nearly straight beam.
  if (std::abs(kappa0) < 1e-6) return {1.0 - kappa0 * kappa0 / 6.0, kappa0 / 2.0, kappa0};
  return {std::sin(kappa0) / kappa0, (1.0 - std::cos(kappa0)) / kappa0, kappa0};
}

double prb_link_length(double gamma, const UnloadedTip& u) {
  return std::hypot(u.a - (1.0 - gamma), u.b);  // eq. 5.116
}

double prb_initial_angle(double gamma, const UnloadedTip& u) {
  return std::atan2(u.b, u.a - (1.0 - gamma));  // eq. 5.115
}

double relative_position_error(const PathSample& s, double gamma, const UnloadedTip& u) {
  const double theta = prb_angle(s, gamma);
  const double rho = prb_link_length(gamma, u);
  const double dx = s.a - (1.0 - gamma + rho * std::cos(theta));  // eqs. 5.46, 5.119
  const double dy = s.b - rho * std::sin(theta);                  // eq. 5.120
  const double deflection = std::hypot(s.a - u.a, s.b - u.b);     // eq. 5.44
  return std::hypot(dx, dy) / deflection;                         // eq. 5.47
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
  check(curved_reference_gamma, 0.05, 1.0, "curved_reference_gamma");
  check(curved_alpha2_max, 1.0, 1e6, "curved_alpha2_max");
}

PrbmDerivation derive_from_path(
    const std::vector<PathSample>& samples,
    const std::function<PathSample(double)>& exact,
    const std::function<double(const PathSample&, double, double)>& tangential_load,
    double theta_max_K,
    const PrbmDerivationOptions& options,
    const UnloadedTip& u) {
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
      samples, options.gamma_min, options.gamma_max, options.gamma_coarse_step, limit, u);
  for (double step = options.gamma_coarse_step; step > options.gamma_fine_step;) {
    const double half_width = 2.0 * step;
    step = std::max(options.gamma_fine_step, step / 10.0);
    gamma = best_gamma_on_grid(samples,
                               std::max(options.gamma_min, gamma - half_width),
                               std::min(options.gamma_max, gamma + half_width),
                               step,
                               limit,
                               u);
  }
  {
    // If Theta_max drops sharply just above gamma, a hump of the error curve touches the limit
    // between gamma and gamma + fine_step: locate that edge to 1e-10.
    const double here = theta_max_on_samples(samples, gamma, limit, u).theta_max;
    double lo = gamma;
    double hi = std::min(options.gamma_max, gamma + options.gamma_fine_step);
    const double there = theta_max_on_samples(samples, hi, limit, u).theta_max;
    if (hi > lo && here - there > 0.1 * kDeg) {
      while (hi - lo > 1e-10) {
        const double mid = 0.5 * (lo + hi);
        const double t = theta_max_on_samples(samples, mid, limit, u).theta_max;
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
  d.rho = prb_link_length(gamma, u);
  d.theta_i = prb_initial_angle(gamma, u);

  // Refine Theta_max(gamma) on the exact error function between the bracketing samples; the
  // unloaded state has path parameter 0 (theta0 = 0, alpha2 = 0).
  const ThetaMaxOnSamples coarse = theta_max_on_samples(samples, gamma, limit, u);
  if (coarse.first_violation < 0) {
    d.theta_max_gamma = coarse.theta_max;
    d.theta0_at_theta_max = samples.back().theta0;
    d.theta_max_at_path_end = true;
    d.residual = 0.0;
  } else {
    const int i = coarse.first_violation;
    double lo = i > 0 ? samples[i - 1].path_parameter : 0.0;
    double hi = samples[i].path_parameter;
    double e_lo = i > 0 ? relative_position_error(samples[i - 1], gamma, u) - limit : -limit;
    double e_hi = relative_position_error(samples[i], gamma, u) - limit;
    PathSample best = samples[i];
    // Illinois (modified regula falsi): bracketed, superlinear, ~10 exact tips.
    int side = 0;
    for (int it = 0; it < 60 && hi - lo > 1e-12; ++it) {
      const double x = (lo * e_hi - hi * e_lo) / (e_hi - e_lo);
      const PathSample s = exact(x);
      ++d.iterations;
      const double e = relative_position_error(s, gamma, u) - limit;
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
    d.theta_max_gamma = prb_angle(best, gamma) - d.theta_i;
    d.residual = std::abs(relative_position_error(best, gamma, u) - limit);
  }

  // Step 4: c_theta.
  const OriginFit c_fit = fit_through_origin(
      samples, gamma, d.theta_i, d.theta_max_gamma, [&](const PathSample& s, double) {
        return s.theta0 - u.theta0;
      });
  d.c_theta = c_fit.slope;
  d.samples_c_theta_fit = c_fit.count;

  // Step 5: K_theta.
  d.theta_max_K = theta_max_K > 0.0 ? theta_max_K : d.theta_max_gamma;
  const OriginFit k_fit = fit_through_origin(
      samples, gamma, d.theta_i, d.theta_max_K, [&](const PathSample& s, double theta) {
        return tangential_load(s, theta, gamma);
      });
  d.K_theta = k_fit.slope;
  d.samples_K_theta_fit = k_fit.count;

  d.set_converged(c_fit.count >= 2 && k_fit.count >= 2 && std::isfinite(d.c_theta) &&
                  std::isfinite(d.K_theta) && d.theta_max_gamma > 0.0);
  if (!d.converged()) {
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

  std::string source;
  const double theta_max_K = straight_theta_max_K(n, options, source);

  const EllipticSolver solver;
  int failures = 0;
  std::string failure;
  const auto exact = [&](double theta0) {
    const EllipticResult r = solver.solve_for_tip_angle(n, theta0);
    if (!r.converged()) throw NoConvergence(r.message);
    return PathSample{theta0, r.tip.a_over_l, r.tip.b_over_l, r.load.Fy, true, theta0};
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
    d.set_converged(false);
    d.message = fmt::format("refining Theta_max failed: {}", e.what());
  }
  d.segment = PrbmSegment::kFixedPinned;
  d.load_ratio_n = n;
  d.phi = phi;
  d.theta_max_K_source = source;
  if (failures > 0) d.message += "; sampling stopped early: " + failure;
  return d;
}

std::string_view to_string(PrbmSegment segment) {
  switch (segment) {
    case PrbmSegment::kFixedPinned:
      return "fixed-pinned";
    case PrbmSegment::kEndMoment:
      return "end-moment";
    case PrbmSegment::kInitiallyCurved:
      return "initially-curved";
  }
  return "unknown";
}

PrbmSegment prbm_segment_from_string(std::string_view name) {
  for (PrbmSegment s :
       {PrbmSegment::kFixedPinned, PrbmSegment::kEndMoment, PrbmSegment::kInitiallyCurved}) {
    if (name == to_string(s)) return s;
  }
  throw InvalidInput(fmt::format(
      "segment '{}' is unknown (allowed: fixed-pinned, end-moment, initially-curved)", name));
}

PrbmDerivation derive_end_moment(const PrbmDerivationOptions& options) {
  options.validate();
  // Pure end moment: theta = mu s, a circular arc (eqs. 2.53, 2.59, 2.64); mu = theta0.
  const auto exact = [](double theta0) {
    return PathSample{
        theta0, std::sin(theta0) / theta0, (1.0 - std::cos(theta0)) / theta0, theta0, true, theta0};
  };
  std::vector<PathSample> samples;
  const double step = options.theta0_step_deg * kDeg;
  const double end = options.end_moment_theta0_max_deg * kDeg;
  for (int i = 1; i * step <= end * (1.0 + 1e-12); ++i) samples.push_back(exact(i * step));
  // K = gamma K_theta (eq. 5.111) and mu = K Theta, so K_theta Theta is fitted to mu / gamma.
  const auto tangential = [](const PathSample& s, double, double gamma) { return s.load / gamma; };
  PrbmDerivation d = derive_from_path(samples, exact, tangential, 0.0, options);
  d.segment = PrbmSegment::kEndMoment;
  d.phi = std::numbers::pi;
  d.theta_max_K_source = "Theta_max(gamma) (Howell gives one limit for the end moment)";
  return d;
}

}  // namespace flexure

namespace flexure {
namespace {

// The sampled exact path of an initially curved cantilever under a tip force at load ratio n.
struct CurvedPath {
  double kappa0 = 0.0;
  double n = 0.0;
  double phi = 0.0;
  double eta = 1.0;
  UnloadedTip unloaded;
  std::vector<PathSample> samples;
  std::string refusal;     // non-empty: the force does not open the PRB link, nothing sampled
  std::string end_reason;  // why the sampled path ends
  int solves = 0;          // elliptic solves, sampling and refinements
};

PathSample curved_tip(const EllipticSolver& solver, CurvedPath& path, double alpha2) {
  // theta(s) of the curved beam = straight beam with end moment mu = kappa0 (EI(theta' - 1/R_i) =
  // M, Howell eq. 2.103).
  const EllipticResult r = solver.solve(EndLoad::howell(path.n, alpha2, path.kappa0));
  ++path.solves;
  if (!r.converged()) throw NoConvergence(r.message);
  return PathSample{r.tip.theta0, r.tip.a_over_l, r.tip.b_over_l, alpha2, true, alpha2};
}

CurvedPath sample_curved_path(double kappa0, double n, const PrbmDerivationOptions& options) {
  if (!std::isfinite(kappa0) || kappa0 < 0.0 || kappa0 > 3.0) {
    throw InvalidInput(fmt::format(
        "initial curvature kappa0 = l/R_i = {} is outside the range [0, 3] supported by the "
        "derivation",
        kappa0));
  }
  if (!std::isfinite(n) || n < -5.0 || n > 10.0) {
    throw InvalidInput(fmt::format(
        "load ratio n = {} is outside the range [-5, 10] supported by the curved-beam derivation",
        n));
  }
  options.validate();
  CurvedPath path;
  path.kappa0 = kappa0;
  path.n = n;
  path.phi = std::atan2(1.0, -n);  // eq. 5.122 (sign as in erratum 5.41)
  path.eta = std::sqrt(1.0 + n * n);
  path.unloaded = UnloadedTip::circular_arc(kappa0);
  const double gamma_ref = options.curved_reference_gamma;
  const double theta_i_ref = prb_initial_angle(gamma_ref, path.unloaded);
  if (path.phi <= theta_i_ref + kDeg) {
    path.refusal = fmt::format(
        "the force angle phi = {:.2f} deg does not exceed the unloaded PRB angle Theta_i = {:.2f} "
        "deg by 1 deg: the tip force does not open the PRB link (eq. 5.121 gives F_t <= 0)",
        path.phi / kDeg,
        theta_i_ref / kDeg);
    return path;
  }
  const EllipticSolver solver;
  const auto exact = [&](double alpha2) { return curved_tip(solver, path, alpha2); };
  const auto reference_angle = [&](const PathSample& s) { return prb_angle(s, gamma_ref); };

  // Tips at Theta_ref = Theta_i,ref + i step about the reference pivot; each target is bracketed
  // in alpha2 (predicted from the previous step, doubled until passed) and hit by Illinois to
  // 1e-11 rad. theta0 is not monotone in alpha2 (it overshoots phi and returns), the PRB angle is.
  const double step = options.theta0_step_deg * kDeg;
  PathSample last{path.unloaded.theta0, path.unloaded.a, path.unloaded.b, 0.0, true, 0.0};
  double last_angle = theta_i_ref;
  double dalpha2 = 1e-3;  // first trial increment; later the secant of the previous step
  path.end_reason = fmt::format("the path ends at alpha2 = {:g}", options.curved_alpha2_max);
  try {
    for (int i = 1;; ++i) {
      const double target = theta_i_ref + i * step;
      double lo = last.path_parameter;
      double f_lo = last_angle - target;
      double hi = lo + dalpha2;
      PathSample s_hi = exact(hi);
      double f_hi = reference_angle(s_hi) - target;
      bool beyond = false;
      while (f_hi < 0.0) {
        lo = hi;
        f_lo = f_hi;
        if (hi >= options.curved_alpha2_max) {
          beyond = true;
          break;
        }
        hi = std::min(options.curved_alpha2_max, lo + 2.0 * (hi - last.path_parameter));
        s_hi = exact(hi);
        f_hi = reference_angle(s_hi) - target;
      }
      if (beyond) break;
      PathSample best = s_hi;
      double f_best = f_hi;
      int side = 0;
      for (int it = 0; it < 60 && std::abs(f_best) > 1e-11 && hi - lo > 1e-15 * hi; ++it) {
        const double x = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
        const PathSample s = exact(x);
        const double f = reference_angle(s) - target;
        best = s;
        f_best = f;
        if (f > 0.0) {
          hi = x;
          f_hi = f;
          if (side == 1) f_lo /= 2.0;
          side = 1;
        } else {
          lo = x;
          f_lo = f;
          if (side == -1) f_hi /= 2.0;
          side = -1;
        }
      }
      dalpha2 = 1.05 * (best.path_parameter - last.path_parameter);
      last = best;
      last_angle = reference_angle(best);
      path.samples.push_back(best);
    }
  } catch (const std::exception& e) {
    path.end_reason =
        fmt::format("sampling stopped at alpha2 = {:g}: {}", last.path_parameter, e.what());
  }
  return path;
}

// Steps 2-5 on a sampled curved path; fixed_gamma > 0 skips the gamma search (Table 5.2's K_theta
// belongs to the one gamma used for all n) and then only the K_theta fit decides convergence.
PrbmDerivation derive_on_curved_path(CurvedPath& path,
                                     const PrbmDerivationOptions& options,
                                     double fixed_gamma) {
  PrbmDerivation d;
  if (path.refusal.empty()) {
    PrbmDerivationOptions o = options;
    if (fixed_gamma > 0.0) {
      o.gamma_min = fixed_gamma;
      o.gamma_max = fixed_gamma + 1e-6;  // the search cannot move gamma by more than this
      o.gamma_coarse_step = 1e-5;
      o.gamma_fine_step = 1e-5;
    }
    const EllipticSolver solver;
    const auto exact = [&](double alpha2) { return curved_tip(solver, path, alpha2); };
    std::string source;
    const double theta_max_K =
        options.curved_K_range_from_gamma ? 0.0 : straight_theta_max_K(path.n, options, source);
    const double phi = path.phi;
    const double eta = path.eta;
    const auto tangential = [phi, eta](const PathSample& s, double theta, double) {
      return s.load * eta * std::sin(phi - theta);  // (alpha2)_t, eqs. 5.121-5.123
    };
    try {
      d = derive_from_path(path.samples, exact, tangential, theta_max_K, o, path.unloaded);
    } catch (const NoConvergence& e) {
      d.set_converged(false);
      d.message = fmt::format("refining Theta_max failed: {}", e.what());
    }
    if (!options.curved_K_range_from_gamma && d.gamma > 0.0 &&
        (d.converged() || fixed_gamma > 0.0)) {
      // The straight beam's range scaled to the angle the link can turn before it lines up with
      // the force, phi - Theta_i (for kappa0 = 0 the straight rule itself; for n < 0 it is
      // 0.7 (phi - Theta_i), eq. 5.63 measured from Theta_i). Unscaled, the range would pass
      // Theta = phi, where (alpha2)_t changes sign while alpha2 grows without bound.
      d.theta_max_K = theta_max_K * (phi - d.theta_i) / phi;
      const OriginFit k_fit = fit_through_origin(
          path.samples, d.gamma, d.theta_i, d.theta_max_K, [&](const PathSample& s, double theta) {
            return tangential(s, theta, d.gamma);
          });
      d.K_theta = k_fit.slope;
      d.samples_K_theta_fit = k_fit.count;
      d.set_converged(k_fit.count >= 2 && std::isfinite(d.K_theta));
      if (!d.converged()) {
        d.message = "too few samples in the K_theta range; use a smaller step";
      } else if (fixed_gamma > 0.0) {
        d.message = fmt::format(
            "gamma fixed at {:.5f}: K_theta from {} samples; Theta_max(gamma) - Theta_i = {:.3f} "
            "deg",
            d.gamma,
            k_fit.count,
            d.theta_max_gamma / kDeg);
      }
    }
    d.theta_max_K_source =
        options.curved_K_range_from_gamma
            ? "Theta_max(gamma) of this curved beam"
            : "straight beam (" + source + ") x (phi - Theta_i)/phi, on Theta - Theta_i";
    d.message += fmt::format("; {} elliptic solves so far on this path", path.solves);
    if (d.theta_max_at_path_end) d.message += "; " + path.end_reason;
  } else {
    d.message = path.refusal;
  }
  d.segment = PrbmSegment::kInitiallyCurved;
  d.kappa0 = path.kappa0;
  d.load_ratio_n = path.n;
  d.phi = path.phi;
  d.iterations = path.solves;
  return d;
}

}  // namespace

PrbmDerivation derive_initially_curved(double kappa0,
                                       double n,
                                       const PrbmDerivationOptions& options) {
  CurvedPath path = sample_curved_path(kappa0, n, options);
  return derive_on_curved_path(path, options, 0.0);
}

CurvedCantileverAverage derive_initially_curved_average(double kappa0,
                                                        double n_min,
                                                        double n_max,
                                                        int n_intervals,
                                                        const PrbmDerivationOptions& options) {
  if (!std::isfinite(n_min) || !std::isfinite(n_max) || n_min < -5.0 || n_max > 10.0 ||
      !(n_max > n_min)) {
    throw InvalidInput(fmt::format(
        "load-ratio range [{}, {}] for the average must satisfy -5 <= n_min < n_max <= 10",
        n_min,
        n_max));
  }
  if (n_intervals < 1 || n_intervals > 200) {
    throw InvalidInput(
        fmt::format("number of load-ratio intervals = {} is outside [1, 200]", n_intervals));
  }
  CurvedCantileverAverage avg;
  avg.kappa0 = kappa0;
  avg.n_min = n_min;
  avg.n_max = n_max;
  double w_sum = 0.0;
  double gamma = 0.0;
  double K_theta = 0.0;
  double c_theta = 0.0;
  std::string left_out;
  avg.theta_max_gamma_min = std::numeric_limits<double>::infinity();
  std::vector<CurvedPath> paths;
  std::vector<double> weights;
  for (int j = 0; j <= n_intervals; ++j) {
    const double n = n_min + (n_max - n_min) * j / n_intervals;
    paths.push_back(sample_curved_path(kappa0, n, options));
    PrbmDerivation d = derive_on_curved_path(paths.back(), options, 0.0);
    // Trapezoid weights: (int f dn)/(int dn), Howell eqs. 5.51 and 5.64.
    const double w = (j == 0 || j == n_intervals) ? 0.5 : 1.0;
    weights.push_back(w);
    if (d.converged() && !d.theta_max_at_path_end) {
      w_sum += w;
      gamma += w * d.gamma;
      K_theta += w * d.K_theta;
      c_theta += w * d.c_theta;
      avg.residual = std::max(avg.residual, d.residual);
      avg.theta_max_gamma_min = std::min(avg.theta_max_gamma_min, d.theta_max_gamma);
      ++avg.used;
    } else {
      left_out += fmt::format("{}n = {:g} ({})", left_out.empty() ? "" : "; ", n, d.message);
    }
    avg.per_n.push_back(std::move(d));
  }
  if (avg.used == 0) {
    avg.message = "no load ratio gave a derivation: " + left_out;
    avg.theta_max_gamma_min = 0.0;
    for (const CurvedPath& p : paths) avg.iterations += p.solves;
    return avg;
  }
  avg.gamma = gamma / w_sum;
  avg.K_theta_per_n_gamma = K_theta / w_sum;
  avg.c_theta = c_theta / w_sum;
  const UnloadedTip unloaded = UnloadedTip::circular_arc(kappa0);
  avg.rho = prb_link_length(avg.gamma, unloaded);
  avg.theta_i = prb_initial_angle(avg.gamma, unloaded);

  // Second pass: K_theta of every load ratio with the averaged gamma (the PRB link, rho and Theta_i
  // the model will use for all n), on the same samples.
  double w_K = 0.0;
  double K_common = 0.0;
  std::string K_left_out;
  for (std::size_t j = 0; j < paths.size(); ++j) {
    PrbmDerivation d = derive_on_curved_path(paths[j], options, avg.gamma);
    if (d.converged() && !d.theta_max_at_path_end) {
      w_K += weights[j];
      K_common += weights[j] * d.K_theta;
      ++avg.used_K;
    } else {
      K_left_out +=
          fmt::format("{}n = {:g} ({})", K_left_out.empty() ? "" : "; ", d.load_ratio_n, d.message);
    }
    avg.per_n_at_average_gamma.push_back(std::move(d));
  }
  for (const CurvedPath& p : paths) avg.iterations += p.solves;
  if (avg.used_K == 0) {
    avg.message = "no load ratio gave K_theta at the averaged gamma: " + K_left_out;
    return avg;
  }
  avg.K_theta = K_common / w_K;
  avg.set_converged(true);
  avg.message =
      fmt::format("gamma averaged over {} of {} load ratios in [{:g}, {:g}], K_theta over {}",
                  avg.used,
                  n_intervals + 1,
                  n_min,
                  n_max,
                  avg.used_K);
  if (!left_out.empty()) avg.message += "; left out of gamma: " + left_out;
  if (!K_left_out.empty()) avg.message += "; left out of K_theta: " + K_left_out;
  return avg;
}

}  // namespace flexure
