// The dynamics study of `flexure dynamics` as a library call (dynamics_study.h), against values
// found without it:
// - the static nominal force (mean of F over N equally spaced Delta x in (0, stroke]) tends to the
//   work done on the springs over the stroke, [V(stroke) - V(0)]/stroke (F = dV/dDelta x), with
//   the first-order error of a one-sided rectangle rule: halving the spacing halves the error;
// - at omega = 0 the mean force is the mean of the quasi-static force at the time samples of the
//   motion, computed here from the model's energy derivatives (1e-12). (The plan's "mean at
//   omega -> 0 equals the static nominal force" does not hold: the motion samples Delta x with
//   the cosine law preload + stroke (1 - cos)/2 and from the preload, the nominal force uniformly
//   from 0; on 2B-lplm they differ by 0.48 %);
// - the inertia terms grow as omega^2 (eq. D7): F(2 w) - F(0) = 4 (F(w) - F(0));
//   without masses the force does not depend on omega;
// - the natural frequency of the unloaded, straight mechanism is sqrt(V''(0)/M(0));
// - forces of one half are those of the whole mechanism halved, exactly;
// - the file of dynamics_study_file.h holds the struct's numbers bit for bit.
#include "flexure/benchmarks/studies/dynamics_study.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "flexure/benchmarks/studies/dynamics_study_file.h"
#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/materials_fatigue.h"
#include "flexure/solver/common/status.h"
#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

using dynamics::DynamicsDesign;
using dynamics::SliderCrankDynamics;

DynamicsDesign design() { return dynamics::builtin_dynamics_design("2B-lplm", std::nullopt); }

DynamicsStudyOptions options(std::vector<double> omegas) {
  DynamicsStudyOptions o;
  o.omegas = std::move(omegas);
  o.history_omegas = {0.0, 31.416};
  return o;
}

// A material for the springs (`flexure dynamics --material`): the design holds the library row's
// whole Material and its id, and its springs k = EI/L (pure bending, Howell eq. 5.14) scale with
// E alone against the same strips in Table 5's E of 207 GPa.
TEST(DynamicsDesignMaterial, SpringsScaleWithTheMaterialsModulus) {
  const MaterialGrade& ss = find_material("ss-301-cr");
  const DynamicsDesign table5 =
      dynamics::builtin_dynamics_design("2B-lplm", mechanism::SpringRule::kPureBending);
  const DynamicsDesign steel =
      dynamics::builtin_dynamics_design("2B-lplm", mechanism::SpringRule::kPureBending, &ss);
  EXPECT_FALSE(table5.material.has_value());
  EXPECT_TRUE(table5.material_id.empty());
  ASSERT_TRUE(steel.material.has_value());
  EXPECT_EQ(steel.material->E, ss.E);
  EXPECT_EQ(steel.material->yield_strength, ss.yield_strength);
  EXPECT_EQ(steel.material_id, "ss-301-cr");
  const double E_table5 = dynamics::find_cfsm_design("2B-lplm").material.E;
  EXPECT_EQ(E_table5, 207e9);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(steel.k[i], table5.k[i] * ss.E / E_table5, 1e-12 * table5.k[i]) << "pivot " << i;
  }
}

TEST(DynamicsStudy, StrokeAndPreloadArePercentagesOfTheLinkLengths) {
  const DynamicsDesign d = design();
  const DynamicsStudy s = run_dynamics_study(d, options({0.0}));
  ASSERT_TRUE(s.converged()) << s.message;
  EXPECT_NEAR(s.motion.stroke, 0.40 * (d.r2 + d.r3), 1e-15);
  EXPECT_NEAR(s.motion.preload, 0.01 * (d.r2 + d.r3), 1e-15);
  DynamicsStudyOptions o = options({0.0});
  o.stroke_percent = 25.0;
  EXPECT_NEAR(run_dynamics_study(d, o).motion.stroke, 0.25 * (d.r2 + d.r3), 1e-15);
}

