// What is checked against what: BeamSolver (beam/beam_problem.h), the solver object with Options,
// against the shorthand solve_beam(method, problem) it stands for.
//  * Seeded random loads x every exact method, auto and the PRBM (tip forces only): the solver's
//  answer equals solve_beam's
//    with the same settings bitwise (tip, alpha2, iterations, method, status), and Options built
//    from a problem's own settings (beam_solver_options) give the same answer again.
//  * The Options' settings reach the solve: the chain algorithm with 20 elements differs from 100,
//    and equals solve_beam with problem.elements = 20; a shape of K points has K points.
//  * validate(): every bad setting is InvalidInput naming it.
#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <string>

#include "flexure/beam/beam_problem.h"
#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

void expect_same(const BeamSolution& a, const BeamSolution& b) {
  EXPECT_EQ(a.method, b.method);
  EXPECT_EQ(a.termination, b.termination);
  EXPECT_EQ(a.iterations, b.iterations);
  EXPECT_EQ(a.alpha2, b.alpha2);
  EXPECT_EQ(a.tip.a_over_l, b.tip.a_over_l);
  EXPECT_EQ(a.tip.b_over_l, b.tip.b_over_l);
  EXPECT_EQ(a.tip.theta0, b.tip.theta0);
  EXPECT_EQ(a.shape.size(), b.shape.size());
}

TEST(BeamSolver, EqualsSolveBeamOnSeededRandomLoadsAndMethods) {
  std::mt19937 rng(20261128);
  std::uniform_real_distribution<double> n(-1.0, 2.0), alpha2(0.2, 6.0), mu(-0.5, 0.5);
  const BeamMethod methods[] = {BeamMethod::kAuto,
                                BeamMethod::kElliptic,
                                BeamMethod::kShooting,
                                BeamMethod::kChain,
                                BeamMethod::kPrbm};
  for (int i = 0; i < 8; ++i) {
    BeamProblem p;
    p.load_ratio_n = n(rng);
    p.value = alpha2(rng);
    const double end_moment = mu(rng);
    for (BeamMethod m : methods) {
      // The 1R PRBM carries a tip force or an end moment, not both.
      p.mu = m == BeamMethod::kPrbm ? 0.0 : end_moment;
      BeamSolver::Options o;
      o.method = m;
      o.elements = 50;
      p.elements = 50;
      const BeamSolution by_solver = BeamSolver(o).solve(p);
      const BeamSolution by_function = solve_beam(m, p);
      expect_same(by_solver, by_function);
      expect_same(BeamSolver(beam_solver_options(m, p)).solve(p), by_function);
    }
  }
}

TEST(BeamSolver, TheOptionsReachTheSolve) {
  BeamProblem p;
  p.value = 3.0;
  BeamSolver::Options o;
  o.method = BeamMethod::kChain;
  o.elements = 20;
  o.shape_points = 7;
  const BeamSolution coarse = BeamSolver(o).solve(p);
  ASSERT_TRUE(coarse.converged());
  EXPECT_EQ(coarse.elements, 20);
  EXPECT_EQ(coarse.shape.size(), 7u);
  p.elements = 20;
  p.shape_points = 7;
  expect_same(coarse, solve_beam(BeamMethod::kChain, p));
  o.elements = 100;
  EXPECT_NE(BeamSolver(o).solve(p).tip.a_over_l, coarse.tip.a_over_l);
}

std::string refusal(const BeamSolver::Options& o) {
  try {
    BeamSolver solver(o);
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(BeamSolver, ValidateNamesTheSetting) {
  const auto with = [](auto&& edit) {
    BeamSolver::Options o;
    edit(o);
    return refusal(o);
  };
  EXPECT_EQ(refusal(BeamSolver::Options{}), "(accepted)");
  EXPECT_NE(with([](auto& o) { o.auto_tolerance = 0.0; }).find("auto_tolerance"),
            std::string::npos);
  EXPECT_NE(with([](auto& o) {
              o.auto_tolerance = std::numeric_limits<double>::quiet_NaN();
            }).find("auto_tolerance"),
            std::string::npos);
  EXPECT_NE(with([](auto& o) { o.elements = 0; }).find("elements = 0"), std::string::npos);
  EXPECT_NE(with([](auto& o) { o.increments = -1; }).find("increments"), std::string::npos);
  EXPECT_NE(with([](auto& o) { o.shape_points = 1; }).find("shape_points"), std::string::npos);
  EXPECT_NE(with([](auto& o) { o.cbcm_elements = 0; }).find("cbcm_elements"), std::string::npos);
  EXPECT_NE(with([](auto& o) { o.slenderness = -1.0; }).find("slenderness"), std::string::npos);
  EXPECT_NE(with([](auto& o) {
              o.prbm3r_constants = static_cast<Prbm3rConstantSet>(7);
            }).find("Prbm3rConstantSet 7"),
            std::string::npos);
}

// The stored PR-3R sets by name: each name gives the set whose to_string it is, case-insensitive;
// an unknown name is refused listing the four.
TEST(BeamSolverOptions, Prbm3rConstantSetNames) {
  for (Prbm3rConstantSet set : {Prbm3rConstantSet::kSu,
                                Prbm3rConstantSet::kSuMoment,
                                Prbm3rConstantSet::kSuForce,
                                Prbm3rConstantSet::kFlexure}) {
    EXPECT_EQ(prbm3r_constant_set_from_string(to_string(set)), set);
    EXPECT_EQ(Prbm3rConstants::of(set).name, to_string(set));
  }
  EXPECT_EQ(prbm3r_constant_set_from_string("SU-Moment"), Prbm3rConstantSet::kSuMoment);
  try {
    prbm3r_constant_set_from_string("nope");
    ADD_FAILURE() << "an unknown set was accepted";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(),
                 "PR-3R constants 'nope' are unknown (allowed: su, su-moment, su-force, flexure)");
  }
}

}  // namespace
}  // namespace flexure
