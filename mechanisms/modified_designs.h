#pragma once
// The eleven "modified" constant-force slider mechanisms of Ugwuoke & Abolarin (JETIR 2023, Tables
// 1-6) as dimensional MechanismDesigns for `flexure mechanism analyze` (docs/mechanisms.md
// "Modified configurations"). Tables 2 and 4 are data/paper_tables_2_4.csv, Tables 5 and 6 come
// with cfsm_designs.h.
//
// Geometry, as Tables 1, 3, 5 and 6 imply: every flexible segment (l or s) is a strip of length
// L_i clamped at both ends into rigid bodies and centred on its PRB pivot (a fixed-fixed segment;
// SegmentKind::kFixedFixed with PivotType::kSmall), so the half mechanism is the thesis topology of
// the same pins with every flexure an s ("lplm" -> "sps"). The ground clamp lies L1/2 before PRB
// pivot 1 (Table 1's r5 = L1/2) and the slider clamp L3/2 behind pivot 3 (r6). Lengths follow
// Table 3 as Table 5 applies it: L1 = f1 r2', L2 = f2 r'_ave, L3 = f3 r3' with f = 3/7 (l) or 0.1
// (s) of the RIGID remainders r2' = r2 - (L1 + L2)/2, r3' = r3 - (L2 + L3)/2 (only the flexible
// pivots counted) -- for one l on a link this is L = (6/17) r = (0.3/gamma) r.
#include <array>
#include <string>
#include <vector>

#include "flexure/mechanisms/mechanism.h"

namespace flexure::mechanism {

// One row of the paper's Tables 1-4.
struct ModifiedConfiguration {
  std::string name;                     // "lplm": pivots 1, 2, 3 and the trailing m
  std::string class_name;               // "2B"
  std::array<char, 3> letters{};        // 'p' pin, 's' small-length, 'l' long segment
  std::array<double, 3> length_factor;  // Table 3: 3/7 (l), 0.1 (s), 0 (pin)
  std::array<double, 3> table2_factor;  // Table 2: n of n gamma K_theta EI/L (l), 1 (s: EI/L)
  double R = 1.0;                       // Table 4 R = r3/r2
  double Lambda = 1.0;                  // Table 4 length parameter, as printed

  // The thesis pattern of the same pins with every flexible segment an s ("lplm" -> "sps").
  std::string thesis_pattern() const;
};

const std::vector<ModifiedConfiguration>& modified_configurations();  // the paper's order
// "lplm" or "2B-lplm" (case-insensitive); throws InvalidInput listing the eleven.
const ModifiedConfiguration& find_modified_configuration(const std::string& name);

// Table 3 lengths (m) for PRBM links r2, r3: the linear system above (0 for a pin).
std::array<double, 3> table3_lengths(const ModifiedConfiguration& c, double r2, double r3);

// k = factor EI/L of a fixed-fixed segment under `rule` (mechanism.h SpringRule): pure bending 1;
// Table 2: l n gamma K_theta (paper eq. 1: Howell's averages, howell_average_fixed_pinned(); n =
// joint.table2_factor), s 1;
// Table 5: twice Table 2. Throws InvalidInput for a joint that is not fixed-fixed.
double spring_rule_factor(SpringRule rule, const JointDesign& joint);
// "pure-bending", "table2", "table5"; throws InvalidInput naming the allowed values.
SpringRule parse_spring_rule(const std::string& text);
std::string spring_rule_name(SpringRule rule);
// The default rule: pure bending, k = EI/L -- the rule the exact model confirms
// (docs/validation.md "Modified configurations").
inline constexpr SpringRule kDefaultSpringRule = SpringRule::kPureBending;

// True if any pivot of `design` is a fixed-fixed segment.
bool has_fixed_fixed(const MechanismDesign& design);
// Sets the spring rule; throws InvalidInput for a design without fixed-fixed segments.
void apply_spring_rule(MechanismDesign& design, SpringRule rule);
// Part of MechanismDesign::finalise(): the rigid rest of a link carrying fixed-fixed segments,
// r minus half of each centred segment on it, must be > 0 (the segment is shorter than its link).
void check_fixed_fixed_lengths(const MechanismDesign& design);

// Yield strength of the built-in modified designs: the paper gives none. Carbon spring steel
// (E = 207 GPa as in Table 5) at the thesis's upper bound S_y = 200 ksi (thesis Table 8.6).
inline constexpr double kModifiedYieldStrength = 200.0e3 * 6894.757293;  // Pa

// The built-in design of configuration `c` (name "2B-lplm"): nine from their Table 5 column
// (cfsm_designs.h), 2A-slpm and 2B-lpsm constructed from Tables 1-4 (see the .cpp);
// stroke 40 % of r2 + r3 (Table 6).
MechanismDesign modified_design(const ModifiedConfiguration& c,
                                SpringRule rule = kDefaultSpringRule);
// All eleven with the default rule, in the paper's order.
const std::vector<MechanismDesign>& modified_designs();

}  // namespace flexure::mechanism
