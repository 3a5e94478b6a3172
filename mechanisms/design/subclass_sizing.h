#pragma once
// One thesis sub-class dimensioned for a specification at one total length l_tot (Weight 2001
// ch. 8; docs/design.md "Dimensional design"): stroke (eq. 8.6), force (eq. 8.2), the section
// family of section_family.h inside the specification's ranges and its SectionBounds, the
// thickness the stress rule allows, Table 8.1's segments, and what the design does in the PRBM and
// (with the exact model) the elastica. design_mechanisms (mechanism_synthesis.h) chooses the
// length: the longest, or the one --minimize asks for.
#include <optional>
#include <string>

#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/design/mechanism_synthesis.h"
#include "flexure/mechanisms/design/section_family.h"
#include "flexure/mechanisms/mechanism_analysis.h"

namespace flexure::design {

// Which member of the section family a design takes at its length:
enum class SectionPolicy {
  kWidest,    // the least stressed: the widest section the ranges and bounds allow (width given)
  kThickest,  // the least material: the thickest section the stress allows (width free; mass)
};
SectionPolicy section_policy(const MechanismSpec& spec);

enum class SizingDepth {
  kPrbm,  // without the exact model: a necessary condition of kFull, cheap (length searches)
  kFull,  // as the specification says (the exact model when spec.exact)
};

// kCheck: only whether the design is feasible, from its least stressed section (t = lo): every
// stress grows with t, so a family has a section within the safety factor iff its widest one is
// (one PRBM stroke and one exact stroke instead of the thickness search). The design returned
// then has that section, not the one the policy would take.
enum class SizingPurpose { kDesign, kCheck };

// The section of a family chosen by the stress rule, evaluated.
struct StressedSection {
  bool feasible = false;
  std::string binding;  // why not
  std::optional<double> shortfall;
  LengthCure cure = LengthCure::kNone;
  double t = 0.0;  // primary thickness, m
  mechanism::PrbmStrokeResult prbm;
  std::optional<mechanism::MechanismAnalysis> analysis;  // with the exact model, converged
  std::string exact_note;                                // why there is no exact analysis
};

// The thickness t of `family` for `design` (geometry, E, stroke set; its sections are set to the
// answer and it is finalised): t in [interval.lo, interval.hi], the widest (kWidest: t = lo) or
// the thickest (kThickest) section whose stresses leave spec.safety_factor against the yield
// strength -- under StressRule::kComputed the PRBM stresses and, with `exact`, the exact ones
// (both grow with t: t S/sigma(t) is always safe, docs/design.md), under kThesis eq. 8.5's
// thickness `t_thesis` (the caller checks eq. 8.5 itself). Without a yield strength nothing
// limits the stress: t = lo or hi.
StressedSection choose_section(const MechanismSpec& spec,
                               mechanism::MechanismDesign& design,
                               const SectionFamily& family,
                               const SectionInterval& interval,
                               SectionPolicy policy,
                               bool exact,
                               std::optional<double> t_thesis,
                               SizingPurpose purpose = SizingPurpose::kDesign);

// A sub-class prepared for sizing at any length (its PRBM model evaluated once).
class SubclassSizer {
 public:
  SubclassSizer(const MechanismSpec& spec, const cfm::CfmSubclass& row);

  // The sub-class at l_tot. Infeasible designs name the binding constraint, its shortfall and
  // which way the length would cure it (`cure`).
  DimensionedDesign at(double l_tot,
                       SectionPolicy policy,
                       SizingDepth depth,
                       SizingPurpose purpose = SizingPurpose::kDesign) const;

  // The largest l_tot in [lower, upper] at which the section family fits its ranges and bounds,
  // for a design too thick at `upper` (thesis §8.4.2: "above h_max the length shrinks"). Empty
  // when even `lower` does not fit.
  std::optional<double> longest_fitting_length(double lower, double upper) const;

  const cfm::CfmSubclass& row() const { return row_; }

 private:
  mechanism::MechanismDesign geometry(double l_tot) const;
  SectionFamily family(const mechanism::MechanismDesign& geometry, double l_tot) const;

  const MechanismSpec& spec_;
  const cfm::CfmSubclass& row_;
  cfm::CfmResult model_;
  std::array<double, 3> tau_{}, w_{};  // section rule: h_i = tau_i h_p, b_i = w_i b_p
  std::string section_rule_;
};

// The plan area swept by both halves of `design` over its stroke: l_tot (the straight
// mechanism's length) by twice the highest PRBM pivot 2 (r2 sin theta2), m^2; and the volume of
// the flexible segments of both halves, m^3.
double mechanism_footprint(const mechanism::MechanismDesign& design, double l_tot, int points);
double flexure_volume(const mechanism::MechanismDesign& design);

}  // namespace flexure::design
