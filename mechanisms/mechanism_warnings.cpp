#include "flexure/mechanisms/mechanism_warnings.h"

#include <fmt/format.h>

#include <algorithm>

#include "flexure/mechanisms/cfm/constant_force.h"
#include "flexure/mechanisms/inversion.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_exact.h"

namespace flexure::mechanism {

std::vector<std::string> yield_warnings(const MechanismAnalysis& a) {
  std::vector<std::string> texts;
  for (int p : a.yielding_pivots) {
    texts.push_back(
        fmt::format("pivot {} of {} yields: max stress {:.4g} Pa >= yield strength {:.4g} Pa",
                    described_pivot(a.design, p),
                    a.design.name,
                    a.max_stress[p - 1],
                    a.design.material.yield_strength.value_or(0.0)));
  }
  return texts;
}

std::vector<std::string> force_vanishing_warnings(const MechanismAnalysis& a, bool exact) {
  std::vector<std::string> texts;
  auto warn_force = [&](const char* model, const std::vector<double>& force) {
    const ConstantForceMeasure m = constant_force_measure(force);
    if (!m.vanishes) return;
    texts.push_back(fmt::format(
        "{}: the {} force {} within the stroke (min {:.4g} N, max {:.4g} N, "
        "{}): not a constant-force mechanism over this stroke; its percent constant force is "
        "reported as 0",
        a.design.name,
        model,
        m.changes_sign ? "changes sign" : "vanishes",
        m.min_force,
        m.max_force,
        force_of_label(a.force_of)));
  };
  warn_force("PRBM", a.prbm.force);
  if (exact) warn_force("exact", a.force_exact);
  return texts;
}

std::vector<std::string> stability_warnings(const MechanismAnalysis& a) {
  std::vector<std::string> texts;
  if (!a.has_exact_stability) return texts;
  const StrokeStability& dc = a.stability_exact.displacement_control;
  if (dc.unstable_points > 0) {
    texts.push_back(fmt::format(
        "{}: the exact model's equilibrium is unstable with the slider held at {} of {} stroke "
        "points (least stability margin {:.3g}): the mechanism cannot hold these shapes and would "
        "buckle into another one, which this force curve does not describe (docs/stability.md "
        "\"Mechanisms\"){}",
        a.design.name,
        dc.unstable_points,
        dc.points.size(),
        dc.least_margin,
        a.stable_search.empty() && exact_support(a.design) == ExactSupport::kDirectChain
            ? "; --stable follows a stable branch instead"
            : ""));
  }
  if (dc.not_checked_points > 0 || a.stability_exact.force_control.not_checked_points > 0) {
    texts.push_back(fmt::format(
        "{}: no stability verdict at {} stroke points of the exact model (the JSON's "
        "not_checked lists the reasons)",
        a.design.name,
        std::max(dc.not_checked_points, a.stability_exact.force_control.not_checked_points)));
  }
  return texts;
}

std::vector<Warning> analysis_warnings(const MechanismAnalysis& a) {
  std::vector<Warning> out;
  const auto add = [&out](WarningKind kind, std::vector<std::string> texts) {
    for (std::string& text : texts) out.push_back({kind, std::move(text)});
  };
  add(WarningKind::kYield, yield_warnings(a));
  // force_exact is filled exactly when the exact stroke ran and converged.
  add(WarningKind::kForceVanishes, force_vanishing_warnings(a, !a.force_exact.empty()));
  add(WarningKind::kOther, stability_warnings(a));
  return out;
}

}  // namespace flexure::mechanism
