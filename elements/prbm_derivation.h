#pragma once
// Re-derivation of the PRB constants gamma, Theta_max(gamma), c_theta and K_theta from exact tips,
// by Howell's definitions (§5.2, eqs. 5.42-5.47, 5.53, 5.59). The procedure (docs/prbm.md):
//
//  1. Sample the exact tip path uniformly in the tip angle theta0 (step `theta0_step_deg`), from
//  the
//     elliptic solver's inverse problem (fixed-pinned, 0 < theta0 < phi = atan2(1, -n)) or from the
//     circle of a pure end moment (a/l = sin theta0/theta0, b/l = (1 - cos theta0)/theta0).
//  2. For a trial gamma, Theta = atan2(b, a - (1 - gamma)) (eq. 5.42) and the relative position
//  error
//     error/delta (eq. 5.47). Theta_max(gamma) is the PRB angle at which error/delta first exceeds
//     `error_limit` (0.5 %), linearly interpolated between samples. For the force, extra samples at
//     theta0 = phi - step/2^k (k = 1..`tail_samples`) resolve the end of the path, where the load
//     grows without bound; they are used for Theta_max only, never in the fits.
//  3. gamma maximises Theta_max(gamma): a coarse grid, then grids ten times finer (+-2 steps of the
//     previous grid around its best point) down to `gamma_fine_step`, then bisection on the jump
//     where a hump of the error curve touches the limit (Theta_max(gamma) is discontinuous there,
//     so golden-section search is not safe). Finally Theta_max is refined by root finding on the
//     exact error function between the bracketing samples.
//  4. c_theta: least squares through the origin of theta0 against Theta, 0 < Theta <=
//  Theta_max(gamma).
//  5. K_theta: least squares through the origin of the tangential load against Theta over
//     0 < Theta <= Theta_max(K_theta): (alpha2)_t = alpha2 eta sin(phi - Theta) for the force (eq.
//     5.57), mu/gamma for the end moment (eq. 5.111, K = gamma K_theta). Theta_max(K_theta) is an
//     input (Howell does not state its criterion): Table 5.1's value when n is a row, 0.7 phi
//     (eq. 5.63) for other n < 0, Table 5.1 interpolated in n for other n >= 0.
#include <functional>
#include <string>
#include <vector>

namespace flexure {

// One exact tip on the load path: tip angle, tip position and the load that produces it.
struct PathSample {
  double theta0 = 0.0;  // rad
  double a = 1.0;       // a/l
  double b = 0.0;       // b/l
  double load = 0.0;    // alpha2 = P l^2/EI (force) or mu = M l/EI (end moment)
  bool in_fit = true;   // false for the extra tail samples approaching theta0 -> phi, which locate
                        // Theta_max(gamma) but stay out of the uniformly weighted fits
};

// PRB angle of an exact tip for characteristic radius factor gamma (Howell eq. 5.42).
double prb_angle(const PathSample& sample, double gamma);
// Position error of the PRB tip relative to the tip deflection, error/delta (eqs. 5.44-5.47).
double relative_position_error(const PathSample& sample, double gamma);

struct PrbmDerivationOptions {
  double theta0_step_deg = 0.1;  // sampling step of the exact tip angle, degrees (> 0, <= 5)
  double error_limit = 0.005;    // error/delta defining Theta_max(gamma) (eq. 5.43), 0.5 %
  double gamma_min = 0.60;       // search interval for gamma
  double gamma_max = 0.99;
  double gamma_coarse_step = 0.002;  // first grid in gamma
  double gamma_fine_step = 1e-5;     // finest grid (each grid is 10x finer than the previous)
  double theta_max_K_deg = 0.0;      // Theta_max(K_theta) in degrees; <= 0 selects the rule above
  double end_moment_theta0_max_deg = 350.0;  // sampled tip-angle range for the end moment
  int tail_samples = 0;  // extra samples approaching phi (0..60); 0 = uniform only
  // Throws InvalidInput naming the field unless every option is finite and in its range.
  void validate() const;
};

struct PrbmDerivation {
  bool converged = false;
  std::string message;    // what limited the result, or why it failed
  int iterations = 0;     // exact tip evaluations (samples + root-finding refinements)
  double residual = 0.0;  // |error/delta - error_limit| at the refined Theta_max(gamma)

  std::string segment;  // "fixed-pinned" or "end-moment"
  double load_ratio_n = 0.0;
  double phi = 0.0;  // force angle atan2(1, -n), rad (pi for the end moment: unused)
  double gamma = 0.0;
  double theta_max_gamma = 0.0;        // rad
  double theta0_at_theta_max = 0.0;    // rad, tip angle where the error reaches the limit
  bool theta_max_at_path_end = false;  // error never reached the limit before theta0 -> phi
  double c_theta = 0.0;
  double K_theta = 0.0;
  double theta_max_K = 0.0;  // rad, the range used for the K_theta fit
  std::string theta_max_K_source;
  int samples = 0;  // exact tips on the sampled path
  int samples_c_theta_fit = 0;
  int samples_K_theta_fit = 0;
};

// Howell's Table 5.1 constants for load ratio n (-20 <= n <= 20) from the exact elliptic solution.
PrbmDerivation derive_fixed_pinned(double load_ratio_n, const PrbmDerivationOptions& options = {});

// End-moment constants (Howell §5.4) from the closed-form circular tip path.
PrbmDerivation derive_end_moment(const PrbmDerivationOptions& options = {});

// The generic procedure on a sampled path (theta0 increasing). `exact` evaluates a tip at any
// theta0 inside the sampled range (used to refine Theta_max); `tangential_load(sample, Theta,
// gamma)` gives the quantity fitted by K_theta Theta.
PrbmDerivation derive_from_path(
    const std::vector<PathSample>& samples,
    const std::function<PathSample(double)>& exact,
    const std::function<double(const PathSample&, double, double)>& tangential_load,
    double theta_max_K,
    const PrbmDerivationOptions& options);

}  // namespace flexure
