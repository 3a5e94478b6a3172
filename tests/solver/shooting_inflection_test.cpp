// What is checked against what: the inflection points of a shooting solution counted from the
// moment along the integrator's own steps (solver/shooting/inflection_count.h, no sampled shape)
// against
//  * the count on a shape of 401 points (the sign changes of theta's increments, the count the
//    beam command used before), and
//  * the elliptic solver's count of the same load (Howell's branch, an independent method),
// on seeded random loads with end moments (0, 1 and 2 inflection points occur); and the CVODES
// backend, which shows no steps, falls back to the shape's count.
#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "flexure/solver/elliptic/elliptic_solver.h"
#include "flexure/solver/shooting/inflection_count.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {
namespace {

int shape_count(const ShootingResult& r) {
  std::vector<double> increments;
  for (std::size_t i = 1; i < r.shape.size(); ++i) {
    increments.push_back(r.shape[i].theta - r.shape[i - 1].theta);
  }
  return sign_changes(increments, 1e-12);
}

TEST(ShootingInflections, CountFromTheStepsEqualsTheShapeAndTheEllipticCount) {
  std::mt19937_64 rng(27004);
  std::uniform_real_distribution<double> n(-5.0, 15.0), alpha2(0.0, 20.0), unit(0.0, 1.0);
  ShootingSolver::Options counted;
  counted.count_inflections = true;
  ShootingSolver::Options sampled;
  sampled.shape_points = 401;
  int seen[3] = {0, 0, 0};
  for (int i = 0; i < 120; ++i) {
    const double nn = n(rng), a = alpha2(rng);
    const double mu = unit(rng) < 0.25 ? 0.0 : (2.0 * unit(rng) - 1.0) * 2.0 * std::numbers::pi;
    const EndLoad load = EndLoad::howell(nn, a, mu);
    SCOPED_TRACE(::testing::Message() << "n = " << nn << ", alpha2 = " << a << ", mu = " << mu);
    const ShootingResult c = ShootingSolver(counted).solve(load);
    const ShootingResult s = ShootingSolver(sampled).solve(load);
    const EllipticResult e = EllipticSolver().solve(load);
    ASSERT_TRUE(c.converged()) << c.message;
    ASSERT_TRUE(s.converged()) << s.message;
    EXPECT_EQ(c.inflection_points, shape_count(s));
    if (e.converged()) EXPECT_EQ(c.inflection_points, e.inflection_points);
    if (c.inflection_points >= 0 && c.inflection_points < 3) ++seen[c.inflection_points];
  }
  EXPECT_GT(seen[0], 10);
  EXPECT_GT(seen[1], 10);
}

TEST(ShootingInflections, CvodesFallsBackToTheShapeCount) {
  ShootingSolver::Options o;
  o.count_inflections = true;
  o.backend = ElasticaIntegrator::Backend::kCvodes;
  // An end moment against the force: one inflection point (the moment changes sign once).
  const ShootingResult r = ShootingSolver(o).solve(EndLoad::howell(0.0, 4.0, -2.0));
  ASSERT_TRUE(r.converged()) << r.message;
  EXPECT_EQ(r.inflection_points,
            EllipticSolver().solve(EndLoad::howell(0.0, 4.0, -2.0)).inflection_points);
  EXPECT_EQ(r.inflection_points, 1);
}

}  // namespace
}  // namespace flexure
