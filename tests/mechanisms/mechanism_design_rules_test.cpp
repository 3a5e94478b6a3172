// Dimensional design by the tool's own stresses (issue 27; docs/design.md "The stress rule",
// "Section bounds", "--minimize", "Length hints"). Every design listed as feasible is analysed
// again here with the library's PRBM and exact models (analyze_mechanism, the same analysis as
// `flexure mechanism analyze` of its file): its safety factor by both models, its exact force
// against the specification and its sections against the bounds are recomputed from the design
// itself, not read from the report. The reproducers of the issue are the specifications.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/design/length_search.h"
#include "flexure/mechanisms/design/mechanism_synthesis.h"
#include "flexure/mechanisms/design/section_family.h"
#include "flexure/mechanisms/design/subclass_sizing.h"
#include "flexure/mechanisms/mechanism_analysis.h"

namespace flexure::design {
namespace {

constexpr double kInch = 0.0254;
constexpr double kPoundForce = 4.4482216152605;
constexpr double kPsi = kPoundForce / (kInch * kInch);
// A ratio computed to rounding on its bound is on it.
constexpr double kRounding = 1e-9;

// Issue 27's first reproducer: 20 N over 10 mm, steel, S_y 1200 MPa, SF 1.5, l_tot 30-150 mm.
MechanismSpec steel_20N() {
  MechanismSpec s;
  s.force = 20.0;
  s.stroke = 10e-3;
  s.material.E = 200e9;
  s.material.yield_strength = 1200e6;
  s.safety_factor = 1.5;
  s.length = {30e-3, 150e-3};
  s.width = MechanismSpec::free_range();
  s.thickness = MechanismSpec::free_range();
  return s;
}

// Issue 27's second reproducer: 25 lbf over 4 in, E 30 Msi, S_y 167 ksi, SF 1.5, 10-20 in.
MechanismSpec spring_steel_25lbf() {
  MechanismSpec s;
  s.force = 25.0 * kPoundForce;
  s.stroke = 4.0 * kInch;
  s.material.E = 30e6 * kPsi;
  s.material.yield_strength = 167e3 * kPsi;
  s.safety_factor = 1.5;
  s.length = {10.0 * kInch, 20.0 * kInch};
  s.width = MechanismSpec::free_range();
  s.thickness = MechanismSpec::free_range();
  return s;
}

// The tool before issue 27: eq. 8.5, no section bounds, no force check.
void before_issue_27(MechanismSpec& s) {
  s.stress_rule = StressRule::kThesis;
  s.bounds.max_width_to_thickness = 1e6;
  s.bounds.max_width_to_length = 1e3;
  s.force_tolerance = 1.0;
}

struct Checked {
  double sf_prbm = 0.0, sf_exact = 0.0, force_exact = 0.0;
};

// The design analysed again: its safety factors by the PRBM and exact stresses and its exact
// mean force.
Checked analyse(const mechanism::MechanismDesign& design, int points = 50) {
  mechanism::AnalysisOptions o;
  o.points = points;
  const mechanism::MechanismAnalysis a = mechanism::analyze_mechanism(design, o);
  EXPECT_TRUE(a.has_exact && a.exact.converged() && a.has_exact_stress) << design.name;
  Checked c;
  c.sf_prbm = *design.material.yield_strength / a.prbm.max_stress_all;
  c.sf_exact = *design.material.yield_strength /
               *std::max_element(a.max_stress_exact.begin(), a.max_stress_exact.end());
  c.force_exact = a.mean_force_exact;
  return c;
}

// Every listed design: SF by both models >= the specification's, exact force within the
// tolerance, every flexure within the section bounds -- all from the design itself.
void expect_meets(const MechanismSpec& spec, const DimensionedDesign& d) {
  const Checked c = analyse(d.design, spec.points);
  const double SF = spec.safety_factor * (1.0 - kRounding);
  EXPECT_GE(c.sf_prbm, SF) << d.subclass;
  EXPECT_GE(c.sf_exact, SF) << d.subclass;
  EXPECT_LE(std::abs(c.force_exact / spec.force - 1.0), spec.force_tolerance) << d.subclass;
  EXPECT_NEAR(c.sf_prbm, d.safety_factor_prbm, 1e-9 * c.sf_prbm) << d.subclass;
  EXPECT_NEAR(c.sf_exact, *d.safety_factor_exact, 1e-9 * c.sf_exact) << d.subclass;
  for (const mechanism::JointDesign& j : d.design.joints) {
    if (j.type == mechanism::PivotType::kPin) continue;
    EXPECT_LE(j.width / j.thickness, spec.bounds.max_width_to_thickness * (1.0 + kRounding))
        << d.subclass;
    EXPECT_LE(j.width, spec.bounds.max_width_to_length * d.l_tot * (1.0 + kRounding)) << d.subclass;
  }
}

// The issue's numbers, before: 38 designs listed, 30 of them below SF 1.5 by the exact stresses
// and 20 by the PRBM stresses (lowest exact 1.12, slp-a90I).
TEST(DesignStressRule, BeforeTheIssueEqEightFiveListedDesignsBelowTheSafetyFactor) {
  MechanismSpec spec = steel_20N();
  before_issue_27(spec);
  const MechanismDesignReport r = design_mechanisms(spec);
  int below_exact = 0, below_prbm = 0;
  for (const DimensionedDesign& d : r.designs) {
    const Checked c = analyse(d.design);
    below_exact += c.sf_exact < 1.5;
    below_prbm += c.sf_prbm < 1.5;
  }
  EXPECT_EQ(r.designs.size(), 38u);
  EXPECT_EQ(below_exact, 30);
  EXPECT_EQ(below_prbm, 20);
}

// Now: every listed design meets SF 1.5 by both models, and where nothing else bounds it the
// thickness is the thickest that does (the least safety factor is the one asked for).
TEST(DesignStressRule, EveryListedDesignMeetsTheSafetyFactorByBothModels) {
  const MechanismSpec spec = steel_20N();
  const MechanismDesignReport r = design_mechanisms(spec);
  ASSERT_GE(r.designs.size(), 10u);
  for (const DimensionedDesign& d : r.designs) {
    expect_meets(spec, d);
    const double least = std::min(d.safety_factor_prbm, *d.safety_factor_exact);
    // The thickest section: SF within the stopping tolerance of the secant (1e-4), unless the
    // slender-beam limit b >= h stopped the thickness first.
    if (d.width_to_thickness > 1.0 + 1e-6) EXPECT_LE(least, 1.5 * (1.0 + 2e-4)) << d.subclass;
  }
  // The rejected name the model whose stresses bind and the safety factor it gives.
  for (const DimensionedDesign& d : r.rejected) {
    if (d.binding.rfind("stress", 0) != 0) continue;
    EXPECT_NE(d.binding.find("safety factor"), std::string::npos) << d.binding;
  }
}

// The width given (widest section): the least stressed design is checked, not re-sized.
TEST(DesignStressRule, WidthGivenDesignsAreCheckedByBothModels) {
  MechanismSpec spec = steel_20N();
  spec.width = {5e-3, 30e-3};
  spec.thickness = {0.05e-3, 2e-3};
  const MechanismDesignReport r = design_mechanisms(spec);
  ASSERT_FALSE(r.designs.empty());
  for (const DimensionedDesign& d : r.designs) expect_meets(spec, d);
}

// The metre-wide strips of the second reproducer (sss-b: 3.0 m and 4.1 m wide on a 0.5 m half)
// come back under eq. 8.5 without bounds, and are rejected with the bound named, the bounds on.
TEST(DesignSectionBounds, StripsWiderThanTheMechanismAreRejectedWithTheBound) {
  MechanismSpec spec = spring_steel_25lbf();
  before_issue_27(spec);
  const MechanismDesignReport before = design_mechanisms(spec);
  ASSERT_FALSE(before.designs.empty());
  EXPECT_EQ(before.designs.front().subclass, "sss-b");
  EXPECT_GT(before.designs.front().width_to_length, 5.0);
  spec.bounds = SectionBounds{};
  const MechanismDesignReport now = design_mechanisms(spec);
  const auto sss_b = std::find_if(now.rejected.begin(), now.rejected.end(), [](const auto& d) {
    return d.subclass == "sss-b";
  });
  ASSERT_NE(sss_b, now.rejected.end());
  // The section bounds force a thicker flexure, which then fails the stress: both named.
  EXPECT_NE(sss_b->binding.find("--max-width-to-"), std::string::npos) << sss_b->binding;
  // The default rule: every design within both bounds and the safety factor.
  const MechanismSpec computed = spring_steel_25lbf();
  const MechanismDesignReport c = design_mechanisms(computed);
  ASSERT_FALSE(c.designs.empty());
  for (const DimensionedDesign& d : c.designs) expect_meets(computed, d);
  // The bounds are options: a tighter width/thickness leaves fewer designs, each within it.
  MechanismSpec tight = computed;
  tight.bounds.max_width_to_thickness = 60.0;
  const MechanismDesignReport t = design_mechanisms(tight);
  EXPECT_LT(t.designs.size(), c.designs.size());
  for (const DimensionedDesign& d : t.designs) expect_meets(tight, d);
}

// --model exact on the second reproducer: the refined design makes the specified force in the
// exact model and meets SF 1.5 by both models; by eq. 8.5 the refinement is not feasible
// (before the issue it was written anyway).
TEST(DesignStressRule, RefinedDesignMeetsTheSpecificationInTheExactModel) {
  const MechanismSpec spec = spring_steel_25lbf();
  const MechanismDesignReport r = design_mechanisms(spec);
  ASSERT_FALSE(r.designs.empty());
  const DimensionedDesign x = refine_design_exact(spec, r.designs.front());
  ASSERT_TRUE(x.feasible) << x.binding;
  const Checked c = analyse(x.design);
  EXPECT_NEAR(c.force_exact / spec.force, 1.0, 1e-5);
  EXPECT_GE(c.sf_exact, 1.5 * (1.0 - kRounding));
  EXPECT_GE(c.sf_prbm, 1.5 * (1.0 - kRounding));
  for (const mechanism::JointDesign& j : x.design.joints) {
    if (j.type != mechanism::PivotType::kPin) EXPECT_LE(j.width, x.l_tot);
  }
  MechanismSpec thesis = spec;
  thesis.stress_rule = StressRule::kThesis;
  const MechanismDesignReport rt = design_mechanisms(thesis);
  ASSERT_FALSE(rt.designs.empty());
  const DimensionedDesign xt = refine_design_exact(thesis, rt.designs.front());
  EXPECT_FALSE(xt.feasible);
  EXPECT_NE(xt.binding.find("stress"), std::string::npos) << xt.binding;
}

// A design whose exact force is far from the specified one (the PRBM sizes it) is rejected.
TEST(DesignForce, ExactForceOutsideTheToleranceIsRejected) {
  MechanismSpec spec = steel_20N();
  spec.minimize = SizeObjective::kLength;
  spec.configs = {"plp"};
  spec.force_tolerance = 1.0;
  const MechanismDesignReport loose = design_mechanisms(spec);
  ASSERT_FALSE(loose.designs.empty());
  double worst = 0.0;
  for (const DimensionedDesign& d : loose.designs) {
    worst = std::max(worst, std::abs(*d.force_exact / spec.force - 1.0));
  }
  EXPECT_GT(worst, 0.2);  // measured: plp-a80 at its shortest makes 12.5 N in the exact model
  spec.force_tolerance = 0.1;
  const MechanismDesignReport r = design_mechanisms(spec);
  for (const DimensionedDesign& d : r.designs) expect_meets(spec, d);
  bool named = false;
  for (const DimensionedDesign& d : r.rejected) {
    named |= d.binding.find("--force-tolerance") != std::string::npos;
  }
  EXPECT_TRUE(named);
}

// --minimize length: every sub-class at its shortest feasible l_tot, ranked shortest first; a
// mechanism 0.5 % shorter than the shortest has no feasible design at all.
TEST(DesignMinimize, LengthIsTheShortestFeasible) {
  MechanismSpec spec = steel_20N();
  spec.minimize = SizeObjective::kLength;
  const MechanismDesignReport r = design_mechanisms(spec);
  ASSERT_GE(r.designs.size(), 3u);
  for (std::size_t k = 0; k < r.designs.size(); ++k) {
    const DimensionedDesign& d = r.designs[k];
    expect_meets(spec, d);
    if (k > 0) EXPECT_GE(d.l_tot, r.designs[k - 1].l_tot);
    // This sub-class is not feasible 0.5 % shorter (where its length is above the range's end).
    if (d.l_tot > spec.length.lower * 1.006) {
      const SubclassSizer sizer(spec, cfm::find_thesis_subclass(d.subclass));
      EXPECT_FALSE(sizer.at(d.l_tot * 0.995, section_policy(spec), SizingDepth::kFull).feasible)
          << d.subclass;
    }
  }
  MechanismSpec shorter = spec;
  shorter.length.upper = 0.995 * r.designs.front().l_tot;
  EXPECT_TRUE(design_mechanisms(shorter).designs.empty());
}

// The slider-crank of the PRBM in closed form (law of cosines at the end of the stroke, where the
// crank stands highest): the footprint of both halves, l_tot by 2 r2 sin theta2.
double footprint_closed_form(const DimensionedDesign& d, double stroke) {
  const double x = d.r2 + d.r3 - stroke;
  const double c = (x * x + d.r2 * d.r2 - d.r3 * d.r3) / (2.0 * x * d.r2);
  const double s = std::sqrt(1.0 - c * c);
  return (d.l_tot - std::min(0.0, d.r2 * c)) * 2.0 * d.r2 * s;
}

TEST(DesignMinimize, FootprintAndMassAreRankedAndNoWorseThanTheLongestDesign) {
  MechanismSpec spec = steel_20N();
  spec.minimize = SizeObjective::kFootprint;
  const MechanismDesignReport f = design_mechanisms(spec);
  ASSERT_GE(f.designs.size(), 3u);
  for (std::size_t k = 0; k < f.designs.size(); ++k) {
    const DimensionedDesign& d = f.designs[k];
    EXPECT_NEAR(d.footprint, footprint_closed_form(d, spec.stroke), 1e-9 * d.footprint)
        << d.subclass;
    if (k > 0) EXPECT_GE(d.footprint, f.designs[k - 1].footprint);
  }
  spec.minimize = SizeObjective::kMass;
  const MechanismDesignReport m = design_mechanisms(spec);
  const MechanismDesignReport longest = design_mechanisms(steel_20N());
  ASSERT_GE(m.designs.size(), 3u);
  for (std::size_t k = 0; k < m.designs.size(); ++k) {
    const DimensionedDesign& d = m.designs[k];
    expect_meets(spec, d);
    double volume = 0.0;
    for (const mechanism::JointDesign& j : d.design.joints) {
      volume += 2.0 * j.width * j.thickness * j.length;  // both halves
    }
    EXPECT_NEAR(d.flexure_volume, volume, 1e-12 * volume);
    if (k > 0) EXPECT_GE(d.flexure_volume, m.designs[k - 1].flexure_volume);
    for (const DimensionedDesign& l : longest.designs) {
      if (l.subclass == d.subclass) {
        EXPECT_LE(d.flexure_volume, l.flexure_volume * (1.0 + 1e-9)) << d.subclass;
      }
    }
  }
}

// The length hint of an infeasible specification: fed back (as printed, rounded up), it is
// feasible; 0.5 % shorter nothing is. Before the issue the hints of this specification (eq. 8.5
// at the thinnest flexure) walked 40 -> 54.79 -> 54.79 mm, never feasible.
TEST(DesignLengthHint, TheHintedLengthIsFeasibleAndAShorterOneIsNot) {
  MechanismSpec spec = steel_20N();
  spec.thickness = {0.2e-3, 1e-3};
  spec.length = {40e-3, 40e-3};
  const MechanismDesignReport r = design_mechanisms(spec);
  ASSERT_TRUE(r.designs.empty());
  ASSERT_TRUE(r.length_needed.has_value());
  const double hint = length_hint(*r.length_needed);
  EXPECT_GE(hint, *r.length_needed);
  EXPECT_LE(hint, *r.length_needed * (1.0 + 2e-3));
  MechanismSpec fed = spec;
  fed.length = {hint, hint};
  const MechanismDesignReport ok = design_mechanisms(fed);
  ASSERT_FALSE(ok.designs.empty());
  for (const DimensionedDesign& d : ok.designs) expect_meets(fed, d);
  EXPECT_TRUE(std::any_of(ok.designs.begin(), ok.designs.end(), [&](const auto& d) {
    return d.subclass == r.length_needed_subclass;
  }));
  fed.length = {0.995 * hint, 0.995 * hint};
  EXPECT_TRUE(design_mechanisms(fed).designs.empty());
}

// Along a section family (b_i h_i^3 fixed) the PRBM and the exact model give the same force, and
// every PRBM stress is a t + c t^2 exactly (bending like t, axial like t^2): the structure the
// sizing relies on (section_family.h). The exact stresses grow at least like t.
TEST(DesignSectionFamily, ForceIsFixedAndStressesGrowLikeATPlusCTSquared) {
  const MechanismSpec spec = steel_20N();
  const MechanismDesignReport r = design_mechanisms(spec);
  ASSERT_FALSE(r.designs.empty());
  for (const std::string name : {"lpp-a", "slp-aIo"}) {
    const auto it = std::find_if(
        r.designs.begin(), r.designs.end(), [&](const auto& d) { return d.subclass == name; });
    ASSERT_NE(it, r.designs.end()) << name;
    mechanism::MechanismDesign d = it->design;
    const int p = it->model.primary_pivot;
    const SectionFamily f = family_of(d, p);
    const double t0 = d.joints[p - 1].thickness;
    const auto at = [&](double t) {
      mechanism::MechanismDesign x = d;
      f.apply(t, x);
      x.finalise();
      mechanism::AnalysisOptions o;
      return mechanism::analyze_mechanism(x, o);
    };
    const mechanism::MechanismAnalysis a1 = at(t0), a2 = at(0.5 * t0), a3 = at(0.8 * t0);
    EXPECT_NEAR(a2.prbm.mean_force, a1.prbm.mean_force, 1e-12 * a1.prbm.mean_force);
    EXPECT_NEAR(a2.mean_force_exact, a1.mean_force_exact, 1e-7 * a1.mean_force_exact);
    for (int i = 0; i < 3; ++i) {
      for (std::size_t k = 0; k < a1.prbm.stress[i].size(); ++k) {
        const double s1 = a1.prbm.stress[i][k], s2 = a2.prbm.stress[i][k];
        const double c = 2.0 * s1 - 4.0 * s2, a = s1 - c;  // sigma(u t0) = a u + c u^2
        EXPECT_NEAR(a3.prbm.stress[i][k], 0.8 * a + 0.64 * c, 1e-9 * s1) << name;
      }
      const double e1 = a1.max_stress_exact[i], e3 = a3.max_stress_exact[i];
      EXPECT_LE(e3, 0.8 * e1 * (1.0 + 1e-6)) << name;  // superlinear: sigma(0.8 t) <= 0.8 sigma(t)
      EXPECT_GE(e3, 0.64 * e1) << name;
    }
  }
}

// The search itself, on a known threshold: the answer is feasible and within the tolerance of it.
TEST(DesignLengthSearch, FindsTheThresholdThroughTheCheapCondition) {
  const double cheap_at = 1.1, full_at = 1.234567;
  int full_calls = 0;
  const auto cheap = [&](double l) { return l >= cheap_at; };
  const auto with_ratio = [&](double l) {
    ++full_calls;
    return LengthProbe{l >= full_at, std::pow(full_at / l, 1.3)};
  };
  const std::optional<double> l = first_feasible_length(cheap, with_ratio, 0.5, 10.0);
  ASSERT_TRUE(l.has_value());
  EXPECT_GE(*l, full_at);
  EXPECT_LE(*l, full_at * (1.0 + 1e-4));
  EXPECT_LE(full_calls, 12);  // interpolated, not bisected from 1 % steps
  const auto without_ratio = [&](double l) { return LengthProbe{l >= full_at, std::nullopt}; };
  const std::optional<double> b = first_feasible_length(cheap, without_ratio, 0.5, 10.0);
  ASSERT_TRUE(b.has_value());
  EXPECT_GE(*b, full_at);
  EXPECT_LE(*b, full_at * (1.0 + 1e-4));
  EXPECT_FALSE(first_feasible_length(cheap, without_ratio, 0.5, 1.2).has_value());
}

}  // namespace
}  // namespace flexure::design
