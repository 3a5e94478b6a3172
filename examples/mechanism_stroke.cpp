// The force over the stroke of a constant-force mechanism, by the pseudo-rigid-body model and by
// the exact model of the same mechanism: design example 1 of Weight's thesis (configuration 1A,
// a long flexure and two pins, designed for 25 lbf).
#include <flexure/flexure.h>

#include <cstdio>

int main() {
  const flexure::mechanism::MechanismDesign design =
      flexure::mechanism::find_builtin_mechanism("1A-lpp");
  flexure::mechanism::AnalysisOptions options;
  options.points = 20;
  const flexure::mechanism::MechanismAnalysis a =
      flexure::mechanism::analyze_mechanism(design, options);
  std::printf("%10s %12s %12s\n", "dx [mm]", "F PRBM [N]", "F exact [N]");
  for (std::size_t k = 0; k < a.prbm.force.size(); ++k) {
    std::printf("%10.3f %12.3f %12.3f\n",
                1e3 * a.prbm.displacement[k],
                a.prbm.force[k],
                a.has_exact && k < a.force_exact.size() ? a.force_exact[k] : 0.0);
  }
  std::printf("mean force: PRBM %.2f N (%.2f lbf), exact %.2f N\n",
              a.prbm.mean_force,
              a.prbm.mean_force / 4.4482216152605,
              a.mean_force_exact);
  std::printf("percent constant force: PRBM %.2f %%, exact %.2f %%\n",
              a.prbm.percent_constant_force,
              a.percent_constant_force_exact);
  std::printf("exact model: %s\n", a.exact.converged() ? "converged" : a.exact.message.c_str());
  return a.exact.converged() ? 0 : 3;
}
