#pragma once
// Dimensional design of a constant-force slider mechanism from a specification (Weight 2001
// ch. 8; docs/design.md "Dimensional design"): for every thesis sub-class (Tables 7.2-7.12) that
// the specification admits, the total length, width and thickness of the primary flexure from
// the displacement and force design equations 8.6 and 8.2 and the stress rule, the other
// flexures by eq. 8.7, the segments by Table 8.1 (MechanismDesign::finalise), and what the result
// does in the PRBM and in the exact model (subclass_sizing.h). Feasible designs come back ranked,
// the others with the constraint that binds and by how much; with nothing feasible, the shortest
// length at which something is (length_search.h).
//
// Sizing rule (thesis §8.4.2 "maximise length", Fig. 8.6): the stress of the primary flexure
// grows like h l^-(1+n) and the force like b h^3/l^2, so the design at the longest length and the
// widest section is the least stressed one that makes the force: l_tot = l_max, b_p = b_max, h_p
// from eq. 8.2; below h_min the width shrinks instead (h_p = h_min); above h_max the length does
// (h_p = h_max). With the width free the thickest section the stress allows (and the narrowest
// width that then makes the force). Every section stays within SectionBounds.
//
// Stress rule (docs/design.md "The stress rule"): by default the stresses the tool computes for
// the dimensioned design -- the PRBM's and, with the exact model, the exact ones, axial stress and
// an l segment's clamp moment included -- must both leave the safety factor; the thesis's eq. 8.5
// (the primary flexure's spring rotation alone) on request, to reproduce ch. 8's examples.
#include <array>
#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/materials_fatigue.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/solver/common/status.h"

