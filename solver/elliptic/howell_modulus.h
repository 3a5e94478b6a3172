#pragma once
// The modulus of the mu = 0 branch (howell_branch.h) in the form that keeps full precision at
// small loads and near the separatrix, shared by the forward solve and the inverse problems.
#include <cmath>

namespace flexure::elliptic {

// The modulus of the branch, held as p = k'^2 and q = k^2 - s0^2 with p + q = c0^2
// (s0 = sin(chi0/2) = cos(psi/2), c0 = cos(chi0/2) = sin(psi/2)).
struct SplitModulus {
  double p = 0.0;
  double q = 0.0;
};

// The split at tip angle theta0 in (0, psi): k = sin(chi1/2) with chi1 = chi0 + theta0, so
// p = cos^2(chi1/2) = sin^2((psi - theta0)/2) and q = sin(theta0/2) sin(psi - theta0/2), both
// without cancellation.
inline SplitModulus split_from_tip_angle(double psi, double theta0) {
  const double half_gap = std::sin(0.5 * (psi - theta0));
  return {half_gap * half_gap, std::sin(0.5 * theta0) * std::sin(psi - 0.5 * theta0)};
}

// Amplitude beta* with K - F(beta, k) = F(beta*, k), from tan(beta) tan(beta*) = 1/k' (DLMF
// 19.11.4 with phi + psi = K): the arguments of the Carlson integrals for F(beta*, k).
struct ComplementAmplitude {
  double sin2 = 0.0;    // sin^2 beta*
  double cos2 = 0.0;    // cos^2 beta*
  double delta2 = 0.0;  // 1 - k^2 sin^2 beta*
  double k2 = 0.0;      // k^2
};

inline ComplementAmplitude complement_amplitude(SplitModulus split, double s0_sq) {
  ComplementAmplitude c;
  const double inverse = 1.0 / (split.q + split.p * s0_sq);
  c.k2 = s0_sq + split.q;
  c.sin2 = split.q * inverse;
  c.cos2 = split.p * s0_sq * inverse;
  c.delta2 = split.p * c.k2 * inverse;
  return c;
}

}  // namespace flexure::elliptic
