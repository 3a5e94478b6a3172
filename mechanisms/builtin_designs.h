#pragma once
// The built-in dimensional designs, three catalogues in one header: Howell's constant-force
// slider mechanisms, the modified designs of Ugwuoke & Abolarin (JETIR 2023) and that paper's
// Table 5 data (CfsmDesign, namespace flexure::dynamics).
//
// Howell's constant-force slider mechanisms (Compliant Mechanisms, §10.1, Table 10.1 and the
// worked examples of §10.1.4) as named dimensional designs for
// `flexure mechanism analyze` (docs/mechanisms.md "Howell's designs"):
//
//   howell-1A-spp-b  example 1: s pivot at the ground, Delta x/(r2+r3) = 0.40, r2 = 78.74 mm,
//                    polypropylene E = 1655 MPa, l = 5.08, w = 12.70, h = 0.76 mm (k1 = 151
//                    N mm/rad, F = 0.92 N)                                      alias howell-ex1
//   howell-1A-lpp-b  example 2: fixed-pinned segment L = 203.2 mm, w = 12.7, h = 3.175 mm
//                    (I = 33.86 mm^4); r2 = gamma L with the library's l segment, Howell's
//                    averages (§5.2, howell_average_fixed_pinned()); the book's numbers for this
//                    example imply gamma = 0.83, K_theta ~ 2.6 (docs/mechanisms.md)
//                                                                               alias howell-ex2
//   howell-3A-sss-a  example 3: R = 2.6633, K1 = 1, K2 = 12.6704, r2 = 40.2 mm, h1 = h2 = 0.76,
//                    h3 = h1 K2^(1/3) (F = 13 N)                                alias howell-ex3
//   howell-1A-spp-a, howell-1B-psp-a/-b, howell-2A-ssp-a/-b, howell-3A-sss-b: the other rows of
//                    Table 10.1 with example 1's material, width, flexure length (5.08 mm) and
//                    reference thickness (0.76 mm), r2 + r3 = example 1's 148.45 mm, the other
//                    flexures sized with size_flexures_for_spring_ratios.
//
// Class -> configuration: 1A s pivot = spp (Fig. 10.2a), 1A fixed-pinned = lpp (Fig. 10.2c),
// 1B = psp, 2A = ssp, 3A = sss. The 2B rows are left out: their printed Xi and Phi do not follow
// from the printed K2 = 0.1208 (they belong to K2 ~ 1, docs/errata.md); the thesis's sps/lps
// sub-classes cover class 2B. Yield strength: Howell Table C.2, polypropylene tensile yield
// strength 4500-5400 psi; the lower end, 4500 psi = 31.0 MPa, is used.
//
// The eleven "modified" constant-force slider mechanisms of Ugwuoke & Abolarin (JETIR 2023, Tables
// 1-6) as dimensional MechanismDesigns for `flexure mechanism analyze` (docs/mechanisms.md
// "Modified configurations"). Tables 2 and 4 are data/paper_tables_2_4.csv, Tables 5 and 6 are
// CfsmDesign (below).
//
// Geometry, as Tables 1, 3, 5 and 6 imply: every flexible segment (l or s) is a strip of length
// L_i clamped at both ends into rigid bodies and centred on its PRB pivot (a fixed-fixed segment;
// SegmentKind::kFixedFixed with PivotType::kSmall), so the half mechanism is the thesis topology of
// the same pins with every flexure an s ("lplm" -> "sps"). The ground clamp lies L1/2 before PRB
// pivot 1 (Table 1's r5 = L1/2) and the slider clamp L3/2 behind pivot 3 (r6). Lengths follow
// Table 3 as Table 5 applies it: L1 = f1 r2', L2 = f2 r'_ave, L3 = f3 r3' with f = 3/7 (l) or 0.1
// (s) of the RIGID remainders r2' = r2 - (L1 + L2)/2, r3' = r3 - (L2 + L3)/2 (only the flexible
// pivots counted) -- for one l on a link this is L = (6/17) r = (0.3/gamma) r.
//
// The modified constant-force slider mechanisms of Ugwuoke & Abolarin (JETIR 2023), with the
// dimensions, masses and spring constants of their Table 5 (data/paper_table_5.csv) and the nominal
// force and non-dimensional force of Table 6 (data/paper_table_6.csv); docs/dynamics.md. The files
// are compiled into the library and read at the first call.
//
// Only nine of the eleven configurations of Tables 1-4 have a column in Table 5 (2A-slpm and
// 2B-lpsm have none); the "3A-lllRig" column has no counterpart elsewhere and is left out. The
// spring constants are Table 5's values: for every flexible pivot they are twice Table 2's formula
// (0.6 gamma K_theta EI/L where Table 2 prints 0.3, 2 EI/L where it prints EI/L) and they
// reproduce Table 6's F_Nom = 2 (k_ref/r2) Phi, so Table 5 is taken as the consistent data set
// (docs/dynamics.md §2).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "flexure/mechanisms/mechanism.h"

