// Howell's worked example (§2.9.2) through the beam API alone (<flexure/beam.h>, flexure::beam):
// alpha2 = P l^2/EI = 3.0870030 turns the cantilever's tip by 1 rad, with a/l = 0.7383564 and
// b/l = 0.6103718. Solved by `auto` (the elliptic solution) and by shooting; exit 1 when either
// misses the book's seven digits.
#include <flexure/beam.h>

#include <cmath>
#include <cstdio>

int main() {
  flexure::BeamProblem problem;
  problem.given = flexure::BeamProblem::Given::kAlpha2;
  problem.value = 3.0870030;
  int failures = 0;
  for (const flexure::BeamMethod method :
       {flexure::BeamMethod::kAuto, flexure::BeamMethod::kShooting}) {
    const flexure::BeamSolution s = flexure::solve_beam(method, problem);
    const bool ok = s.converged() && std::abs(s.tip.a_over_l - 0.7383564) < 1e-6 &&
                    std::abs(s.tip.b_over_l - 0.6103718) < 1e-6 &&
                    std::abs(s.tip.theta0 - 1.0) < 1e-6;
    std::printf("%-8s a/l = %.7f  b/l = %.7f  theta0 = %.7f  %s\n",
                flexure::to_string(method),
                s.tip.a_over_l,
                s.tip.b_over_l,
                s.tip.theta0,
                ok ? "ok" : "MISSES Howell's example");
    if (!ok) ++failures;
  }
  return failures == 0 ? 0 : 1;
}
