// A model per flexure of a mechanism (solve_general_mixed, general_analysis.h; docs/mechanisms.md
// "A model per flexure") on the built-in constant-force designs in their general form
// (catalogue_general.h), against the all-exact analysis of the same mechanism.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "flexure/mechanisms/general/catalogue_general.h"
#include "flexure/mechanisms/general/general_analysis.h"
#include "flexure/mechanisms/general/general_mechanism.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism::general {
namespace {

// The designs whose general form the exact model solves (general_mechanism_test: equal to the
// catalogue's exact model to 1e-8).
const char* const kDesigns[] = {"3A-sss", "2A-ssp", "1A-spp", "1A-lpp", "2B-sps"};
constexpr int kPoints = 10;

GeneralMechanism with_models(const char* name, FlexureModel model, double tolerance = 0.0) {
  GeneralMechanism m = general_from_design(find_builtin_mechanism(name), kPoints);
  for (Flexure& f : m.flexures) {
    f.model = model;
    f.tolerance = tolerance;
  }
  return m;
}

double largest_load(const GeneralPrbmResult& r) {
  double largest = 0.0;
  for (const GeneralPrbmPoint& p : r.points) largest = std::max(largest, std::fabs(p.input_load));
  return largest;
}

// Every flexure set to exact is today's exact analysis, number for number.
TEST(MixedFlexureModels, AllExactIsTheExactAnalysis) {
  for (const char* name : kDesigns) {
    const GeneralMechanism m = with_models(name, FlexureModel::kExact);
    const GeneralPrbmResult exact = solve_general_exact(m);
    const GeneralPrbmResult mixed = solve_general_mixed(m);
    ASSERT_TRUE(exact.converged() && mixed.converged()) << name;
    ASSERT_EQ(mixed.points.size(), exact.points.size());
    for (std::size_t i = 0; i < exact.points.size(); ++i) {
      EXPECT_EQ(mixed.points[i].input_load, exact.points[i].input_load) << name << " point " << i;
      EXPECT_EQ(mixed.points[i].energy, exact.points[i].energy) << name;
    }
    ASSERT_EQ(mixed.flexure_models.size(), m.flexures.size());
    for (const FlexureModelReport& r : mixed.flexure_models) {
      EXPECT_EQ(r.model, FlexureModel::kExact);
      EXPECT_EQ(r.expected_error_per_length, 0.0);
      EXPECT_EQ(r.loads.size(), static_cast<std::size_t>(kPoints));
    }
  }
}

// A cheaper model's expected (mapped) error bounds the error measured against the exact elastica
// under the loads the flexure carries, at every point of every design it solves.
TEST(MixedFlexureModels, ExpectedErrorBoundsTheMeasuredError) {
  GeneralExactOptions o;
  o.measure_flexure_errors = true;
  int bounded = 0;
  for (FlexureModel model :
       {FlexureModel::kLinear, FlexureModel::kBcm, FlexureModel::kPrbm3r, FlexureModel::kCbcm}) {
    for (const char* name : kDesigns) {
      const GeneralPrbmResult r = solve_general_mixed(with_models(name, model), o);
      if (!r.converged()) continue;  // e.g. the BCM past its buckling load on the way
      for (const FlexureModelReport& f : r.flexure_models) {
        EXPECT_EQ(f.model, model);
        for (std::size_t k = 0; k < f.loads.size(); ++k) {
          if (std::isnan(f.mapped_error[k])) continue;
          ASSERT_FALSE(std::isnan(f.measured_error[k])) << name << " " << f.name;
          EXPECT_LE(f.measured_error[k], f.mapped_error[k])
              << name << " " << f.name << " " << flexure_model_name(model) << " point " << k;
          ++bounded;
        }
      }
    }
  }
  // Not vacuous: most flexures' loads lie on the map.
  EXPECT_GT(bounded, 100);
}

// auto with a tolerance: each flexure's expected error within it, and the mechanism's input load
// within it (relative to its largest value) of the all-exact analysis.
TEST(MixedFlexureModels, AutoStaysWithinItsToleranceOfExact) {
  for (double tol : {1e-2, 1e-3, 1e-4}) {
    for (const char* name : kDesigns) {
      const GeneralPrbmResult exact = solve_general_exact(with_models(name, FlexureModel::kExact));
      const GeneralPrbmResult r = solve_general_mixed(with_models(name, FlexureModel::kAuto, tol));
      ASSERT_TRUE(r.converged()) << name << ": " << r.message;
      for (const FlexureModelReport& f : r.flexure_models) {
        EXPECT_EQ(f.requested, FlexureModel::kAuto);
        EXPECT_LE(f.expected_error_per_length, tol) << name << " " << f.name << ": " << f.reason;
        EXPECT_FALSE(f.reason.empty());
      }
      const double scale = largest_load(exact);
      double worst = 0.0;
      for (std::size_t i = 0; i < exact.points.size(); ++i) {
        worst = std::max(worst, std::fabs(r.points[i].input_load - exact.points[i].input_load));
      }
      EXPECT_LE(worst, tol * scale) << name << " tol " << tol;
      std::cout << name << " tol " << tol << ": load error " << worst / scale;
      for (const FlexureModelReport& f : r.flexure_models) {
        std::cout << " " << f.name << "=" << flexure_model_name(f.model) << "("
                  << f.expected_error_per_length << ")";
      }
      std::cout << "\n";
    }
  }
}

// The tips of the cheap models against the exact elastica at seeded random loads on the maps (the
// main map's |n| <= 2, alpha2 <= 10 and the axial map's 2 <= |n| <= 100, alpha2 <= 2): the mapped
// error bounds the measured one (the bound the mechanism's reports rest on).
TEST(MixedFlexureModels, SeededRandomLoadsMappedErrorBoundsModelTip) {
  std::mt19937 rng(30);
  std::uniform_real_distribution<double> n(-2.0, 2.0), a2(0.0, 10.0), mu(-2.0, 2.0), sign(-1, 1);
  std::uniform_real_distribution<double> log_n(std::log(2.0), std::log(100.0)), a2_axial(0.0, 2.0);
  int checked = 0;
  for (int k = 0; k < 120; ++k) {
    const bool axial = k % 2 == 1;
    const double alpha2 = axial ? a2_axial(rng) : a2(rng);
    const double ratio = axial ? (sign(rng) < 0.0 ? -1.0 : 1.0) * std::exp(log_n(rng)) : n(rng);
    const double s = sign(rng) < 0.0 ? -1.0 : 1.0;
    const FlexureTipLoad load{-ratio * alpha2, s * alpha2, mu(rng)};
    FlexureTip exact;
    if (!exact_flexure_tip(load, exact)) continue;
    for (FlexureModel model : auto_ladder()) {
      const double E = mapped_flexure_error(model, 6, load);
      FlexureTip tip;
      if (std::isnan(E) || !model_tip(model, PrbmKind::kSmallLengthPivot, 6, load, tip)) continue;
      EXPECT_LE(std::hypot(tip.x - exact.x, tip.y - exact.y), E)
          << flexure_model_name(model) << " at Fx " << load.Fx << " Fy " << load.Fy << " mu "
          << load.mu;
      ++checked;
    }
  }
  EXPECT_GT(checked, 200);
}

// The small-length PRBM element as a tip-loaded cantilever: pin at l/2, K = EI/l (Howell eq.
// 5.14), so under a pure end moment mu the link turns mu/K = mu and the tip sits at
// (1/2 + cos(mu)/2, sin(mu)/2).
TEST(MixedFlexureModels, PrbmElementUnderEndMoment) {
  FlexureTip tip;
  ASSERT_TRUE(model_tip(FlexureModel::kPrbm, PrbmKind::kSmallLengthPivot, 6, {0, 0, 0.7}, tip));
  EXPECT_NEAR(tip.theta, 0.7, 1e-12);
  EXPECT_NEAR(tip.x, 0.5 + 0.5 * std::cos(0.7), 1e-12);
  EXPECT_NEAR(tip.y, 0.5 * std::sin(0.7), 1e-12);
  std::string why;
  EXPECT_FALSE(model_tip(FlexureModel::kPrbm, PrbmKind::kFixedGuided, 6, {0, 1, 0}, tip, &why));
  EXPECT_NE(why.find("fixed-guided"), std::string::npos);
}

TEST(MixedFlexureModels, BadChoicesAreNamedErrors) {
  GeneralMechanism m = with_models("3A-sss", FlexureModel::kAuto, 0.0);
  try {
    solve_general_mixed(m);
    ADD_FAILURE() << "auto without a tolerance accepted";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("tolerance"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("f1"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_flexure_model("fem"), InvalidInput);
  EXPECT_EQ(parse_flexure_model("prbm3r"), FlexureModel::kPrbm3r);
  EXPECT_THROW(general_from_design(find_builtin_mechanism("1B-plp"), 1), InvalidInput);
}

}  // namespace
}  // namespace flexure::mechanism::general
