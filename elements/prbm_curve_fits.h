#pragma once
// Howell's published curve fits of the PRB constants (eqs. 5.48, 5.60-5.62). They deviate from the
// tables they were fitted to by up to ~0.002 in gamma and ~0.02 in K_theta, and are discontinuous
// at the branch boundaries (gamma at n = 0.5, K_theta at n = -1); tests check them against their
// printed coefficients, not against the tables.
namespace flexure {

// Characteristic radius factor gamma(n) of a fixed-pinned segment, eq. 5.48, for -5 <= n <= 10.
// At n = 0.5 (which the printed ranges leave out) the middle branch is used: it matches Table 5.1.
double gamma_curve_fit(double load_ratio_n);

// Stiffness coefficient K_theta(n) of a fixed-pinned segment, eqs. 5.60-5.62, for -5 <= n <= 10.
double K_theta_curve_fit(double load_ratio_n);

// Theta_max(K_theta) ~ 0.7 phi (eq. 5.63), phi = atan2(1, -n). Equals Table 5.1 for n < 0 only.
double theta_max_K_rule(double load_ratio_n);

// Initially curved pinned-pinned segment, eqs. 5.138-5.139 (0.5 <= kappa0 <= 1.5).
double pinned_pinned_gamma_curve_fit(double kappa0);
// Eq. 5.142 (0.5 <= kappa0 <= 1.5).
double pinned_pinned_K_theta_curve_fit(double kappa0);

}  // namespace flexure
