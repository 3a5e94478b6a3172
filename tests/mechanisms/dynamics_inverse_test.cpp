// What is checked against what (inverse dynamics of the constant-force slider mechanisms):
//  - omega -> 0: the inverse-dynamics force equals the static PRBM force of mechanisms/cfm
//    (Weight eq. 2.14, force_function_phi, dimensionalised as halves k_ref Phi/r2) to 1e-8, for
//    every Table 5 design;
//  - the static nominal force of every design against Table 6's F_Nom (2 %), and Table 5's spring
//    constants against twice Table 2's formulas (the factor decision of docs/dynamics.md);
//  - dM/dtheta2 against a central difference of M (the derivative used in the equation of motion);
//  - power balance over one period: the work of the input force is zero without friction and
//    equals the Coulomb dissipation sum 2 halves C_i (range of psi_i) with friction;
//  - the paper's qualitative claims for 2B-lplm: a band of frequencies where the peak-to-peak
//    force is below its static value, no dip with all inertias zero, a wider band without slider
//    mass; the frequency of lowest peak-to-peak force against Table 10 (one fitted preload);
//  - one half (halves = 1 with half the slider mass) against the whole mechanism: exactly half the
//    force at every sample, with inertia, friction and the axial term (mechanism.h, the factor
//    `flexure dynamics --force-of half` applies).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/cfm/slider_crank.h"
#include "flexure/mechanisms/dynamics/dynamics.h"
#include "flexure/solver/common/status.h"

