#include "flexure/mechanisms/design/design_status.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <string>
#include <vector>

namespace flexure::design {

void stamp_design_status(DimensionedDesign& design) {
  design.termination = design.feasible ? Termination::kConverged : Termination::kInfeasible;
  design.message = design.feasible ? std::string() : design.binding;
}

void stamp_report_status(const MechanismSpec& spec, MechanismDesignReport& report) {
  for (DimensionedDesign& d : report.designs) stamp_design_status(d);
  for (DimensionedDesign& d : report.rejected) stamp_design_status(d);
  report.warnings.clear();
  if (report.designs.empty()) {
    report.termination = Termination::kInfeasible;
    std::string message = "no sub-class meets the specification";
    if (report.rejected.empty()) {
      message +=
          " (no sub-class passed the configuration, percent-constant-force and orientation "
          "filters for this stroke)";
    } else {
      const DimensionedDesign& closest = report.rejected.front();
      message += fmt::format("; the closest, {}, fails on {}", closest.subclass, closest.binding);
      if (report.length_needed) {
        // Rounded up to 4 digits (length_hint): fed back, the printed length is feasible.
        message += fmt::format(
            ". The shortest mechanism that meets it: l_tot = {:.4g} mm ({}, by the full sizing)",
            length_hint(*report.length_needed) * 1e3,
            report.length_needed_subclass);
      }
    }
    report.message = std::move(message);
    return;
  }
  report.termination = Termination::kConverged;
  report.message = fmt::format("{} feasible design{}, best {}",
                               report.designs.size(),
                               report.designs.size() == 1 ? "" : "s",
                               report.designs.front().subclass);
  // The thesis's rule (eq. 8.5) lists designs that their own stresses would not pass: say which.
  std::vector<std::string> short_of;
  for (const SafetyShortfall& s : designs_short_of_safety_factor(report, spec.safety_factor)) {
    short_of.push_back(fmt::format("{} {:.3g}", s.subclass, s.safety_factor));
  }
  if (!short_of.empty()) {
    report.warn(WarningKind::kSafetyFactor,
                fmt::format("{} of {} designs miss safety factor {:g} by the PRBM or exact "
                            "stresses (eq. 8.5, the thesis's stress rule, leaves out the axial "
                            "stress and the clamp moment): {}",
                            short_of.size(),
                            report.designs.size(),
                            spec.safety_factor,
                            fmt::join(short_of, ", ")));
  }
}

}  // namespace flexure::design
