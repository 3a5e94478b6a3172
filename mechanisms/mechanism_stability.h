#pragma once
// Stability of every stroke point of a mechanism (docs/stability.md "Mechanisms"), by the PRBM and
// by the exact model, under the two ways a slider is driven:
//
//  * displacement control: the slider's position is prescribed (a cam, a screw, a stop): the
//    admissible variations keep the slider where it is;
//  * force control: a dead load F equal to the point's slider force acts on the slider, which is
//    free to move along its guide (a weight, a constant-force actuator): the slider's travel is a
//    degree of freedom of its own.
//
// Both are judged from the second variation of the total potential energy of the half mechanism
// (one half, as every model here computes; "The whole mechanism" in docs/stability.md says what
// changes for two halves on one slider) and reported in the vocabulary of
// solver/common/status.h: kind, index (negative directions), margin.
//
// PRBM. The pseudo-rigid-body linkage has one degree of freedom, the slider's travel Delta x
// (Howell ch. 5; thesis §2.1.1); its energy is V = sum k_i psi_i^2 / 2 on the loop-closure
// manifold (Howell eqs. 6.47, 11.6; prbm_virtual_work.h), stable where d^2V/dq^2 > 0 (Howell
// §11.2).
//   displacement control: with the slider held the linkage has no degree of freedom left (the loop
//     closure fixes theta2 and theta3 away from the toggle, where the stroke ends): nothing can
//     move, so the point is stable with index 0; the margin is 1 by convention (the unloaded
//     value: no direction in which to lose stiffness). The message says so.
//   force control: Pi(Delta x) = V - F Delta x with F dead; Pi'' = V'' = dF/dDelta x. The margin is
//     V'' / (sum k_i psi_i'^2), the slider's stiffness relative to the stiffness its springs would
//     give it at the same pose without their preload (the chain's B); index 1 where the force
//     falls (snap-through under a dead load), critical within the tolerance of a flat force.
// Exact. The elastic path from the ground to the slider (mechanism_second_variation.h), with the
// shape, the internal force and the reactions of the solved point; margin as a chain's (1
// unloaded, 1 - P/P_cr for a column, 0 critical). A serial chain (ssp, slp, sss) is judged by
// solver/chain_model/segment_chain.h itself wherever its end is one of the chain's end
// conditions (displacement control: pinned or fixed; force control with a pin at the slider:
// slider end); the path's discretisation judges the rest (the force control of a flexure clamped
// into the slider: y and angle held, x free; the pinned crank of psp and plp; the rigid two-force
// coupler of spp and lpp; the pinned middle of sps and lps).
#include <string>
#include <vector>

#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_exact.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {

struct MechanismPath;  // mechanism_second_variation.h (internal)

enum class SliderControl { kDisplacement, kForce };
// "displacement control", "force control".
const char* to_string(SliderControl control);

struct PointStability {
  Stability displacement_control;
  Stability force_control;
};

// PRBM verdicts at 0 < Delta x <= the toggle stroke (design finalised; an inversion is judged on
// its original, whose relative motion and energy are the same).
PointStability prbm_point_stability(const MechanismDesign& design,
                                    double displacement,
                                    double critical_tolerance = kCriticalMarginTolerance);

// Exact verdicts of a converged point of ExactMechanismSolver for `design` (kNotChecked with the
// reason for an unconverged point). The shape is integrated again from the point's unknowns at
// the stations the verdict needs, doubled until the margin's estimated error is below
// options.margin_accuracy (segment_chain.h). Throws NoConvergence when that integration
// fails or does not close the mechanism (the tip misses the slider joint or pivot 2 by more than
// 1e-7 of the slider's distance).
PointStability exact_point_stability(const MechanismDesign& design,
                                     const ExactPoint& point,
                                     const StabilityOptions& options = {});

// The path the exact verdict judges for `point` under `control`, sampled at the stations of
// `options` (what exact_point_stability uses where the serial chain's end conditions do not
// suffice, and for every topology in the tests).
MechanismPath exact_mechanism_path(const MechanismDesign& design,
                                   const ExactPoint& point,
                                   SliderControl control,
                                   const StabilityOptions& options = {});

// A run of consecutive stroke points with the same kind (and, for unstable ones, index).
struct StabilityStretch {
  StabilityKind kind = StabilityKind::kNotChecked;
  int index = 0;
  std::size_t first = 0, last = 0;  // stroke point indices, inclusive
  double from = 0.0, to = 0.0;      // their displacements, m
  double least_margin = 0.0;        // lowest margin over the stretch
};
std::vector<StabilityStretch> stability_stretches(const std::vector<double>& displacement,
                                                  const std::vector<Stability>& verdicts);

// The verdicts of one model and control over a stroke.
struct StrokeStability {
  std::vector<Stability> points;
  // One line: the stretches in words, with the least margin and, under force control of a force
  // that barely changes, the note that the mechanism is near-critical by design.
  std::string summary;
  int unstable_points = 0;
  int critical_points = 0;
  int not_checked_points = 0;
  double least_margin = 1.0;  // over the judged points
  double largest_margin = 0.0;
};
// Both controls of one model.
struct ModelStability {
  StrokeStability displacement_control;
  StrokeStability force_control;
};

// Builds the summary of `points` at `displacement` (m, printed in mm) for `model` ("PRBM",
// "exact") under `control`. Under force control `held` (the same model's displacement-control
// verdicts, if given) tells an unstable stretch where the force falls (one negative direction
// more than with the slider held: snap-through under a dead load) from one that is unstable with
// the slider held as well.
StrokeStability summarise_stroke_stability(std::vector<Stability> points,
                                           const std::vector<double>& displacement,
                                           const char* model,
                                           SliderControl control,
                                           const std::vector<Stability>* held = nullptr);

// Force control of a constant-force mechanism: where every judged margin lies within this of 0 the
// summary calls the mechanism near-critical by design (docs/stability.md "Constant force and
// force control").
inline constexpr double kNearCriticalMargin = 0.1;

}  // namespace flexure::mechanism
