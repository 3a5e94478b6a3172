#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "flexure/mechanisms/materials_fatigue.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {

FatigueMaterial design_fatigue_material(const MechanismDesign& design) {
  const std::string which = design.material_id.empty()
                                ? std::string("the design's material")
                                : fmt::format("material '{}'", design.material_id);
  if (!design.ultimate_strength) {
    throw InvalidInput(fmt::format(
        "{} has no ultimate strength S_ut, which the fatigue check needs (Howell eq. 3.110)",
        which));
  }
  if (!design.endurance_limit) {
    throw InvalidInput(fmt::format(
        "{} has no endurance limit S_e' (or fatigue strength), which the fatigue check needs "
        "(Howell eq. 3.74)",
        which));
  }
  FatigueMaterial m;
  m.ultimate_strength = *design.ultimate_strength;
  m.uncorrected_strength = *design.endurance_limit;
  m.fatigue_cycles = design.endurance_cycles;
  m.yield_strength = design.material.yield_strength.value_or(0.0);
  m.ductile = design.ductile;
  m.source = design.material_id.empty() ? "given" : "data/materials.csv: " + design.material_id;
  m.validate();
  return m;
}

MechanismFatigue mechanism_fatigue(const MechanismAnalysis& a,
                                   const FatigueMaterial& material,
                                   const FatigueOptions& options) {
  material.validate();
  options.validate();
  const MechanismDesign& d = a.design;
  MechanismFatigue out;
  out.material = material;
  out.options = options;
  const std::size_t n = a.prbm.displacement.size();
  // The PRBM moment's sign at each stroke point (closed form, cheap).
  std::vector<PrbmState> states;
  states.reserve(n);
  for (double dx : a.prbm.displacement) states.push_back(prbm_state(d, dx));
  double lowest = 0.0;
  for (int p = 0; p < 3; ++p) {
    const JointDesign& j = d.joints[p];
    if (j.type == PivotType::kPin) continue;
    PivotFatigue& f = out.pivots[p];
    f.present = true;
    f.equivalent_diameter = equivalent_diameter_rectangle(j.width, j.thickness);
    f.strength = part_fatigue_strength(material, options, f.equivalent_diameter);
    double top = 0.0, bottom = 0.0;  // rest: unstressed
    bool positive = false, negative = false;
    for (std::size_t k = 0; k < n; ++k) {
      double s = a.prbm.stress[p][k];
      if (a.has_exact_stress && k < a.stress_exact[p].size()) {
        s = std::max(s, a.stress_exact[p][k]);
      }
      const double m = states[k].moment[p];
      const double signed_stress = m < 0.0 ? -s : s;
      positive |= m > 0.0;
      negative |= m < 0.0;
      top = std::max(top, signed_stress);
      bottom = std::min(bottom, signed_stress);
    }
    f.moment_changes_sign = positive && negative;
    // One face sees the history, the other its negative.
    const FatigueCheck face1 = check_fatigue(top, bottom, material, f.strength, options.loading);
    const FatigueCheck face2 = check_fatigue(-bottom, -top, material, f.strength, options.loading);
    f.check = face1.safety_factor <= face2.safety_factor ? face1 : face2;
    if (out.critical_pivot == 0 || f.check.safety_factor < lowest) {
      lowest = f.check.safety_factor;
      out.critical_pivot = p + 1;
    }
  }
  if (out.critical_pivot == 0) {
    throw InvalidInput(fmt::format("{} has no flexible pivot to check for fatigue", d.name));
  }
  return out;
}

void apply_material(MechanismDesign& design, const MaterialGrade& grade) {
  const std::optional<double> strength = grade.static_strength();
  if (!strength) {
    throw InvalidInput(fmt::format(
        "material '{}' ({}) has no {} strength in data/materials.csv: give the yield strength",
        grade.id,
        grade.source,
        grade.ductile ? "yield" : "ultimate"));
  }
  design.material_id = grade.id;
  design.material.E = grade.E;
  design.set_nu(grade.nu);
  design.material.yield_strength = *strength;
  design.ultimate_strength = grade.ultimate_strength;
  design.endurance_limit = grade.fatigue_strength;
  design.endurance_cycles = grade.fatigue_cycles;
  design.ductile = grade.ductile;
}

}  // namespace flexure::mechanism
