#pragma once
// Which spring constant is right for a fixed-fixed segment? The exact model decides
// (docs/validation.md "Modified configurations"): the PRBM force of each spring rule (pure bending
// k = EI/L, the paper's Table 2, Table 5) against the exact force over the stroke, the single
// factor c in k = c EI/L that fits the exact force best, and the equivalent spring of every segment
// in the exact model, k_eq = 2 U / dtheta^2 (U its strain energy, dtheta the relative rotation of
// the two rigid bodies it joins). Under a pure end moment k_eq = EI/L exactly; a transverse force
// through the strip makes the moment vary along it and k_eq > EI/L (mean of m^2 >= square of the
// mean).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_exact.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {

// Per flexible pivot (empty for a pin): k_eq/(EI/L) of the segment at one exact point.
std::array<std::optional<double>, 3> equivalent_spring_ratios(const MechanismDesign& design,
                                                              const ExactPoint& point,
                                                              int shape_points = 4001);

struct SpringRuleComparison : SolveStatus {
  std::string name;
  // Indexed by rule: pure-bending, table2, table5.
  std::array<double, 3> max_force_error{};   // max |F_prbm - F_exact|/|F_exact| over the stroke
  std::array<double, 3> mean_force_ratio{};  // mean F_prbm / mean F_exact
  double fitted_factor = 0.0;                // c minimising sum (F_exact - c F_prbm(EI/L))^2
  double fitted_max_error = 0.0;             // max |c F_prbm(EI/L) - F_exact|/|F_exact|
  // k_eq/(EI/L) per pivot at the first and last stroke point.
  std::array<std::optional<double>, 3> k_ratio_start, k_ratio_end;
};

// `design` must have fixed-fixed segments; `points` stroke points as in analyze_mechanism.
SpringRuleComparison compare_spring_rules(const MechanismDesign& design, int points);

}  // namespace flexure::mechanism
