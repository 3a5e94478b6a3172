#include "flexure/mechanisms/load_cycle_fatigue.h"

#include <fmt/format.h>

#include <cmath>

#include "flexure/solver/common/status.h"

namespace flexure {

const char* load_cycle_name(LoadCycle cycle) {
  return cycle == LoadCycle::kReversed ? "reversed" : "repeated";
}

LoadCycle parse_load_cycle(const std::string& name) {
  if (name == "reversed") return LoadCycle::kReversed;
  if (name == "repeated") return LoadCycle::kRepeated;
  throw InvalidInput(fmt::format(
      "unknown load cycle '{}'; allowed: reversed (the load and its mirror image), repeated "
      "(unloaded to the load)",
      name));
}

FatigueCheck check_load_cycle(double peak_stress,
                              LoadCycle cycle,
                              const FatigueMaterial& material,
                              const PartFatigueStrength& strength,
                              FatigueLoading loading) {
  if (!std::isfinite(peak_stress) || peak_stress < 0.0) {
    throw InvalidInput(fmt::format(
        "the peak stress of a load cycle must be finite and >= 0 (got {})", peak_stress));
  }
  const double low = cycle == LoadCycle::kReversed ? -peak_stress : 0.0;
  return check_fatigue(peak_stress, low, material, strength, loading);
}

std::vector<std::string> load_cycle_warnings(LoadCycle cycle, const FatigueCheck& check) {
  if (check.infinite_life) return {};
  return {fmt::format(
      "the {} load cycle has a finite life: about {:.3g} cycles (fatigue safety factor {:.3g})",
      load_cycle_name(cycle),
      check.cycles_to_failure,
      check.safety_factor)};
}

}  // namespace flexure
