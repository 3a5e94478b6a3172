// How far the pseudo-rigid-body model of a cantilever can be trusted: the fixed-pinned PRBM
// (Howell §5.2, Table 5.1 constants for n = 0) against the exact elliptic solution. The PRBM moves
// the tip on a circle of radius gamma l about a pivot (1 - gamma) l from the clamp (eqs. 5.49,
// 5.50); Howell chose gamma so that the exact tip stays within 0.5 % of its deflection from that
// circle up to Theta_max(gamma). This program measures that distance for exact equilibria of
// growing load.
#include <flexure/flexure.h>

#include <cmath>
#include <cstdio>

int main() {
  const flexure::FixedPinnedConstants constants = flexure::FixedPinnedConstants::from_table(0.0);
  const flexure::EllipticSolver exact;
  const double gamma = constants.gamma;

  std::printf("gamma = %.4f  Theta_max(gamma) = %.1f deg\n",
              gamma,
              constants.theta_max_gamma * 180.0 / M_PI);
  std::printf("%8s %10s %10s %10s %14s\n", "alpha2", "a/l", "b/l", "Theta", "error/deflection");
  double worst = 0.0;
  for (int k = 1; k <= 12; ++k) {
    const double alpha2 = 0.75 * k;
    const flexure::EllipticResult r = exact.solve(flexure::EndLoad::howell(0.0, alpha2));
    if (!r.converged()) return 3;
    // The exact tip relative to the PRB pivot at x = (1 - gamma) l.
    const double dx = r.tip.a_over_l - (1.0 - gamma), dy = r.tip.b_over_l;
    const double Theta = std::atan2(dy, dx);
    if (Theta > constants.theta_max_gamma) break;
    const double deflection = std::hypot(1.0 - r.tip.a_over_l, r.tip.b_over_l);
    const double error = std::fabs(std::hypot(dx, dy) - gamma) / deflection;
    worst = std::fmax(worst, error);
    std::printf("%8.3f %10.6f %10.6f %10.4f %14.2e\n",
                alpha2,
                r.tip.a_over_l,
                r.tip.b_over_l,
                Theta,
                error);
  }
  std::printf("largest relative tip error up to Theta_max(gamma): %.4f\n", worst);
  return 0;
}
