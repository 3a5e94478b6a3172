#pragma once
// The pseudo-rigid-body model of a uniform cantilever under a tip load (Howell ch. 5): which
// element models which case, in one place. `flexure beam --method prbm`, the benchmark runner and
// the method selector of `--method auto` all solve through it.
//   * far end guided (Howell §5.3): the fixed-guided segment, with the constants of the
//     fixed-pinned half at the load ratio n (Table 5.1); the tip moment is the guide's reaction;
//   * free end, tip moment only (§5.4): the end-moment segment;
//   * free end, tip force (§5.2): the fixed-pinned segment with the Table 5.1 constants at n (it
//     refuses a tip moment with the force: a pinned tip carries no moment).
#include <memory>
#include <string>

#include "flexure/elements/prbm_element.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/status.h"

namespace flexure {

// The element for this end condition and load. Throws InvalidInput for an end condition no
// element of Howell ch. 5 models as a cantilever (pinned, slider, fixed), for a tip moment on a
// guided end, and for a load ratio outside Table 5.1.
// The load is Howell's (eq. 2.67, EndLoad::howell): transverse force alpha2, axial -n alpha2 (n > 0
// compressive), end moment mu.
std::unique_ptr<PrbmElement> prbm_cantilever_element(EndCondition end,
                                                     double load_ratio_n,
                                                     double alpha2,
                                                     double mu);

struct PrbmCantileverSolution : SolveStatus {
  // iterations, residual: those of PrbmElement::solve (virtual-work residual)
  std::string element;           // the element's name, e.g. "fixed-pinned segment"
  std::string constants_source;  // where its constants come from, e.g. "Table 5.1, n = 0"
  double Theta = 0.0;            // PRB angle, rad
  TipPose tip;
  double root_moment = 0.0;  // M(0) l/EI at the clamp (the element's max_moment)
  // Of the modelled shape: 1 for the guided end (antisymmetric about mid-length, Howell §5.3),
  // else 0 (curvature of one sign).
  int inflection_points = 0;
  ValidityLimits limits;
  bool inside_validity = false;  // limits.contains(Theta): Howell eqs. 5.47 and 5.63
  // The PRBM's own verdict: the sign of d^2V/dTheta^2 of its potential energy (prbm_stability.h);
  // not_checked when the solve did not converge.
  Stability stability;
};

// Solves the cantilever's PRBM. Throws as prbm_cantilever_element, and InvalidInput for a load the
// element refuses.
PrbmCantileverSolution solve_prbm_cantilever(EndCondition end,
                                             double load_ratio_n,
                                             double alpha2,
                                             double mu);

}  // namespace flexure
