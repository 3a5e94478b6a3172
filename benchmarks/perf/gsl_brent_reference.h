#pragma once
// The yardstick of the speed goals of issues 14 and 27: a straightforward solve of Howell's
// cantilever (n = 0, mu = 0, alpha2 between 0.5 and 20) with GSL's elliptic integrals and GSL's
// Brent root finder. The machine is shared, so docs/performance.md quotes each path as a ratio to
// it measured in the same run; elliptic_bench and shooting_sweep_bench both register it.
//
// Howell eq. 2.90 for n = 0, alpha = K(t) - F(gamma, t) with lambda = sin(theta0),
// t = sqrt((1 + lambda)/2), gamma = asin(sqrt(1/(1 + lambda))) (eqs. 2.84, 2.91, 2.92), solved
// for theta0 by gsl_root_fsolver_brent to 1e-13 rad, then the tip by eqs. 2.96 and 2.98. The same
// loads as elliptic_bench's BM_ForwardVerticalLoad.
#include <benchmark/benchmark.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_sf_ellint.h>

#include <cmath>
#include <numbers>

namespace flexure_bench {

// The loads of the reference, alpha2 in [0.5, 20].
inline double reference_load(int i) { return 0.5 + 19.5 * (i % 997) / 997.0; }

struct HowellN0 {
  double alpha = 0.0;
};

inline double howell_n0_residual(double theta0, void* params) {
  const double alpha = static_cast<HowellN0*>(params)->alpha;
  const double lambda = std::sin(theta0);
  const double t = std::sqrt(0.5 * (1.0 + lambda));
  const double gamma = std::asin(std::sqrt(1.0 / (1.0 + lambda)));
  return gsl_sf_ellint_Kcomp(t, GSL_PREC_DOUBLE) - gsl_sf_ellint_F(gamma, t, GSL_PREC_DOUBLE) -
         alpha;
}

inline void BM_GslBrentReference(benchmark::State& state) {
  constexpr double kPi = std::numbers::pi;
  gsl_set_error_handler_off();
  gsl_root_fsolver* brent = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  HowellN0 params;
  gsl_function f{&howell_n0_residual, &params};
  int i = 0;
  for (auto _ : state) {
    params.alpha = std::sqrt(reference_load(i++));
    // theta0 lies in (0, pi/2): at 0 the residual is -alpha, near pi/2 K(t) grows without bound.
    gsl_root_fsolver_set(brent, &f, 0.0, 0.5 * kPi - 1e-6);
    double lo = 0.0, hi = 0.5 * kPi;
    for (int it = 0; it < 100; ++it) {
      gsl_root_fsolver_iterate(brent);
      lo = gsl_root_fsolver_x_lower(brent);
      hi = gsl_root_fsolver_x_upper(brent);
      if (gsl_root_test_interval(lo, hi, 1e-13, 0.0) == GSL_SUCCESS) break;
    }
    const double theta0 = gsl_root_fsolver_root(brent);
    const double lambda = std::sin(theta0);
    const double t = std::sqrt(0.5 * (1.0 + lambda));
    const double gamma = std::asin(std::sqrt(1.0 / (1.0 + lambda)));
    const double span =
        gsl_sf_ellint_Kcomp(t, GSL_PREC_DOUBLE) - gsl_sf_ellint_F(gamma, t, GSL_PREC_DOUBLE);
    const double bracket = span + 2.0 * (gsl_sf_ellint_E(gamma, t, GSL_PREC_DOUBLE) -
                                         gsl_sf_ellint_Ecomp(t, GSL_PREC_DOUBLE));
    const double b_over_l = bracket / params.alpha;  // 2.96
    const double a_over_l =
        std::sqrt(2.0 * (1.0 + lambda)) * std::cos(gamma) / params.alpha;  // 2.98
    benchmark::DoNotOptimize(a_over_l);
    benchmark::DoNotOptimize(b_over_l);
  }
  gsl_root_fsolver_free(brent);
}

}  // namespace flexure_bench
