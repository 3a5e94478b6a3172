// Optimisation against the exact model (mechanisms/design/cfm_synthesis.h): from a thesis
// sub-class, the refined design's exact percent constant force is at least the sub-class's own
// (checked by an independent exact solve at twice the points), its constraints hold, and a run is
// reproducible.
#include <gtest/gtest.h>

#include <iostream>
#include <string>
#include <vector>

#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/design/cfm_synthesis.h"
#include "flexure/mechanisms/design/subclass_problem.h"
#include "flexure/solver/common/status.h"

namespace flexure::design {
namespace {

CfmDesignProblem problem_of(const cfm::CfmSubclass& row, std::vector<double>& start) {
  const SubclassProblem s = subclass_problem(row);
  start = s.printed;
  return s.problem;
}

// docs/validation.md: lpp-b 97.6 % by the PRBM, 93.3 % exact; slp-b90Io 90.0 -> 81.2.
TEST(CfmExactRefinement, BeatsTheThesisOptimumInTheExactModel) {
  for (const char* name : {"lpp-b", "slp-b90Io"}) {
    std::vector<double> start;
    const CfmDesignProblem p = problem_of(cfm::find_thesis_subclass(name), start);
    ExactRefinementOptions o;
    o.sequence_starts = 8;
    const CfmExactRefinement r = refine_cfm_exact(p, {start}, o);
    std::cerr << name << ": " << r.start_percent_constant_force_exact << " -> "
              << r.percent_constant_force_exact << " in " << r.evaluations << " strokes, "
              << r.message << "\n";
    EXPECT_GE(r.percent_constant_force_exact, r.start_percent_constant_force_exact) << name;
    EXPECT_TRUE(r.prbm.feasible()) << name;
    // Independent solves at 100 and 200 points. Xi' of a sampled stroke converges at first order
    // in 1/N (the sampled extremum): measured 96.729, 96.643, 96.600, 96.578 at N = 50, 100, 200,
    // 400 for lpp-b (differences 0.086, 0.043, 0.022) and 97.750, 97.685, 97.652, 97.636 for
    // slp-b90Io. So the reported 50-point value must differ from the 100-point one by about twice
    // the 100 -> 200 change, not by a fixed allowance.
    const double check = exact_percent_constant_force(p, r.x, 100, 2e7);
    const double finer = exact_percent_constant_force(p, r.x, 200, 2e7);
    const double ratio = (r.percent_constant_force_exact - check) / (check - finer);
    EXPECT_NEAR(ratio, 2.0, 0.3) << name << ": 50 -> 100 -> 200 points "
                                 << r.percent_constant_force_exact << ", " << check << ", "
                                 << finer;
    if (p.pcf_min) EXPECT_GE(r.percent_constant_force_exact, *p.pcf_min - 1e-9) << name;
  }
}

TEST(CfmExactRefinement, SameProblemSameAnswer) {
  std::vector<double> start;
  const CfmDesignProblem p = problem_of(cfm::find_thesis_subclass("lps-b95I"), start);
  ExactRefinementOptions o;
  o.sequence_starts = 2;
  const CfmExactRefinement a = refine_cfm_exact(p, {start}, o), b = refine_cfm_exact(p, {start}, o);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.evaluations, b.evaluations);
  EXPECT_EQ(a.percent_constant_force_exact, b.percent_constant_force_exact);
  EXPECT_GE(a.percent_constant_force_exact, a.start_percent_constant_force_exact);
}

TEST(CfmExactRefinement, RefusesAStartOutsideItsBounds) {
  std::vector<double> start;
  CfmDesignProblem p = problem_of(cfm::find_thesis_subclass("lpp-b"), start);
  EXPECT_THROW(refine_cfm_exact(p, {{5.0}}), InvalidInput);  // R = 5 is past the toggle at 40 %
  EXPECT_THROW(refine_cfm_exact(p, {{0.9, 1.0}}), InvalidInput);
  EXPECT_THROW(refine_cfm_exact(p, {}), InvalidInput);
}

}  // namespace
}  // namespace flexure::design
