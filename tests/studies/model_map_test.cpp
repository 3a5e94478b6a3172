// The model map (benchmarks/studies/model_map.h) reports honest errors: on seeded random loads,
// every model's tip in the map equals the model's own solver called directly here (linear theory
// from its closed form written out in this file), and every recorded error equals the distance
// to an exact solution computed independently (the shooting method for the free end, where the
// map's reference is the elliptic solver; the chained BCM at N = 256 for the guided end, where
// the reference is the shooting method). Statuses: the 1R model refuses an end moment with a
// force (2), the BCM a load past its element's buckling load (2).
#include "flexure/benchmarks/studies/model_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>
#include <string>

#include "flexure/elements/ladder_models.h"
#include "flexure/elements/prbm_cantilever.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure::studies {
namespace {

constexpr int kOk = static_cast<int>(ModelPointStatus::kConverged);
constexpr int kNotRepresented = static_cast<int>(ModelPointStatus::kNotRepresented);

std::vector<double> random_axis(std::mt19937& rng, double lo, double hi, int count) {
  std::uniform_real_distribution<double> u(lo, hi);
  std::vector<double> v;
  for (int i = 0; i < count; ++i) v.push_back(u(rng));
  return v;
}

CantileverCase case_at(const ModelMapSpec& spec, double n, double alpha2, double third) {
  CantileverCase c;
  c.load = EndLoad::howell(n, alpha2, spec.boundary == EndCondition::kGuided ? 0.0 : third);
  c.end = spec.boundary;
  if (spec.boundary == EndCondition::kGuided) c.guided_tip_angle = third;
  return c;
}

// The model's tip, computed here without the map (and without solve_beam).
std::optional<TipPose> direct_tip(BeamMethod method,
                                  const ModelMapSpec& spec,
                                  const CantileverCase& c) {
  const double Fy = c.load.Fy;
  switch (method) {
    case BeamMethod::kLinear:
      // Gere & Timoshenko's cantilever: b = F/3 + M/2, theta = F/2 + M; guided: M = phi - F/2.
      if (c.end == EndCondition::kGuided) {
        const double M = c.guided_tip_angle - Fy / 2.0;
        return TipPose{1.0, Fy / 3.0 + M / 2.0, Fy / 2.0 + M};
      }
      return TipPose{1.0, Fy / 3.0 + c.load.mu / 2.0, Fy / 2.0 + c.load.mu};
    case BeamMethod::kPrbm3r: {
      Prbm3rSolver::Options o;
      o.constants = Prbm3rConstants::of(spec.prbm3r_constants);
      const Prbm3rResult r = Prbm3rSolver(o).solve(c);
      if (!r.converged()) return std::nullopt;
      return r.tip;
    }
    case BeamMethod::kBcm:
      return BcmSolver().solve(c).tip;
    case BeamMethod::kCbcm: {
      ChainedBcmSolver::Options o;
      o.elements = spec.cbcm_elements;
      const CbcmResult r = ChainedBcmSolver(o).solve(c);
      if (!r.converged()) return std::nullopt;
      return r.tip_pose();
    }
    case BeamMethod::kPrbm:
      return solve_prbm_cantilever(c.end, -c.load.Fx / c.load.Fy, Fy, c.load.mu).tip;
    default:
      return std::nullopt;
  }
}

// The exact tip, independently of the map's reference.
TipPose independent_exact(const ModelMapSpec& spec, const CantileverCase& c) {
  if (spec.boundary == EndCondition::kFree) {
    const ShootingResult s = solve_shooting(c.to_chain(), ShootingSolver::Options{});
    EXPECT_TRUE(s.converged()) << s.message;
    return {s.tip.x, s.tip.y, s.tip.theta};
  }
  ChainedBcmSolver::Options o;
  o.elements = 256;  // tip error about 1e-9 at these loads (order 3, docs/models.md)
  const CbcmResult r = ChainedBcmSolver(o).solve(c);
  EXPECT_TRUE(r.converged()) << r.message;
  return r.tip_pose();
}

void expect_honest(const ModelMapSpec& spec, double exact_tolerance) {
  const ModelMap map = compute_model_map(spec);
  const std::vector<double>& third = spec.third_axis();
  std::size_t k = 0;
  int checked = 0;
  for (double n : spec.n) {
    for (double alpha2 : spec.alpha2) {
      for (double t : third) {
        SCOPED_TRACE(::testing::Message() << "n " << n << " alpha2 " << alpha2 << " "
                                          << spec.third_axis_name() << " " << t);
        const CantileverCase c = case_at(spec, n, alpha2, t);
        ASSERT_EQ(map.reference.status[k], kOk);
        const TipPose exact = independent_exact(spec, c);
        EXPECT_NEAR(map.reference.a_over_l[k], exact.a_over_l, exact_tolerance);
        EXPECT_NEAR(map.reference.b_over_l[k], exact.b_over_l, exact_tolerance);
        for (const ModelMapModel& m : map.models) {
          SCOPED_TRACE(to_string(m.method));
          const ModelMapColumns& v = m.values;
          if (m.method == BeamMethod::kPrbm && c.load.mu != 0.0 && alpha2 != 0.0) {
            EXPECT_EQ(v.status[k], kNotRepresented);
            EXPECT_TRUE(std::isnan(v.position_error[k]));
            continue;
          }
          ASSERT_EQ(v.status[k], kOk);
          const std::optional<TipPose> tip = direct_tip(m.method, spec, c);
          if (tip) {
            EXPECT_NEAR(v.a_over_l[k], tip->a_over_l, 1e-10);
            EXPECT_NEAR(v.b_over_l[k], tip->b_over_l, 1e-10);
            EXPECT_NEAR(v.theta0[k], tip->theta0, 1e-10);
          }
          const double error =
              std::hypot(v.a_over_l[k] - exact.a_over_l, v.b_over_l[k] - exact.b_over_l);
          EXPECT_NEAR(v.position_error[k], error, 2.0 * exact_tolerance);
          EXPECT_NEAR(
              v.angle_error[k], std::fabs(v.theta0[k] - exact.theta0), 2.0 * exact_tolerance);
          const double displacement = std::hypot(exact.a_over_l - 1.0, exact.b_over_l);
          EXPECT_NEAR(v.relative_error[k] * displacement, error, 3.0 * exact_tolerance);
          EXPECT_GT(v.seconds[k], 0.0);
          ++checked;
        }
        ++k;
      }
    }
  }
  EXPECT_GT(checked, 0);
}

TEST(ModelMap, FreeEndErrorsAreTheDistanceToAnIndependentExactSolution) {
  std::mt19937 rng(3001);
  ModelMapSpec spec;
  spec.n = random_axis(rng, -0.5, 0.8, 2);
  spec.alpha2 = random_axis(rng, 0.2, 2.0, 3);
  spec.mu = random_axis(rng, -0.5, 0.5, 2);
  spec.mu.push_back(0.0);  // where the 1R model answers
  spec.models = {BeamMethod::kLinear,
                 BeamMethod::kPrbm,
                 BeamMethod::kPrbm3r,
                 BeamMethod::kBcm,
                 BeamMethod::kCbcm};
  spec.min_seconds = 0.0;
  expect_honest(spec, 1e-9);
}

TEST(ModelMap, GuidedEndErrorsAreTheDistanceToAnIndependentExactSolution) {
  std::mt19937 rng(3002);
  ModelMapSpec spec;
  spec.boundary = EndCondition::kGuided;
  spec.n = random_axis(rng, -0.5, 0.8, 2);
  spec.alpha2 = random_axis(rng, 0.5, 4.0, 2);
  spec.tip_angle = random_axis(rng, -0.3, 0.3, 2);
  spec.models = {BeamMethod::kLinear, BeamMethod::kPrbm3r, BeamMethod::kBcm, BeamMethod::kCbcm};
  spec.min_seconds = 0.0;
  expect_honest(spec, 1e-7);
}

TEST(ModelMap, StatusesAndSummaries) {
  ModelMapSpec spec;
  spec.n = {1.0};
  spec.alpha2 = {3.0};  // p = -3: past the BCM cantilever's buckling load -2.468
  spec.mu = {0.0, 0.5};
  spec.models = {BeamMethod::kBcm, BeamMethod::kPrbm, BeamMethod::kCbcm};
  spec.min_seconds = 0.0;
  const ModelMap map = compute_model_map(spec);
  EXPECT_EQ(map.models[0].values.status[0], kNotRepresented);  // BCM past buckling
  EXPECT_EQ(map.models[1].values.status[0], kOk);              // 1R, force alone
  EXPECT_EQ(map.models[1].values.status[1], kNotRepresented);  // 1R, force and moment
  EXPECT_EQ(map.models[2].converged, 2);
  EXPECT_EQ(map.models[0].converged, 0);
  EXPECT_TRUE(std::isnan(map.models[0].median_position_error));
  EXPECT_DOUBLE_EQ(
      map.models[2].max_position_error,
      std::max(map.models[2].values.position_error[0], map.models[2].values.position_error[1]));
}

TEST(ModelMap, RefusesWhatItCannotMap) {
  const auto refused = [](const ModelMapSpec& s, const std::string& word) {
    try {
      s.validate();
      ADD_FAILURE() << "accepted; expected a refusal naming " << word;
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
    }
  };
  ModelMapSpec s;
  s.alpha2 = {1.0};
  EXPECT_NO_THROW(s.validate());
  ModelMapSpec t = s;
  t.boundary = EndCondition::kPinned;
  refused(t, "free or a guided");
  t = s;
  t.models = {BeamMethod::kElliptic};
  refused(t, "reference");
  t = s;
  t.models = {BeamMethod::kLinear, BeamMethod::kLinear};
  refused(t, "twice");
  t = s;
  t.alpha2 = {};
  refused(t, "alpha2");
  t = s;
  t.n = {std::nan("")};
  refused(t, "n axis");
  t = s;
  t.boundary = EndCondition::kGuided;
  t.mu = {0.5};
  refused(t, "tip angle");
  t = s;
  t.tip_angle = {0.2};
  refused(t, "guided");
}

}  // namespace
}  // namespace flexure::studies
