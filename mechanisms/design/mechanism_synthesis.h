#pragma once
// Dimensional design of a constant-force slider mechanism from a specification (Weight 2001
// ch. 8; docs/design.md "Dimensional design"): for every thesis sub-class (Tables 7.2-7.12) that
// the specification admits, the total length, width and thickness of the primary flexure from
// the displacement, stress and force design equations 8.5, 8.6 and 8.2, the other flexures by
// eq. 8.7, the segments by Table 8.1 (MechanismDesign::finalise), and what the result does in
// the PRBM and in the exact model. Feasible designs come back ranked, the others with the
// constraint that binds and by how much.
//
// Sizing rule (thesis §8.4.2 "maximise length", Fig. 8.6): the stress of the primary flexure
// grows like h l^-(1+n) and the force like b h^3/l^2, so the design at the longest length and the
// widest section is the least stressed one that makes the force: l_tot = l_max, b_p = b_max, h_p
// from eq. 8.2; below h_min the width shrinks instead (h_p = h_min); above h_max the length does
// (h_p = h_max).
#include <array>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/mechanism.h"

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

struct MechanismSpec {
  double force = 0.0;                    // N, mean slider force of one half (eq. 8.2's F)
  double stroke = 0.0;                   // m, slider travel (eq. 8.6's disp)
  double E = 0.0;                        // Pa
  std::optional<double> yield_strength;  // Pa; without it the design reports what it needs
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

  // Throws InvalidInput naming the first field outside its range (non-finite, <= 0, a range with
  // lower > upper, an unknown configuration).
  void validate() const;
};

struct DimensionedDesign {
  std::string subclass;  // "lpp-b"
  const char* config = "";
  bool feasible = false;
  // Why not: the binding constraint with the numbers, and shortfall = needed/available (>= 1;
  // the closest infeasible design has the smallest).
  std::string binding;
  std::optional<double> shortfall;  // empty where no ratio measures it (a geometry limit)

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
  std::string exact_note;             // why there is no exact value
  int exact_evaluations = 0;          // refine_design_exact: exact strokes of the optimisation
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

struct MechanismDesignReport {
  std::vector<DimensionedDesign> designs;   // feasible, best first
  std::vector<DimensionedDesign> rejected;  // closest first
  DesignScreens screens;
};

// Throws InvalidInput for an invalid specification.
MechanismDesignReport design_mechanisms(const MechanismSpec& spec);

// Beyond the thesis (docs/design.md "Against the exact model"): the feasible design `prbm_design`
// refined against the exact model. R, K1, K2 maximise the exact percent constant force at the
// design's stroke d under the sub-class's orientation rules and Xi' floor (cfm_exact_refinement.h;
// Xi'_exact depends on them and d only), the links are re-derived at the same l_tot, and all
// thicknesses are scaled together until the exact mean force is the specified one (the
// elastica's force scales as h^3 at fixed geometry, its bending stress as h); the widths follow
// the design's section rule. Returns the refined design with its exact values, or an infeasible
// one naming the binding constraint (the exact stress over the yield strength, a range).
DimensionedDesign refine_design_exact(const MechanismSpec& spec,
                                      const DimensionedDesign& prbm_design);

// Table 8.2's screens on their own (DesignScreens), for the specification.
DesignScreens design_screens(const MechanismSpec& spec);

}  // namespace flexure::design
