#include "flexure/solver/elliptic/carlson_integrals.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "flexure/solver/common/errors.h"

namespace flexure::elliptic {
namespace {

// The duplication x -> (x + lambda)/4 (DLMF 19.26.18) shrinks the relative spread of the
// arguments about their mean A by 4 per step. The series is summed once the spread is below
// these fractions of A: R_F's seventh-order series then errs by about 0.008^8 ~ 2e-17, R_D's
// fifth-order series (Carlson 1995, eq. 2.29) by about 0.0015^6 ~ 1e-17.
constexpr double kSpreadRF = 0.008;
constexpr double kSpreadRD = 0.0015;

double spread(double a, double x, double y, double z) {
  return std::max({std::fabs(a - x), std::fabs(a - y), std::fabs(a - z)});
}

}  // namespace

double carlson_rf(double x, double y, double z) {
  if (!(x >= 0.0 && y >= 0.0 && z >= 0.0) || std::min({x + y, y + z, z + x}) == 0.0) {
    throw NoConvergence(fmt::format(
        "Carlson R_F({}, {}, {}): arguments outside the domain (all >= 0, at most one zero)",
        x,
        y,
        z));
  }
  const double a0 = (x + y + z) / 3.0;
  // Carlson's stopping rule: step n is the last when Q / 4^n < |A_n|, with Q the initial spread
  // over the tolerated relative spread; the deviations of the last step follow from the first
  // (A_n - x_n = (A_0 - x_0) / 4^n exactly), so they are formed without cancellation.
  double q = spread(a0, x, y, z) / kSpreadRF;
  double a = a0, xn = x, yn = y, zn = z, scale = 1.0;
  while (q >= std::fabs(a)) {
    const double sx = std::sqrt(xn), sy = std::sqrt(yn), sz = std::sqrt(zn);
    const double lambda = sx * (sy + sz) + sy * sz;
    xn = 0.25 * (xn + lambda);
    yn = 0.25 * (yn + lambda);
    zn = 0.25 * (zn + lambda);
    a = 0.25 * (a + lambda);
    q *= 0.25;
    scale *= 0.25;
  }
  const double X = (a0 - x) * scale / a;
  const double Y = (a0 - y) * scale / a;
  const double Z = -(X + Y);
  const double E2 = X * Y - Z * Z;
  const double E3 = X * Y * Z;
  // DLMF 19.36.1.
  const double series = 1.0 - E2 / 10.0 + E3 / 14.0 + E2 * E2 / 24.0 - 3.0 * E2 * E3 / 44.0 -
                        5.0 * E2 * E2 * E2 / 208.0 + 3.0 * E3 * E3 / 104.0 + E2 * E2 * E3 / 16.0;
  return series / std::sqrt(a);
}

double carlson_rd(double x, double y, double z) {
  if (!(x >= 0.0 && y >= 0.0 && z > 0.0) || x + y == 0.0) {
    throw NoConvergence(fmt::format(
        "Carlson R_D({}, {}, {}): arguments outside the domain (x, y >= 0 not both zero, z > 0)",
        x,
        y,
        z));
  }
  const double a0 = (x + y + 3.0 * z) / 5.0;
  double q = spread(a0, x, y, z) / kSpreadRD;
  double a = a0, xn = x, yn = y, zn = z, scale = 1.0, sum = 0.0;
  while (q >= std::fabs(a)) {
    const double sx = std::sqrt(xn), sy = std::sqrt(yn), sz = std::sqrt(zn);
    const double lambda = sx * (sy + sz) + sy * sz;
    sum += scale / (sz * (zn + lambda));
    xn = 0.25 * (xn + lambda);
    yn = 0.25 * (yn + lambda);
    zn = 0.25 * (zn + lambda);
    a = 0.25 * (a + lambda);
    q *= 0.25;
    scale *= 0.25;
  }
  const double X = (a0 - x) * scale / a;
  const double Y = (a0 - y) * scale / a;
  const double Z = -(X + Y) / 3.0;
  const double XY = X * Y, Z2 = Z * Z;
  const double E2 = XY - 6.0 * Z2;
  const double E3 = (3.0 * XY - 8.0 * Z2) * Z;
  const double E4 = 3.0 * (XY - Z2) * Z2;
  const double E5 = XY * Z2 * Z;
  // Carlson (1995), eq. 2.29.
  const double series = 1.0 - 3.0 * E2 / 14.0 + E3 / 6.0 + 9.0 * E2 * E2 / 88.0 - 3.0 * E4 / 22.0 -
                        9.0 * E2 * E3 / 52.0 + 3.0 * E5 / 26.0;
  return scale * series / (a * std::sqrt(a)) + 3.0 * sum;
}

}  // namespace flexure::elliptic
