// Optimisation against the exact model (mechanisms/design/cfm_exact_refinement.h): from a thesis
// sub-class, the refined design's exact percent constant force is at least the sub-class's own
// (checked by an independent exact solve at twice the points), its constraints hold, and a run is
// reproducible.
#include "flexure/mechanisms/design/cfm_exact_refinement.h"

#include <gtest/gtest.h>

#include <cctype>
#include <iostream>
#include <string>
#include <vector>

#include "flexure/mechanisms/cfm/cfm_subclasses.h"
#include "flexure/solver/common/errors.h"

namespace flexure::design {
namespace {

// The sub-class's own problem (Ch. 7 semantics, docs/design.md): max-pcf without digits, else
// Xi' >= digits with the orientation flags as constraints.
CfmDesignProblem problem_of(const cfm::CfmSubclass& row, std::vector<double>& start) {
  CfmDesignProblem p;
  p.config = row.config;
  p.stroke_percent = row.stroke_percent;
  const std::string name = row.name;
  std::string digits, flags;
  for (std::size_t k = name.find('-') + 2; k < name.size(); ++k) {
    (std::isdigit(static_cast<unsigned char>(name[k])) ? digits : flags) += name[k];
  }
  p.objective = DesignObjective::kMaxPcf;
  if (!digits.empty()) {
    p.pcf_min = std::stod(digits);
    p.orientation = flags;
  }
  p.model = default_model_options(p.objective);
  start.clear();
  for (const std::string& v : p.variables()) {
    start.push_back(v == "R" ? row.R : (v == "K1" ? row.K1 : row.K2));
  }
  return p;
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
    // An independent solve at 100 points.
    const double check = exact_percent_constant_force(p, r.x, 100, 2e7);
    EXPECT_NEAR(check, r.percent_constant_force_exact, 0.2) << name;
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
