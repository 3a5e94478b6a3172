#pragma once
// One stroke of a MechanismDesign computed both ways -- PRBM (prbm_stroke, above) and exact
// (exact_stroke, above) -- with the comparison the issue asks for: force error of the PRBM relative
// to the exact model, percent constant force both ways, largest stress and safety factor, and the
// first slider position where the PRBM leaves its validity range.
//
// Validity range of the PRBM (docs/mechanisms.md): a long (fixed-pinned) segment is modelled with
// Howell's average constants (§5.2, howell_average_fixed_pinned()); Howell Table 5.1 gives for its
// load ratio n the largest PRB angle Theta_max(K_theta) up to which the force stays within 0.5 %
// of the exact one. The limit is the first stroke point where Theta of an l segment exceeds
// Theta_max(K_theta) at its current n (ValidityLimits::contains_force of the Table 5.1 element; or
// n lies outside Table 5.1, or the pin force opposes the deflection). s pivots have no such table
// (they are assumed valid; their error shows in the comparison with the exact model).
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure::mechanism {

// The exact model (mechanism_exact.h: the physical segments of thesis Table 8.1 as a segment
// chain, solved by shooting at each slider position): which configurations it covers, its
// settings, its points and strokes. The solver itself (ExactMechanismSolver) is internal.

enum class ExactSupport { kDirectChain, kTwoForceCoupler, kPinnedMiddle, kPinnedEnds, kPrbmOnly };
ExactSupport exact_support(const MechanismDesign& design);
// Why a configuration is PRBM-only (empty when an exact model exists).
std::string exact_support_reason(const MechanismDesign& design);

struct ExactPoint : SolveStatus {
  double displacement = 0.0;  // Delta x, m
  double force = 0.0;         // slider input force, N (= -x reaction of the slider on the chain)
  double Nx = 0.0, Ny = 0.0;  // internal force of the chain (force on the chain's tip), N
  double m0 = 0.0;            // bending moment at the ground clamp, N m
  double phi = 0.0;  // coupler angle above the axis (two-force, middle pin); crank angle alpha
                     // at the ground pin (kPinnedEnds), rad
  // The solved chain, NONDIMENSIONAL (lengths / length_scale, EI / EI_scale; the shooting solver's
  // Newton tolerances are absolute, so the chain is solved in units where lengths and loads are
  // O(1)): kDirectChain with its slider end condition; kTwoForceCoupler the crank as a free
  // cantilever under the dead coupler force.
  SegmentChain chain;
  // Two-force case: d(mismatch)/d(Q, phi), row-major, to start the next point's Newton iteration.
  std::array<double, 4> jacobian{};
  double length_scale = 1.0;     // m (the undeflected slider position)
  double EI_scale = 1.0;         // N m^2 (the largest flexural rigidity)
  std::vector<double> unknowns;  // shooting unknowns, to start the next point
  // kPinnedMiddle: the coupler cantilever (nondimensional, its own frame), its unknowns and its
  // root moment at the slider clamp (N m, own frame).
  SegmentChain coupler_chain;
  std::vector<double> coupler_unknowns;
  double coupler_m0 = 0.0;
  // kPinnedMiddle: determinant of the tangent matrix (Jacobian of the closure and pin-moment
  // residuals in the pin force, root moments and cut states) at the solution, nondimensional. A
  // change of sign between stroke points (with the same multiple-shooting cuts) means a singular
  // point was passed (fold or bifurcation).
  double stiffness_determinant = 0.0;
  // kDirectChain: sign of det dg/dz of the shooting problem at the solution (0: not known). It
  // changes at every fold and bifurcation of the stroke, so between stroke points with the same
  // multiple-shooting cuts a change means Newton landed on another branch (exact_stroke).
  int jacobian_sign = 0;
  // iterations: shooting Newton iterations, all solves of this point
  // residual: shooting residual; two-force case |pivot 2 mismatch|/slider_x0
};

// The exact model's settings (ExactMechanismSolver::Options is this type).
struct ExactMechanismOptions {
  // Inner shooting solves: GSL's rk8pd at rtol 1e-12 (the shooting default; about 4x fewer
  // right-hand sides than the Dormand-Prince 5(4) used before, docs/performance.md).
  // A Newton trial may cost at most 4 times the integration of the current point
  // (NewtonOptions::trial_cost_factor): the far trials of an undamped step (loads 100x the
  // solution's on the thin strips of 3A-lssm) cost most of its stroke's work and are rejected.
  ShootingSolver::Options shooting = [] {
    ShootingSolver::Options o;
    o.rtol = 1e-12;
    o.atol = 1e-14;
    o.newton.trial_cost_factor = 4.0;
    return o;
  }();
  double position_tolerance = 1e-10;  // middle pin: |pivot 2 mismatch| / slider_x0
  // Middle pin: a Newton step that no longer decreases the mismatch ends the iteration as
  // converged when the mismatch is below this (integrator rtol 1e-12 times the FD Jacobian).
  double noise_floor = 1e-9;
  int max_newton_iterations = 30;  // Newton steps per point on (Q, phi), (F, alpha) or, for the
                                   // middle pin, (P, root moments)
  bool reuse_jacobian = false;     // two-force case: start from the previous point's Jacobian
  // Work budget of a stroke (docs/mechanisms.md "Work budget"), counted in integrator steps so
  // that the same design gives up at the same point on any machine, under a sanitizer or on a
  // loaded one: exact_stroke gives up, each remaining solve returning converged = false with a
  // message naming the budget, once work_budget + work_budget_per_point * (stroke points)
  // integrator steps have been spent by all its solves (the shooting solver's own steps are
  // counted when it returns, the middle-pin Newton's at every evaluation). An rk8pd step costs
  // about 2.5 Dormand-Prince steps (about 1.1e6 steps/s here), so the budget, 4e7 + 2e5 per
  // point when steps were Dormand-Prince's, was halved to keep its time (about 20 s). The slowest
  // built-in stroke takes 4.4e5 steps (3A-lssm at 5 points, where the start strategies run) and
  // 5.1e4 at the default 50 points, so the budget leaves a factor of about 45; near a fold or
  // with very unequal flexures the start strategies and substeps could otherwise run for minutes
  // (issue 11). A large value lifts it.
  double work_budget = 2e7;            // integrator steps
  double work_budget_per_point = 1e5;  // integrator steps per stroke point
  // Set by exact_stroke (solve() called directly has none): the steps spent so far by every
  // solver of the stroke, shared between them, and the limit.
  std::shared_ptr<long> work_spent;
  double work_limit = 0.0;  // 0: no limit
  // Newton trial points that load a flexible segment beyond |F| L^2/EI = this are not
  // integrated (counted as failed evaluations, so the step is damped): the designs are limited
  // to 1e3 (SlenderBeamLimits), and 1e4 is EllipticSolver's domain. A Newton step of the
  // pinned-ends model of 1B-plp near its toggle tried F L^2/EI = 2e8, one shooting solve
  // there took 21 s.
  double max_load_parameter = 1e4;
  // exact_stroke of a serial chain (`mechanism analyze --stable`): when a point of the stroke
  // from the PRBM start is unstable with the slider held, return instead the stable stroke of
  // exact_stable_stroke (from the branch of the straight chain's lowest buckling mode, stable
  // neighbours taken where it turns unstable); ExactStrokeResult::stable_search says what was
  // done. Off by default: the documented answer is the proportional one, labelled by its
  // verdicts. 3A-lssm: 11.03-19.53 N, 3A-lslm: 11.30-43.63 N, stable at every point
  // (docs/stability.md "Mechanisms").
  bool stable_start = false;

  // Throws InvalidInput naming the first field outside its range.
  void validate() const;
};

struct ExactStrokeResult : SolveStatus {
  std::vector<ExactPoint> points;
  // converged(): every point converged
  long integrator_steps = 0;  // work spent by all solves of the stroke (see Options::work_budget)
  // The first point solved from the PRBM start was unstable with the slider held, and the stroke
  // starts on the branch of the straight chain's lowest buckling mode instead
  // (exact_lowest_mode_point). When that branch cannot be followed to the end, exact_stroke
  // returns the stroke from the PRBM start (this flag then false, the message saying so).
  bool lowest_mode_start = false;
  // With Options::stable_start: what was done, in words (the branch followed and how many stable
  // neighbours were taken at pitchforks, "not needed: ..." when the PRBM start's stroke is stable,
  // or why the proportional stroke was kept); empty without it.
  std::string stable_search;
};
ExactStrokeResult exact_stroke(const MechanismDesign& design,
                               const std::vector<double>& displacements);
// `progress(done, total)`, if set, is called after every stroke point (for a progress display on
// long strokes, e.g. near a fold where substeps multiply the work).
using StrokeProgress = std::function<void(std::size_t done, std::size_t total)>;
ExactStrokeResult exact_stroke(const MechanismDesign& design,
                               const std::vector<double>& displacements,
                               const ExactMechanismOptions& options,
                               const StrokeProgress& progress = nullptr);

// Dimensional PRBM of a half constant-force mechanism (MechanismDesign) over its stroke: slider
// force by virtual work (thesis eq. 2.14 scaled by eq. 2.13, F = k1 Phi/r2; class 1B F = k2
// Phi'/r2, eq. 2.19), the pin force between crank and coupler by statics of the two PRB links, and
// the largest stress of every flexible segment:
//   s pivot: sigma = K psi h/(2I) + |P|/A   (bending by the spring moment, Howell eq. 5.14, plus
//            the link force carried axially -- an upper bound on the axial part);
//   l segment: sigma = M_clamp h/(2I) + |P|/A with M_clamp the moment of the pin force P about the
//            clamp (a fixed-pinned segment carries no other load), the clamp 0.15 l behind its
//            characteristic pivot along the clamp tangent (Howell eq. 5.49 geometry).

// Slider displacements Delta x = k stroke/points, k = 1..points (Delta x = 0 is left out: the
// straight position is the 0/0 point of eq. 2.14 and a bifurcation of the exact model).
std::vector<double> stroke_displacements(const MechanismDesign& design, int points);

struct PrbmState {
  double displacement = 0.0;  // Delta x, m
  double theta2 = 0.0;        // crank angle, rad
  double theta3 = 0.0;        // principal coupler angle, rad (<= 0)
  double force = 0.0;         // slider input force F, N (positive = pushing the slider inward)
  double pin_force_x = 0.0;   // force of the coupler on the crank at pivot 2, N
  double pin_force_y = 0.0;
  std::array<double, 3> stress{};  // largest stress of each flexible pivot, Pa (0 for a pin)
  // The bending moment behind each stress with its sign (K psi at an s pivot, the pin force's
  // moment about the clamp of an l segment), N m: whether a fibre's stress changes sign over a
  // stroke (materials_fatigue.h).
  std::array<double, 3> moment{};
};

// PRBM state at one slider displacement 0 < Delta x <= toggle stroke (design finalised).
PrbmState prbm_state(const MechanismDesign& design, double displacement);

struct PrbmStrokeResult : SolveStatus {
  std::vector<double> displacement;           // m
  std::vector<double> force;                  // N
  std::array<std::vector<double>, 3> stress;  // Pa, per pivot (empty for a pin)
  std::array<double, 3> max_stress{};         // over the stroke, Pa
  double max_stress_all = 0.0;                // largest of max_stress, Pa
  int critical_pivot = 0;                     // pivot of max_stress_all (1..3)
  double safety_factor = 0.0;                 // yield_strength/max_stress_all
  double mean_force = 0.0;                    // N
  double percent_constant_force = 0.0;        // 100 min F/max F (thesis eq. 5.22); 0 when
                                              // the force vanishes (constant_force.h)
  bool force_vanishes = false;      // the force is zero within the stroke (or changes sign)
  bool force_changes_sign = false;  // the force takes both signs over the stroke
  // converged(): closed form: all values finite
  // iterations: stroke points
  // residual: largest |F_statics - F_virtual_work|/|F| (two routes to the force)
};

PrbmStrokeResult prbm_stroke(const MechanismDesign& design, int points);

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

// The PRBM's validity over a stroke (docs/mechanisms.md "Validity range of the PRBM"): at every
// stroke point, whether each long (fixed-pinned) segment is inside the range of Howell Table 5.1
// from which its Theta_max(K_theta) comes; where it first is not, WHAT is outside (the quantity,
// its value and the table's range), at how many points; and, from the exact model when it was
// solved, how large the PRBM's force error actually is there, so that "outside the table" is not
// read as "wrong" (lpp-a: load ratio n = 11.3 > 10 from the first point on, while the force error
// stays at 4.9-5.1 %, as inside the table).
//
// Three things put a point outside, checked in this order per l segment:
//  * the pin force points to the far side of the beam axis: load angle phi >= 180 deg, while the
//    table covers 11.3 deg (n = -5) to 174.3 deg (n = 10), phi = atan2(1, -n);
//  * the load ratio n lies outside -5 <= n <= 10;
//  * the PRB angle |Theta| exceeds Theta_max(K_theta) at that n (Howell eq. 5.63, Table 5.1).
// Small-length pivots (s) and fixed-fixed segments (paper 004) have no such table.

struct PrbmStrokeValidity {
  bool has_table = false;   // the design has a fixed-pinned l segment (Table 5.1 applies)
  std::string no_table;     // when it has none: why ("s pivots only", "fixed-fixed segments")
  std::vector<int> inside;  // per stroke point: 1 inside, 0 outside; -1 where no table applies
  int points_outside = 0;
  // The first point outside (none: every point is inside, or no table applies).
  std::optional<std::size_t> first_outside;  // index into the stroke
  std::optional<double> limit;               // its Delta x, m
  int pivot = 0;           // the segment there (the described pivot number, 1 at the fixed body)
  std::string quantity;    // "load_angle_phi", "load_ratio_n" or "Theta"
  std::string unit;        // "deg" or "1"
  double value = 0.0;      // the quantity there (deg for angles)
  double table_min = 0.0;  // the range the table covers for it (Theta: 0 .. Theta_max(K_theta))
  double table_max = 0.0;
  std::string reason;  // the above in words
  // Delta x of each run of consecutive points outside, first and last point, m (lpp-a at 50
  // points: only the first point, where the pin force is nearly along the beam and n = 11.3).
  std::vector<std::pair<double, double>> outside_ranges;
  // |F_prbm - F_exact| / |F_exact| from the exact model (NaN where it was not solved, or no point
  // falls in the group): at the first point outside, the largest over the points outside, and
  // the largest over the points inside.
  double force_error_at_limit;
  double max_force_error_outside;
  double max_force_error_inside;
  PrbmStrokeValidity();
};

// The validity at each stroke point (Delta x > 0, design finalised); no force errors yet.
PrbmStrokeValidity prbm_stroke_validity(const MechanismDesign& design,
                                        const std::vector<double>& displacement);

// Fills the force errors from the two force curves of the same stroke points (exact forces of 0
// are left out: their relative error is undefined).
void add_force_errors(PrbmStrokeValidity& validity,
                      const std::vector<double>& force_prbm,
                      const std::vector<double>& force_exact);

// One line for people: "left at 1 of 50 stroke points (Delta x = 0.00032 m, 2 % of the stroke):
// <reason>; the PRBM force error (against the exact model) is 5.10 % there, at most 5.10 % outside
// the table and 5.05 % inside"; or "inside Howell Table 5.1 at all 50 stroke points; ...", or why
// no table applies.
std::string describe_validity(const PrbmStrokeValidity& validity, double stroke);

struct AnalysisOptions {
  int points = 50;           // stroke points (Delta x = k stroke/points, k = 1..points)
  bool exact = true;         // solve the exact model where one exists
  bool exact_stress = true;  // stresses of each exact point (one integration of its solution)
  // Stability verdicts of every stroke point under displacement and force control of the slider,
  // PRBM and (when it ran) exact (exact_point_stability above, docs/stability.md "Mechanisms").
  bool stability = true;
  // Follow a stable branch of the exact model (`mechanism analyze --stable`): where the stroke
  // from the PRBM start is unstable with the slider held, start on the branch of the straight
  // chain's lowest buckling mode instead and keep to stable equilibria along the stroke
  // (ExactMechanismSolver::Options::stable_start; serial chains). MechanismAnalysis::stable_search
  // says what was done.
  bool stable = false;
  // Called after each exact stroke point, each exact stress evaluation and each exact stability
  // verdict: (done, total) over the passes (total = points times the passes; with `stable` the
  // stable stroke is a pass of its own, skipped when not needed), done never decreasing. Empty:
  // no calls.
  StrokeProgress progress;

  // Throws InvalidInput naming the first field outside its range.
  void validate() const;
};

// A SolveStatus (solver/common/status.h): converged when the PRBM stroke is (it always is when
// the analysis returns: a non-finite PRBM force throws NoConvergence) and, where the exact model
// was asked for and exists, the exact stroke converged; otherwise the exact stroke's termination
// with the message "<design>: <solver message>". iterations and residual are the exact stroke's
// (Newton iterations in all, its largest residual), the PRBM's where no exact stroke ran.
// warnings: yielding pivots, forces that vanish or change sign, exact states the mechanism cannot
// hold (analysis_warnings, mechanism_warnings.h), which the CLI prints and Python raises as
// FlexureWarning.
struct MechanismAnalysis : SolveStatus {
  MechanismDesign design;
  PrbmStrokeResult prbm;
  bool has_exact = false;  // the configuration has an exact model (exact_support)
  std::string exact_note;  // why not, or the solver's message
  ExactStrokeResult exact;
  std::vector<double> force_exact;           // N, one per stroke point (when has_exact)
  std::array<double, 3> max_stress_exact{};  // Pa, per pivot
  // Pa, per pivot and stroke point (max |m| h/(2I) + |N|/A along the segment,
  // exact_segment_state): empty for a pin or where has_exact_stress is false.
  std::array<std::vector<double>, 3> stress_exact;
  // max_stress_exact was computed (options.exact_stress and a converged exact stroke); else the
  // zeros above mean "not computed", not "unstressed".
  bool has_exact_stress = false;
  // Eq. 5.22 of the exact force; 0 when it vanishes or changes sign (constant_force.h).
  double percent_constant_force_exact = 0.0;
  bool force_vanishes_exact = false;
  bool force_changes_sign_exact = false;
  double mean_force_exact = 0.0;
  // max |F_prbm - F_exact|/|F_exact| over the stroke points where F_exact != 0 (next to a zero of
  // the exact force the relative error is unbounded; force_vanishes_exact flags that case).
  double max_force_error = 0.0;
  double max_force_error_at = 0.0;  // Delta x of that maximum, m
  // First Delta x where the PRBM leaves its validity range (see above); empty if it never does.
  std::optional<double> prbm_validity_limit;
  std::string prbm_validity_reason;
  // The validity at every stroke point: what is outside Table 5.1 and the PRBM's force error
  // there against the exact model (prbm_stroke_validity above).
  PrbmStrokeValidity prbm_validity;
  // Governing stress: the larger of the PRBM and (if computed) exact values, per pivot.
  std::array<double, 3> max_stress{};
  double max_stress_all = 0.0;
  double safety_factor = 0.0;        // yield_strength/max_stress_all
  std::vector<int> yielding_pivots;  // pivots whose max stress reaches the yield strength
  // Stability of every stroke point (when AnalysisOptions::stability): PRBM always, exact when
  // has_exact_stability (the exact model ran and converged). A point whose verdict could not be
  // computed is kNotChecked with the reason.
  ModelStability stability_prbm;
  ModelStability stability_exact;
  bool has_exact_stability = false;
  // With AnalysisOptions::stable: what the stable search did ("not needed: ...", the branch it
  // followed, or why it kept the proportional stroke); empty without it.
  std::string stable_search;
  // What the slider forces prbm.force, prbm.mean_force, force_exact and mean_force_exact are the
  // force of: one half as analyze_mechanism computes them; report_forces_of() rescales them. The
  // solver's own points (exact), pin forces and stresses always belong to one half.
  ForceOf force_of = ForceOf::kOneHalf;
};

MechanismAnalysis analyze_mechanism(const MechanismDesign& design, const AnalysisOptions& options);

// Rescales the slider forces of `analysis` (see MechanismAnalysis::force_of) to the force of `of`:
// F_whole = 2 F_half (mechanism.h). Ratios (percent constant force, force errors), displacements
// and stresses do not change.
void report_forces_of(MechanismAnalysis& analysis, ForceOf of);

// The four stroke verdicts (control x model) an analysis computed, in output order (the JSON's
// and the HDF5 file's): displacement control PRBM, exact; force control PRBM, exact. `stroke` is
// null for the exact model where it did not run (or converge, or its stability was not judged);
// the list is empty where the PRBM's stability was not computed.
struct StrokeStabilityEntry {
  const char* control;  // JSON/HDF5 name: "displacement_control" or "force_control"
  const char* model;    // "prbm" or "exact"
  const StrokeStability* stroke;
};
std::vector<StrokeStabilityEntry> stroke_stability_entries(const MechanismAnalysis& analysis);

}  // namespace flexure::mechanism