namespace flexure::dynamics {
namespace {

// Inertial terms scale with omega^2: at 1e-5 rad/s they are ~1e-10 of the spring terms.
constexpr double kQuasiStaticOmega = 1e-5;
constexpr double kQuasiStaticTolerance = 1e-8;
// Table 6 is printed to 4-6 digits but comes from a sampled mean; the issue allows 2 %.
constexpr double kNominalForceTolerance = 0.02;
// Table 5 k are printed to 4 digits, h to 3-4 digits (h^3 of h = 0.0395 mm: up to 4 %; the
// observed spread is 0.2 %).
constexpr double kSpringTolerance = 0.005;
// Central difference with step 1e-5: truncation ~1e-10, rounding ~1e-11 relative.
constexpr double kDerivativeTolerance = 1e-7;
// Rectangle rule with 4096 samples on F dx/dt: spectral without friction, O(h^2) with the
// friction jump at the stroke ends (where dx/dt = 0).
constexpr double kWorkTolerance = 1e-6;
constexpr double kStrokeFraction = 0.40;   // the paper's 40 % slider displacement
constexpr double kPreloadFraction = 0.01;  // "a slight pre-displacement"

SliderCrankDynamics model_of(const CfsmDesign& d) {
  return SliderCrankDynamics(from_bar_links(d.r2, d.r3, d.m2, d.m3, d.m_slider, d.k));
}
SinusoidalMotion motion_of(const CfsmDesign& d, double omega) {
  const double r_tot = d.r2 + d.r3;
  return SinusoidalMotion{kPreloadFraction * r_tot, kStrokeFraction * r_tot, omega};
}

TEST(DynamicsInverse, QuasiStaticLimitEqualsStaticPrbmForce) {
  for (const CfsmDesign& d : cfsm_designs()) {
    InverseDynamics inverse(model_of(d), InverseDynamicsOptions{.samples_per_period = 64});
    const double R = d.r3 / d.r2;
    const bool reference_k2 = d.k[0] == 0.0;  // class 1B (eq. 2.19)
    const double k_ref = reference_k2 ? d.k[1] : d.k[0];
    const double K1 = reference_k2 ? 1.0 : d.k[1] / k_ref;
    const double K2 = d.k[2] / k_ref;
    for (const ForceSample& s : inverse.history(motion_of(d, kQuasiStaticOmega))) {
      const cfm::SliderCrankPose pose = cfm::slider_crank_pose(R, s.delta_x / (d.r2 + d.r3));
      const double expected =
          2.0 * k_ref / d.r2 * cfm::force_function_phi(R, K1, K2, reference_k2, pose);
      EXPECT_NEAR(s.force, expected, kQuasiStaticTolerance * expected) << d.name;
    }
  }
}

TEST(DynamicsInverse, StaticNominalForceMatchesTable6) {
  for (const CfsmDesign& d : cfsm_designs()) {
    const double F = static_nominal_force(model_of(d), kStrokeFraction * (d.r2 + d.r3));
    EXPECT_NEAR(F, d.F_nom_paper, kNominalForceTolerance * d.F_nom_paper) << d.name;
  }
}

TEST(DynamicsInverse, Table5SpringsAreTwiceTable2Formulas) {
  // Table 2's coefficient c of k = c gamma K_theta EI/L (long segments, gamma K_theta =
  // 0.85 * 2.65) or k = c EI/L (small-length pivots, gamma = K_theta = 1), per pivot; 0 = pin.
  struct Row {
    const char* name;
    double c[3];
  };
  const Row table2[] = {{"1A-lppm", {0.3, 0, 0}},
                        {"1B-plpm", {0, 0.3, 0}},
                        {"2A-llpm", {0.6, 0.3, 0}},
                        {"2B-lplm", {0.3, 0, 0.3}},
                        {"3A-lssm", {0.3, 1, 1}},
                        {"3A-slsm", {1, 0.3, 1}},
                        {"3A-llsm", {0.6, 0.3, 1}},
                        {"3A-lslm", {0.3, 1, 0.3}},
                        {"3A-lllm", {0.6, 0.6, 0.6}}};
  for (const Row& row : table2) {
    const CfsmDesign& d = find_cfsm_design(row.name);
    for (int i = 0; i < 3; ++i) {
      if (d.pivots[i] == 'p') continue;
      const double gamma_K_theta = d.pivots[i] == 'l' ? 0.85 * 2.65 : 1.0;
      const double EI = d.material.E * d.width_b * std::pow(d.h[i], 3) / 12.0;
      const double k_table2 = row.c[i] * gamma_K_theta * EI / d.l[i];
      // The factor 2 (docs/dynamics.md "Spring constants") holds for every pivot of Table 5.
      EXPECT_NEAR(d.k[i], 2.0 * k_table2, kSpringTolerance * d.k[i])
          << d.name << " pivot " << i + 1;
    }
  }
}

TEST(DynamicsInverse, InertiaDerivativeMatchesCentralDifference) {
  const SliderCrankDynamics model = model_of(find_cfsm_design("2B-lplm"));
  const double h = 1e-5;
  for (double theta : {0.05, 0.3, 0.7, 1.1}) {
    const ConfigurationTerms t = model.terms(theta);
    const double dM = (model.terms(theta + h).M - model.terms(theta - h).M) / (2 * h);
    const double dV = (model.terms(theta + h).V - model.terms(theta - h).V) / (2 * h);
    const double d2V = (model.terms(theta + h).dV - model.terms(theta - h).dV) / (2 * h);
    EXPECT_NEAR(t.dM, dM, kDerivativeTolerance * std::abs(t.M)) << theta;
    EXPECT_NEAR(t.dV, dV, kDerivativeTolerance * std::abs(t.dV)) << theta;
    EXPECT_NEAR(t.d2V, d2V, kDerivativeTolerance * std::abs(t.d2V)) << theta;
  }
}

// Work of the input force over one period, by the rectangle rule in time.
double cycle_work(const InverseDynamics& inverse, const SinusoidalMotion& m) {
  const std::vector<ForceSample> h = inverse.history(m);
  const double a = 0.5 * m.stroke;
  double work = 0.0;
  const double dt = 2.0 * std::numbers::pi / m.omega / static_cast<double>(h.size());
  for (const ForceSample& s : h) work += s.force * a * m.omega * std::sin(m.omega * s.t) * dt;
  return work;
}

TEST(DynamicsInverse, CycleWorkIsZeroWithoutFrictionAndEqualsCoulombDissipation) {
  const CfsmDesign& d = find_cfsm_design("2B-lplm");
  const SinusoidalMotion m = motion_of(d, 40.0);
  const InverseDynamics conservative(model_of(d), {.samples_per_period = 4096});
  const double scale = 2.0 * static_nominal_force(conservative.model(), m.stroke) * m.stroke;
  EXPECT_NEAR(cycle_work(conservative, m), 0.0, kWorkTolerance * scale);

  DynamicsParameters p = from_bar_links(d.r2, d.r3, d.m2, d.m3, d.m_slider, d.k);
  p.coulomb = {0.01, 0.02, 0.03};
  const SliderCrankDynamics friction_model(p);
  const InverseDynamics with_friction(friction_model, {.samples_per_period = 4096});
  // Each pin turns through its range twice per cycle (psi_i is monotonic in theta2 on the branch).
  const ConfigurationTerms lo = friction_model.terms(friction_model.theta2_at(m.preload));
  const ConfigurationTerms hi =
      friction_model.terms(friction_model.theta2_at(m.preload + m.stroke));
  const double range[3] = {hi.theta2 - lo.theta2,
                           (hi.theta2 - hi.theta3) - (lo.theta2 - lo.theta3),
                           -hi.theta3 + lo.theta3};
  double dissipated = 0.0;
  for (int i = 0; i < 3; ++i) dissipated += 2.0 * p.halves * p.coulomb[i] * range[i];
  EXPECT_NEAR(cycle_work(with_friction, m), dissipated, kWorkTolerance * scale);
}

// Upper edge of the band 0 < omega < omega_b where the peak-to-peak force is below its static
// value (scanned in 0.25 rad/s steps); 0 if there is no dip.
double dip_band_edge(const InverseDynamics& inverse, const SinusoidalMotion& base) {
  const double p2p_static = inverse.statistics(base).peak_to_peak;
  SinusoidalMotion m = base;
  double edge = 0.0;
  for (double w = 0.25; w <= 100.0; w += 0.25) {
    m.omega = w;
    if (inverse.statistics(m).peak_to_peak >= p2p_static) break;
    edge = w;
  }
  return edge;
}

TEST(DynamicsInverse, Class2BlplmShowsThePaperDipInPeakToPeakForce) {
  const CfsmDesign& d = find_cfsm_design("2B-lplm");
  const SinusoidalMotion base = motion_of(d, 0.0);
  const InverseDynamics full(model_of(d), {.samples_per_period = 512});
  const double edge = dip_band_edge(full, base);
  EXPECT_GT(edge, 5.0) << "no band of frequencies with a smaller peak-to-peak force";
  EXPECT_LT(edge, 100.0) << "the peak-to-peak force must rise again (paper Fig. 10)";

  // Paper: "setting all inertias to zero ... exhibits no dip" - the force is then omega-free.
  const InverseDynamics massless(SliderCrankDynamics(from_bar_links(d.r2, d.r3, 0, 0, 0, d.k)),
                                 {.samples_per_period = 512});
  SinusoidalMotion fast = base;
  fast.omega = 0.5 * edge;
  EXPECT_DOUBLE_EQ(massless.statistics(fast).peak_to_peak, massless.statistics(base).peak_to_peak);

  // Paper: "this range of frequencies can be maximized by minimizing the slider mass".
  const InverseDynamics no_slider(
      SliderCrankDynamics(from_bar_links(d.r2, d.r3, d.m2, d.m3, 0.0, d.k)),
      {.samples_per_period = 512});
  EXPECT_GT(dip_band_edge(no_slider, base), edge);
}

// Table 10's "frequency with very low peak-to-peak force" against the minimum of the computed
// peak-to-peak force, with ONE preload for all designs. The paper gives no preload value ("a slight
// pre-displacement"); 7 % of r2 + r3 was chosen (docs/dynamics.md, "Comparison with Table 10") by
// scanning 5-8 % in 1 % steps, so this is a one-parameter fit to eight printed frequencies, not an
// independent prediction. Rows 2B-lpsm and 3A-lssm of Table 10 are copies of other rows and left
// out. Tolerance: Table 10 frequencies are printed to 0.5-1 rad/s; the fit leaves up to 5 %.
TEST(DynamicsInverse, LowestPeakToPeakFrequencyFollowsTable10WithOnePreload) {
  constexpr double kPreloadFit = 0.07;
  constexpr double kTable10Tolerance = 0.06;
  constexpr double kScanStep = 0.25;  // rad/s
  struct Row {
    const char* name;
    double omega;  // rad/s, Table 10
  };
  const Row table10[] = {{"1A-lppm", 27.0},
                         {"1B-plpm", 18.0},
                         {"2A-llpm", 20.0},
                         {"2B-lplm", 32.0},
                         {"3A-slsm", 15.0},
                         {"3A-llsm", 17.0},
                         {"3A-lslm", 29.0},
                         {"3A-lllm", 14.5}};
  for (const Row& row : table10) {
    const CfsmDesign& d = find_cfsm_design(row.name);
    const InverseDynamics inverse(model_of(d), {.samples_per_period = 256});
    const double r_tot = d.r2 + d.r3;
    SinusoidalMotion m{kPreloadFit * r_tot, kStrokeFraction * r_tot, 0.0};
    double best = 1e300, best_omega = 0.0;
    for (double w = kScanStep; w <= 60.0; w += kScanStep) {
      m.omega = w;
      const double p2p = inverse.statistics(m).peak_to_peak;
      if (p2p < best) {
        best = p2p;
        best_omega = w;
      }
    }
    EXPECT_NEAR(best_omega, row.omega, kTable10Tolerance * row.omega) << row.name;
  }
}

TEST(DynamicsInverse, SweepReportsProgressAfterEachRowAndMatchesSingleRows) {
  const CfsmDesign& d = find_cfsm_design("2B-lplm");
  const InverseDynamics inverse(model_of(d), {.samples_per_period = 64});
  const std::vector<double> omegas = {0.0, 10.0, 20.0, 30.0};
  std::vector<std::size_t> done;
  const std::vector<ForceStatistics> rows =
      inverse.sweep(motion_of(d, 0.0), omegas, [&](std::size_t k, std::size_t total) {
        EXPECT_EQ(total, omegas.size());
        done.push_back(k);
      });
  EXPECT_EQ(done, (std::vector<std::size_t>{1, 2, 3, 4}));
  ASSERT_EQ(rows.size(), omegas.size());
  SinusoidalMotion m = motion_of(d, 0.0);
  m.omega = 20.0;
  EXPECT_EQ(rows[2].peak_to_peak, inverse.statistics(m).peak_to_peak);
}

TEST(DynamicsInverse, OneHalfWithHalfTheSliderCarriesHalfTheForce) {
  // The per-half model built separately (docs/dynamics.md §1: halves = 1, m_S halved) against the
  // whole mechanism's force / 2, at a frequency where inertia dominates the force (62.832 rad/s:
  // peak-to-peak 162 N against 16 N statically), with friction and the axial term on. The two
  // evaluate the same sums with one factor 2 moved, so they agree to rounding.
  constexpr double kRounding = 1e-13;
  for (const CfsmDesign& d : cfsm_designs()) {
    DynamicsParameters whole = from_bar_links(d.r2, d.r3, d.m2, d.m3, d.m_slider, d.k);
    whole.coulomb = {0.01, 0.02, 0.03};
    whole.axial_alpha = 0.05;
    DynamicsParameters half = whole;
    half.halves = 1.0;
    half.m_slider = 0.5 * d.m_slider;
    const InverseDynamics w(SliderCrankDynamics(whole), {.samples_per_period = 64});
    const InverseDynamics h(SliderCrankDynamics(half), {.samples_per_period = 64});
    const std::vector<ForceSample> fw = w.history(motion_of(d, 62.832));
    const std::vector<ForceSample> fh = h.history(motion_of(d, 62.832));
    ASSERT_EQ(fw.size(), fh.size());
    for (std::size_t i = 0; i < fw.size(); ++i) {
      EXPECT_NEAR(fh[i].force, 0.5 * fw[i].force, kRounding * std::abs(fw[i].force)) << d.name;
    }
  }
}

TEST(DynamicsInverse, RejectsBadMotion) {
  const CfsmDesign& d = find_cfsm_design("2B-lplm");
  const InverseDynamics inverse(model_of(d));
  SinusoidalMotion m = motion_of(d, 10.0);
  m.preload = 0.0;
  EXPECT_THROW(inverse.statistics(m), InvalidInput);
  m = motion_of(d, -1.0);
  EXPECT_THROW(inverse.statistics(m), InvalidInput);
  EXPECT_THROW(find_cfsm_design("2B-xxxm"), InvalidInput);
}

}  // namespace
}  // namespace flexure::dynamics