namespace flexure::design {

struct LengthRange {
  double lower = 0.0;  // m
  double upper = 0.0;  // m (lower == upper: a fixed value)
};

enum class FlexureOrientation {
  kAny,         // in-plane where the sub-class allows it (flag I), else out-of-plane (O, o)
  kInPlane,     // sub-classes with flag I (and the one-flexure classes 1A, 1B): equal widths
  kOutOfPlane,  // flags O or o: equal thicknesses
};

enum class DesignRanking {
  kPrbm,   // the sub-class's PRBM Xi' (thesis §8.5.1 "Xi' highest"), then the least S_y
  kExact,  // the exact model's Xi' of the dimensioned design, then the least S_y
};

enum class StressRule {
  kComputed,  // the PRBM and exact stresses of the design (axial and clamp stresses included)
  kThesis,    // thesis eq. 8.5 alone (sizes and filters as ch. 8 does; reproduces its examples)
};

// What `design_mechanisms` minimises per sub-class and ranks by (kNone: the thesis's sizing at the
// longest length, ranked by Xi').
enum class SizeObjective {
  kNone,
  kLength,     // l_tot, the total link length of one half
  kFootprint,  // the plan area the whole mechanism (both halves) sweeps over the stroke
  kMass,       // the volume of the flexible segments of both halves (mass = density x volume)
};

// Bounds on every flexure's section beyond the specification's ranges (docs/design.md "Section
// bounds"). Eq. 8.2 trades width for thickness freely (F ~ b h^3), so without them a thin strip
// can be sized metres wide: b h^3 stays, b grows like h^-3.
struct SectionBounds {
  // b/h of every flexure. Thesis example 1's strip (5 in x 0.049 in) has b/h = 102; beyond a few
  // hundred a strip is foil that the planar beam model (plane stress, one bending plane) and the
  // clamps no longer describe: twice example 1.
  double max_width_to_thickness = 200.0;
  // b/l_tot of every flexure: no flexure wider than the half mechanism is long (thesis examples:
  // 0.33 and 0.21).
  double max_width_to_length = 1.0;
};

struct MechanismSpec {
  double force = 0.0;  // N, mean slider force of one half (eq. 8.2's F)
  // What the user's force was the force of (mechanism.h): labels the designs (their notes and the
  // `force_of` their files carry); `force` above is one half's whatever it says.
  mechanism::ForceOf force_of = mechanism::ForceOf::kOneHalf;
  double stroke = 0.0;  // m, slider travel (eq. 8.6's disp)
  // The strips' material as the library's one Material (solver/common/section.h), copied onto
  // every design (MechanismDesign::material): E (Pa; the effective modulus once the plate rule is
  // applied), S_y (Pa; without it the design reports the strength it needs), nu and the density.
  Material material;
  double safety_factor = 1.0;
  LengthRange length;  // l_tot, total length of one half's links (eq. 5.1)
  // b and h of every flexure; free_range() where the specification leaves them open (the width
  // then follows from the force at the thickest flexure the stress and the thickness range
  // allow; the thickness from the force at the widest flexure).
  LengthRange width;
  LengthRange thickness;
  static LengthRange free_range() { return {0.0, std::numeric_limits<double>::infinity()}; }
  FlexureOrientation orientation = FlexureOrientation::kAny;
  std::optional<double> pcf_min;     // keep sub-classes with Xi' >= this (printed-model value)
  std::vector<std::string> configs;  // empty: all nine
  DesignRanking ranking = DesignRanking::kPrbm;
  bool exact = true;  // evaluate the feasible designs with the exact model
  int points = 50;    // stroke points of the PRBM and exact strokes
  StressRule stress_rule = StressRule::kComputed;
  // Largest |F_exact/F - 1| of a design's exact mean force against the specified force, with the
  // exact model (docs/design.md "The force"): eq. 8.2 sizes by the PRBM, which is 2-8 % off the
  // elastica for the thesis's sub-classes at their strokes but 40 % for some at short lengths.
  double force_tolerance = 0.10;
  SectionBounds bounds;
  SizeObjective minimize = SizeObjective::kNone;
  // Where the material came from and what fatigue needs beyond Material (a data/materials.csv id,
  // empty when given by value; S_ut, S_e' or S_f'), written onto every design (MechanismDesign's
  // fields of the same names; materials_fatigue.h).
  std::string material_id;
  std::optional<double> ultimate_strength, endurance_limit, endurance_cycles;
  bool ductile = true;
  // Set: keep only designs whose modified Goodman safety factor over rest -> full stroke -> rest
  // (Howell eq. 3.110, materials_fatigue.h) is at least safety_factor; the others are rejected
  // with binding "fatigue: ...". Needs ultimate_strength and endurance_limit. With a fatigue
  // strength (no endurance limit) that is a life of at least endurance_cycles, not infinite.
  std::optional<FatigueOptions> fatigue;
  // Set by design_mechanisms for its sizing pass under `fatigue` (not by callers): the safety
  // factor the fatigue check asks for, while safety_factor is raised to the static one that gives
  // the rest -> full stroke cycle that fatigue safety factor (docs/fatigue.md).
  std::optional<double> fatigue_safety_factor;
  // Called after each sub-class the specification admits is sized (with its exact evaluation),
  // (done, total) over those sub-classes, and with (total, total) at each length of the search
  // that follows when none is feasible; done never decreases. refine_design_exact calls it after
  // each exact stroke instead, with ExactRefinementOptions::progress's (done, total): total = 1 +
  // (1 + 2 free variables) * 301 for its one start, its sequence starts and the default
  // max_evaluations. For a progress display; a caller stops a long synthesis by throwing from it
  // (the Python module does on Ctrl-C). Empty: none.
  std::function<void(std::size_t done, std::size_t total)> progress;