namespace flexure::cfm {

// The exact (elastica) model of a nondimensional constant-force mechanism (issue 5, `flexure cfm
// --exact`): the design variables (configuration, R, K1, K2, stroke d) are turned into an
// equivalent dimensional MechanismDesign -- r2 + r3 = 1, E = 1, unit widths, flexible segments
// sized by the PRBM rules of thesis Table 8.1 (an l segment r/gamma long, an s pivot 0.1 r long,
// mechanism.h) with flexural rigidities in the ratios K1 = k2/k1, K2 = k3/k1 imply (thesis eqs.
// 2.11-2.12; class 1B: k2 is the reference, eq. 2.19) -- and solved over the stroke both ways, the
// PRBM (prbm_stroke) and the exact model (exact_stroke), starting from the straight
// position. Forces are reported in the nondimensional form of the PRBM, Phi = F r2/k1 (class 1B:
// F r2/k2; thesis eq. 2.13), so Phi_exact is directly comparable with CfmResult::Phi.
//
// The thesis optimised the PRBM only, so the exact values differ from the tabulated ones; the
// differences are listed in docs/validation.md.

// The equivalent design of a nondimensional CFM (see above); stroke_percent is the
// effective stroke (after the toggle clamp). Throws InvalidInput as MechanismDesign::finalise.
mechanism::MechanismDesign cfm_equivalent_design(
    const std::string& config, double R, double K1, double K2, double stroke_percent);

struct CfmExactOptions {
  int points = 50;  // equally spaced stroke points Delta x = k d (r2 + r3)/points, k = 1..points
  mechanism::ExactMechanismOptions solver;  // the exact model's solver settings
  // Called after every exact stroke point, (done, points); empty: no calls (a progress display:
  // `cfm --table --exact` runs 68 strokes).
  mechanism::StrokeProgress progress;

