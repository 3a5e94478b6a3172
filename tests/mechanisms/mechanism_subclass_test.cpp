// What is checked against what: every sub-class of the thesis tables (Tables 7.2-7.12, 68 rows)
// resolves to a dimensional design whose geometry and spring ratios reproduce the printed R, K1, K2
// (thesis eqs. 2.11-2.12: k2/k_ref = K1, k3/k_ref = K2; class 1B: k2 is the reference), whose PRBM
// stroke is finite, and whose flexures were thinned to the stated PRBM safety factor of 1.5.
#include <gtest/gtest.h>

#include <cmath>

#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_analysis.h"

namespace flexure::mechanism {
namespace {

TEST(MechanismSubclasses, EveryThesisRowIsAConcreteDesignWithItsRatios) {
  int checked = 0;
  for (const cfm::CfmSubclass& row : cfm::thesis_subclasses()) {
    const MechanismDesign d = find_builtin_mechanism(row.name);
    const cfm::CfmConfiguration& cfg = cfm::find_cfm_configuration(row.config);
    SCOPED_TRACE(row.name);
    EXPECT_EQ(d.config, std::string(row.config));
    EXPECT_NEAR(d.r3 / d.r2, row.R, 1e-12 * row.R);
    const int ref = cfg.is_class_1B() ? 2 : 1;
    const double k_ref = d.spring_constant(ref);
    if (cfg.has_spring(2) && !cfg.is_class_1B()) {
      EXPECT_NEAR(d.spring_constant(2) / k_ref, row.K1, 1e-10 * std::max(1.0, row.K1));
    }
    if (cfg.has_spring(3)) {
      EXPECT_NEAR(d.spring_constant(3) / k_ref, row.K2, 1e-10 * std::max(1.0, row.K2));
    }
    const PrbmStrokeResult stroke = prbm_stroke(d, 20);
    EXPECT_TRUE(std::isfinite(stroke.percent_constant_force));
    EXPECT_GT(stroke.percent_constant_force, 0.0);
    EXPECT_LE(stroke.percent_constant_force, 100.0);
    EXPECT_GE(stroke.safety_factor, 1.5 * (1.0 - 1e-2));
    ++checked;
  }
  EXPECT_EQ(checked, 68);
}

}  // namespace
}  // namespace flexure::mechanism
