// The starts of `flexure design cfm --model exact` (cfm_synthesis.h
// exact_refinement_starts): the PRBM optimum first, then exactly the printed sub-classes of the
// same configuration and stroke that the thesis did not clamp at the toggle position (its own
// toggle_clamped annotation, not the closed-form R interval the function uses) and that lie inside
// the problem's bounds, in table order.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/design/cfm_synthesis.h"
#include "flexure/solver/common/status.h"

namespace flexure::design {
namespace {

std::vector<double> values_of(const cfm::CfmSubclass& row, const CfmDesignProblem& p) {
  std::vector<double> x;
  for (const std::string& v : p.variables())
    x.push_back(v == "R" ? row.R : v == "K1" ? row.K1 : row.K2);
  return x;
}

bool inside(const std::vector<double>& x, const CfmDesignProblem& p) {
  const std::vector<std::string> v = p.variables();
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Bounds& b = v[i] == "R" ? p.R : v[i] == "K1" ? p.K1 : p.K2;
    if (x[i] < b.lower || x[i] > b.upper) return false;
  }
  return true;
}

TEST(CfmExactStarts, OptimumFirstThenThePrintedRowsNotClampedAndInsideTheBounds) {
  int compared = 0;
  for (const char* config : {"spp", "lpp", "psp", "plp", "ssp", "slp", "sps", "lps", "sss"}) {
    for (double d : {16.0, 40.0}) {
      CfmDesignProblem p;
      p.config = config;
      p.stroke_percent = d;
      const std::vector<double> optimum(p.variables().size(), 0.123);
      std::vector<std::vector<double>> expected{optimum};
      for (const cfm::CfmSubclass& row : cfm::thesis_subclasses()) {
        if (std::string(row.config) != config || row.stroke_percent != d || row.toggle_clamped) {
          continue;
        }
        const std::vector<double> x = values_of(row, p);
        if (inside(x, p)) expected.push_back(x);
      }
      EXPECT_EQ(exact_refinement_starts(p, optimum), expected) << config << " " << d;
      compared += static_cast<int>(expected.size()) - 1;
    }
  }
  EXPECT_EQ(compared, 68 - 3);  // every row but the three clamped ones, with the default bounds
}

TEST(CfmExactStarts, BoundsLeaveOutTheRowsOutsideThem) {
  CfmDesignProblem p;
  p.config = "slp";
  p.stroke_percent = 16.0;
  // slp-a90I has K1 = 15.0000; the others of slp at 16 % have K1 <= 1.637.
  const std::vector<double> optimum{0.5, 0.3};
  EXPECT_EQ(exact_refinement_starts(p, optimum).size(), 1u + 5u);
  p.K1.upper = 10.0;
  const std::vector<std::vector<double>> starts = exact_refinement_starts(p, optimum);
  ASSERT_EQ(starts.size(), 1u + 4u);
  EXPECT_EQ(starts.front(), optimum);
  for (const std::vector<double>& x : starts) EXPECT_LE(x[1], 10.0);
}

TEST(CfmExactStarts, ARefinementNeedsAPrbmDesign) {
  CfmDesignProblem p;
  p.config = "lpp";
  EXPECT_THROW(refine_cfm_exact_from_prbm(p, CfmSynthesisResult{}), InvalidInput);
}

}  // namespace
}  // namespace flexure::design
