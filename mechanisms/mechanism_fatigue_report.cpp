// The fatigue check of an analysed stroke as `mechanism analyze` reports it (materials_fatigue.h):
// the check, or why there is none, its one-line summary, and the warning of a finite life.
#include <fmt/format.h>

#include "flexure/mechanisms/inversion.h"
#include "flexure/mechanisms/materials_fatigue.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {

MechanismFatigueReport mechanism_fatigue_report(const MechanismAnalysis& analysis,
                                                const FatigueOptions& options) {
  MechanismFatigueReport out;
  try {
    out.fatigue = mechanism_fatigue(analysis, design_fatigue_material(analysis.design), options);
  } catch (const InvalidInput& e) {
    // A design without S_ut or S_e' (design_fatigue_material) has no check; the caller says how
    // to give them.
    out.not_checked = e.what();
    return out;
  }
  if (!out.fatigue->critical().check.infinite_life) {
    out.warnings.push_back(
        {WarningKind::kSafetyFactor,
         fmt::format(
             "{}: {}", analysis.design.name, fatigue_summary(analysis.design, *out.fatigue))});
  }
  return out;
}

std::string fatigue_summary(const MechanismDesign& design, const MechanismFatigue& f) {
  const PivotFatigue& c = f.critical();
  const std::string life =
      c.check.infinite_life
          ? (f.material.fatigue_cycles ? fmt::format("life >= {:.3g} cycles (no endurance limit)",
                                                     *f.material.fatigue_cycles)
                                       : std::string("infinite life"))
          : fmt::format("FINITE LIFE, about {:.3g} cycles", c.check.cycles_to_failure);
  return fmt::format(
      "fatigue (rest to full stroke, pivot {}): sigma_a {:.5g} Pa, sigma_m {:.5g} Pa, S_e {:.5g} "
      "Pa (S_e' {:.5g} Pa x Marin {:.3f}: {}, R {:g}, K_f {:g}); fatigue safety factor {:.3f} "
      "(modified Goodman), {}",
      described_pivot(design, f.critical_pivot),
      c.check.alternating_stress,
      c.check.mean_stress,
      c.check.endurance_limit,
      f.material.uncorrected_strength,
      c.strength.factors.product(),
      surface_finish_name(f.options.finish),
      f.options.reliability,
      f.options.K_f,
      c.check.safety_factor,
      life);
}

}  // namespace flexure::mechanism
