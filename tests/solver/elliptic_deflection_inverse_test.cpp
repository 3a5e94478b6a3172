// What is checked against what:
// - The exact slope d(b/l)/d theta0 on the mu = 0 branch (solver/elliptic/howell_deflection.h)
//   against central differences of b/l itself, for tension and compression, small and large
//   loads: to 1e-6 relative (the differences' own truncation error is about 1e-8).
// - The b/l inverse with mu = 0 (Newton in the tip angle) against the general verified load search
//   that the solver used before (solver/common/load_search.h: alpha2 scanned geometrically on both
//   signs, Brent on each sign change, every root checked by a forward solve), which shares no code
//   with it: on 2000 seeded targets, n uniform in [-5, 10], b/l uniform in [-0.95, 0.95], both must
//   agree on whether the target is reachable, and where it is, on the load to 1e-9 relative (the
//   reference's own tolerance is 1e-13 on alpha2, but near the peak of b/l the load is
//   ill-conditioned) and on b/l to 1e-12.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <random>

#include "flexure/solver/common/load_search.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/elliptic/elliptic_solver.h"
#include "flexure/solver/elliptic/howell_deflection.h"

namespace flexure {
namespace {

TEST(EllipticDeflectionInverse, SlopeMatchesCentralDifferences) {
  for (double n : {-5.0, -1.0, 0.0, 2.0, 10.0}) {
    const double psi = std::atan2(1.0, -n);
    for (double fraction : {0.01, 0.2, 0.5, 0.8, 0.95}) {
      const double theta0 = fraction * psi;
      const elliptic::BranchDeflection d = elliptic::branch_deflection(psi, theta0);
      ASSERT_TRUE(d.slope_reliable) << "n = " << n << ", theta0 = " << theta0;
      const double h = 1e-5 * theta0;
      const double central = (elliptic::branch_deflection(psi, theta0 + h).b -
                              elliptic::branch_deflection(psi, theta0 - h).b) /
                             (2.0 * h);
      EXPECT_NEAR(d.slope, central, 1e-6 * std::max(1.0, std::fabs(central)))
          << "n = " << n << ", theta0 = " << theta0;
    }
  }
}

TEST(EllipticDeflectionInverse, ReturnsTheSmallestLoadFoundByTheGeneralSearch) {
  const EllipticSolver solver;
  std::mt19937_64 rng(20261215u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int reachable = 0;
  for (int i = 0; i < 2000; ++i) {
    const double n = -5.0 + 15.0 * unit(rng);
    const double target = -0.95 + 1.9 * unit(rng);
    auto deflection = [&](double alpha2) -> std::optional<double> {
      try {
        const EllipticResult r = solver.solve(EndLoad::howell(n, alpha2));
        if (!r.converged()) return std::nullopt;
        return r.tip.b_over_l;
      } catch (const OutsideMethodDomain&) {
        return std::nullopt;
      }
    };
    LoadSearchOptions options;
    options.max_alpha2 = EllipticSolver::kMaxForce / std::hypot(1.0, n);
    options.target_tolerance = EllipticSolver::kInverseTolerance * std::max(1.0, std::fabs(target));
    const LoadSearchResult reference = find_load_for_target(deflection, target, 0.0, options);
    SCOPED_TRACE(::testing::Message() << "n = " << n << ", b/l = " << target);
    if (!reference.found()) {
      EXPECT_THROW(solver.solve_for_deflection(n, target), InvalidInput);
      continue;
    }
    ++reachable;
    const EllipticResult r = solver.solve_for_deflection(n, target);
    ASSERT_TRUE(r.converged()) << r.message;
    EXPECT_NEAR(r.load.Fy, reference.alpha2, 1e-9 * std::fabs(reference.alpha2));
    EXPECT_NEAR(r.tip.b_over_l, target, 1e-12);
  }
  EXPECT_GT(reachable, 1000);  // the grid exercises the inverse, not only its refusals
}

}  // namespace
}  // namespace flexure
