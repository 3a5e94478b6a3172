#pragma once
// The pseudo-rigid-body model (PRBM) of one beam against its exact solution, load by load: the
// PRBM tip and the exact tip under the same load, the PRBM's position error relative to the
// exact deflection, the path error of Howell eq. 5.47 at the exact tip (the 0.5 % criterion that
// defines Theta_max(gamma), eq. 5.43), and the load the PRBM needs to reach the exact tip's PRB
// angle (eq. 5.42) beside the given load (the force-deflection relation, eqs. 5.56-5.59, 5.111).
//
// Two beams: the fixed-pinned segment (Howell §5.2, a tip force at load ratio n; exact tip from
// the elliptic solver, eqs. 2.83-2.98) and the end-moment segment (§5.4; exact tip on the circle
// of eqs. 2.59 and 2.64). This is what `flexure prbm compare` prints (docs/prbm.md).
#include <array>
#include <string>
#include <string_view>
#include <variant>

#include "flexure/elements/prbm_element.h"
#include "flexure/solver/common/end_load.h"

namespace flexure {

// Where the fixed-pinned segment's constants come from.
enum class PrbmConstantsSource {
  kTable,      // Howell's Table 5.1 (FixedPinnedConstants::from_table)
  kCurveFits,  // curve fits eqs. 5.48, 5.60-5.62 (FixedPinnedConstants::from_curve_fits)
  kDerived,    // derived from the exact solution (derive_fixed_pinned, prbm_element.h)
};

// "table", "fits", "derived", in the order of the enum.
inline constexpr std::array<const char*, 3> kPrbmConstantsSourceNames = {
    "table", "fits", "derived"};

const char* to_string(PrbmConstantsSource source);
// Throws InvalidInput naming the allowed names.
PrbmConstantsSource prbm_constants_source_from_string(std::string_view name);

// PRBM and exact tips under one load, and the errors between them (angles in rad).
struct PrbmComparison {
  double load = 0.0;            // the given load: alpha2 = P l^2/EI (fixed-pinned) or mu = M l/EI
  TipPose exact;                // exact tip under the load
  TipPose prbm;                 // PRBM tip under the load
  double Theta = 0.0;           // PRB angle under the load
  double Theta_exact = 0.0;     // PRB angle of the exact tip (eq. 5.42)
  double position_error = 0.0;  // |PRBM tip - exact tip| / exact deflection, same load
  double path_error = 0.0;      // eq. 5.47 at the exact tip: the 0.5 % criterion quantity
  double load_prbm_at_exact = 0.0;  // load the PRBM needs to reach the exact tip's Theta
  double force_error = 0.0;         // (load_prbm_at_exact - load) / load
  bool inside_position = false;     // Theta <= Theta_max(gamma)
  bool inside_force = false;        // Theta <= Theta_max(K_theta)
};

// The PRBM of one beam and the exact solution it is compared with.
class PrbmComparator {
 public:
  enum class Segment { kFixedPinned, kEndMoment };

  // Fixed-pinned segment at load ratio n (-5 <= n <= 10, n > 0 compressive, eq. 2.67) with the
  // constants of `source`; `options` are those of the derivation (kDerived only). Throws
  // InvalidInput for n outside [-5, 10] or bad options, NoConvergence if the derivation fails.
  static PrbmComparator fixed_pinned(double load_ratio_n,
                                     PrbmConstantsSource source,
                                     const PrbmDerivationOptions& options = {});
  // End-moment segment with the book's constants (eqs. 5.107-5.110).
  static PrbmComparator end_moment();

  Segment segment() const;
  // Where the PRB constants come from, in words (e.g. "Table 5.1, n = 0").
  const std::string& constants_source() const { return constants_source_; }
  const ValidityLimits& limits() const { return limits_; }

  // The comparison under `load`: alpha2 in [1e-9, 1e4] (fixed-pinned) or mu in [1e-9, 6] (end
  // moment), else InvalidInput; NoConvergence if the exact or the PRBM solve fails.
  PrbmComparison at(double load) const;

 private:
  using Element = std::variant<FixedPinnedSegment, EndMomentSegment>;
  PrbmComparator(Element element, std::string constants_source);

  Element element_;
  std::string constants_source_;
  ValidityLimits limits_;
};

}  // namespace flexure