TEST(DynamicsStudy, StaticNominalForceTendsToTheSpringWorkPerStroke) {
  const DynamicsDesign d = design();
  DynamicsStudyOptions o = options({0.0});
  const DynamicsStudy coarse = run_dynamics_study(d, o);
  o.static_force_points = 2000;
  const DynamicsStudy fine = run_dynamics_study(d, o);
  const SliderCrankDynamics model(coarse.parameters);
  const double stroke = coarse.motion.stroke;
  const double work =
      (model.terms(model.theta2_at(stroke)).V - model.terms(model.theta2_at(0.0)).V) / stroke;
  const double e1 = coarse.static_nominal_force - work;
  const double e2 = fine.static_nominal_force - work;
  EXPECT_LT(std::abs(e1), 2e-3 * std::abs(work)) << coarse.static_nominal_force << " " << work;
  EXPECT_NEAR(e1 / e2, 2.0, 0.02) << e1 << " " << e2;
  // Not the time mean of the motion: see the file comment.
  EXPECT_GT(std::abs(coarse.rows[0].mean - coarse.static_nominal_force),
            4e-3 * coarse.static_nominal_force);
}

TEST(DynamicsStudy, MeanForceAtRestIsTheQuasiStaticMeanOverTheMotion) {
  const DynamicsStudy s = run_dynamics_study(design(), options({0.0}));
  ASSERT_TRUE(s.converged()) << s.message;
  const SliderCrankDynamics model(s.parameters);
  const int n = s.samples;
  double sum = 0.0;
  for (int k = 0; k < n; ++k) {
    const double x =
        s.motion.preload + 0.5 * s.motion.stroke * (1.0 - std::cos(2.0 * std::numbers::pi * k / n));
    const dynamics::ConfigurationTerms c = model.terms(model.theta2_at(x));
    sum += c.dV / -c.dr1;
  }
  EXPECT_NEAR(s.rows[0].mean, sum / n, 1e-12 * std::abs(sum / n));
  // The history at omega = 0 is the static force sample by sample.
  ASSERT_EQ(s.histories.size(), 2u);
  for (std::size_t k = 0; k < s.histories[0].force.size(); ++k) {
    EXPECT_NEAR(s.histories[0].force[k], s.histories[0].static_force[k], 1e-12);
  }
}

TEST(DynamicsStudy, InertiaForcesGrowAsOmegaSquared) {
  const double w = 2.0;
  const DynamicsStudy s = run_dynamics_study(design(), options({0.0, w, 2.0 * w}));
  ASSERT_TRUE(s.converged()) << s.message;
  // At the fixed phases of the samples theta2' grows as w and theta2'' as w^2: every sample, and
  // so the mean, moves by exactly w^2 times a constant (no friction).
  const double d1 = s.rows[1].mean - s.rows[0].mean;
  const double d2 = s.rows[2].mean - s.rows[0].mean;
  ASSERT_GT(std::abs(d1), 1e-6 * std::abs(s.rows[0].mean));
  EXPECT_NEAR(d2 / d1, 4.0, 1e-6) << d1 << " " << d2;

  DynamicsStudyOptions o = options({0.0, 50.0});
  o.zero_inertia = true;
  const DynamicsStudy still = run_dynamics_study(design(), o);
  EXPECT_NEAR(still.rows[1].mean, still.rows[0].mean, 1e-12 * std::abs(still.rows[0].mean));
  EXPECT_EQ(still.natural_frequency, 0.0);
}

TEST(DynamicsStudy, NaturalFrequencyOfTheStraightMechanism) {
  const DynamicsStudy s = run_dynamics_study(design(), options({0.0}));
  const dynamics::ConfigurationTerms c = SliderCrankDynamics(s.parameters).terms(0.0);
  EXPECT_NEAR(s.natural_frequency, std::sqrt(c.d2V / c.M), 1e-9 * s.natural_frequency);
}

