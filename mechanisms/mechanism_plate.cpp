#include "flexure/mechanisms/mechanism_plate.h"

#include <fmt/format.h>

#include "flexure/solver/common/status.h"

namespace flexure::mechanism {

void apply_plate_modulus(MechanismDesign& design) {
  if (!design.modulus.empty()) return;
  if (design.plate == PlateRule::kAuto) {
    throw InvalidInput(
        fmt::format("{}: plate = auto is decided from an analysis (analyze_mechanism_with_modulus)",
                    design.name));
  }
  const ModulusChoice choice =
      choose_modulus(design.plate, design.material.E, design.given_nu(), {}, {}, {}, design.name);
  design.material.E = choice.effective_E;
  design.modulus = {choice};
}

MechanismAnalysis analyze_mechanism_with_modulus(MechanismDesign design,
                                                 const AnalysisOptions& options) {
  if (design.plate != PlateRule::kAuto || !design.modulus.empty()) {
    apply_plate_modulus(design);
    return analyze_mechanism(design, options);
  }
  // Checked before the first analysis: nu, and a width and thickness on every strip (they are).
  choose_modulus(
      PlateRule::kAuto, design.material.E, design.given_nu(), 1.0, 1.0, 0.0, design.name);
  MechanismAnalysis first = analyze_mechanism(design, options);
  std::vector<ModulusChoice> choices;
  bool all_plates = true;
  for (int p = 1; p <= 3; ++p) {
    const JointDesign& j = first.design.joints[p - 1];
    if (j.type == PivotType::kPin) continue;
    // The largest bending stress sigma = E kappa h/2 gives the largest curvature.
    const double curvature = 2.0 * first.max_stress[p - 1] / (design.material.E * j.thickness);
    choices.push_back(choose_modulus(PlateRule::kAuto,
                                     design.material.E,
                                     design.given_nu(),
                                     j.width,
                                     j.thickness,
                                     curvature,
                                     fmt::format("{} pivot {}", design.name, p)));
    all_plates = all_plates && choices.back().plate;
  }
  if (choices.empty()) all_plates = false;
  if (!all_plates) {
    // One material, one modulus: the beam's, and each strip's choice reported with it.
    for (ModulusChoice& c : choices) {
      if (c.plate) {
        c.note = fmt::format(
            "auto: Searle parameter b^2/(R h) = {:.4g} >= {:.4g}, but another strip of the "
            "mechanism is below the threshold: the mechanism's one modulus is the beam's E",
            c.beta.value_or(0.0),
            c.threshold.value_or(0.0));
      }
      c.plate = false;
      c.effective_E = c.E;
    }
    first.design.modulus = choices;
    return first;
  }
  design.material.E = choices.front().effective_E;
  design.modulus = choices;
  return analyze_mechanism(design, options);
}

}  // namespace flexure::mechanism
