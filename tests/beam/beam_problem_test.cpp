// What is checked against what: beam problems solved through the library (solve_beam,
// beam/beam_problem.h), without the command-line tool.
//  * Seeded random forward loads: elliptic and shooting agree on the tip (1e-8); the method used
//    is reported as an enum and the status is converged.
//  * Seeded random inverse problems (theta0 given): every method's load reproduces the target
//    within its stated tolerance (self-check of the inverse).
//  * The PRBM of a guided end (Howell §5.3, the fixed-guided segment): by the antisymmetry of the
//    guided beam its tip under alpha2 is the tip of a fixed-pinned half under alpha2/4, for the
//    PRBM (to 1e-10) and for the exact solutions (guided shooting against elliptic, 1e-8); at
//    equal load the PRBM is within 5 % of the exact deflection (the PRBM's stiffness error,
//    3.8 % in the small-deflection limit with gamma = 0.85, K_theta = 2.65).
//  * The PRBM dispatch (elements/prbm_cantilever.h) picks the element of the end and the load,
//    and refuses ends no element models with InvalidInput.
#include "flexure/beam/beam_problem.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "flexure/elements/prbm_cantilever.h"
#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

BeamProblem forward(double n, double alpha2, double mu) {
  BeamProblem p;
  p.load_ratio_n = n;
  p.value = alpha2;
  p.mu = mu;
  return p;
}

TEST(BeamProblem, RandomForwardLoadsAgreeBetweenEllipticAndShooting) {
  std::mt19937 rng(20261124);
  std::uniform_real_distribution<double> n(-3.0, 3.0), alpha2(0.1, 10.0), mu(-1.5, 1.5);
  for (int i = 0; i < 25; ++i) {
    const BeamProblem p = forward(n(rng), alpha2(rng), mu(rng));
    const BeamSolution e = solve_beam(BeamMethod::kElliptic, p);
    const BeamSolution s = solve_beam(BeamMethod::kShooting, p);
    SCOPED_TRACE(::testing::Message()
                 << "n = " << p.load_ratio_n << ", alpha2 = " << p.value << ", mu = " << p.mu);
    ASSERT_EQ(e.termination, Termination::kConverged) << e.message;
    ASSERT_EQ(s.termination, Termination::kConverged) << s.message;
    EXPECT_EQ(e.method, BeamMethod::kElliptic);
    EXPECT_EQ(s.method, BeamMethod::kShooting);
    EXPECT_NEAR(e.tip.a_over_l, s.tip.a_over_l, 1e-8);
    EXPECT_NEAR(e.tip.b_over_l, s.tip.b_over_l, 1e-8);
    EXPECT_NEAR(e.tip.theta0, s.tip.theta0, 1e-8);
    EXPECT_NEAR(e.root_moment, s.root_moment, 1e-7);
  }
}

TEST(BeamProblem, RandomInverseProblemsHitTheirTarget) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> n(-1.0, 2.0), theta0(0.05, 1.2);
  for (int i = 0; i < 6; ++i) {
    BeamProblem p;
    p.given = BeamProblem::Given::kTheta0;
    p.load_ratio_n = n(rng);
    p.value = theta0(rng);
    for (BeamMethod m : {BeamMethod::kElliptic, BeamMethod::kShooting}) {
      const BeamSolution r = solve_beam(m, p);
      SCOPED_TRACE(::testing::Message()
                   << to_string(m) << ": n = " << p.load_ratio_n << ", theta0 = " << p.value);
      ASSERT_TRUE(r.converged()) << r.message;
      EXPECT_NEAR(r.tip.theta0, p.value, 1e-8 * std::max(1.0, std::fabs(p.value)));
      EXPECT_LE(r.target_residual, 1e-8 * std::max(1.0, std::fabs(p.value)));
      // The load found reproduces the target in an independent forward solve.
      const BeamSolution again = solve_beam(m, forward(p.load_ratio_n, r.alpha2, 0.0));
      EXPECT_NEAR(again.tip.theta0, p.value, 1e-7);
    }
  }
}

