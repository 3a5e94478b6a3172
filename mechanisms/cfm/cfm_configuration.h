#pragma once
// The nine constant-force slider configurations of Weight (2001), thesis §3.2 and Tables 4.4, 5.1,
// 8.1 (docs/cfm.md §1.2): a
// slider-crank (ground pivot 1, crank r2, middle pivot 2, coupler r3, slider pivot 3) whose three
// pivots are each a pin (p), a small-length flexural pivot (s) or a long fixed-pinned flexible
// segment (l). The configuration string lists the pivots in the order ground, middle, slider.
//
// Only what the nondimensional PRBM needs is kept here: which torsional springs exist, the PRBM
// constants of each flexible segment, and the link each long segment replaces. Dimensional
// segment sizes belong to the mechanism assembler, not to this file.
#include <array>
#include <string>
#include <vector>

namespace flexure::cfm {

enum class PivotType { kPin, kSmall, kLong };

// PRBM constants of one pivot type (Weight 2001 §2.2, App. A.2/A.3; code `gamma`, `Ktheta`,
// `roedata`), taken from the elements: s the small-length flexural pivot (gamma 1, K = EI/l,
// Howell eq. 5.14), l the fixed-pinned segment with Howell's averages (§5.2,
// howell_average_fixed_pinned()).
struct SegmentConstants {
  double gamma = 0.0;    // characteristic radius factor (s: 1)
  double K_theta = 0.0;  // stiffness coefficient (s: 1)
  double rho = 1.0;      // flexible length / associated rigid length (s: mu = 0.1, l: 1/gamma)
};
// Constants of each pivot type; a pin has gamma = K_theta = 0 (no spring, no stress).
SegmentConstants segment_constants(PivotType type);

struct CfmConfiguration {
  std::string name;                   // "lpp", "sss", ... (pivots 1, 2, 3)
  std::string class_name;             // PRBM class: "1A", "1B", "2A", "2B", "3A" (thesis §3.2.1)
  std::array<PivotType, 3> pivots{};  // pivot 1 (ground), 2 (middle), 3 (slider)
  // A long segment at pivot 2 replaces link 2 (r2, as in the tabulated plp rows, "pl2p") or
  // link 3 (r3, as in slp); thesis code `pivotparam(2,2)` (App. B.1.3).
  bool middle_long_on_r2 = false;

  bool has_spring(int pivot) const { return pivots[pivot - 1] != PivotType::kPin; }  // 1..3
  // Class 1B has no spring at the ground, so k2 is the reference stiffness (thesis eq. 2.19).
  bool is_class_1B() const { return !has_spring(1); }
};

// The nine configurations in the thesis's order (1A spp, lpp; 1B psp, plp; 2A ssp, slp;
// 2B sps, lps; 3A sss).
const std::vector<CfmConfiguration>& cfm_configurations();
// The configuration named `name` (lower case, e.g. "lps"); throws InvalidInput listing the nine
// names otherwise.
const CfmConfiguration& find_cfm_configuration(const std::string& name);

}  // namespace flexure::cfm
