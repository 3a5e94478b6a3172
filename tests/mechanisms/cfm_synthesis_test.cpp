// Synthesis of R, K1, K2 (mechanisms/design/, docs/design.md) against Table 2.1 of Weight's
// thesis (the optimisation of Millar et al., 50 equally spaced stroke points), an exhaustive scan
// of the one-variable problems, and the toggle interval in closed form.
#include "flexure/mechanisms/design/cfm_synthesis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/cfm/slider_crank.h"
#include "flexure/solver/common/status.h"

namespace flexure::design {
namespace {

const cfm::CfmClassRow& row(const std::string& name) {
  const cfm::CfmClassRow* r = cfm::find_class_row(name);
  if (r == nullptr) throw std::runtime_error("no row " + name);
  return *r;
}

CfmDesignProblem min_xi_problem(const cfm::CfmClassRow& r) {
  CfmDesignProblem p;
  p.config = r.config;
  p.stroke_percent = r.stroke_percent;
  p.objective = DesignObjective::kMinXi;
  p.model = default_model_options(p.objective);
  return p;
}

TEST(CfmSynthesis, ToggleIntervalInvertsTheToggleStroke) {
  for (double d : {5.0, 16.0, 40.0, 70.0}) {
    const auto [lo, hi] = toggle_R_interval(d);
    EXPECT_NEAR(cfm::toggle_stroke_percent(lo), d, 1e-9) << d;
    EXPECT_NEAR(cfm::toggle_stroke_percent(hi), d, 1e-9) << d;
    EXPECT_GT(cfm::toggle_stroke_percent(0.5 * (lo + hi)), d) << d;
  }
  const auto [lo16, hi16] = toggle_R_interval(16.0);
  EXPECT_NEAR(lo16, 0.1726, 5e-5);
  EXPECT_NEAR(hi16, 5.793, 5e-4);
  EXPECT_THROW(toggle_R_interval(100.0), InvalidInput);
}

// Class 1A (one variable): the optimiser against a scan of 20001 values of R over the toggle
// interval, and against Table 2.1. The printed 1A-b optimum (Xi 1.0241) is not the minimum:
// R = 0.8858 gives 1.02369 (docs/errata.md), so the printed Xi is an upper bound.
TEST(CfmSynthesis, ClassOneAMatchesAScanAndTableTwoOne) {
  for (const char* name : {"table2.1-1A-a", "table2.1-1A-b"}) {
    const cfm::CfmClassRow& r = row(name);
    const CfmDesignProblem p = min_xi_problem(r);
    const CfmSynthesisResult s = synthesize_cfm(p);
    ASSERT_TRUE(s.converged()) << name << ": " << s.message;
    const double R = s.best.result.R, Xi = s.best.result.Xi;
    EXPECT_NEAR(R, r.R, 1e-3) << name;
    EXPECT_LE(Xi, r.Xi + 2e-4) << name;
    const cfm::CfmModel model(p.model);
    const auto [lo, hi] = toggle_R_interval(p.stroke_percent);
    double best_Xi = INFINITY, best_R = 0.0;
    for (int k = 0; k <= 20000; ++k) {
      const double Rk = std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * k / 20000.0);
      const cfm::CfmResult e =
          model.evaluate({r.config, Rk, std::nullopt, std::nullopt, r.stroke_percent});
      if (e.Xi < best_Xi) best_Xi = e.Xi, best_R = Rk;
    }
    EXPECT_LE(Xi, best_Xi + 1e-9) << name << ": the scan found a better R = " << best_R;
    EXPECT_NEAR(R, best_R, 2e-3) << name;
  }
}

// Class 3A with K1 = 1 held, as Table 2.1 prints it (K1 free turns 3A into 2B: K1 -> 0). The
// optimum is flat in R: 2.6595 against the printed 2.6633 at d = 16 (Xi 1.0002165 against the
// printed point's 1.0002249), hence R within 0.01.
TEST(CfmSynthesis, ClassThreeAWithKOneFixedMatchesTableTwoOne) {
  for (const char* name : {"table2.1-3A-a", "table2.1-3A-b"}) {
    const cfm::CfmClassRow& r = row(name);
    CfmDesignProblem p = min_xi_problem(r);
    p.fixed_K1 = 1.0;
    const CfmSynthesisResult s = synthesize_cfm(p);
    ASSERT_TRUE(s.converged()) << name << ": " << s.message;
    EXPECT_NEAR(s.best.result.R, r.R, 0.01) << name;
    EXPECT_NEAR(s.best.result.K2, *r.K2, 0.05 * *r.K2) << name;
    EXPECT_LE(s.best.result.Xi, r.Xi + 2e-4) << name;
  }
}

// Classes 1B, 2A, 2B: no worse than printed (the printed 2A and 2B optima are not global). 2A-b
// is printed over the stroke clamped at the toggle position of its R (37.04 %, docs/cfm.md), so it
// is re-optimised at that stroke.
TEST(CfmSynthesis, OtherClassesAreNoWorseThanTableTwoOne) {
  for (const char* name : {"table2.1-1B-a",
                           "table2.1-1B-b",
                           "table2.1-2A-a",
                           "table2.1-2A-b",
                           "table2.1-2B-a",
                           "table2.1-2B-b"}) {
    const cfm::CfmClassRow& r = row(name);
    CfmDesignProblem p = min_xi_problem(r);
    if (std::string(name) == "table2.1-2A-b") p.stroke_percent = cfm::toggle_stroke_percent(r.R);
    const CfmSynthesisResult s = synthesize_cfm(p);
    ASSERT_TRUE(s.converged()) << name << ": " << s.message;
    EXPECT_LE(s.best.result.Xi, r.Xi + 5e-5) << name;
    EXPECT_TRUE(s.best.feasible()) << name;
  }
}

// max-psi under Xi' >= 95 (thesis sub-class lpp-a95): the constraint holds at the optimum and no
// R of a scan that meets it has a larger Psi.
TEST(CfmSynthesis, MaxPsiMeetsItsConstraintAndBeatsAScan) {
  CfmDesignProblem p;
  p.config = "lpp";
  p.stroke_percent = 16.0;
  p.objective = DesignObjective::kMaxPsi;
  p.pcf_min = 95.0;
  p.model = default_model_options(p.objective);
  const CfmSynthesisResult s = synthesize_cfm(p);
  ASSERT_TRUE(s.converged()) << s.message;
  EXPECT_GE(s.best.result.percent_constant_force, 95.0 - 1e-7);
  const cfm::CfmModel model(p.model);
  const auto [lo, hi] = toggle_R_interval(16.0);
  double best = 0.0;
  for (int k = 0; k <= 4000; ++k) {
    const double R = lo + (hi - lo) * k / 4000.0;
    const cfm::CfmResult e = model.evaluate({"lpp", R, std::nullopt, std::nullopt, 16.0});
    if (e.percent_constant_force >= 95.0) best = std::max(best, e.Psi_raw);
  }
  EXPECT_GE(s.best.result.Psi_raw, best * (1.0 - 1e-6));
  const cfm::CfmSubclass& printed = cfm::find_thesis_subclass("lpp-a95");
  EXPECT_NEAR(s.best.result.R, printed.R, 2e-3);
  ASSERT_TRUE(s.nearest_subclass.has_value());
  EXPECT_EQ(*s.nearest_subclass, "lpp-a95");
}

TEST(CfmSynthesis, SameSeedSameAnswer) {
  CfmDesignProblem p = min_xi_problem(row("table2.1-2B-a"));
  const CfmSynthesisResult a = synthesize_cfm(p), b = synthesize_cfm(p);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.evaluations, b.evaluations);
  // Three variables, the regions of the primary pivot, the coarse and full samplings (thesis
  // sub-class sss-b90I): bitwise the same answer.
  CfmDesignProblem q;
  q.config = "sss";
  q.stroke_percent = 40.0;
  q.objective = DesignObjective::kMaxPsi;
  q.pcf_min = 90.0;
  q.orientation = {OrientationRule::kInPlane};
  q.model = default_model_options(q.objective);
  const CfmSynthesisResult c = synthesize_cfm(q), d = synthesize_cfm(q);
  EXPECT_EQ(c.x, d.x);
  EXPECT_EQ(c.evaluations, d.evaluations);
  EXPECT_EQ(c.fine_evaluations, d.fine_evaluations);
  EXPECT_EQ(c.best.objective, d.best.objective);
}