  // Throws InvalidInput naming the first field outside its range.
  void validate() const;
};

struct CfmExactResult : SolveStatus {
  mechanism::MechanismDesign design;    // the equivalent design (r2 + r3 = 1, E = 1)
  double reference_stiffness = 0.0;     // k1 (class 1B: k2) of the design, to scale F to Phi
  std::vector<double> stroke_percent;   // 100 Delta x/(r2 + r3) of every point
  std::vector<double> Phi_prbm;         // PRBM F r2/k_ref per point (dimensional PRBM, rescaled)
  std::vector<double> Phi_exact_curve;  // exact F r2/k_ref per point
  double Phi_prbm_mean = 0.0;           // mean of Phi_prbm (equals CfmModel with kUniform)
  // 100 min/max of Phi_prbm and of Phi_exact_curve; 0 where that force vanishes or changes sign
  // within the stroke (mechanisms/cfm/constant_force.h; the exact force of a class 1A mechanism
  // clamped at the toggle turns negative before it: -5.33 % for lpp, R = 0.8853).
  double percent_constant_force_prbm = 0.0;
  double Phi_exact = 0.0;  // mean of Phi_exact_curve
  double percent_constant_force_exact = 0.0;
  bool force_vanishes_exact = false;        // Phi_exact_curve is zero within the stroke
  bool force_changes_sign_exact = false;    // Phi_exact_curve takes both signs
  double max_force_error = 0.0;             // max over the stroke of |F_prbm - F_exact|/|F_exact|
  double max_force_error_at_percent = 0.0;  // stroke (% of r2 + r3) of that maximum
  // converged(): every exact point converged
  // iterations: shooting Newton iterations over the stroke
  // residual: largest exact-point residual
};

// Solves the mechanism of `prbm` (its config, R, K1, K2 as used and effective stroke) with the
// PRBM and the exact model. Never throws for non-convergence (converged = false, message says at
// which point it stopped); throws InvalidInput for options.points outside [2, 100000].
CfmExactResult solve_cfm_exact(const CfmResult& prbm, const CfmExactOptions& options);

}  // namespace flexure::cfm
