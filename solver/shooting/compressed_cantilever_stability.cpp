#include "flexure/solver/shooting/compressed_cantilever_stability.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <variant>

#include "flexure/solver/chain_model/equilibrium_stability.h"
#include "flexure/solver/common/gsl_guard.h"
#include "flexure/solver/shooting/tension_stability.h"

namespace flexure {
namespace {

constexpr double kPi = std::numbers::pi;
// The elastica and the Jacobi system on the beam scaled to length 1 and EI 1 (compressed_
// cantilever_stability.h): 1e-10 keeps the margin within about 1e-12 of the general verdict's
// refined value (tests) at a third of the steps of the solve's 1e-12.
constexpr double kRtol = 1e-10;
constexpr double kAtol = 1e-12;
// The re-integrated far end must meet the solution within this (rad; relative for the moment): the
// solve converges to about 1e-11; a larger gap means the result is not this chain's equilibrium.
constexpr double kTipAngleCheck = 1e-8;
// Newton in q = sqrt(sigma) stops when its step is below this times q: the error of the last
// iterate is then about the square of it (quadratic convergence), far below the 1e-9 of the
// general verdict's margin.
constexpr double kStepTolerance = 1e-7;
constexpr int kMaxIterations = 60;
// The search for sigma_1 stops here (margin above 1 - 1e-4) and leaves the equilibrium to the
// general verdict: a weakly compressed beam whose lowest mode lives in a short compressed stretch
// next to long tensioned ones makes the Jacobi solutions grow like exp(sqrt(sigma F . t)) and the
// integration stiff, and such margins are rare in practice (docs/stability.md).
constexpr double kMaxSigma = 1e4;

// The tangent (cos theta, sin theta) is integrated instead of theta: the right-hand side is then
// polynomial (t' = kappa R90 t, EI kappa = m), without a sine and cosine per evaluation, which
// were a third of a pass's time (docs/stability.md, "Cost").
enum : int { kCos = 0, kSin, kM, kU, kV, kUs, kVs, kSize };

struct Jacobi {
  double fx = 0.0, fy = 0.0;  // F L^2 / EI
  double sigma = 1.0;
};

int rhs(double, const double y[], double dydt[], void* params) {
  const Jacobi& p = *static_cast<const Jacobi*>(params);
  const double cs = y[kCos], sn = y[kSin];
  const double w = p.fx * cs + p.fy * sn;  // F . t
  dydt[kCos] = -sn * y[kM];
  dydt[kSin] = cs * y[kM];
  dydt[kM] = p.fx * sn - p.fy * cs;
  dydt[kU] = y[kV];
  dydt[kV] = p.sigma * w * y[kU];
  dydt[kUs] = y[kVs];
  dydt[kVs] = w * y[kU] + p.sigma * w * y[kUs];
  return GSL_SUCCESS;
}

// One integration at sigma. `f` is the eigen-condition, decreasing through 0 at every eigenvalue:
// forward (from the clamp, u(0) = 0) pi/2 - phi(L), backward (from the tip, EI u'(L) = 0) the
// angle atan2(u, EI u') at the clamp; `count` the eigenvalues below 1 - 1/sigma.
struct Pass {
  double f = 0.0;
  double df = 0.0;  // d f / d sigma
  int count = 0;
  double end_cos = 1.0;  // the tangent where the integration ended (the tip, or the clamp)
  double end_sin = 0.0;
  double end_m = 0.0;  // m there
  double gamma = 0.0;  // int sqrt(max(0, -F . t)) ds (scaled), the straight column's guess
  bool ok = false;
};

struct GslFree {
  void operator()(gsl_odeiv2_step* s) const { gsl_odeiv2_step_free(s); }
  void operator()(gsl_odeiv2_control* c) const { gsl_odeiv2_control_free(c); }
  void operator()(gsl_odeiv2_evolve* e) const { gsl_odeiv2_evolve_free(e); }
};

class JacobiPasses {
 public:
  // From the clamp (theta 0, moment m0) or, `backward`, from the tip (theta_tip, m_tip).
  JacobiPasses(double fx, double fy, double m0, double theta_tip, double m_tip, bool backward)
      : m0_(m0), theta_tip_(theta_tip), m_tip_(m_tip), backward_(backward) {
    params_.fx = fx;
    params_.fy = fy;
    force_ = std::hypot(fx, fy);
    step_.reset(gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, kSize));
    control_.reset(gsl_odeiv2_control_y_new(kAtol, kRtol));
    evolve_.reset(gsl_odeiv2_evolve_alloc(kSize));
  }
  bool ready() const { return step_ && control_ && evolve_; }

