#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numeric>

#include "flexure/elements/ladder_models.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/elliptic/elliptic_solver.h"

namespace flexure {
namespace {

constexpr int kParameters = 6;
using Point = std::array<double, kParameters>;
constexpr double kMinGamma = 0.02;

struct ExactLoad {
  EndLoad load;
  TipPose tip;
};

// gamma1..3 and ln k1..3 -> constants; false where a gamma falls below kMinGamma.
bool constants_of(const Point& v, Prbm3rConstants& c) {
  c.gamma = {1.0 - v[0] - v[1] - v[2], v[0], v[1], v[2]};
  for (double g : c.gamma) {
    if (!(g >= kMinGamma)) return false;
  }
  for (int i = 0; i < 3; ++i) c.k[i] = std::exp(v[3 + i]);
  c.name = "flexure";
  return true;
}

struct Errors {
  double rms = 0.0;
  double max_position = 0.0;
};

Errors errors_of(const Prbm3rConstants& c, const std::vector<ExactLoad>& loads) {
  Prbm3rSolver::Options options;
  options.constants = c;
  options.tolerance = 1e-11;
  const Prbm3rSolver solver(options);
  Errors out;
  double sum = 0.0;
  for (const ExactLoad& l : loads) {
    CantileverCase problem;
    problem.load = l.load;
    const Prbm3rResult r = solver.solve(problem);
    double e2 = 1.0;
    if (r.converged()) {
      const double delta = std::hypot(l.tip.a_over_l - 1.0, l.tip.b_over_l);
      const double position =
          std::hypot(r.tip.a_over_l - l.tip.a_over_l, r.tip.b_over_l - l.tip.b_over_l) / delta;
      const double angle =
          std::fabs(r.tip.theta0 - l.tip.theta0) / std::max(std::fabs(l.tip.theta0), delta);
      e2 = position * position + angle * angle;
      out.max_position = std::max(out.max_position, position);
    } else {
      out.max_position = std::max(out.max_position, 1.0);
    }
    sum += e2;
  }
  out.rms = std::sqrt(sum / static_cast<double>(loads.size()));
  return out;
}

// Nelder-Mead (standard coefficients 1, 2, 1/2, 1/2) from `start` with initial steps `step`.
Point nelder_mead(const std::function<double(const Point&)>& f,
                  const Point& start,
                  const Point& step,
                  int max_evaluations,
                  int& evaluations,
                  double& best) {
  std::array<Point, kParameters + 1> x{};
  std::array<double, kParameters + 1> fx{};
  x[0] = start;
  for (int i = 0; i < kParameters; ++i) {
    x[i + 1] = start;
    x[i + 1][i] += step[i];
  }
  for (int i = 0; i <= kParameters; ++i) fx[i] = f(x[i]);
  evaluations += kParameters + 1;
  int used = kParameters + 1;
  std::array<int, kParameters + 1> order{};
  while (used < max_evaluations) {
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return fx[a] < fx[b]; });
    const int lo = order[0], hi = order[kParameters], second = order[kParameters - 1];
    if (fx[hi] - fx[lo] <= 1e-10 * (std::fabs(fx[lo]) + 1e-12)) break;
    Point centroid{};
    for (int i = 0; i <= kParameters; ++i) {
      if (i == hi) continue;
      for (int j = 0; j < kParameters; ++j) centroid[j] += x[i][j] / kParameters;
    }
    const auto along = [&](double t) {
      Point p{};
      for (int j = 0; j < kParameters; ++j) p[j] = centroid[j] + t * (x[hi][j] - centroid[j]);
      return p;
    };
    const Point reflected = along(-1.0);
    const double f_reflected = f(reflected);
    ++used;
    if (f_reflected < fx[lo]) {
      const Point expanded = along(-2.0);
      const double f_expanded = f(expanded);
      ++used;
      if (f_expanded < f_reflected) {
        x[hi] = expanded;
        fx[hi] = f_expanded;
      } else {
        x[hi] = reflected;
        fx[hi] = f_reflected;
      }
    } else if (f_reflected < fx[second]) {
      x[hi] = reflected;
      fx[hi] = f_reflected;
    } else {
      const bool outside = f_reflected < fx[hi];
      const Point contracted = along(outside ? -0.5 : 0.5);
      const double f_contracted = f(contracted);
      ++used;
      if (f_contracted < (outside ? f_reflected : fx[hi])) {
        x[hi] = contracted;
        fx[hi] = f_contracted;
      } else {
        for (int i = 0; i <= kParameters; ++i) {
          if (i == lo) continue;
          for (int j = 0; j < kParameters; ++j) x[i][j] = x[lo][j] + 0.5 * (x[i][j] - x[lo][j]);
          fx[i] = f(x[i]);
          ++used;
        }
      }
    }
  }
  evaluations += used - (kParameters + 1);
  const int lo = static_cast<int>(std::min_element(fx.begin(), fx.end()) - fx.begin());
  best = fx[lo];
  return x[lo];
}

}  // namespace

void Prbm3rDerivationOptions::validate() const {
  const auto axis = [](const std::vector<double>& v, const char* name) {
    if (v.empty()) throw InvalidInput(fmt::format("PR-3R derivation: the {} axis is empty", name));
    for (double x : v) require_finite(x, fmt::format("PR-3R derivation: a value of {}", name));
  };
  axis(load_ratio_n, "n");
  axis(alpha2, "alpha2");
  axis(mu, "mu");
  if (!(max_tip_angle > 0.0) || max_tip_angle > 3.14159265358979323846) {
    throw InvalidInput(
        fmt::format("PR-3R derivation: max_tip_angle must be in (0, pi] (got {})", max_tip_angle));
  }
  if (max_evaluations < 10 || restarts < 1) {
    throw InvalidInput("PR-3R derivation: max_evaluations must be >= 10 and restarts >= 1");
  }
}

