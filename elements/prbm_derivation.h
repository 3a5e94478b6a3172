#pragma once
// Re-derivation of the PRB constants gamma, Theta_max(gamma), c_theta and K_theta from exact tips,
// by Howell's definitions (§5.2, eqs. 5.42-5.47, 5.53, 5.59; §5.5 for curved beams). The procedure
// (docs/prbm.md):
//
//  1. Sample the exact tip path: uniformly in the tip angle theta0 (step `theta0_step_deg`) from
//     the elliptic solver's inverse problem (fixed-pinned, 0 < theta0 < phi = atan2(1, -n)) or
//     from the circle of a pure end moment (a/l = sin theta0/theta0, b/l = (1 - cos
//     theta0)/theta0); for the initially curved cantilever uniformly in the PRB angle
//     (derive_initially_curved).
//  2. For a trial gamma, Theta = atan2(b, a - (1 - gamma)) (eq. 5.42 / 5.115) and the relative
//     position error error/delta (eq. 5.47), delta measured from the unloaded tip. Theta_max(gamma)
//     is the PRB deflection Theta - Theta_i at which error/delta first exceeds `error_limit`
//     (0.5 %), linearly interpolated between samples. For the force, extra samples at
//     theta0 = phi - step/2^k (k = 1..`tail_samples`) resolve the end of the path, where the load
//     grows without bound; they are used for Theta_max only, never in the fits.
//  3. gamma maximises Theta_max(gamma): a coarse grid, then grids ten times finer (+-2 steps of the
//     previous grid around its best point) down to `gamma_fine_step`, then bisection on the jump
//     where a hump of the error curve touches the limit (Theta_max(gamma) is discontinuous there,
//     so golden-section search is not safe). Finally Theta_max is refined by root finding on the
//     exact error function between the bracketing samples.
//  4. c_theta: least squares through the origin of theta0 - theta0_i against Theta - Theta_i over
//     0 < Theta - Theta_i <= Theta_max(gamma).
//  5. K_theta: least squares through the origin of the tangential load against Theta - Theta_i
//     over 0 < Theta - Theta_i <= Theta_max(K_theta): (alpha2)_t = alpha2 eta sin(phi - Theta) for
//     the force (eqs. 5.57, 5.123), mu/gamma for the end moment (eq. 5.111, K = gamma K_theta; as
//     mu = theta0 on the circle, c_theta = gamma K_theta identically, eq. 5.112).
//     Theta_max(K_theta) is an input (Howell does not state its criterion): Table 5.1's value when
//     n is a row, 0.7 phi (eq. 5.63) for other n < 0, Table 5.1 interpolated in n for other n >= 0
//     (curved beams: that value scaled by (phi - Theta_i)/phi).
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "flexure/solver/common/status.h"