  Pass run(double sigma) {
    Pass out;
    params_.sigma = sigma;
    gsl_odeiv2_system system{rhs, nullptr, kSize, &params_};
    gsl_odeiv2_step_reset(step_.get());
    gsl_odeiv2_evolve_reset(evolve_.get());
    // Forward: u(0) = 0, EI u'(0) = 1. Backward: u(L) = 1, EI u'(L) = 0.
    double y[kSize] = {1.0, 0.0, m0_, 0.0, 1.0, 0.0, 0.0};
    if (backward_) {
      y[kCos] = std::cos(theta_tip_);
      y[kSin] = std::sin(theta_tip_);
      y[kM] = m_tip_;
      y[kU] = 1.0;
      y[kV] = 0.0;
    }
    const double t_end = backward_ ? 0.0 : 1.0;
    const double direction = backward_ ? -1.0 : 1.0;
    // At most one radian of the Pruefer angle per step (see the header).
    const double h_max = 1.0 / std::max(1.0, std::sqrt(sigma * force_));
    double t = backward_ ? 1.0 : 0.0, h = direction * std::min(1e-2, h_max);
    double angle = std::atan2(y[kU], y[kV]);  // before the step
    double phi = angle;                       // unwrapped
    const auto compression = [&](const double* state) {
      return std::sqrt(std::max(0.0, -(params_.fx * state[kCos] + params_.fy * state[kSin])));
    };
    double g_before = compression(y);
    for (int steps = 0; direction * (t_end - t) > 0.0; ++steps) {
      if (steps > 100000) return out;
      h = direction * std::min(std::fabs(h), h_max);
      const double t_before = t;
      const int status = gsl_odeiv2_evolve_apply(
          evolve_.get(), control_.get(), step_.get(), &system, &t, t_end, &h, y);
      if (status != GSL_SUCCESS || !std::isfinite(y[kU]) || !std::isfinite(y[kV])) return out;
      const double now = std::atan2(y[kU], y[kV]);
      double turn = now - angle;
      if (turn > kPi) turn -= 2.0 * kPi;
      if (turn <= -kPi) turn += 2.0 * kPi;
      phi += turn;
      angle = now;
      const double g_after = compression(y);
      out.gamma += 0.5 * std::fabs(t - t_before) * (g_before + g_after);
      g_before = g_after;
      // Keep the linear solution of order one (it grows exponentially in tension): the angle
      // and its derivative are invariant under scaling u, v, u_sigma, v_sigma together.
      const double r = std::hypot(y[kU], y[kV]);
      if (r > 1e100 || r < 1e-100) {
        for (int k = kU; k < kSize; ++k) y[k] /= r;
      }
    }
    // The count from the unwrapped angle; the eigen-condition from the modified angle
    // atan2(S u, v), S = (1 + (sigma w)^2)^(1/4) at the end (Pruefer's scaled angle; Pryce,
    // Numerical Solution of Sturm-Liouville Problems, 1993, sec. 5.2), which meets the multiples of
    // pi/2 where the plain one does (S > 0) and, as a function of sigma, is nearly linear in
    // sqrt(sigma) where the end is compressed (a straight column: S u / v = tan(sqrt(sigma P) L)),
    // so Newton's method converges from further away.
    const double w_end = params_.fx * y[kCos] + params_.fy * y[kSin];
    const double A = 1.0 + sigma * sigma * w_end * w_end;
    const double S = std::sqrt(std::sqrt(A));
    const double dS = sigma * w_end * w_end / (2.0 * S * S * S);
    const double modified = phi + (std::atan2(S * y[kU], y[kV]) - std::atan2(y[kU], y[kV]));
    const double d_modified = (y[kV] * (dS * y[kU] + S * y[kUs]) - S * y[kU] * y[kVs]) /
                              (y[kV] * y[kV] + S * S * y[kU] * y[kU]);
    if (backward_) {
      // Integrated from s = L down to 0, the angle decreases with sigma; u(0) = 0 at an
      // eigenvalue: phi(0) = 0 at the first, -pi at the second, ...
      out.f = modified;
      out.df = d_modified;
      out.count = phi <= 0.0 ? static_cast<int>(std::floor(-phi / kPi)) + 1 : 0;
    } else {
      out.f = 0.5 * kPi - modified;
      out.df = -d_modified;
      out.count = static_cast<int>(std::floor((phi + 0.5 * kPi) / kPi));
    }
    out.end_cos = y[kCos];
    out.end_sin = y[kSin];
    out.end_m = y[kM];
    out.ok = std::isfinite(out.f) && std::isfinite(out.df) && out.count >= 0;
    return out;
  }

