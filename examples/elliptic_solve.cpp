// The exact tip of a cantilever under a tip load, forward and inverse (Howell §2.9.2 example:
// a vertical load with alpha2 = P l^2/EI = 3.087 turns the tip by 1 rad).
#include <flexure/flexure.h>

#include <cstdio>

int main() {
  const flexure::EllipticSolver solver;

  // Forward: the load in Howell's parameters (n = 0: no horizontal component; mu: no end moment).
  const flexure::EllipticResult forward =
      solver.solve(flexure::EndLoad::howell(0.0, 3.087003, 0.0));
  if (!forward.converged()) {
    std::fprintf(stderr, "not converged: %s\n", forward.message.c_str());
    return 3;
  }
  std::printf("forward alpha2 = 3.087003: a/l = %.7f  b/l = %.7f  theta0 = %.7f rad\n",
              forward.tip.a_over_l,
              forward.tip.b_over_l,
              forward.tip.theta0);

  // Inverse: the load that turns the tip by 1 rad.
  const flexure::EllipticResult inverse = solver.solve_for_tip_angle(0.0, 1.0);
  std::printf("inverse theta0 = 1: alpha2 = %.7f  a/l = %.7f  b/l = %.7f\n",
              inverse.load.Fy,
              inverse.tip.a_over_l,
              inverse.tip.b_over_l);
  return 0;
}
