#pragma once
// Computed values beside the printed ones, for the 68 thesis sub-classes and the class-level rows
// of thesis Table 2.1 / Howell Table 10.1 (used by `flexure cfm --table` and docs/cfm.md).
//
// "Reproduced within printed rounding" is judged with
//   tolerance = half a unit of the printed value's last digit
//             + input band: the largest change of the computed value when each printed design
//               variable R, K1, K2 (4 decimals) moves by half a unit of its last digit, summed.
// The input band matters where the optimiser sat on a steep slope (plp-a90: dPhi/dR ~ -6, so the
// rounding of R alone moves Phi by 3e-4, six times Phi's own rounding).
#include <array>
#include <optional>
#include <string>

#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/cfm/cfm_subclasses.h"

namespace flexure::cfm {

struct PrintedComparison {
  double computed = 0.0;
  double printed = 0.0;
  double tolerance = 0.0;  // half unit of the printed digit + input band (see above)
  double deviation() const { return computed - printed; }
  bool within() const;  // |deviation| <= tolerance (with a 1e-12 allowance for decimal data)
};

// The model inputs of a printed row: the printed design variables, with K1/K2 omitted where the
// configuration has no such spring (and K1 for class 1B, which is 1 by definition).
CfmParameters parameters_of(const CfmSubclass& row);
CfmParameters parameters_of(const CfmClassRow& row);

struct SubclassComparison {
  const CfmSubclass* row = nullptr;
  CfmResult result;  // thesis-code sampling
  PrintedComparison Phi;
  PrintedComparison percent_constant_force;  // Xi'
  PrintedComparison beta;
  PrintedComparison lambda;
  PrintedComparison Psi;  // normalised (thesis normalisers for 16 % and 40 %)
  PrintedComparison d_N_max;
  // Primary pivot agrees, or the two candidates tie exactly (mirror-symmetric sps-b86IO: R = 1,
  // K2 = 1, where the thesis's Matlab picked pivot 3 by rounding noise).
  bool primary_pivot_matches = false;
  bool primary_pivot_tie = false;
  bool all_within() const;
};
SubclassComparison compare_with_thesis(const CfmSubclass& row);

// C, D_equal, D_min of one multi-flexure sub-class (thesis Tables 7.7, 7.10, 7.13); index = pivot
// - 1, empty where the pivot is a pin.
struct RatioComparison {
  const CfmThicknessRatios* row = nullptr;
  std::array<std::optional<PrintedComparison>, 3> C;
  std::array<std::optional<PrintedComparison>, 3> D_equal;
  std::array<std::optional<PrintedComparison>, 3> D_min;
  bool pins_agree = true;  // the computed ratios are empty exactly where the printed ones are
  bool all_within() const;
};
RatioComparison compare_with_thesis_ratios(const CfmThicknessRatios& row);

struct ClassRowComparison {
  const CfmClassRow* row = nullptr;
  CfmResult result;  // 50 equally spaced points (Howell §10.1)
  PrintedComparison Xi;
  PrintedComparison Phi;
};
// `extra_tolerance` is added to both tolerances (class 1B: the mean of a force that rises
// steeply from Delta x = 0 depends on sampling details at ~1e-3, docs/cfm.md §3 item 4).
ClassRowComparison compare_with_class_row(const CfmClassRow& row, double extra_tolerance = 0.0);

}  // namespace flexure::cfm
