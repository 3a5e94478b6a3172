// What is checked against what: `--method auto` (beam/beam_problem.h).
//  * With a loose tolerance inside the PRBM validity limits it picks the PRBM, and the PRBM's
//    error at that load, measured here against the INDEPENDENT exact elliptic solution, is
//    indeed within the tolerance (so the embedded accuracy map does not flatter the PRBM).
//  * With the default 1e-6, or outside the validity limits (Theta > Theta_max, Howell Table 5.1),
//    or with a tip moment, it picks the exact elliptic solver; off the free cantilever, shooting.
//  * The reason names the deciding quantity.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "flexure/beam/beam_problem.h"
#include "flexure/elements/prbm_element.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/elliptic/elliptic_solver.h"

namespace flexure {
namespace {

// A loose tolerance a designer would accept from a PRBM sketch (1 %).
constexpr double kLooseTolerance = 1e-2;

double prbm_error_against_elliptic(double n, double alpha2) {
  const FixedPinnedSegment element(FixedPinnedConstants::from_table(n));
  const PrbEquilibrium prbm = element.solve(EndLoad::howell(n, alpha2));
  const EllipticResult exact = EllipticSolver().solve(EndLoad::howell(n, alpha2));
  EXPECT_TRUE(prbm.converged() && exact.converged());
  const double deflection = std::hypot(exact.tip.a_over_l - 1.0, exact.tip.b_over_l);
  return std::hypot(prbm.tip.a_over_l - exact.tip.a_over_l,
                    prbm.tip.b_over_l - exact.tip.b_over_l) /
         deflection;
}

TEST(AutoMethod, PicksPrbmInsideItsValidityRangeForALooseTolerance) {
  // n = 0, alpha2 = 3: Theta = 45 deg < min(Theta_max(gamma), Theta_max(K_theta)) = 58.5 deg
  // (Table 5.1, n = 0).
  const AutoMethodChoice choice = choose_beam_method({0.0, 3.0, 0.0, true, kLooseTolerance});
  EXPECT_EQ(choice.method, BeamMethod::kPrbm) << choice.reason;
  EXPECT_NE(choice.reason.find("Theta_max"), std::string::npos) << choice.reason;
  EXPECT_LE(prbm_error_against_elliptic(0.0, 3.0), kLooseTolerance);
  // n = -1 (tension), alpha2 = 2.
  EXPECT_EQ(choose_beam_method({-1.0, 2.0, 0.0, true, kLooseTolerance}).method, BeamMethod::kPrbm);
  EXPECT_LE(prbm_error_against_elliptic(-1.0, 2.0), kLooseTolerance);
}

TEST(AutoMethod, MapNeverUnderstatesTheMeasuredPrbmError) {
  // Between measured loads the map takes 1.5 times the largest neighbour; check it against the
  // exact solution on a grid four times finer than the measured one, inside the validity limits.
  for (double n = -2.0; n <= 3.0; n += 0.25) {
    const FixedPinnedSegment element(FixedPinnedConstants::from_table(n));
    const ValidityLimits limits = element.limits();
    for (double alpha2 = 0.5; alpha2 <= 20.0; alpha2 += 0.25) {
      const PrbEquilibrium eq = element.solve(EndLoad::howell(n, alpha2));
      if (std::fabs(eq.Theta) > std::min(limits.theta_max_position, limits.theta_max_force)) {
        continue;
      }
      const double map = prbm_measured_error(n, alpha2);
      ASSERT_TRUE(std::isfinite(map));
      EXPECT_GE(map, prbm_error_against_elliptic(n, alpha2)) << n << " " << alpha2;
    }
  }
  EXPECT_TRUE(std::isnan(prbm_measured_error(5.0, 1.0)));
  EXPECT_TRUE(std::isnan(prbm_measured_error(0.0, 25.0)));
  EXPECT_TRUE(std::isnan(prbm_measured_error(0.0, 0.25)));
}

TEST(AutoMethod, PicksAnExactMethodOtherwise) {
  // The default tolerance: no PRBM is that accurate.
  AutoMethodChoice c = choose_beam_method({0.0, 3.0, 0.0, true, 1e-6});
  EXPECT_EQ(c.method, BeamMethod::kElliptic);
  EXPECT_NE(c.reason.find("exceeds the tolerance"), std::string::npos) << c.reason;
  // Outside the validity limits: alpha2 = 15 at n = 0 turns the PRB link to 76 deg > 58.5 deg.
  c = choose_beam_method({0.0, 15.0, 0.0, true, 0.5});
  EXPECT_EQ(c.method, BeamMethod::kElliptic);
  EXPECT_NE(c.reason.find("validity limit"), std::string::npos) << c.reason;
  // A tip moment: the fixed-pinned element has none.
  EXPECT_EQ(choose_beam_method({0.0, 1.0, 0.5, true, 0.5}).method, BeamMethod::kElliptic);
  // Not a free cantilever (guided end, follower force, chain file): shooting.
  EXPECT_EQ(choose_beam_method({0.0, 1.0, 0.0, false, 0.5}).method, BeamMethod::kShooting);
  // An inverse problem (alpha2 not given).
  EXPECT_EQ(choose_beam_method({0.0, std::nan(""), 0.0, true, 0.5}).method, BeamMethod::kElliptic);
}

TEST(AutoMethod, RejectsANonPositiveTolerance) {
  EXPECT_THROW(choose_beam_method({0.0, 1.0, 0.0, true, 0.0}), InvalidInput);
  EXPECT_THROW(choose_beam_method({0.0, 1.0, 0.0, true, std::nan("")}), InvalidInput);
}

// A tolerance below the error of the most accurate method for the problem is refused, naming the
// smallest tolerance that can be met (issue 27: --tol 1e-16 used to pick the elliptic solver).
TEST(AutoMethod, RefusesAToleranceBelowEveryMethodsError) {
  const auto best = [](AutoMethodRequest r) {
    try {
      choose_beam_method(r);
    } catch (const ToleranceBelowReach& e) {
      EXPECT_NE(std::string(e.what()).find("below the error of every method"), std::string::npos)
          << e.what();
      return std::make_pair(e.best_tolerance(), e.best_method());
    }
    return std::make_pair(0.0, std::string("accepted"));
  };
  // Forward free cantilever: the elliptic solver, 1e-13.
  EXPECT_EQ(best({0.0, 3.0, 0.0, true, 1e-16}), std::make_pair(1e-13, std::string("elliptic")));
  // Inverse: the target tolerance 1e-10 bounds it.
  EXPECT_EQ(best({0.0, std::nan(""), 0.0, true, 1e-12}),
            std::make_pair(1e-10, std::string("elliptic")));
  // Off the free cantilever: the shooting method, measured below 1e-9.
  EXPECT_EQ(best({0.0, 1.0, 0.0, false, 1e-10}), std::make_pair(1e-9, std::string("shooting")));
  // At the bound itself the tolerance is met.
  EXPECT_EQ(best({0.0, 3.0, 0.0, true, 1e-13}).second, "accepted");
  EXPECT_EQ(best({0.0, 1.0, 0.0, false, 1e-9}).second, "accepted");
  EXPECT_EQ(choose_beam_method({0.0, 3.0, 0.0, true, 1e-13}).expected_error, 1e-13);
}

}  // namespace
}  // namespace flexure