std::string Prbm3rDerivationOptions::describe() const {
  return fmt::format(
      "free cantilever; n in {{{}}}; alpha2 in {{{}}}; mu in {{{}}}; loads whose exact tip angle "
      "|theta0| <= {:g} rad",
      fmt::join(load_ratio_n, " "),
      fmt::join(alpha2, " "),
      fmt::join(mu, " "),
      max_tip_angle);
}

Prbm3rDerivation derive_prbm3r_constants(const Prbm3rDerivationOptions& options) {
  options.validate();
  const EllipticSolver elliptic;
  std::vector<ExactLoad> loads;
  for (double n : options.load_ratio_n) {
    for (double a : options.alpha2) {
      for (double m : options.mu) {
        const EndLoad load = EndLoad::howell(n, a, m);
        if (load.Fx == 0.0 && load.Fy == 0.0 && load.mu == 0.0) continue;
        const EllipticResult r = elliptic.solve(load);
        if (!r.converged() || std::fabs(r.tip.theta0) > options.max_tip_angle) continue;
        loads.push_back({load, r.tip});
      }
    }
  }
  Prbm3rDerivation out;
  out.domain = options.describe();
  out.loads = static_cast<int>(loads.size());
  if (loads.empty()) {
    out.termination = Termination::kInvalidInput;
    out.message = "no load of the domain has an exact solution within the tip-angle limit";
    return out;
  }
  const Prbm3rConstants su = Prbm3rConstants::su();
  const Errors su_errors = errors_of(su, loads);
  out.objective_su = su_errors.rms;
  out.max_position_error_su = su_errors.max_position;
  const auto objective = [&](const Point& v) {
    Prbm3rConstants c;
    if (!constants_of(v, c)) return 1e3;
    return errors_of(c, loads).rms;
  };
  Point best{su.gamma[1],
             su.gamma[2],
             su.gamma[3],
             std::log(su.k[0]),
             std::log(su.k[1]),
             std::log(su.k[2])};
  double best_value = objective(best);
  int evaluations = 1;
  for (int restart = 0; restart < options.restarts; ++restart) {
    const Point step{0.05, 0.05, 0.03, 0.1, 0.1, 0.1};
    double value = 0.0;
    const Point found =
        nelder_mead(objective, best, step, options.max_evaluations, evaluations, value);
    const double gain = best_value - value;
    if (value < best_value) {
      best = found;
      best_value = value;
    }
    if (gain < 1e-6) break;
  }
  constants_of(best, out.constants);
  out.constants.source = "derived by flexure against the exact elastica";
  const Errors final_errors = errors_of(out.constants, loads);
  out.objective = final_errors.rms;
  out.max_position_error = final_errors.max_position;
  out.iterations = evaluations;
  out.residual = out.objective;
  out.termination = Termination::kConverged;
  out.message = fmt::format(
      "{} objective evaluations over {} loads: RMS error {:.4g} (Su's general set: {:.4g})",
      evaluations,
      out.loads,
      out.objective,
      out.objective_su);
  return out;
}

std::string prbm3r_constants_csv(const Prbm3rDerivation& d, const std::string& provenance) {
  const Prbm3rConstants& c = d.constants;
  // Six decimals, gamma0 = 1 - the others as printed: the printed lengths sum to 1.
  const auto rounded = [](double x) { return std::round(x * 1e6) / 1e6; };
  const double g1 = rounded(c.gamma[1]), g2 = rounded(c.gamma[2]), g3 = rounded(c.gamma[3]);
  return fmt::format(
      "# PR-3R model constants derived by flexure (elements/ladder_models.h, docs/models.md):\n"
      "# the link lengths gamma0..gamma3 (times l) and spring stiffnesses k1..k3 (times EI/l) "
      "that\n"
      "# minimise the RMS over a load domain of e^2 = (relative tip position error)^2 + (relative\n"
      "# tip angle error)^2 against the exact elliptic elastica, by Nelder-Mead from Su's general\n"
      "# set (data/su_prbm3r_constants.csv).\n"
      "# Domain: {}: {} loads.\n"
      "# Objective (RMS of e): {:.6g}; Su's general set on the same domain: {:.6g}.\n"
      "# Largest relative tip position error over the domain: {:.4g} (Su's general set: {:.4g}).\n"
      "# Provenance: {}\n"
      "# Regenerate with: flexure models prbm3r-constants > data/prbm3r_flexure_constants.csv\n"
      "# Read by elements/prbm3r.cpp (Prbm3rConstants::flexure, --constants flexure).\n"
      "#\n"
      "# Columns (all dimensionless):\n"
      "#   name            flexure (the name --constants takes)\n"
      "#   gamma0..gamma3  link lengths / l, clamp to tip\n"
      "#   k1..k3          spring stiffnesses / (EI/l), clamp to tip\n"
      "#   objective       the RMS error above at these constants\n"
      "name,gamma0,gamma1,gamma2,gamma3,k1,k2,k3,objective\n"
      "flexure,{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6g}\n",
      d.domain,
      d.loads,
      d.objective,
      d.objective_su,
      d.max_position_error,
      d.max_position_error_su,
      provenance,
      1.0 - g1 - g2 - g3,
      g1,
      g2,
      g3,
      c.k[0],
      c.k[1],
      c.k[2],
      d.objective);
}

}  // namespace flexure