namespace flexure {

// One exact tip on the load path: tip angle, tip position and the load that produces it.
struct PathSample {
  double theta0 = 0.0;  // rad
  double a = 1.0;       // a/l
  double b = 0.0;       // b/l
  double load = 0.0;    // alpha2 = P l^2/EI (force) or mu = M l/EI (end moment)
  bool in_fit = true;   // false for the extra tail samples approaching theta0 -> phi, which locate
                        // Theta_max(gamma) but stay out of the uniformly weighted fits
  double path_parameter = 0.0;  // the argument of the path's `exact` function that gives this tip
                                // (theta0 for the straight paths, alpha2 for the curved beam)
};

// The unloaded tip the deflection is measured from: (1, 0, 0) for an initially straight beam, the
// circular arc a_i/l = sin kappa0/kappa0, b_i/l = (1 - cos kappa0)/kappa0, theta0 = kappa0 for an
// initially curved one (Howell eqs. 5.117-5.118).
struct UnloadedTip {
  double a = 1.0;
  double b = 0.0;
  double theta0 = 0.0;
  static UnloadedTip circular_arc(double kappa0);
};

// PRB angle of an exact tip for characteristic radius factor gamma (Howell eq. 5.42 / 5.115): the
// pivot sits at ((1 - gamma) l, 0) whether or not the beam is initially curved.
double prb_angle(const PathSample& sample, double gamma);
// PRB link length rho l (eq. 5.116; rho = gamma for a straight beam) and its unloaded angle
// Theta_i (eq. 5.115; 0 for a straight beam).
double prb_link_length(double gamma, const UnloadedTip& unloaded);
double prb_initial_angle(double gamma, const UnloadedTip& unloaded);
// Position error of the PRB tip (eqs. 5.119-5.120, or 5.49-5.50 when straight) relative to the tip
// deflection from the unloaded tip, error/delta (eqs. 5.44-5.47).
double relative_position_error(const PathSample& sample,
                               double gamma,
                               const UnloadedTip& unloaded = {});

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
  // Initially curved cantilever only (derive_initially_curved):
  double curved_reference_gamma = 0.85;    // pivot ((1 - this) l, 0) about which the samples are
                                           // spaced uniformly in Theta (theta0 is not monotone)
  double curved_alpha2_max = 200.0;        // the sampled path ends at this load
  bool curved_K_range_from_gamma = false;  // fit K_theta over Theta_max(gamma) of the curved beam
                                           // instead of the straight-beam Theta_max(K_theta) of n
  // Throws InvalidInput naming the field unless every option is finite and in its range.
  void validate() const;
};

// The segment a derivation is for: fixed-pinned under a tip force (Howell §5.2), the end moment
// (§5.4), the initially curved cantilever (§5.5).
enum class PrbmSegment { kFixedPinned, kEndMoment, kInitiallyCurved };
// "fixed-pinned", "end-moment", "initially-curved": the names of `flexure prbm --segment` and of
// the JSON key "segment".
std::string_view to_string(PrbmSegment segment);
// The segment of that name; throws InvalidInput quoting the name and listing the allowed ones.
PrbmSegment prbm_segment_from_string(std::string_view name);

struct PrbmDerivation : SolveStatus {
  // message: what limited the result, or why it failed
  // iterations: exact tip evaluations (samples + root-finding refinements)
  // residual: |error/delta - error_limit| at the refined Theta_max(gamma)

  PrbmSegment segment = PrbmSegment::kFixedPinned;
  double load_ratio_n = 0.0;
  double kappa0 = 0.0;   // initial curvature l/R_i (0 unless initially curved)
  double rho = 0.0;      // PRB link length / l at the derived gamma (eq. 5.116; gamma if straight)
  double theta_i = 0.0;  // unloaded PRB angle Theta_i, rad (eq. 5.115; 0 if straight)
  double phi = 0.0;      // force angle atan2(1, -n), rad (pi for the end moment: unused)
  double gamma = 0.0;
  double theta_max_gamma = 0.0;        // rad, measured from Theta_i (the PRB deflection)
  double theta0_at_theta_max = 0.0;    // rad, tip angle where the error reaches the limit
  bool theta_max_at_path_end = false;  // error never reached the limit before theta0 -> phi
  double c_theta = 0.0;                // (theta0 - theta0_i) = c_theta (Theta - Theta_i)
  double K_theta = 0.0;                // (alpha2)_t = K_theta (Theta - Theta_i)
  double theta_max_K = 0.0;            // rad, the range of Theta - Theta_i used for the K_theta fit
  std::string theta_max_K_source;
  int samples = 0;  // exact tips on the sampled path
  int samples_c_theta_fit = 0;
  int samples_K_theta_fit = 0;
};

// Howell's Table 5.1 constants for load ratio n (-20 <= n <= 20) from the exact elliptic solution.
PrbmDerivation derive_fixed_pinned(double load_ratio_n, const PrbmDerivationOptions& options = {});

// End-moment constants (Howell §5.4) from the closed-form circular tip path.
PrbmDerivation derive_end_moment(const PrbmDerivationOptions& options = {});

