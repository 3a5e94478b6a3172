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
#include <vector>

#include "flexure/mechanisms/cfm/cfm_model.h"
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
    q.orientation = orientation_rules_from_string(m[4].str());
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

// The constraints of the posed problem judged here from their definitions (docs/design.md), on
// the model evaluated afresh at the found R, K1, K2, not by the synthesis's own verdicts: the
// toggle (eq. 2.16: R in [(1 - q)/(1 + q), (1 + q)/(1 - q)], q = (1 - d/100)^2), Xi' >= the
// sub-class's digits (eq. 6.8) and the orientation rules of its flags (Table 5.4) at every flexure.
// Returns what is not met.
std::vector<std::string> unmet_rules(const Posed& p, const cfm::CfmResult& found) {
  constexpr double kSlack = 1e-9;  // a design on its bound is met, as the optimiser's
  const CfmDesignProblem& q = p.problem;
  const cfm::CfmConfiguration& c = cfm::find_cfm_configuration(q.config);
  cfm::CfmParameters at{q.config, found.R, std::nullopt, std::nullopt, q.stroke_percent};
  if (c.has_spring(2) && !c.is_class_1B()) at.K1 = found.K1;
  if (c.has_spring(3)) at.K2 = found.K2;
  const cfm::CfmResult r = cfm::CfmModel(q.model).evaluate(at);
  std::vector<std::string> unmet;
  const auto need = [&](bool ok, const std::string& what, double value) {
    if (!ok) unmet.push_back(what + " = " + std::to_string(value));
  };
  const double t = (1.0 - q.stroke_percent / 100.0) * (1.0 - q.stroke_percent / 100.0);
  need(found.R >= (1.0 - t) / (1.0 + t) - kSlack && found.R <= (1.0 + t) / (1.0 - t) + kSlack,
       "R inside the toggle interval",
       found.R);
  if (q.pcf_min) {
    need(r.percent_constant_force >= *q.pcf_min - kSlack, "Xi'", r.percent_constant_force);
  }
  const OrientationLimits& l = q.orientation_limits;
  for (int i = 0; i < 3; ++i) {
    if (!r.C[i]) continue;  // a pin
    const double C = *r.C[i], De = *r.D_equal[i], Dm = *r.D_min[i];
    const std::string pivot = "pivot " + std::to_string(i + 1);
    for (char flag : to_string(q.orientation)) {
      if (flag == 'I') need(Dm <= l.I_D_min_max + kSlack, pivot + " I: D_min", Dm);
      if (flag == 'O' || flag == 'o') need(C >= l.C_min - kSlack, pivot + ": C", C);
      const Bounds& b = flag == 'O' ? l.O_D_equal : l.o_D_equal;
      if (flag == 'O' || flag == 'o') {
        need(De >= b.lower - kSlack && De <= b.upper + kSlack, pivot + ": D_equal", De);
      }
    }
  }
  return unmet;
}

TEST(SubclassSynthesisRules, TheThesisRuleLimitsAreTheDefaults) {
  // Table 5.4 (docs/design.md): I: D_min <= 1; O: C >= 1, 0.5 <= D_equal <= 2; o: C >= 1,
  // 0.1 <= D_equal <= 10. unmet_rules() takes the problem's limits: they must be these unless
  // loosened above.
  const OrientationLimits l;
  EXPECT_EQ(l.I_D_min_max, 1.0);
  EXPECT_EQ(l.C_min, 1.0);
  EXPECT_EQ(l.O_D_equal.lower, 0.5);
  EXPECT_EQ(l.O_D_equal.upper, 2.0);
  EXPECT_EQ(l.o_D_equal.lower, 0.1);
  EXPECT_EQ(l.o_D_equal.upper, 10.0);
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
  for (const std::string& u : unmet_rules(p, s.best.result)) ADD_FAILURE() << row.name << ": " << u;
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
