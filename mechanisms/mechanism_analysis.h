#pragma once
// One stroke of a MechanismDesign computed both ways -- PRBM (mechanism_prbm.h) and exact
// (mechanism_exact.h) -- with the comparison the issue asks for: force error of the PRBM relative
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
#include <optional>
#include <string>
#include <vector>

#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_exact.h"
#include "flexure/mechanisms/mechanism_prbm.h"
#include "flexure/mechanisms/mechanism_stability.h"
#include "flexure/mechanisms/prbm_validity.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {

struct AnalysisOptions {
  int points = 50;           // stroke points (Delta x = k stroke/points, k = 1..points)
  bool exact = true;         // solve the exact model where one exists
  bool exact_stress = true;  // stresses of each exact point (one integration of its solution)
  // Stability verdicts of every stroke point under displacement and force control of the slider,
  // PRBM and (when it ran) exact (mechanism_stability.h, docs/stability.md "Mechanisms").
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
  // there against the exact model (prbm_validity.h).
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