TEST(BeamProblem, GuidedPrbmIsTwoFixedPinnedHalvesAndNearTheExactGuidedBeam) {
  for (double alpha2 : {2.0, 5.0, 10.0, 15.0}) {
    BeamProblem p = forward(0.0, alpha2, 0.0);
    p.boundary = EndCondition::kGuided;
    const BeamSolution prbm = solve_beam(BeamMethod::kPrbm, p);
    const BeamSolution exact = solve_beam(BeamMethod::kShooting, p);
    // Each half, of length l/2, is a fixed-pinned cantilever under the same force:
    // alpha2_half = F (l/2)^2/EI = alpha2/4, and the halves' tips add up to the guided tip.
    const BeamSolution prbm_half = solve_beam(BeamMethod::kPrbm, forward(0.0, alpha2 / 4, 0.0));
    const BeamSolution exact_half =
        solve_beam(BeamMethod::kElliptic, forward(0.0, alpha2 / 4, 0.0));
    SCOPED_TRACE(::testing::Message() << "alpha2 = " << alpha2);
    ASSERT_TRUE(prbm.converged() && prbm_half.converged()) << prbm.message;
    ASSERT_TRUE(exact.converged() && exact_half.converged()) << exact.message;
    EXPECT_EQ(prbm.method, BeamMethod::kPrbm);
    EXPECT_EQ(prbm.tip.theta0, 0.0);  // the guide holds the tip angle
    EXPECT_NEAR(prbm.tip.a_over_l, prbm_half.tip.a_over_l, 1e-10);
    EXPECT_NEAR(prbm.tip.b_over_l, prbm_half.tip.b_over_l, 1e-10);
    EXPECT_NEAR(exact.tip.a_over_l, exact_half.tip.a_over_l, 1e-8);
    EXPECT_NEAR(exact.tip.b_over_l, exact_half.tip.b_over_l, 1e-8);
    const double deflection = std::hypot(exact.tip.a_over_l - 1.0, exact.tip.b_over_l);
    const double error =
        std::hypot(prbm.tip.a_over_l - exact.tip.a_over_l, prbm.tip.b_over_l - exact.tip.b_over_l);
    EXPECT_LE(error, 0.05 * deflection);
    EXPECT_NEAR(prbm.root_moment, exact.root_moment, 0.05 * exact.root_moment);
    EXPECT_EQ(prbm.inflection_points, exact.inflection_points);
  }
}

TEST(PrbmCantilever, PicksTheElementOfTheEndAndTheLoad) {
  EXPECT_EQ(solve_prbm_cantilever(EndCondition::kFree, 0.0, 2.0, 0.0).element,
            "fixed-pinned segment");
  EXPECT_EQ(solve_prbm_cantilever(EndCondition::kFree, 0.0, 0.0, 1.0).element,
            "end-moment segment");
  EXPECT_EQ(solve_prbm_cantilever(EndCondition::kGuided, 0.0, 2.0, 0.0).element,
            "fixed-guided segment");
  EXPECT_THROW(solve_prbm_cantilever(EndCondition::kPinned, 0.0, 2.0, 0.0), InvalidInput);
  EXPECT_THROW(solve_prbm_cantilever(EndCondition::kGuided, 0.0, 2.0, 0.5), InvalidInput);
  // A pinned tip carries no moment: the fixed-pinned segment refuses a force with a moment.
  EXPECT_THROW(solve_prbm_cantilever(EndCondition::kFree, 0.0, 2.0, 0.5), InvalidInput);
}

TEST(BeamProblem, MethodNamesRoundTripAndUnknownNamesAreRefused) {
  for (const char* name : kBeamMethodNames) {
    EXPECT_STREQ(to_string(beam_method_from_string(name)), name);
  }
  EXPECT_THROW(beam_method_from_string("fem"), InvalidInput);
}

}  // namespace
}  // namespace flexure