namespace flexure::mechanism {

const std::vector<MechanismDesign>& howell_mechanisms();

// The design named `name` or one of its aliases (case-insensitive): the full name, the name
// without the class ("howell-spp-b"), "howell-ex1".."howell-ex3"; nullopt if none matches.
std::optional<MechanismDesign> find_howell_mechanism(const std::string& name);

// Name of the Howell Table 10.1 row a design implements ("howell10.1-1A-b", the names of
// cfm::howell_table_10_1()); empty for a name that is not a Howell design.
std::string howell_table_row_name(const std::string& design_name);

}  // namespace flexure::mechanism

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
// (cfsm_designs(), below), 2A-slpm and 2B-lpsm constructed from Tables 1-4 (see the .cpp);
// stroke 40 % of r2 + r3 (Table 6).
MechanismDesign modified_design(const ModifiedConfiguration& c,
                                SpringRule rule = kDefaultSpringRule);
// All eleven with the default rule, in the paper's order.
const std::vector<MechanismDesign>& modified_designs();

}  // namespace flexure::mechanism

namespace flexure::dynamics {

struct CfsmDesign {
  std::string name;              // "2B-lplm": class, pivots (ground, middle, slider), trailing m
  double r2 = 0.0;               // crank (PRBM link 2) length, m
  double r3 = 0.0;               // coupler (PRBM link 3) length, m
  double r5 = 0.0;               // rigid extension at the ground, m (0 where Table 5 prints "-")
  double r6 = 0.0;               // rigid extension at the slider, m
  double m2 = 0.0;               // mass of link 2 (one half of the mechanism), kg
  double m3 = 0.0;               // mass of link 3 (one half), kg
  double m_slider = 0.0;         // slider mass (shared by both halves), kg
  std::array<double, 3> k{};     // torsional springs at pivots 1, 2, 3 (one half), N m
  std::array<char, 3> pivots{};  // 'p' pin, 's' small-length pivot, 'l' long segment
  double width_b = 0.0;          // flexure width, m
  std::array<double, 3> h{};     // flexure thicknesses, m (0 for a pin)
  std::array<double, 3> l{};     // flexure lengths, m (0 for a pin)
  // The strips' material as the library's one Material: Table 5's E (Pa) alone (the paper gives
  // no nu, yield strength or density; modified_design adds kModifiedYieldStrength).
  Material material;
  double F_nom_paper = 0.0;  // Table 6 nominal force of the whole mechanism, N (0: none)
  double Phi_paper = 0.0;    // Table 6 mean non-dimensional force (0: not printed)
};

// The nine designs with a Table 5 column, in the paper's order.
const std::vector<CfsmDesign>& cfsm_designs();
// The design named `name` (e.g. "2B-lplm"); throws InvalidInput listing the names otherwise.
const CfsmDesign& find_cfsm_design(const std::string& name);

}  // namespace flexure::dynamics
