#include "flexure/mechanisms/mechanism_validation.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <utility>

#include "flexure/mechanisms/mechanism_warnings.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {

void MechanismValidationOptions::validate() const {
  if (points < 2 || points > 100000) {
    throw InvalidInput(
        fmt::format("MechanismValidationOptions::points must be in [2, 100000] (got {})", points));
  }
  // Below 1: at the toggle itself every built-in set has R = 1 designs (1B-psp, the modified
  // ones), folded flat there with a PRBM force of 0/0 (MechanismDesign::finalise refuses it).
  if (toggle_fraction && !(*toggle_fraction >= 1e-6 && *toggle_fraction < 1.0)) {
    throw InvalidInput(
        fmt::format("MechanismValidationOptions::toggle_fraction must be in [1e-06, 1) (got {})",
                    *toggle_fraction));
  }
  if (chain_check_elements < 1) {
    throw InvalidInput(
        fmt::format("MechanismValidationOptions::chain_check_elements must be >= 1 (got {})",
                    chain_check_elements));
  }
}

const std::vector<ValidationColumn>& validation_columns() {
  static const std::vector<ValidationColumn> columns = {
      {"percent_constant_force", "%", "PRBM Xi' over the stroke"},
      {"percent_constant_force_exact", "%", "exact-model Xi'; NaN where status != 0"},
      {"max_force_error", "1", "largest |F_prbm - F_exact|/|F_exact|; NaN where status != 0"},
      {"max_force_error_at",
       "1",
       "displacement of that largest error / stroke; NaN where status != 0"},
      {"prbm_validity_limit",
       "1",
       "displacement where the PRBM leaves its validity limit / stroke; -1 where it never does"},
      {"safety_factor", "1", "yield strength / the largest stress over the stroke"},
      {"chain_check_tip_error",
       "1",
       "tip error / r2 of Howell's chain algorithm on the last exact point; NaN where status != "
       "0"},
      {"stroke", "m", "the stroke evaluated"},
      {"unstable_points_displacement_control_exact",
       "1",
       "exact stroke points unstable with the slider held (docs/stability.md); NaN where status "
       "is 1 or 2"},
      {"unstable_points_force_control_exact",
       "1",
       "exact stroke points unstable under a dead slider load; NaN where status is 1 or 2"},
      {"unstable_points_force_control_prbm",
       "1",
       "PRBM stroke points unstable under a dead slider load (where the force falls)"}};
  return columns;
}

MechanismValidationRow validate_mechanism(MechanismDesign d,
                                          const MechanismValidationOptions& options) {
  options.validate();
  MechanismValidationRow row;
  if (options.toggle_fraction) d.stroke = *options.toggle_fraction * d.toggle_stroke();
  if (options.spring_rule && has_fixed_fixed(d)) apply_spring_rule(d, *options.spring_rule);
  AnalysisOptions o;
  o.points = options.points;
  o.exact_stress = false;
  // Name the design in an error: the table runs many of them.
  try {
    row.analysis = analyze_mechanism(d, o);
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("{}: {}", d.name, e.what()));
  } catch (const NoConvergence& e) {
    throw NoConvergence(fmt::format("{}: {}", d.name, e.what()));
  }
  const MechanismAnalysis& a = row.analysis;
  row.exact = a.has_exact && a.exact.converged();
  row.exact_stability = row.exact && a.has_exact_stability;
  // Second opinion on the last stroke point: Howell's chain algorithm (corrected variant) on the
  // exact model's solution.
  row.chain_check_elements = options.chain_check_elements;
  if (row.exact && !a.exact.points.empty()) {
    row.chain_check = chain_algorithm_check(a.exact.points.back(), options.chain_check_elements);
  }
  const std::optional<ChainCheck>& check = row.chain_check;
  row.status = !a.has_exact                   ? ValidationStatus::kPrbmOnly
               : !row.exact                   ? ValidationStatus::kExactNotConverged
               : check && !check->converged() ? ValidationStatus::kChainCheckNotConverged
                                              : ValidationStatus::kExactConverged;
  row.warnings = force_vanishing_warnings(a, row.exact);
  for (std::string& text : stability_warnings(a)) row.warnings.push_back(std::move(text));
  const bool exact = row.exact;
  const double none = std::numeric_limits<double>::quiet_NaN();
  row.values = {a.prbm.percent_constant_force,
                exact ? a.percent_constant_force_exact : none,
                exact ? a.max_force_error : none,
                exact ? a.max_force_error_at / d.stroke : none,
                a.prbm_validity_limit ? *a.prbm_validity_limit / d.stroke : -1.0,
                a.safety_factor,
                check && check->converged() ? check->tip_error / d.r2 : none,
                d.stroke,
                row.exact_stability
                    ? static_cast<double>(a.stability_exact.displacement_control.unstable_points)
                    : none,
                row.exact_stability
                    ? static_cast<double>(a.stability_exact.force_control.unstable_points)
                    : none,
                static_cast<double>(a.stability_prbm.force_control.unstable_points)};
  return row;
}

}  // namespace flexure::mechanism