  // Throws InvalidInput naming the first field outside its range (non-finite, <= 0, a range with
  // lower > upper, an unknown configuration).
  void validate() const;
};

// Which way l_tot would have to move to cure an infeasible design (at the length tried).
enum class LengthCure { kNone, kLonger, kShorter };

// A SolveStatus: kConverged when feasible; kInfeasible, with `binding` as the message, when not.
struct DimensionedDesign : SolveStatus {
  std::string subclass;  // "lpp-b"
  const char* config = "";
  bool feasible = false;
  // Why not: the binding constraint with the numbers, and shortfall = needed/available (>= 1;
  // the closest infeasible design has the smallest).
  std::string binding;
  std::optional<double> shortfall;  // empty where no ratio measures it (a geometry limit)
  LengthCure cure = LengthCure::kNone;
  // m: the shortest l_tot (above the range) at which the full sizing makes this sub-class
  // feasible, when none is feasible in the range and a longer mechanism cures it (a bisection to
  // 1e-4; this value itself was sized feasible). Empty where not searched or not found.
  std::optional<double> length_needed;

  cfm::CfmResult model;     // the sub-class by the PRBM model (thesis sampling, its design stroke)
  double M = 0.0, n = 0.0;  // stress power law (printed Ch. 7 values; eq. 8.5)
  double stroke_percent = 0.0;  // d of the dimensioned design (eq. 8.6)
  double l_tot = 0.0, r2 = 0.0, r3 = 0.0;
  std::string section_rule;  // "equal widths (in-plane)", "equal thicknesses (out-of-plane)",
                             // "h = C h_p, b = D_min b_p"
  // Per pivot 1..3 (0 for a pin): flexible segment length, thickness, width.
  std::array<double, 3> segment_length{}, thickness{}, width{};
  double primary_stress = 0.0;  // Pa, eq. 8.5
  // Pa, SF times the stress of eq. 8.5 (the thesis's design rule: the primary flexure at the end
  // of the stroke, alpha = M d^n; the rules C, D keep the others below it). It leaves out the
  // axial stress and, for an l segment, the clamp moment of the pin force (Howell §5.2), so
  // the PRBM and exact stresses of the design are higher: their values below (thesis example 1:
  // 167 ksi by eq. 8.5, 190 ksi by the PRBM stresses, 186 ksi exact).
  double required_yield_strength = 0.0;
  double required_yield_strength_prbm = 0.0;  // SF times the largest PRBM stress of any flexure
  std::optional<double> required_yield_strength_exact;  // SF times the largest exact stress
  double force_prbm = 0.0;                              // N, mean over the stroke
  double percent_constant_force_prbm = 0.0;
  double safety_factor_prbm = 0.0;
  std::optional<double> force_exact;
  std::optional<double> percent_constant_force_exact;
  std::optional<double> safety_factor_exact;
  std::string exact_note;  // why there is no exact value
  // The size of the mechanism (docs/design.md "--minimize"): plan area swept by both halves over
  // the stroke (l_tot by twice the highest PRBM pivot 2), m^2, and the volume of the flexible
  // segments of both halves, m^3.
  double footprint = 0.0;
  double flexure_volume = 0.0;
  double width_to_thickness = 0.0;  // largest b/h of any flexure
  double width_to_length = 0.0;     // largest b/l_tot of any flexure
  int exact_evaluations = 0;        // refine_design_exact: exact strokes of the optimisation
  // MechanismSpec::fatigue: the check of the design (its critical pivot, stresses, S_e, SF).
  std::optional<mechanism::MechanismFatigue> fatigue;
  mechanism::MechanismDesign design;  // ready for analyze_mechanism (when feasible)
};

// Table 8.2's screens, reported for orientation (the per-design sizing decides): Method 1's
// M_max (longest length, thinnest flexure) and M_min (shortest, thickest), both with lambda = 1 and
// n = 0.5 as the thesis's examples 2 and 3 evaluate them (eq. 8.17); Method 2's Psi_min by lpp-a or
// lpp-b. Empty without a yield strength.
struct DesignScreens {
  double omega = 0.0;                                         // S_y/E (eq. 4.18)
  double stroke_percent_min = 0.0, stroke_percent_max = 0.0;  // eq. 8.6 at l_max, l_min
  std::optional<double> M_max, M_min;
  std::optional<double> Psi_min;
  std::optional<double> lpp_thickness_max, lpp_force_max;  // Method 2: h_max, F_max of lpp-a/b
  std::string lpp_subclass;
};

// A SolveStatus: kConverged with at least one feasible design; kInfeasible otherwise, the message
// naming the closest design's binding constraint and the shortest length that would do. Its
// warnings: feasible designs short of the safety factor by their PRBM or exact stresses (possible
// under StressRule::kThesis, see SafetyShortfall below).
struct MechanismDesignReport : SolveStatus {
  std::vector<DimensionedDesign> designs;   // feasible, best first
  std::vector<DimensionedDesign> rejected;  // closest first
  DesignScreens screens;
  // Nothing feasible in the length range: the shortest l_tot (up to 100 l_max) at which a
  // sub-class is feasible by the full sizing, and which (it may be a row the thesis's choice of
  // a or b rows left out at l_max). A bisection to 1e-4: this length was sized feasible, and
  // 1e-4 less was not.
  std::optional<double> length_needed;
  std::string length_needed_subclass;
  // MechanismSpec::fatigue with a yield strength: the static safety factor the designs were sized
  // at so that their cycle 0 -> sigma_max meets the fatigue safety factor (c_size = 1); empty
  // otherwise.
  std::optional<double> sizing_safety_factor;
};

// Throws InvalidInput for an invalid specification.
MechanismDesignReport design_mechanisms(const MechanismSpec& spec);

// Beyond the thesis (docs/design.md "Against the exact model"): the feasible design `prbm_design`
// refined against the exact model. R, K1, K2 maximise the exact percent constant force at the
// design's stroke d under the sub-class's orientation rules and Xi' floor (cfm_synthesis.h;
// Xi'_exact depends on them and d only), the links are re-derived at the same l_tot, and all
// thicknesses are scaled together until the exact mean force is the specified one (the
// elastica's force scales as h^3 at fixed geometry, its bending stress as h); the widths follow
// the design's section rule; then the section of that force (section_family.h) is chosen within
// the ranges and SectionBounds by the stress rule (kComputed: the exact and PRBM stresses; kThesis:
// the exact stress against the yield strength). Returns the refined design with its exact values,
// or an infeasible one naming the binding constraint (an unmet Xi' floor, the stress, a range).
DimensionedDesign refine_design_exact(const MechanismSpec& spec,
                                      const DimensionedDesign& prbm_design);

// A feasible design whose safety factor by its PRBM or exact stresses falls below the one
// specified: possible under StressRule::kThesis, whose eq. 8.5 leaves out the axial stress and
// the clamp moment (docs/errata.md). The smaller of the two safety factors.
struct SafetyShortfall {
  std::string subclass;
  double safety_factor = 0.0;
};
// The report's feasible designs short of `safety_factor` (a relative allowance of 1e-9), in the
// report's order.
std::vector<SafetyShortfall> designs_short_of_safety_factor(const MechanismDesignReport& report,
                                                            double safety_factor);

// The design `design mechanism` writes (--out, --drawing): the refinement against the exact
// model where there is one, else the best feasible design. A refinement that is not feasible
// comes back marked so (feasible = false, binding and the design's note saying why, and whether
// it is still the PRBM design): it is written only on request (--allow-infeasible).
// Precondition: the report has a feasible design.
DimensionedDesign design_for_output(const MechanismDesignReport& report,
                                    const std::optional<DimensionedDesign>& refined);

// Table 8.2's screens on their own (DesignScreens), for the specification.
DesignScreens design_screens(const MechanismSpec& spec);

// "F = 10 N (one half)" or "F = 20 N for the whole symmetric mechanism (10 N per half)".
std::string specified_force_text(const MechanismSpec& spec);

// A length hint as printed: l_tot rounded up to 4 significant digits in mm (m), so that the
// printed value, fed back, is no shorter than the feasible length found.
double length_hint(double l_tot);

}  // namespace flexure::design
