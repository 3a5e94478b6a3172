#include "flexure/solver/chain/element_flexibility.h"

namespace flexure {

ElementFlexibility element_flexibility(double length, double EI, double P_ax) {
  const double L = length;
  const double L2P = L * L * P_ax;
  // Common denominator of eq. 7.30, D = Q2 + 240 E^2 I^2 with Q2 from eq. 7.32; it is proportional
  // to the determinant of the eq. 7.29 block.
  const double D = 240.0 * EI * EI + 104.0 * EI * L2P + 3.0 * L2P * L2P;
  ElementFlexibility f;
  // Past the first root of D the block is indefinite: the element has buckled (tension never gets
  // here since every term of D is then positive). Require a positive f33 as well.
  const double kBucklingMargin = 1e-12;
  if (!(D > kBucklingMargin * 240.0 * EI * EI) || !(10.0 * EI + L2P > 0.0)) return f;
  f.f22 = 8.0 * L * L * L * (30.0 * EI + L2P) / (3.0 * D);  // Howell eq. 7.30, [K]^-1_22
  f.f23 = 2.0 * L * L * (60.0 * EI + L2P) / D;              // Howell eq. 7.30, [K]^-1_23
  f.f33 = 24.0 * L * (10.0 * EI + L2P) / D;                 // Howell eq. 7.30, [K]^-1_33
  f.valid = true;
  return f;
}

ElementStiffness element_stiffness(double length, double EI, double P_ax) {
  const double L = length;
  ElementStiffness k;
  // Howell eq. 7.29: the free-end rows of eq. 7.28 with u1 = u2 = u3 = 0.
  k.k22 = 12.0 * EI / (L * L * L) + P_ax * 36.0 / (30.0 * L);
  k.k23 = -6.0 * EI / (L * L) - P_ax * 3.0 / 30.0;
  k.k33 = 4.0 * EI / L + P_ax * 4.0 * L / 30.0;
  return k;
}

}  // namespace flexure