// SynthesisOptions::progress: one step per scan point (the first 32 calls, in order), one per
// local run, (total, total) last with total = 32 scan points + 3 starts counted from the options;
// the answer is the one without it, and an exception thrown from it stops the synthesis.
TEST(CfmSynthesis, ProgressCountsScanPointsAndLocalRuns) {
  const CfmDesignProblem p = min_xi_problem(row("table2.1-1A-a"));
  SynthesisOptions o;
  o.scan_points = 32;
  o.starts = 3;
  o.coarse_stride = 1;  // one phase: no polish step
  const CfmSynthesisResult plain = synthesize_cfm(p, o);
  std::vector<std::pair<std::size_t, std::size_t>> calls;
  o.progress = [&](std::size_t done, std::size_t total) { calls.emplace_back(done, total); };
  const CfmSynthesisResult s = synthesize_cfm(p, o);
  EXPECT_EQ(s.x, plain.x);
  EXPECT_EQ(s.evaluations, plain.evaluations);
  ASSERT_GE(calls.size(), 33u);
  for (std::size_t k = 0; k < 32; ++k) {
    EXPECT_EQ(calls[k], std::make_pair(k + 1, std::size_t{35}));
  }
  for (std::size_t k = 1; k < calls.size(); ++k) {
    EXPECT_GE(calls[k].first, calls[k - 1].first);
    EXPECT_EQ(calls[k].second, 35u);
  }
  EXPECT_EQ(calls.back(), std::make_pair(std::size_t{35}, std::size_t{35}));
  EXPECT_LE(calls.size(), 32u + static_cast<std::size_t>(s.starts) + 1u);

  struct Stop {};
  o.progress = [](std::size_t done, std::size_t) {
    if (done == 5) throw Stop{};
  };
  EXPECT_THROW(synthesize_cfm(p, o), Stop);
}

