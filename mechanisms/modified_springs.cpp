#include "flexure/mechanisms/modified_springs.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {
std::array<std::optional<double>, 3> equivalent_spring_ratios(const MechanismDesign& design,
                                                              const ExactPoint& point,
                                                              int shape_points) {
  if (!point.converged()) throw InvalidInput("equivalent_spring_ratios needs a converged point");
  const ExactSegmentState st = exact_segment_state(design, point, shape_points);
  std::array<std::optional<double>, 3> ratio;
  for (int p = 0; p < 3; ++p) {
    if (!st.has_pivot[p]) continue;
    const JointDesign& j = design.joints[p];
    const double EI_over_L = j.flexural_rigidity(design.material) / j.length;
    ratio[p] =
        2.0 * st.pivot_strain_energy[p] / (st.pivot_rotation[p] * st.pivot_rotation[p]) / EI_over_L;
  }
  return ratio;
}

SpringRuleComparison compare_spring_rules(const MechanismDesign& design, int points) {
  SpringRuleComparison c;
  c.name = design.name;
  MechanismDesign d = design;
  d.finalise();
  const std::vector<double> dx = stroke_displacements(d, points);
  const ExactStrokeResult exact = exact_stroke(d, dx);
  if (!exact.converged()) {
    c.message = exact.message;
    return c;
  }
  double mean_exact = 0.0;
  for (const ExactPoint& p : exact.points) mean_exact += p.force / points;
  const SpringRule rules[3] = {SpringRule::kPureBending, SpringRule::kTable2, SpringRule::kTable5};
  std::vector<double> F_pure;
  for (int r = 0; r < 3; ++r) {
    apply_spring_rule(d, rules[r]);
    const PrbmStrokeResult prbm = prbm_stroke(d, points);
    if (r == 0) F_pure = prbm.force;
    for (int k = 0; k < points; ++k) {
      const double Fe = exact.points[k].force;
      c.max_force_error[r] =
          std::max(c.max_force_error[r], std::abs(prbm.force[k] - Fe) / std::abs(Fe));
    }
    c.mean_force_ratio[r] = prbm.mean_force / mean_exact;
  }
  // The PRBM force is linear in the spring constants: F_prbm(c EI/L) = c F_prbm(EI/L).
  double num = 0.0, den = 0.0;
  for (int k = 0; k < points; ++k) {
    num += exact.points[k].force * F_pure[k];
    den += F_pure[k] * F_pure[k];
  }
  c.fitted_factor = num / den;
  for (int k = 0; k < points; ++k) {
    const double Fe = exact.points[k].force;
    c.fitted_max_error =
        std::max(c.fitted_max_error, std::abs(c.fitted_factor * F_pure[k] - Fe) / std::abs(Fe));
  }
  c.k_ratio_start = equivalent_spring_ratios(design, exact.points.front());
  c.k_ratio_end = equivalent_spring_ratios(design, exact.points.back());
  c.set_converged(true);
  c.message = exact.message;
  return c;
}

}  // namespace flexure::mechanism
