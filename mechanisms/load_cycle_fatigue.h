#pragma once
// The fatigue of a beam loaded in a cycle between two states (Howell 2001, §3.3.10-3.3.11;
// docs/fatigue.md): `flexure beam --cycle`. The largest stress of the beam at its load is the
// peak of the critical fibre's cycle:
//   reversed: the load and its mirror image (Fy and M reversed): by symmetry every fibre's stress
//             changes sign, sigma_min = -sigma_max, sigma_m = 0 (Howell's completely reversed
//             cantilever, eqs. 3.86, 3.88);
//   repeated: unloaded to the load: the fibre goes 0 -> sigma_max, sigma_m = sigma_a = sigma_max/2
//             (eqs. 3.107-3.108).
#include <string>
#include <vector>

#include "flexure/mechanisms/materials_fatigue.h"

namespace flexure {

enum class LoadCycle { kReversed, kRepeated };

const char* load_cycle_name(LoadCycle cycle);
// "reversed" or "repeated"; throws InvalidInput listing them.
LoadCycle parse_load_cycle(const std::string& name);

// The check of the cycle whose peak stress is `peak_stress` (Pa, >= 0).
FatigueCheck check_load_cycle(double peak_stress,
                              LoadCycle cycle,
                              const FatigueMaterial& material,
                              const PartFatigueStrength& strength,
                              FatigueLoading loading = FatigueLoading::kBending);

// The warning of a cycle of finite life (about N cycles to failure, with the fatigue safety
// factor), as every front end reports it; none for an infinite life.
std::vector<std::string> load_cycle_warnings(LoadCycle cycle, const FatigueCheck& check);

}  // namespace flexure
