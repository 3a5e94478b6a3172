// How far the pseudo-rigid-body model of a cantilever can be trusted: the fixed-pinned PRBM
// (Howell §5.2, Table 5.1 constants for n = 0) against the exact elliptic solution at the same
// load, over the PRB angle Theta. Howell states that the PRBM tip stays within 0.5 % of the exact
// one (relative to the beam length) up to Theta_max(gamma).
#include <cmath>
#include <cstdio>
#include <flexure/flexure.h>

int main() {
  const flexure::FixedPinnedConstants constants = flexure::FixedPinnedConstants::from_table(0.0);
  const flexure::FixedPinnedSegment prbm(constants);
  const flexure::EllipticSolver exact;

  std::printf("gamma = %.4f  K_theta = %.4f  Theta_max(gamma) = %.1f deg\n", constants.gamma,
              constants.K_theta, constants.theta_max_gamma * 180.0 / M_PI);
  std::printf("%8s %10s %12s %12s %12s\n", "Theta", "alpha2", "b/l PRBM", "b/l exact", "tip error");
  double worst = 0.0;
  for (int k = 1; k <= 8; ++k) {
    const double Theta = constants.theta_max_gamma * k / 8.0;
    const double alpha2 = prbm.alpha2_at(Theta);
    const flexure::TipPose model = prbm.tip(Theta);
    const flexure::EllipticResult reference = exact.solve(flexure::EndLoad::howell(0.0, alpha2));
    if (!reference.converged) return 3;
    const double error = std::hypot(model.a_over_l - reference.tip.a_over_l,
                                    model.b_over_l - reference.tip.b_over_l);
    worst = std::fmax(worst, error);
    std::printf("%8.4f %10.4f %12.6f %12.6f %12.2e\n", Theta, alpha2, model.b_over_l,
                reference.tip.b_over_l, error);
  }
  std::printf("largest tip error up to Theta_max(gamma): %.4f beam lengths\n", worst);
  return 0;
}
