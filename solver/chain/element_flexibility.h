#pragma once
// Flexibility of one chain-algorithm beam element: a cantilever of length L clamped at its near
// end, loaded at its far end by a transverse force P_tr, an end moment M and an axial force P_ax.
//
// Howell eq. 7.30 inverts the 2x2 transverse/rotation block of the reduced stiffness matrix
// (eq. 7.29): the linear Euler-Bernoulli stiffness plus the consistent geometric stiffness of the
// axial force (eq. 7.28). P_ax is positive in TENSION (tension stiffens the element); the
// simplified alternative of eqs. 7.33-7.36 needs the opposite sign (erratum 7.34,
// docs/theory-chain.md) and is not used here. The axial flexibility L/AE of eq. 7.30 is omitted:
// the element is inextensible.
namespace flexure {

// Symmetric 2x2 flexibility [f22 f23; f23 f33] mapping (P_tr, M) to (delta_tr, delta_theta).
struct ElementFlexibility {
  double f22 = 0.0;    // transverse deflection per unit transverse force (L^3/3EI at P_ax = 0)
  double f23 = 0.0;    // coupling term (L^2/2EI at P_ax = 0)
  double f33 = 0.0;    // rotation per unit end moment (L/EI at P_ax = 0)
  bool valid = false;  // false when the element is at or past its (discrete) buckling load
};

// Howell eqs. 7.30-7.32, factored (docs/theory-chain.md):
//   f22 = 8L^3 (30EI + L^2 P) / (3D),  f23 = 2L^2 (60EI + L^2 P) / D,  f33 = 24L (10EI + L^2 P) /
//   D, D = 240 EI^2 + 104 EI L^2 P + 3 L^4 P^2.
// D vanishes at L^2 P/EI = -2.4857 (the consistent-geometric-stiffness estimate of the cantilever
// Euler load, exact value -pi^2/4 = -2.4674); for compression at or beyond it `valid` is false.
ElementFlexibility element_flexibility(double length, double EI, double P_ax);

// The reduced stiffness block of eq. 7.29 (transverse/rotation part), for testing the inverse:
// K = EI/L^3 [12, -6L; -6L, 4L^2] + P_ax/(30L) [36, -3L; -3L, 4L^2].
struct ElementStiffness {
  double k22 = 0.0;
  double k23 = 0.0;
  double k33 = 0.0;
};
ElementStiffness element_stiffness(double length, double EI, double P_ax);

}  // namespace flexure
