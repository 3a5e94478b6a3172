#pragma once
// Elliptic integrals and the Jacobi elliptic functions, for real amplitudes and arguments of any
// size.
//
// Every function takes the parameter m = k^2 together with its complement mc = 1 - m, computed by
// the caller from quantities that keep full relative precision. Near the separatrix of the elastica
// (m -> 1) the complement is 1e-8 or smaller; forming it as 1 - m would lose half the digits
// (docs/theory-elliptic.md).
// - Incomplete integrals from Carlson's symmetric forms (carlson_integrals.h), which take the
//   complement directly:
//     F(phi|m) = sin(phi) RF(cos^2 phi, 1 - m sin^2 phi, 1)                      (DLMF 19.25.5)
//     F(phi|m) - E(phi|m) = (m/3) sin^3(phi) RD(cos^2 phi, 1 - m sin^2 phi, 1)   (DLMF 19.25.9)
//   extended to any real phi by F(phi + j pi) = F(phi) + 2 j K (Howell eqs. F.17-F.18).
// - Complete integrals by the arithmetic-geometric mean started from sqrt(mc):
//   K = pi / (2 M(1, k')) and K - E = K sum 2^(n-1) c_n^2 (DLMF 19.8.1, 19.8.2; Howell eqs. F.8,
//   F.10), a fifth of the cost of R_F.
// - sn, cn, dn and the amplitude am by the AGM (DLMF 22.20(ii)), also started from sqrt(mc), in
//   Bulirsch's rational form of the descending transformation (R. Bulirsch, "Numerical calculation
//   of elliptic integrals and elliptic functions", Numer. Math. 7 (1965) 78-90): one sine and
//   cosine at the top of the AGM and a rational recurrence back down. The classical
//   back-substitution phi_{n-1} = (phi_n + asin(c_n/a_n sin phi_n))/2 (DLMF 22.20.2) takes asin
//   within 2 sqrt(mc) of 1 and loses half the digits near the separatrix; the rational form keeps
//   am, sn, cn and dn to a few units of round-off times |u| for any mc (checked against mpmath in
//   tests/solver/elliptic_functions_test.cpp).
namespace flexure::elliptic {

struct Parameter {
  double m = 0.0;   // k^2, in [0, 1]
  double mc = 1.0;  // 1 - k^2, in [0, 1]
};

// K(m) = RF(0, mc, 1), by the AGM.
double complete_K(Parameter k);
// (K(m) - E(m)) / m = RD(0, mc, 1) / 3, finite as m -> 0, by the AGM.
double complete_K_minus_E_over_m(Parameter k);

// F(phi|m) and (F(phi|m) - E(phi|m)) / m for any real phi. Dividing by m keeps the second value
// accurate when m -> 0 (pure end moment limit of the non-inflectional family).
struct IncompleteIntegrals {
  double F = 0.0;
  double D_over_m = 0.0;
};
IncompleteIntegrals incomplete_integrals(double phi, Parameter k);
double incomplete_F(double phi, Parameter k);

// F(phi|m) for phi = half_turns * pi + phi_r, given sin(phi_r) and cos(phi_r) >= 0 directly. Near
// the separatrix the amplitude sits at pi/2 to within 1e-9 and only its cosine, formed by the
// caller without cancellation, carries the digits.
double incomplete_F(int half_turns, double sin_phi_r, double cos_phi_r, Parameter k);

// (F - E)/m at argument u with amplitude phi = am(u). For m > 1/2 it is formed as (u - E(phi))/m:
// E varies slowly where F is steep (phi near pi/2, m near 1), so an amplitude recomputed from u
// costs no digits; for m <= 1/2 the Carlson form keeps the pure-moment limit m -> 0 exact.
double D_over_m_at(double u, double phi, Parameter k);

// Jacobi amplitude am(u|m), continuous in u (am(u + 2K) = am(u) + pi).
double jacobi_amplitude(double u, Parameter k);

// sn(u|m), cn(u|m), dn(u|m) and am(u|m) together, from one Gauss transformation.
struct JacobiFunctions {
  double sn = 0.0;
  double cn = 1.0;
  double dn = 1.0;
  double am = 0.0;  // continuous in u
};
JacobiFunctions jacobi_functions(double u, Parameter k);
// The same without the amplitude (am is left NaN), for callers that need only sn, cn and dn: the
// amplitude costs an atan2, a fifth of the whole.
JacobiFunctions jacobi_sn_cn_dn(double u, Parameter k);
// The same, and M(1, k') = pi / (2 K) from the same AGM (DLMF 19.8.5; 0 at m = 1), for callers
// that count periods.
JacobiFunctions jacobi_sn_cn_dn(double u, Parameter k, double& agm_mean);

// delta(phi) = sqrt(1 - m sin^2 phi) = dn(u) at phi = am(u), formed as sqrt(mc + m cos^2 phi).
double delta_amplitude(double phi, Parameter k);

}  // namespace flexure::elliptic
