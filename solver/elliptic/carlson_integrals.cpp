#include "flexure/solver/elliptic/carlson_integrals.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "flexure/solver/common/status.h"

namespace flexure::elliptic {
namespace {

// The duplication x -> (x + lambda)/4 (DLMF 19.26.18) shrinks the relative spread of the
// arguments about their mean A by 4 per step. The series is summed once the spread is below
// this fraction of A: the seventh-order series (DLMF 19.36.1, 19.36.2) then err by about
// 0.008^8 ~ 2e-17.
constexpr double kSpread = 0.008;

double spread(double a, double x, double y, double z) {
  return std::max({std::fabs(a - x), std::fabs(a - y), std::fabs(a - z)});
}

void require_rf_domain(double x, double y, double z) {
  if (!(x >= 0.0 && y >= 0.0 && z >= 0.0) || std::min({x + y, y + z, z + x}) == 0.0) {
    throw NoConvergence(fmt::format(
        "Carlson R_F({}, {}, {}): arguments outside the domain (all >= 0, at most one zero)",
        x,
        y,
        z));
  }
}

void require_rd_domain(double x, double y, double z) {
  if (!(x >= 0.0 && y >= 0.0 && z > 0.0) || x + y == 0.0) {
    throw NoConvergence(fmt::format(
        "Carlson R_D({}, {}, {}): arguments outside the domain (x, y >= 0 not both zero, z > 0)",
        x,
        y,
        z));
  }
}

// The deviations of the last step follow from the first (A_n - x_n = (A_0 - x_0) / 4^n exactly),
// so they are formed without cancellation; `scale` is 4^-n and `a` is A_n.
double rf_series(double a0, double x, double y, double a, double scale) {
  const double to_relative = scale / a;
  const double X = (a0 - x) * to_relative;
  const double Y = (a0 - y) * to_relative;
  const double Z = -(X + Y);
  const double E2 = X * Y - Z * Z;
  const double E3 = X * Y * Z;
  // DLMF 19.36.1.
  const double series = 1.0 - E2 / 10.0 + E3 / 14.0 + E2 * E2 / 24.0 - 3.0 * E2 * E3 / 44.0 -
                        5.0 * E2 * E2 * E2 / 208.0 + 3.0 * E3 * E3 / 104.0 + E2 * E2 * E3 / 16.0;
  return series / std::sqrt(a);
}

// The same for R_D, plus 3 times the sum of the terms split off at each duplication step.
double rd_series(double a0, double x, double y, double a, double scale, double sum) {
  const double to_relative = scale / a;
  const double X = (a0 - x) * to_relative;
  const double Y = (a0 - y) * to_relative;
  const double Z = -(X + Y) / 3.0;
  const double XY = X * Y, Z2 = Z * Z;
  const double E2 = XY - 6.0 * Z2;
  const double E3 = (3.0 * XY - 8.0 * Z2) * Z;
  const double E4 = 3.0 * (XY - Z2) * Z2;
  const double E5 = XY * Z2 * Z;
  // DLMF 19.36.2.
  const double series = 1.0 - 3.0 * E2 / 14.0 + E3 / 6.0 + 9.0 * E2 * E2 / 88.0 - 3.0 * E4 / 22.0 -
                        9.0 * E2 * E3 / 52.0 + 3.0 * E5 / 26.0 - E2 * E2 * E2 / 16.0 +
                        3.0 * E3 * E3 / 40.0 + 3.0 * E2 * E4 / 20.0 + 45.0 * E2 * E2 * E3 / 272.0 -
                        9.0 * (E3 * E4 + E2 * E5) / 68.0;
  return to_relative * series / std::sqrt(a) + 3.0 * sum;
}

}  // namespace

// Carlson's stopping rule: step n is the last when Q / 4^n < |A_n|, with Q the initial spread over
// the tolerated relative spread.
double carlson_rf(double x, double y, double z) {
  require_rf_domain(x, y, z);
  const double a0 = (x + y + z) / 3.0;
  double q = spread(a0, x, y, z) / kSpread;
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
  return rf_series(a0, x, y, a, scale);
}

double carlson_rd(double x, double y, double z) {
  require_rd_domain(x, y, z);
  const double a0 = (x + y + 3.0 * z) / 5.0;
  double q = spread(a0, x, y, z) / kSpread;
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
  return rd_series(a0, x, y, a, scale, sum);
}

CarlsonPair carlson_rf_rd(double x, double y, double z) {
  require_rf_domain(x, y, z);
  require_rd_domain(x, y, z);
  // Both duplicate the same arguments (only their means differ), so one set of square roots
  // serves both; the loop runs until both stopping rules hold.
  const double af0 = (x + y + z) / 3.0;
  const double ad0 = (x + y + 3.0 * z) / 5.0;
  double qf = spread(af0, x, y, z) / kSpread;
  double qd = spread(ad0, x, y, z) / kSpread;
  double af = af0, ad = ad0, xn = x, yn = y, zn = z, scale = 1.0, sum = 0.0;
  while (qf >= std::fabs(af) || qd >= std::fabs(ad)) {
    const double sx = std::sqrt(xn), sy = std::sqrt(yn), sz = std::sqrt(zn);
    const double lambda = sx * (sy + sz) + sy * sz;
    sum += scale / (sz * (zn + lambda));
    xn = 0.25 * (xn + lambda);
    yn = 0.25 * (yn + lambda);
    zn = 0.25 * (zn + lambda);
    af = 0.25 * (af + lambda);
    ad = 0.25 * (ad + lambda);
    qf *= 0.25;
    qd *= 0.25;
    scale *= 0.25;
  }
  return {rf_series(af0, x, y, af, scale), rd_series(ad0, x, y, ad, scale, sum)};
}

}  // namespace flexure::elliptic