// The coarse sampling (CfmOptions::stride) is a subset of the full one with its mean on straight
// lines between the points: Xi' and C never below the full sampling's, the mean close to it.
TEST(CfmSynthesis, StrideSamplingBracketsTheFullOne) {
  cfm::CfmOptions coarse;
  coarse.stride = 20;
  const cfm::CfmModel full_model, coarse_model(coarse);
  for (const cfm::CfmSubclass& r : cfm::thesis_subclasses()) {
    const cfm::CfmConfiguration& c = cfm::find_cfm_configuration(r.config);
    cfm::CfmParameters at{r.config, r.R, std::nullopt, std::nullopt, r.stroke_percent};
    if (c.has_spring(2) && !c.is_class_1B()) at.K1 = r.K1;
    if (c.has_spring(3)) at.K2 = r.K2;
    const cfm::CfmResult f = full_model.evaluate(at), g = coarse_model.evaluate(at);
    EXPECT_GE(g.percent_constant_force, f.percent_constant_force - 1e-12) << r.name;
    EXPECT_NEAR(g.Phi, f.Phi, 1e-4 * f.Phi) << r.name;
    EXPECT_EQ(g.primary_pivot, f.primary_pivot) << r.name;
    EXPECT_LT(g.iterations, f.iterations / 10) << r.name;
  }
  cfm::CfmOptions one;
  one.stride = 1;
  const cfm::CfmResult a = cfm::CfmModel(one).evaluate({"sss", 2.6633, 1.0, 12.6704, 16.0});
  const cfm::CfmResult b = full_model.evaluate({"sss", 2.6633, 1.0, 12.6704, 16.0});
  EXPECT_EQ(a.Phi, b.Phi);  // stride 1 is the full sampling, bitwise
}

TEST(CfmSynthesis, BadProblemsAreClearErrors) {
  EXPECT_THROW(design_objective_from_string("min-force"), InvalidInput);
  CfmDesignProblem p;
  p.config = "lpp";
  p.objective = DesignObjective::kMaxPsi;
  EXPECT_THROW(synthesize_cfm(p), InvalidInput);  // max-psi needs pcf_min
  p.objective = DesignObjective::kMaxPcf;
  p.fixed_K1 = 1.0;  // lpp has no spring at pivot 2
  EXPECT_THROW(synthesize_cfm(p), InvalidInput);
  p.fixed_K1.reset();
  p.config = "xyz";
  EXPECT_THROW(synthesize_cfm(p), InvalidInput);
  p.config = "lpp";
  // Orientation rules are an enum; their flag text is checked where it is read.
  EXPECT_THROW(orientation_rules_from_string("X"), InvalidInput);
  EXPECT_THROW(orientation_rules_from_string("IX"), InvalidInput);
}

}  // namespace
}  // namespace flexure::design
