#pragma once
// Carlson's symmetric elliptic integrals of the first and second kind,
//   R_F(x, y, z) = 1/2 int_0^inf dt / sqrt((t + x)(t + y)(t + z))             (DLMF 19.16.1)
//   R_D(x, y, z) = 3/2 int_0^inf dt / (sqrt((t + x)(t + y)) (t + z)^(3/2))     (DLMF 19.16.5)
// by the duplication theorem and a truncated Taylor series at the mean (B. C. Carlson, "Numerical
// computation of real or complex elliptic integrals", Numer. Algorithms 10 (1995) 13-26; DLMF
// 19.36.1-19.36.2). They are the building blocks of F(phi|m) and E(phi|m) (DLMF 19.25.5, 19.25.9).
//
// Written here rather than taken from GSL (gsl_sf_ellint_RF/RD, the same method) because the
// solver spends most of its time in them: GSL sums fifth-order series and so duplicates until the
// arguments agree to about 1e-3; this version sums the seventh-order series of DLMF 19.36.1 and
// 19.36.2, which ends the duplication one or two steps earlier at the same accuracy (a few units
// in the last place, checked against mpmath in tests/solver/carlson_integrals_test.cpp).
namespace flexure::elliptic {

// x, y, z >= 0, at most one of them zero. Throws NoConvergence naming the arguments otherwise.
double carlson_rf(double x, double y, double z);
// x, y >= 0 (not both zero), z > 0. Throws NoConvergence naming the arguments otherwise.
double carlson_rd(double x, double y, double z);

// Both at the same arguments, for the cost of one duplication sequence (x, y >= 0 not both zero,
// z > 0).
struct CarlsonPair {
  double rf = 0.0;
  double rd = 0.0;
};
CarlsonPair carlson_rf_rd(double x, double y, double z);

}  // namespace flexure::elliptic
