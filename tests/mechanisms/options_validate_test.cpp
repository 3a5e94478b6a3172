// What is checked: every solver's Options has a public validate() that refuses a field outside its
// range with InvalidInput naming that field, accepts the defaults, and is applied by the solver
// (constructing or running with bad options fails the same way).
#include <gtest/gtest.h>

#include <string>

#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/dynamics/dynamics.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/mechanisms/mechanism_exact.h"
#include "flexure/solver/chain/chain_algorithm_solver.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/elliptic/elliptic_solver.h"
#include "flexure/solver/ode/ode_integrator.h"
#include "flexure/solver/shooting/elastica_integrator.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {
namespace {

// Runs `f`, expects InvalidInput whose message names `field`.
template <class F>
void expect_refused(F f, const std::string& field) {
  try {
    f();
    ADD_FAILURE() << "no InvalidInput for a bad " << field;
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos)
        << "message does not name " << field << ": " << e.what();
  }
}

TEST(OptionsValidate, DefaultsAreValid) {
  EXPECT_NO_THROW(EllipticSolver::Options{}.validate());
  EXPECT_NO_THROW(ShootingSolver::Options{}.validate());
  EXPECT_NO_THROW(ChainAlgorithmSolver::Options{}.validate());
  EXPECT_NO_THROW(ElasticaIntegrator::Options{}.validate());
  EXPECT_NO_THROW(OdeIntegrator::Options{}.validate());
  EXPECT_NO_THROW(mechanism::ExactMechanismSolver::Options{}.validate());
  EXPECT_NO_THROW(cfm::CfmOptions{}.validate());
  EXPECT_NO_THROW(cfm::CfmExactOptions{}.validate());
  EXPECT_NO_THROW(dynamics::ForwardOptions{}.validate());
  EXPECT_NO_THROW(dynamics::InverseDynamicsOptions{}.validate());
  EXPECT_NO_THROW(mechanism::AnalysisOptions{}.validate());
}

TEST(OptionsValidate, BeamSolversNameTheBadField) {
  EllipticSolver::Options e;
  e.tolerance = -1.0;
  expect_refused([&] { e.validate(); }, "tolerance");
  expect_refused([&] { EllipticSolver solver(e); }, "tolerance");
  e = {};
  e.max_continuation_steps = 0;
  expect_refused([&] { e.validate(); }, "max_continuation_steps");

  ShootingSolver::Options s;
  s.rtol = 0.5;
  expect_refused([&] { s.validate(); }, "rtol");
  expect_refused([&] { solve_shooting(uniform_cantilever(EndLoad::howell(0, 1, 0)), s); }, "rtol");
  s = {};
  s.shape_points = -3;
  expect_refused([&] { s.validate(); }, "shape_points");

  ChainAlgorithmSolver::Options c;
  c.elements = 0;
  expect_refused([&] { c.validate(); }, "elements");
  c = {};
  c.anderson_depth = 99;
  expect_refused([&] { c.validate(); }, "anderson_depth");

  ElasticaIntegrator::Options i;
  i.max_steps = 0;
  expect_refused([&] { i.validate(); }, "max_steps");
}

TEST(OptionsValidate, MechanismSolversNameTheBadField) {
  mechanism::ExactMechanismSolver::Options x;
  x.position_tolerance = 0.0;
  expect_refused([&] { x.validate(); }, "position_tolerance");
  x = {};
  x.max_newton_iterations = 0;
  expect_refused([&] { x.validate(); }, "max_newton_iterations");
  x = {};
  x.shooting.atol = -1.0;  // nested options are validated too
  expect_refused([&] { x.validate(); }, "atol");

  cfm::CfmOptions cfm;
  cfm.sampling = cfm::StrokeSampling::kUniform;
  cfm.points = 0;
  expect_refused([&] { cfm.validate(); }, "points");
  expect_refused([&] { cfm::CfmModel model(cfm); }, "points");

  cfm::CfmExactOptions exact;
  exact.points = 1;
  expect_refused([&] { exact.validate(); }, "points");

  dynamics::ForwardOptions f;
  f.friction_sign_velocity = 0.0;
  expect_refused([&] { f.validate(); }, "friction_sign_velocity");

  dynamics::InverseDynamicsOptions inv;
  inv.samples_per_period = 7;
  expect_refused([&] { inv.validate(); }, "samples_per_period");

  mechanism::AnalysisOptions a;
  a.points = 1;
  expect_refused([&] { a.validate(); }, "points");
}

}  // namespace
}  // namespace flexure