// Initially curved cantilever (Howell §5.5) with a tip force at load ratio n: the same procedure on
// the exact path of a circular arc of curvature kappa0 = l/R_i (0 <= kappa0 <= 3). Its theta(s) is
// that of a straight beam with end moment mu = kappa0 (EI(theta' - kappa0/l) = M(s), eq. 2.103), so
// the tips come from EllipticSolver::solve(EndLoad::howell(n, alpha2, kappa0)). The samples are
// spaced uniformly in the PRB angle about the pivot of `curved_reference_gamma` (theta0 is not
// monotone in the load), deflections and angles are measured from the unloaded arc (eqs.
// 5.115-5.120), and K_theta fits (alpha2)_t = alpha2 eta sin(phi - Theta) against Theta - Theta_i
// (eqs. 5.121-5.124) over the straight-beam Theta_max(K_theta) of n (the rule of
// derive_fixed_pinned) or, with `curved_K_range_from_gamma`, over Theta_max(gamma). Not converged
// (with the reason) when the force does not open the PRB link (phi <= Theta_i + 1 deg).
PrbmDerivation derive_initially_curved(double kappa0,
                                       double load_ratio_n,
                                       const PrbmDerivationOptions& options = {});

// Table 5.2's "recommended values": the constants of derive_initially_curved averaged over the
// load ratio, (int f dn)/(int dn) as in Howell eqs. 5.51 and 5.64, by the trapezoid rule on
// n_intervals equal steps of [n_min, n_max]. Two passes on the same exact samples: (1) gamma (and
// c_theta) per n, averaged; rho and Theta_i follow from the averaged gamma (eqs. 5.115-5.118);
// (2) K_theta per n with gamma fixed at that average -- the link the model uses for every n
// ("a constant value of gamma for various values of n", §5.5.1) -- averaged. Load ratios whose
// derivation fails (the force does not open the link, or the path ends first) are left out and
// named in `message`; the average is then over the remaining ones.
struct CurvedCantileverAverage : SolveStatus {
  // iterations: elliptic solves over all load ratios
  // residual: largest per-n residual of pass 1
  double kappa0 = 0.0;
  double n_min = -0.5;
  double n_max = 1.0;
  double gamma = 0.0;
  double rho = 0.0;                   // eq. 5.116 with the averaged gamma
  double theta_i = 0.0;               // eq. 5.115 with the averaged gamma, rad
  double K_theta = 0.0;               // pass 2: per-n fits at the averaged gamma, averaged
  double K_theta_per_n_gamma = 0.0;   // pass 1: per-n fits at each n's own gamma, averaged
  double c_theta = 0.0;               // pass 1
  double theta_max_gamma_min = 0.0;   // smallest per-n Theta_max(gamma) - Theta_i of pass 1, rad
  std::vector<PrbmDerivation> per_n;  // pass 1, every load ratio
  std::vector<PrbmDerivation> per_n_at_average_gamma;  // pass 2, every load ratio
  int used = 0;                                        // load ratios in the gamma average
  int used_K = 0;                                      // load ratios in the K_theta average
};
CurvedCantileverAverage derive_initially_curved_average(double kappa0,
                                                        double n_min = -0.5,
                                                        double n_max = 1.0,
                                                        int n_intervals = 6,
                                                        const PrbmDerivationOptions& options = {});

// The generic procedure on a sampled path (Theta increasing along it). `exact` evaluates a tip at
// any path parameter between two samples' `path_parameter` (used to refine Theta_max);
// `tangential_load(sample, Theta, gamma)` gives the quantity fitted by K_theta (Theta - Theta_i);
// `unloaded` is the tip the deflections and Theta_i are measured from.
PrbmDerivation derive_from_path(
    const std::vector<PathSample>& samples,
    const std::function<PathSample(double)>& exact,
    const std::function<double(const PathSample&, double, double)>& tangential_load,
    double theta_max_K,
    const PrbmDerivationOptions& options,
    const UnloadedTip& unloaded = {});

}  // namespace flexure
