#pragma once
// Fatigue of a mechanism's flexures over its working cycle: rest (the as-made position, where
// every flexure is unstressed) to the full stroke and back, checked by the modified Goodman
// criterion of Howell 2001, §3.3 (fatigue.h; docs/fatigue.md).
//
// Each flexible pivot's stress over the stroke is the governing one `mechanism analyze` reports
// (the larger of the PRBM and exact values at each stroke point: the largest |m| h/(2I) + |N|/A
// of the segment), signed by the PRBM bending moment at that point (PrbmState::moment). A fibre
// on one face sees that signed history, the other face its negative; each starts from 0 at rest.
// For a pivot whose moment keeps its sign -- every built-in design -- the tensile face cycles
// between 0 and sigma_max: sigma_m = sigma_a = sigma_max/2 (eqs. 3.107-3.108), as in Howell's
// orthoplanar spring and bistable switch. Each pivot has its own size factor (d_e of its b x h,
// eq. 3.81); the critical pivot is the one with the lowest Goodman safety factor.
#include <array>
#include <string>

#include "flexure/mechanisms/fatigue.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_analysis.h"

namespace flexure::mechanism {

struct PivotFatigue {
  bool present = false;              // a flexible pivot
  double equivalent_diameter = 0.0;  // d_e, m (eq. 3.81)
  PartFatigueStrength strength;
  FatigueCheck check;                // of the face with the lower safety factor
  bool moment_changes_sign = false;  // the PRBM moment takes both signs over the stroke
};

struct MechanismFatigue {
  FatigueMaterial material;
  FatigueOptions options;
  std::array<PivotFatigue, 3> pivots;  // stored (original) pivot order, 1..3 -> [0..2]
  int critical_pivot = 0;              // 1..3, lowest safety factor
  const PivotFatigue& critical() const { return pivots[critical_pivot - 1]; }
};

// The fatigue material of a design: its S_ut and S_e' (from a data/materials.csv row or given),
// S_y and brittleness. Throws InvalidInput naming what is missing ("--ultimate-strength",
// the TOML key) in library words: "the design's material has no ultimate strength S_ut".
FatigueMaterial design_fatigue_material(const MechanismDesign& design);

// The check of an analysed stroke (analysis.prbm over the stroke; the exact stresses where
// analysis.has_exact_stress).
MechanismFatigue mechanism_fatigue(const MechanismAnalysis& analysis,
                                   const FatigueMaterial& material,
                                   const FatigueOptions& options);

// Sets E, nu-free S_y, S_ut, S_e' (and its life), ductility and the id of `grade` on `design`;
// a brittle grade's static strength is its S_ut (Howell eq. 3.44). Throws InvalidInput when the
// row has no yield (or ultimate) strength for the static safety factor.
void apply_material(MechanismDesign& design, const MaterialGrade& grade);

}  // namespace flexure::mechanism
