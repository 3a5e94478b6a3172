// Issue 16's acceptance: every chapter-7 sub-class of Weight (2001) (Tables 7.2, 7.4, 7.6, 7.9,
// 7.12; data/weight_thesis_subclasses.csv) re-derived by `flexure design cfm` from its own
// objective and constraints, without seeding the search with the printed point, reaching an
// objective no worse than the printed one minus 0.5 % with every constraint met (docs/design.md).
//
// How a name poses its problem (thesis ch. 7, L1846-1852): config-{a|b}{digits}{flags}. With
// digits, max Psi (eq. 6.5; compared as Psi_raw) under Xi' >= digits (eq. 6.8) and the
// orientation rules of the flags (Table 5.4, eqs. 6.10-6.11); without, max Xi' (eq. 6.9) and the
// flags are labels only. The thesis code's sampling. The stroke is the row's effective one: the
// toggle-clamped rows (slp-bIO, ssp-bIo at 37.04 %, ssp-b94I at 26.62 %; docs/cfm.md §1.3) are
// re-derived at the stroke the thesis evaluated. "Printed" means the model at the printed R, K1,
// K2 (which reproduces the printed tables within rounding, cfm_thesis_tables_test).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <functional>
#include <regex>
#include <string>

#include "flexure/mechanisms/cfm/cfm_configuration.h"
#include "flexure/mechanisms/cfm/cfm_subclasses.h"
#include "flexure/mechanisms/cfm/slider_crank.h"
#include "flexure/mechanisms/design/cfm_synthesis.h"

namespace flexure::design {
namespace {

struct Posed {
  CfmDesignProblem problem;
  cfm::CfmResult printed;  // the model at the printed point, same stroke and sampling
  bool max_psi = false;
};

// Printed points that break their own orientation rule (docs/errata.md): the one bound is
// loosened to the printed point's own value (computed by the model at the printed R, K), so that
// the printed point is feasible and the comparison is with the thesis's own optimiser.
void loosen_violated_rules(const std::string& name, OrientationLimits& limits) {
  if (name == "ssp-b90o") limits.o_D_equal.upper = 10.351;   // D_equal1 = 10.3504 ('o': <= 10)
  if (name == "lps-a99IO") limits.O_D_equal.lower = 0.4668;  // D_equal1 = 0.46685 ('O': >= 0.5)
  if (name == "lps-b99IO") limits.C_min = 0.9939;            // C1 = 0.99396 ('O': >= 1)
  if (name == "lps-b95IO") limits.C_min = 0.9935;            // C1 = 0.99355 ('O': >= 1)
  // slp-a90I (D_min2 = 1.0666) and ssp-a95I (D_min1 = 1.0088) also break their rule 'I' (D_min
  // <= 1), but better designs meet it: they are re-derived under the strict rule.
}

Posed pose(const cfm::CfmSubclass& row) {
  static const std::regex kName("([a-z]+)-([ab])([0-9]*)([IOo]*)");
  std::cmatch m;
  if (!std::regex_match(row.name, m, kName)) throw std::runtime_error(row.name);
  Posed p;
  CfmDesignProblem& q = p.problem;
  q.config = row.config;
  q.stroke_percent = row.toggle_clamped ? cfm::toggle_stroke_percent(row.R) : row.stroke_percent;
  p.max_psi = m[3].length() > 0;
  if (p.max_psi) {
    q.objective = DesignObjective::kMaxPsi;
    q.pcf_min = std::stod(m[3].str());
    q.orientation = m[4].str();
    loosen_violated_rules(row.name, q.orientation_limits);
  } else {
    q.objective = DesignObjective::kMaxPcf;
  }
  q.model = default_model_options(q.objective);
  const cfm::CfmConfiguration& c = cfm::find_cfm_configuration(row.config);
  cfm::CfmParameters at{row.config, row.R, std::nullopt, std::nullopt, q.stroke_percent};
  if (c.has_spring(2) && !c.is_class_1B()) at.K1 = row.K1;
  if (c.has_spring(3)) at.K2 = row.K2;
  p.printed = cfm::CfmModel(q.model).evaluate(at);
  return p;
}

class SubclassSynthesis : public ::testing::TestWithParam<int> {};

TEST_P(SubclassSynthesis, ReachesThePrintedObjectiveWithItsConstraintsMet) {
  const cfm::CfmSubclass& row = cfm::thesis_subclasses()[static_cast<std::size_t>(GetParam())];
  const Posed p = pose(row);
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  const CfmSynthesisResult s = synthesize_cfm(p.problem);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const double cpu_ms = 1e3 * static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  const auto objective = [&](const cfm::CfmResult& r) {
    return p.max_psi ? r.Psi_raw : r.percent_constant_force;
  };
  const double printed = objective(p.printed), found = objective(s.best.result);
  std::printf(
      "%-10s d=%6.2f %s printed %.6g found %.6g (%+.2f %%) R %.4f K1 %.4f K2 %.4f  "
      "%d evaluations (%d full) %.1f ms (cpu %.1f ms)\n",
      row.name,
      p.problem.stroke_percent,
      p.max_psi ? "Psi_raw" : "Xi'",
      printed,
      found,
      100.0 * (found / printed - 1.0),
      s.best.result.R,
      s.best.result.K1,
      s.best.result.K2,
      s.evaluations,
      s.fine_evaluations,
      ms,
      cpu_ms);
  EXPECT_TRUE(s.converged()) << s.message;
  EXPECT_GE(found, printed * 0.995) << row.name;
  for (const NamedConstraint& c : s.best.constraints) {
    EXPECT_TRUE(c.satisfied()) << row.name << ": " << c.name << " = " << c.value;
  }
}

// The printed points meet their own orientation rules (within the rounding of their printed R, K:
// slp-a99IO, ssp-a90IO and ssp-b90IO sit on a bound), with the loosened bounds above (each no
// looser than the printed point needs), all but the two rows re-derived under the strict rule.
TEST(SubclassSynthesis, PrintedPointsMeetTheirOwnRules) {
  for (const cfm::CfmSubclass& row : cfm::thesis_subclasses()) {
    const Posed p = pose(row);
    std::vector<double> x;
    for (const std::string& v : p.problem.variables()) {
      x.push_back(v == "R" ? row.R : (v == "K1" ? row.K1 : row.K2));
    }
    const CfmDesignEvaluation e = evaluate_design(p.problem, cfm::CfmModel(p.problem.model), x);
    const std::string name = row.name;
    const bool strict_breaks = name == "slp-a90I" || name == "ssp-a95I";
    bool met = true;
    for (const NamedConstraint& c : e.constraints) {
      // Within the rounding of the printed R, K (4 decimals): 0.1 % of the ratio.
      if (c.kind == ConstraintKind::kRatio && c.normalised_violation() > 1e-3) {
        met = false;
        if (!strict_breaks) ADD_FAILURE() << name << ": " << c.name << " = " << c.value;
      }
    }
    EXPECT_EQ(met, !strict_breaks) << name;
  }
}

INSTANTIATE_TEST_SUITE_P(Thesis,
                         SubclassSynthesis,
                         ::testing::Range(0, static_cast<int>(cfm::thesis_subclasses().size())),
                         [](const ::testing::TestParamInfo<int>& info) {
                           std::string name =
                               cfm::thesis_subclasses()[static_cast<std::size_t>(info.param)].name;
                           for (char& ch : name) {
                             if (ch == '-') ch = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace flexure::design
