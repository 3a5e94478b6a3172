#pragma once
// One flexure of a general mechanism under a model of its own (`mechanism analyze --model mixed`,
// solve_general_mixed in general_exact.h; docs/mechanisms.md "A model per flexure").
//
// In the mixed Newton system a flexure that is not exact is a cantilever clamped into its root
// body and loaded at its tip by the end loads of its far body: its unknowns are those tip loads
// (the exact flexures keep their root loads), and the model gives the tip's pose in the root
// frame. The CBCM is the exception: it keeps the root loads too and is marched from them
// (elements/cbcm_march.h), which needs no load path (model_tip's CBCM remains for callers that
// give tip loads). The models are the beam's --method rungs (elements/): linear theory, the BCM,
// Su's PR-3R (general constants), the chained BCM, Howell's chain algorithm (§7.2, N elements,
// solver/chain/chain_algorithm_solver.h), and the flexure's own PRBM element
// (small-length: a pin at mid-length, K = EI/l, Howell eq. 5.14; fixed-pinned: Howell's average 1R,
// pivot (1 - gamma) l from the clamp, K = gamma K_Theta EI/l, eq. 5.72).
//
// The expected error of a rung is the tip position error per length that the model ladder's map
// gives at the loads the flexure carries (beam/ladder_selector.h: 1.5 times the largest measured
// at the map's loads around it, against the elliptic solution under the same dead loads; for
// 2 < |n| <= 100 the map of axially dominated loads, data/ladder_auto_error_map_axial.csv: a
// flexure in a mechanism carries its pin force nearly along it). A load outside both maps (|n| >
// 100, alpha2 above 10 or, for |n| > 2, above 2, |mu| > 2, no transverse force with an axial one)
// or a model they do not describe (the PRBM element with its average constants, a CBCM of other
// than 6 elements, the chain algorithm) has none.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "flexure/mechanisms/general/general_mechanism.h"

namespace flexure::mechanism::general {

// The end loads on a flexure's tip, nondimensional in its root frame (x along the undeflected
// flexure): the force its far body puts on the tip, F l^2/EI, and the moment there, M l/EI.
struct FlexureTipLoad {
  double Fx = 0.0, Fy = 0.0, mu = 0.0;
};

// A flexure's tip in its root frame: x/l, y/l and the tip angle (rad).
struct FlexureTip {
  double x = 1.0, y = 0.0, theta = 0.0;
};

// The tip of a flexure of `model` (prbm, linear, bcm, prbm3r, or cbcm or chain with `elements`)
// under `load`. False, with the reason in `why`, where the model has no answer (the BCM past its
// buckling load, a PR-3R, CBCM or chain path that does not converge, a fixed-guided PRBM element).
bool model_tip(FlexureModel model,
               PrbmKind prbm,
               int elements,
               const FlexureTipLoad& load,
               FlexureTip& tip,
               std::string* why = nullptr);

// The exact elastica's tip under `load` along proportional loading from the unloaded beam (the
// elliptic solution: the reference of the error map). False for a load without a transverse
// component and a nonzero axial one (no Howell load ratio n) or where it does not converge.
bool exact_flexure_tip(const FlexureTipLoad& load, FlexureTip& tip);

// The mapped tip error per length of `model` at `load` (see above); NaN where it has none.
double mapped_flexure_error(FlexureModel model, int elements, const FlexureTipLoad& load);

// |tip - exact elastica tip| per length under `load` (exact_flexure_tip); NaN without one.
double measured_tip_error(const FlexureTipLoad& load, const FlexureTip& tip);

// The model's tip displacement per length |(x - 1, y)|.
inline double tip_displacement(const FlexureTip& t) { return std::hypot(t.x - 1.0, t.y); }

// The rungs `auto` tries, cheapest first: linear, bcm, prbm3r, cbcm (6 elements); then exact.
const std::vector<FlexureModel>& auto_ladder();

// What one flexure of a mixed solution used, and its expected error.
struct FlexureModelReport {
  std::string name;                               // the flexure's
  FlexureModel requested = FlexureModel::kExact;  // its model key (auto, or the model itself)
  FlexureModel model = FlexureModel::kExact;      // the model solved with
  int elements = 6;                               // cbcm, chain
  double tolerance = 0.0;                         // auto's, per length (0: none given)
  std::string reason;                             // which model and why
  // The largest mapped tip error per length over the recorded points: 0 for the exact elastica,
  // NaN where the map gives none at some point (unmapped_points says at how many).
  double expected_error_per_length = std::numeric_limits<double>::quiet_NaN();
  int unmapped_points = 0;
  // Per recorded point: its tip loads, the model's tip under them, the mapped error (NaN: none).
  std::vector<FlexureTipLoad> loads;
  std::vector<FlexureTip> tips;
  std::vector<double> mapped_error;
  // With GeneralExactOptions::measure_flexure_errors: |model tip - exact elastica tip| per length
  // under the same loads at each point (NaN where the elliptic solution cannot be had), and its
  // largest value.
  std::vector<double> measured_error;
  double measured_error_per_length = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace flexure::mechanism::general
