// The catalogue as data of the general description (catalogue_general.h, issue 31): every one of
// the 40 designs of `flexure mechanism list` (mechanism_catalogue.h, DesignSet::kAll: the nine
// thesis configurations incl. slp and plp, the eleven modified designs of paper 004, Howell's
// eight, the twelve inversions) rebuilt as a general mechanism and solved by the general PRBM
// (solve_general_prbm) and the general exact model (solve_general_mixed with every flexure exact,
// which is solve_general_exact number for number and records each flexure's loads), against the
// catalogue's own analysis (analyze_mechanism: closed-form PRBM, the catalogue's exact chains):
// slider force per stroke point, percent constant force, largest stress per flexure and per
// point (flexure_stress.h), safety factors. The two sides share no solver: the general PRBM is an
// assembled linkage solved by continuation, the catalogue's a closed form of the slider-crank; the
// general exact model is one Newton system over bodies and elastica, the catalogue's a shooting
// solve of one serial chain (or crank and coupler chains).
#include "flexure/mechanisms/general/catalogue_general.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include "flexure/mechanisms/cfm/constant_force.h"
#include "flexure/mechanisms/general/flexure_stress.h"
#include "flexure/mechanisms/general/general_analysis.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/mechanisms/mechanism_catalogue.h"
#include "flexure/mechanisms/mechanism_exact.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism::general {
namespace {

constexpr int kPoints = 10;
constexpr double kTolerance = 1e-9;  // relative, the issue's
// The exact stresses against the catalogue's analysis as `mechanism analyze` runs it: its own
// stresses are converged to about 1e-9 only (shooting residual 1e-10, integrator rtol 1e-12; the
// same analysis re-solved at rtol 1e-13 and residual 5e-13 moves them by up to 1.3e-9: 1A-spp at
// its first point, the thin middle strip of 3A-lssm), so the 1e-9 is asserted against that
// tightened catalogue solution and the default analysis is held to 2e-9.
constexpr double kStressToleranceDefault = 2e-9;

// The catalogue's exact model converged further than its defaults (see above).
ExactMechanismSolver::Options tight_catalogue_options() {
  ExactMechanismSolver::Options o;
  o.shooting.newton.residual_tolerance = 5e-13;
  o.shooting.rtol = 1e-13;
  o.shooting.atol = 1e-15;
  o.position_tolerance = 1e-13;
  o.noise_floor = 1e-12;
  return o;
}

double relative(double a, double b) { return std::fabs(a - b) / std::max(std::fabs(b), 1e-300); }

// Worst relative differences over the designs, printed at the end (docs/mechanisms.md quotes
// them).
struct Worst {
  double value = 0.0;
  std::string where;
  void see(double r, const std::string& w) {
    if (r > value) {
      value = r;
      where = w;
    }
  }
};

TEST(CatalogueGeneral, AllFortyDesignsAreTheirCatalogueNumbers) {
  const std::vector<MechanismDesign> designs = mechanism_designs(DesignSet::kAll);
  ASSERT_EQ(designs.size(), 40u);
  Worst prbm_force, prbm_percent, prbm_stress, prbm_sf, exact_force, exact_percent, exact_stress,
      exact_stress_default, safety;
  for (const MechanismDesign& d : designs) {
    SCOPED_TRACE(d.name);
    AnalysisOptions ao;
    ao.points = kPoints;
    ao.stability = false;
    const MechanismAnalysis a = analyze_mechanism(d, ao);
    ASSERT_TRUE(a.converged()) << a.message;
    const GeneralMechanism m = general_from_design(d, kPoints);

    // PRBM.
    GeneralPrbmOptions po;
    po.tolerance = 1e-13;
    const GeneralPrbmResult p = solve_general_prbm(m, po);
    EXPECT_TRUE(p.converged()) << p.message;
    if (!p.converged()) continue;
    ASSERT_EQ(p.points.size(), static_cast<std::size_t>(kPoints));
    std::vector<double> force;
    for (int k = 0; k < kPoints; ++k) {
      // The catalogue's force pushes the slider inwards; the general input load holds x.
      force.push_back(-p.points[static_cast<std::size_t>(k)].input_load);
      const double r = relative(force.back(), a.prbm.force[static_cast<std::size_t>(k)]);
      EXPECT_LE(r, kTolerance) << "PRBM force at point " << k;
      prbm_force.see(r, d.name);
    }
    const double percent = constant_force_measure(force).percent;
    EXPECT_LE(relative(percent, a.prbm.percent_constant_force), kTolerance);
    prbm_percent.see(relative(percent, a.prbm.percent_constant_force), d.name);
    const GeneralFlexureStresses ps = prbm_flexure_stresses(m, p);
    double max_prbm = 0.0;
    for (int pivot = 1; pivot <= 3; ++pivot) {
      const std::string name = general_flexure_name(d, pivot);
      if (name.empty()) continue;
      const auto it = std::find(ps.names.begin(), ps.names.end(), name);
      ASSERT_NE(it, ps.names.end()) << name;
      const std::size_t i = static_cast<std::size_t>(it - ps.names.begin());
      const std::vector<double>& cat = a.prbm.stress[static_cast<std::size_t>(pivot - 1)];
      ASSERT_EQ(ps.stress[i].size(), cat.size());
      for (std::size_t k = 0; k < cat.size(); ++k) {
        const double r = relative(ps.stress[i][k], cat[k]);
        EXPECT_LE(r, kTolerance) << "PRBM stress of pivot " << pivot << " at point " << k;
        prbm_stress.see(r, d.name + " pivot " + std::to_string(pivot));
      }
      EXPECT_LE(relative(ps.max_stress[i], a.prbm.max_stress[static_cast<std::size_t>(pivot - 1)]),
                kTolerance);
      max_prbm = std::max(max_prbm, ps.max_stress[i]);
    }
    const double sf_prbm = *d.material.yield_strength / max_prbm;
    EXPECT_LE(relative(sf_prbm, a.prbm.safety_factor), kTolerance);
    prbm_sf.see(relative(sf_prbm, a.prbm.safety_factor), d.name);

    // Exact: every flexure an elastica.
    GeneralMechanism me = m;
    set_flexure_model(me, "", FlexureModel::kExact);
    GeneralExactOptions eo;
    eo.tolerance = 1e-12;
    eo.judge_stability = false;
    const GeneralPrbmResult e = solve_general_mixed(me, eo);
    EXPECT_TRUE(e.converged()) << e.message;
    if (!e.converged()) continue;
    ASSERT_EQ(e.points.size(), static_cast<std::size_t>(kPoints));
    ASSERT_EQ(a.force_exact.size(), static_cast<std::size_t>(kPoints));
    std::vector<double> fe;
    for (int k = 0; k < kPoints; ++k) {
      fe.push_back(-e.points[static_cast<std::size_t>(k)].input_load);
      const double r = relative(fe.back(), a.force_exact[static_cast<std::size_t>(k)]);
      EXPECT_LE(r, kTolerance) << "exact force at point " << k;
      exact_force.see(r, d.name);
    }
    const double pe = constant_force_measure(fe).percent;
    EXPECT_LE(relative(pe, a.percent_constant_force_exact), kTolerance);
    exact_percent.see(relative(pe, a.percent_constant_force_exact), d.name);
    const GeneralFlexureStresses es = exact_flexure_stresses(me, e);
    const ExactMechanismSolver::Options tight = tight_catalogue_options();
    const ExactStrokeResult ct = exact_stroke(d, a.prbm.displacement, tight);
    ASSERT_TRUE(ct.converged()) << ct.message;
    double max_all = max_prbm;
    for (int pivot = 1; pivot <= 3; ++pivot) {
      const std::string name = general_flexure_name(d, pivot);
      if (name.empty()) continue;
      const std::size_t i = static_cast<std::size_t>(
          std::find(es.names.begin(), es.names.end(), name) - es.names.begin());
      const std::vector<double>& cat = a.stress_exact[static_cast<std::size_t>(pivot - 1)];
      ASSERT_EQ(es.stress[i].size(), cat.size());
      for (std::size_t k = 0; k < cat.size(); ++k) {
        const double converged = exact_segment_state(d, ct.points[k], tight.shooting)
                                     .max_stress[static_cast<std::size_t>(pivot - 1)];
        const double r = relative(es.stress[i][k], converged);
        EXPECT_LE(r, kTolerance) << "exact stress of pivot " << pivot << " at point " << k;
        exact_stress.see(r, d.name + " pivot " + std::to_string(pivot));
        const double r0 = relative(es.stress[i][k], cat[k]);
        EXPECT_LE(r0, kStressToleranceDefault)
            << "exact stress of pivot " << pivot << " at point " << k << " (default analysis)";
        exact_stress_default.see(r0, d.name + " pivot " + std::to_string(pivot));
      }
      // The largest over the stroke, and the governing one (the larger of the two models).
      EXPECT_LE(relative(es.max_stress[i], a.max_stress_exact[static_cast<std::size_t>(pivot - 1)]),
                kStressToleranceDefault);
      const double governing = std::max(ps.max_stress[i], es.max_stress[i]);
      EXPECT_LE(relative(governing, a.max_stress[static_cast<std::size_t>(pivot - 1)]),
                kStressToleranceDefault);
      max_all = std::max(max_all, es.max_stress[i]);
    }
    // The governing safety factor: the larger of the PRBM and exact stresses.
    const double sf = *d.material.yield_strength / max_all;
    EXPECT_LE(relative(sf, a.safety_factor), kTolerance);
    safety.see(relative(sf, a.safety_factor), d.name);
  }
  std::cout << "worst relative differences over the 40 designs:\n"
            << "  PRBM force " << prbm_force.value << " (" << prbm_force.where << ")\n"
            << "  PRBM percent constant force " << prbm_percent.value << " (" << prbm_percent.where
            << ")\n"
            << "  PRBM stress " << prbm_stress.value << " (" << prbm_stress.where << ")\n"
            << "  PRBM safety factor " << prbm_sf.value << " (" << prbm_sf.where << ")\n"
            << "  exact force " << exact_force.value << " (" << exact_force.where << ")\n"
            << "  exact percent constant force " << exact_percent.value << " ("
            << exact_percent.where << ")\n"
            << "  exact stress (catalogue converged further) " << exact_stress.value << " ("
            << exact_stress.where << ")\n"
            << "  exact stress (default analysis) " << exact_stress_default.value << " ("
            << exact_stress_default.where << ")\n"
            << "  safety factor " << safety.value << " (" << safety.where << ")\n";
}

// The mixed model with every flexure exact is the exact model (general_analysis.h), so the test
// above measures solve_general_exact: checked here on an slp design and an inversion.
TEST(CatalogueGeneral, AllExactMixedIsTheExactModel) {
  for (const char* name : {"2A-slp", "1B-plp'"}) {
    GeneralMechanism m = general_from_design(find_builtin_mechanism(name), kPoints);
    const GeneralPrbmResult exact = solve_general_exact(m);
    set_flexure_model(m, "", FlexureModel::kExact);
    const GeneralPrbmResult mixed = solve_general_mixed(m);
    ASSERT_TRUE(exact.converged()) << name << ": " << exact.message;
    ASSERT_EQ(exact.points.size(), mixed.points.size());
    for (std::size_t k = 0; k < exact.points.size(); ++k) {
      EXPECT_EQ(exact.points[k].input_load, mixed.points[k].input_load) << name << " " << k;
    }
  }
}

TEST(CatalogueGeneral, ForeignSpringRuleAndBadPointsAreNamedErrors) {
  EXPECT_THROW(general_from_design(find_builtin_mechanism("1A-spp"), 1), InvalidInput);
  MechanismDesign d = find_builtin_mechanism("2B-lplm");
  d.spring_rule = SpringRule::kTable5;
  try {
    general_from_design(d, 10);
    ADD_FAILURE() << "no error";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("spring rule table5 has no general form"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace flexure::mechanism::general
