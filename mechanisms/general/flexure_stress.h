#pragma once
// The largest stress of every flexure of a general mechanism at each recorded point, computed from
// the general models' own solutions (docs/mechanisms.md "The catalogue as general mechanisms"),
// with the catalogue's stress rules (mechanism_analysis.h, mechanism_exact.h) so that a built-in
// design's general form (catalogue_general.h) gives the catalogue's stresses:
//
//  * PRBM (solve_general_prbm): sigma = |M| h/(2I) + |P|/A, P the force the flexure's PRB pin
//    carries (the Lagrange multiplier of that pin in the assembled PRBM, prbm_assembly.h: the
//    equations grad V - lambda grad c - J_g^T mu = 0 solved for mu at the recorded pose), M the
//    bending moment: K psi of a small-length pivot (K = EI/l, Howell eq. 5.14; psi the relative
//    rotation of its two bodies), the moment of the pin force about the clamp of a fixed-pinned
//    segment (a fixed-pinned segment carries nothing else; Howell §5.2).
//  * exact (solve_general_mixed with every flexure exact, whose flexure_models record each
//    flexure's tip loads and tip at every point): the elastica integrated once from its root loads,
//    sigma = max |m(s)| h/(2I) + |N|/A along it (solver/shooting/segment_moments.h, the rule of
//    exact_segment_state).
//
// Fixed-guided flexures (PRBM) and extensible ones (exact) are not covered: InvalidInput.
#include <string>
#include <vector>

#include "flexure/mechanisms/general/general_analysis.h"
#include "flexure/mechanisms/general/general_mechanism.h"

namespace flexure::mechanism::general {

struct GeneralFlexureStresses {
  std::vector<std::string> names;           // the flexures, in description order
  std::vector<std::vector<double>> stress;  // [flexure][point], Pa
  std::vector<double> max_stress;           // per flexure over the points, Pa
  // The largest force (N) each flexure carries over the points (the |P| or |N| above).
  std::vector<double> max_force;
};

// The statics of one PRBM point: the multipliers of the assembled PRBM (prbm_assembly.h: scaled,
// joints first, then each flexure's PRB pins) and, per flexure, the end loads its PRB element
// carries, in the exact model's terms (general_analysis.h): the force N its tip body puts on its
// tip (global, N), its root moment m0 (N m; m(s) = m0 - r(s) x N along it, r from the root), the
// moment behind its stress (K psi of a small-length pivot at its pivot, the clamp moment of a
// fixed-pinned segment) and the tip's position relative to the root (global, m).
struct PrbmFlexureLoads {
  double Nx = 0.0, Ny = 0.0;
  double root_moment = 0.0;
  double stress_moment = 0.0;
  double tip_dx = 0.0, tip_dy = 0.0;
};
struct PrbmPointStatics {
  std::vector<double> multipliers;  // scaled, in the assembly's constraint order
  std::vector<PrbmFlexureLoads> flexures;
};
// Throws InvalidInput for a fixed-guided flexure and a point without the bodies' poses.
PrbmPointStatics prbm_point_statics(const GeneralMechanism& mechanism,
                                    const GeneralPrbmPoint& point);

// From a solve_general_prbm result of `mechanism`. Throws InvalidInput for a fixed-guided flexure
// and for a result that is not of this mechanism (its bodies differ).
GeneralFlexureStresses prbm_flexure_stresses(const GeneralMechanism& mechanism,
                                             const GeneralPrbmResult& result);

// From a solve_general_mixed result of `mechanism` in which every flexure is exact. Throws
// InvalidInput where the result has no per-flexure loads (not a mixed result) or a flexure is not
// exact or is extensible; NoConvergence where an integration fails.
GeneralFlexureStresses exact_flexure_stresses(const GeneralMechanism& mechanism,
                                              const GeneralPrbmResult& result);

}  // namespace flexure::mechanism::general