TEST(DynamicsStudy, OneHalfIsTheWholeHalved) {
  const DynamicsStudy whole = run_dynamics_study(design(), options({0.0, 40.0}));
  DynamicsStudyOptions o = options({0.0, 40.0});
  o.force_of = mechanism::ForceOf::kOneHalf;
  const DynamicsStudy half = run_dynamics_study(design(), o);
  for (std::size_t i = 0; i < whole.rows.size(); ++i) {
    EXPECT_EQ(half.rows[i].mean, 0.5 * whole.rows[i].mean);
    EXPECT_EQ(half.rows[i].peak_to_peak, 0.5 * whole.rows[i].peak_to_peak);
    EXPECT_EQ(half.rows[i].percent_constant_force, whole.rows[i].percent_constant_force);
  }
  EXPECT_EQ(half.static_nominal_force, 0.5 * whole.static_nominal_force);
  ASSERT_TRUE(whole.paper_nominal_force.has_value());
  EXPECT_EQ(*half.paper_nominal_force, 0.5 * *whole.paper_nominal_force);
  EXPECT_EQ(half.histories[1].force[7], 0.5 * whole.histories[1].force[7]);
}

TEST(DynamicsStudy, BadOptionsAndAStrokePastTheToggleAreInvalidInput) {
  EXPECT_THROW(run_dynamics_study(design(), options({})), InvalidInput);
  EXPECT_THROW(run_dynamics_study(design(), options({-1.0})), InvalidInput);
  DynamicsStudyOptions o = options({0.0});
  o.samples = 7;
  EXPECT_THROW(run_dynamics_study(design(), o), InvalidInput);
  o = options({0.0});
  o.zero_inertia = o.zero_slider_mass = true;
  EXPECT_THROW(run_dynamics_study(design(), o), InvalidInput);
  o = options({0.0});
  o.stroke_percent = 100.0;
  o.preload_percent = 50.0;
  EXPECT_THROW(dynamics_study_setup(design(), o), InvalidInput);
}

TEST(DynamicsStudyFile, DatasetsEqualTheStudy) {
  ScratchDir dir;
  const auto path = dir / "d.h5";
  const DynamicsStudy s = run_dynamics_study(design(), options({0.0, 20.0, 60.0}));
  {
    DynamicsStudyFile file(path.string());
    file.write(s);
  }
  const hid_t f = open_read_only(path);
  ASSERT_GE(f, 0);
  EXPECT_EQ(read_doubles(f, "omega"), s.omegas);
  const std::vector<double> mean = read_doubles(f, "mean_force");
  const std::vector<double> p2p = read_doubles(f, "peak_to_peak_force");
  const std::vector<double> pcf = read_doubles(f, "percent_constant_force");
  ASSERT_EQ(mean.size(), s.rows.size());
  for (std::size_t i = 0; i < s.rows.size(); ++i) {
    EXPECT_EQ(mean[i], s.rows[i].mean);
    EXPECT_EQ(p2p[i], s.rows[i].peak_to_peak);
    EXPECT_EQ(pcf[i], s.rows[i].percent_constant_force);
  }
  EXPECT_EQ(read_double_attribute(f, "/", "static_nominal_force"), s.static_nominal_force);
  EXPECT_EQ(read_double_attribute(f, "/", "natural_frequency"), s.natural_frequency);
  EXPECT_EQ(read_double_attribute(f, "/", "stroke_m"), s.motion.stroke);
  EXPECT_EQ(read_string_attribute(f, "/", "mechanism"), s.design.name);
  EXPECT_EQ(read_doubles(f, "/history/1/force"), s.histories[1].force);
  EXPECT_EQ(read_double_attribute(f, "/history/1", "omega"), 31.416);
  H5Fclose(f);
  EXPECT_THROW(DynamicsStudyFile("/nonexistent/dir/d.h5"), InvalidInput);
}

}  // namespace
}  // namespace flexure::test
