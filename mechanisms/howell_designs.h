#pragma once
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