 private:
  Jacobi params_;
  double m0_ = 0.0, theta_tip_ = 0.0, m_tip_ = 0.0, force_ = 0.0;
  bool backward_ = false;
  std::unique_ptr<gsl_odeiv2_step, GslFree> step_;
  std::unique_ptr<gsl_odeiv2_control, GslFree> control_;
  std::unique_ptr<gsl_odeiv2_evolve, GslFree> evolve_;
};

// compressed_cantilever_stability() with or without the guess (no fallback).
std::optional<Stability> jacobi_verdict(const SegmentChain& chain,
                                        const ShootingResult& result,
                                        const StabilityOptions& options,
                                        std::optional<double> margin_guess) {
  if (!tension_verdict_applies(chain) || !result.converged()) return std::nullopt;
  options.validate();
  const auto& segment = std::get<FlexibleSegment>(chain.segments.front());
  const double L = segment.length, EI = segment.EI;
  const double fx = chain.tip_load.Fx * L * L / EI, fy = chain.tip_load.Fy * L * L / EI;
  const double m0 = -result.reaction.M * L / EI;
  if (!std::isfinite(fx) || !std::isfinite(fy) || !std::isfinite(m0) ||
      !std::isfinite(result.tip.theta)) {
    return std::nullopt;
  }
  const double tolerance = options.critical_tolerance;
  const auto verdict = [&](int index, double margin) {
    return classify_stability(index, margin, tolerance, "the beam");
  };
  // No force: W = 0, every eigenvalue is 1 (the unloaded beam).
  if (fx == 0.0 && fy == 0.0) return verdict(0, 1.0);
  disable_gsl_abort();
  // The direction in which the eigen-condition is well conditioned: into the clamp when the beam
  // is compressed there (the Jacobi solutions oscillate there and grow, if at all, towards the
  // tip, where the backward integration starts on its natural condition), else from it.
  const bool backward = fx < 0.0;
  const double m_tip = chain.tip_load.M * L / EI;
  JacobiPasses passes(fx, fy, m0, result.tip.theta, m_tip, backward);
  if (!passes.ready()) return std::nullopt;

  // The re-integrated elastica must end where the solution does (the tip angle, or the clamp's
  // angle 0 and moment), compared on the tangent (the angle modulo 2 pi: the pass integrates
  // cos theta and sin theta).
  const auto meets = [&](const Pass& p) {
    if (backward) {
      return std::fabs(std::atan2(p.end_sin, p.end_cos)) <= kTipAngleCheck &&
             std::fabs(p.end_m - m0) <= kTipAngleCheck * std::max(1.0, std::fabs(m0));
    }
    const double c = std::cos(result.tip.theta), s = std::sin(result.tip.theta);
    // The angle from the solution's tangent to the pass's.
    return std::fabs(std::atan2(c * p.end_sin - s * p.end_cos, c * p.end_cos + s * p.end_sin)) <=
           kTipAngleCheck;
  };
  // The index: eigenvalues below -tolerance, i.e. the count at sigma_t = 1 / (1 + tolerance).
  const double sigma_t = 1.0 / (1.0 + tolerance);
  const double q_max = std::sqrt(kMaxSigma);
  // The lowest eigenvalue: f(sigma) = 0, sigma = q^2; f > 0 exactly below sigma_1 (the count is
  // nondecreasing in sigma), so its sign brackets q_1.
  double q_lo = 0.0, q_hi = HUGE_VAL;
  double q = 0.0;
  std::optional<int> index;
  const bool guessed = margin_guess && std::isfinite(*margin_guess) && *margin_guess < 1.0;
  if (guessed) {
    // A sweep's prediction from its neighbours' margins (beam_sweep_solver.h): Newton's method
    // starts there, the index pass is left out unless sigma_1 turns out below sigma_t (an index
    // of 0 follows from sigma_1 >= sigma_t alone: sigma_1 is the lowest eigenvalue's).
    q = std::sqrt(1.0 / (1.0 - *margin_guess));
    if (!(q < q_max)) q = 0.5 * q_max;
  } else {
    const Pass first = passes.run(sigma_t);
    if (!first.ok || !meets(first)) return std::nullopt;
    index = first.count;
    if (*index == 0) {
      q_lo = std::sqrt(sigma_t);
    } else {
      q_hi = std::sqrt(sigma_t);
    }
    // No compression at the first pass's steps: the shape is in tension nearly everywhere, its
    // margin close to 1, which the general verdict resolves.
    if (!(first.gamma > 0.0)) return std::nullopt;
    // The straight column's guess: q int sqrt(max(0, -F . t)) ds = pi/2.
    q = 0.5 * kPi / first.gamma;
    if (!(q > q_lo && q < q_hi)) {
      q = std::isfinite(q_hi) ? 0.5 * (q_lo + q_hi) : std::min(2.0 * q_lo, q_max);
    }
  }
  for (int iteration = 0;; ++iteration) {
    if (iteration >= kMaxIterations) return std::nullopt;
    if (q_lo >= q_max) return std::nullopt;
    const Pass p = passes.run(q * q);
    if (!p.ok) return std::nullopt;
    if (iteration == 0 && guessed && (!meets(p) || !(p.gamma > 0.0))) return std::nullopt;
    (p.f > 0.0 ? q_lo : q_hi) = q;
    const double slope = 2.0 * q * p.df;
    double next = slope < 0.0 ? q - p.f / slope : HUGE_VAL;
    if (std::fabs(next - q) <= kStepTolerance * q && next > 0.0) {
      q = next;
      break;
    }
    // From a guess the iterates may start far above sigma_1, where a step can overshoot past
    // q_max (passes there fail as the Jacobi solutions grow by e^300): kept below it.
    if (!(next > q_lo && next < q_hi) || (guessed && next >= q_max)) {
      next = std::isfinite(q_hi) ? 0.5 * (q_lo + q_hi) : std::min(2.0 * q, q_max);
    }
    if (std::isfinite(q_hi) && q_hi - q_lo <= 1e-15 * q_hi) {
      q = 0.5 * (q_lo + q_hi);
      break;
    }
    q = next;
  }
  // The bracket holds the answer exactly; the last Newton step may overshoot it by rounding.
  q = std::clamp(q, q_lo, q_hi);
  if (!index) {
    // sigma_1 clearly above sigma_t: no eigenvalue below -tolerance. Else (unstable or close to
    // critical) the count at sigma_t, as without a guess.
    if (q * q > sigma_t * (1.0 + 1e-8)) {
      index = 0;
    } else {
      const Pass at_t = passes.run(sigma_t);
      if (!at_t.ok) return std::nullopt;
      index = at_t.count;
    }
  }
  const double sigma_1 = q * q;
  const double margin = 1.0 - 1.0 / sigma_1;
  return verdict(*index, margin);
}

}  // namespace

std::optional<Stability> compressed_cantilever_stability(const SegmentChain& chain,
                                                         const ShootingResult& result,
                                                         const StabilityOptions& options,
                                                         std::optional<double> margin_guess) {
  if (margin_guess) {
    // Where the search from the guess does not settle (a pass fails far from sigma_1, or any
    // other reason to decline), the verdict is the one without it: a guess never changes it.
    if (std::optional<Stability> v = jacobi_verdict(chain, result, options, margin_guess)) return v;
  }
  return jacobi_verdict(chain, result, options, std::nullopt);
}

}  // namespace flexure
