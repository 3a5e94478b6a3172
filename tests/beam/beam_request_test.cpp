// What is checked against what: the beam request of the front ends (beam/beam_request.h).
//  * With the command line's names, every refusal is the tool's text word for word: the expected
//    strings are the messages `flexure beam` printed before the checks moved into the library
//    (copied from cli/beam_command.cpp at the commit before the move), so the command and the
//    Python module keep their messages.
//  * With the default names no message names a flag ("--").
//  * What a request builds: the problem given by alpha2, theta0 in degrees (exact conversion) and
//    b/l, the prescribed tip, the settings, the method; an angle in radians above a full turn is a
//    units warning, not an error; a physical cantilever and a chain given whole.
//  * The warnings of an answer: a PRBM solve past its validity limit (alpha2 = 30, Theta far past
//    Howell's Theta_max) warns with kind outside_validity and points to the exact methods by the
//    caller's name; an unstable or critical verdict warns with the tool's text; a stable PRBM
//    answer inside its limits has none.
//  * The answer checks every front end makes (require_complete_answer): a converged elliptic
//    answer with the shape asked for passes; the same answer with a NaN tip, a NaN alpha2, an
//    infinite physical stress or one shape point missing is refused as NoConvergence with the
//    tool's words (copied from cli/beam_command.cpp before the check moved).
#include "flexure/beam/beam_request.h"

#include <gtest/gtest.h>

#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/elastica_integrator.h"

namespace flexure {
namespace {

std::string refusal(const BeamRequest& r, const BeamRequestNames& names) {
  try {
    make_beam_input(r, names);
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "(accepted)";
}

BeamRequest alpha2(double value) {
  BeamRequest r;
  r.alpha2 = value;
  return r;
}

// The requests that are refused, each with the tool's message.
struct Refused {
  BeamRequest request;
  std::string message;
};

std::vector<Refused> refused_requests() {
  std::vector<Refused> out;
  BeamRequest r = alpha2(1.0);
  r.tolerance = 1e-4;
  r.method = "elliptic";
  out.push_back({r,
                 "--tol is the error --method auto allows when it chooses a method; --method "
                 "elliptic works to its own tolerance, so --tol does not apply (drop it, or use "
                 "--method auto)"});
  r = alpha2(1.0);
  r.tip_x = 0.9;
  out.push_back({r, "--tip-x is not prescribed by --boundary free (it prescribes nothing)"});
  r = alpha2(1.0);
  r.boundary = "slider";
  r.tip_x = 0.9;
  out.push_back({r, "--tip-x is not prescribed by --boundary slider (it prescribes tip y)"});
  r = alpha2(1.0);
  r.elements = 4;
  r.method = "bcm";
  out.push_back(
      {r, "--elements: the BCM is one element; --method cbcm --elements N chains N of them"});
  r = alpha2(1.0);
  r.constants = "su";
  r.method = "prbm";
  out.push_back(
      {r, "--constants chooses the PR-3R model's constants; --method prbm does not use them"});
  r = alpha2(1.0);
  r.slenderness = 50.0;
  r.method = "shooting";
  out.push_back({r,
                 "--slenderness sets the axial stiffness of the BCM and CBCM (d = 12 (L/t)^2); "
                 "--method shooting does not take it (the exact methods are inextensible; a "
                 "chain segment's EA makes the shooting method extensible, docs/extensible.md)"});
  r = alpha2(1.0);
  r.slenderness = -2.0;
  r.method = "bcm";
  out.push_back(
      {r, "--slenderness L/t must be > 0 (got -2); leave it out for the inextensible beam"});
  r = alpha2(1.0);
  r.integrator = "cvodes";
  r.method = "chain";
  out.push_back(
      {r,
       "--integrator chooses the shooting method's integrator; --method chain does not use one"});
  r = alpha2(1.0);
  r.shape_points = 1;
  out.push_back(
      {r, "--shape (number of shape points) = 1 is outside the allowed range [2, 1000000]"});
  r = alpha2(1.0);
  r.increments = 0;
  out.push_back(
      {r, "--increments (load increments) = 0 is outside the allowed range [1, 1000000]"});
  r = BeamRequest{};
  out.push_back({r,
                 "one of --alpha2, --theta0 or --b-over-l is required (or --chain FILE, or a "
                 "physical beam: --length, --E, the section and --Fx, --Fy, --M)"});
  r = alpha2(1.0);
  r.physical = true;
  out.push_back({r,
                 "a physical beam (--length, --E, the section, --Fx, --Fy, --M) is loaded in "
                 "newtons; do not combine it with the nondimensional --alpha2, --theta0, "
                 "--b-over-l, --n, --mu, --follower or with --chain (a chain file can "
                 "be in SI units itself: docs/chain-toml.md)"});
  r = BeamRequest{};
  r.mu = 0.5;
  r.chain = true;
  out.push_back({r,
                 "--chain FILE.toml describes the whole problem (segments, loads, boundary); do "
                 "not combine it with --alpha2, --theta0, --b-over-l, --n, --mu, --follower or "
                 "--boundary"});
  r = BeamRequest{};
  r.b_over_l = 1.5;
  out.push_back({r, "--b-over-l (tip deflection b/l) = 1.5 is outside the allowed range [-1, 1]"});
  r = alpha2(std::numeric_limits<double>::quiet_NaN());
  out.push_back({r,
                 "--alpha2 (P l^2/EI) = nan is not allowed: it must be a finite number (not NaN "
                 "or Inf)"});
  r = alpha2(1.0);
  r.load_ratio_n = std::numeric_limits<double>::infinity();
  out.push_back({r,
                 "--n (load ratio n) = inf is not allowed: it must be a finite number (not NaN or "
                 "Inf)"});
  return out;
}

TEST(BeamRequest, RefusalsWithTheCommandLinesNamesAreTheToolsMessages) {
  for (const Refused& c : refused_requests()) {
    EXPECT_EQ(refusal(c.request, BeamRequestNames::command_line()), c.message);
  }
}

TEST(BeamRequest, RefusalsWithTheDefaultNamesNameNoFlag) {
  for (const Refused& c : refused_requests()) {
    const std::string m = refusal(c.request, BeamRequestNames{});
    EXPECT_NE(m, "(accepted)");
    EXPECT_EQ(m.find("--"), std::string::npos) << m;
  }
  BeamRequest r = alpha2(1.0);
  r.tip_y = 0.1;
  EXPECT_EQ(refusal(r, BeamRequestNames{}),
            "tip_y is not prescribed by boundary free (it prescribes nothing)");
}

TEST(BeamRequest, TwoGivenQuantitiesAreRefusedNotOneSilentlyChosen) {
  // The command line's parser refuses them first; a library or Python caller reaches this check.
  BeamRequest r = alpha2(1.0);
  r.theta0 = "0.5";
  EXPECT_EQ(refusal(r, BeamRequestNames{}),
            "at most one of alpha2, theta0 or b_over_l may be given (got alpha2 and theta0)");
  r.alpha2.reset();
  r.b_over_l = 0.1;
  EXPECT_EQ(refusal(r, BeamRequestNames::command_line()),
            "at most one of --alpha2, --theta0 or --b-over-l may be given (got --theta0 and "
            "--b-over-l)");
}

TEST(BeamRequest, BuildsTheProblemTheValuesDescribe) {
  BeamRequest r;
  r.theta0 = "30deg";
  r.load_ratio_n = 1.5;
  r.mu = -0.25;
  r.method = "shooting";
  r.integrator = "cvodes";
  r.shape_points = 11;
  const BeamInput in = make_beam_input(r);
  EXPECT_EQ(in.method, BeamMethod::kShooting);
  EXPECT_EQ(in.problem.given, BeamProblem::Given::kTheta0);
  EXPECT_EQ(in.problem.value, 30.0 * std::numbers::pi / 180.0);
  EXPECT_EQ(in.problem.load_ratio_n, 1.5);
  EXPECT_EQ(in.problem.mu, -0.25);
  EXPECT_EQ(in.problem.integrator, ElasticaIntegrator::Backend::kCvodes);
  EXPECT_EQ(in.problem.shape_points, 11);
  EXPECT_EQ(in.problem.elements, 100);
  EXPECT_EQ(in.problem.tolerance, 1e-6);
  EXPECT_TRUE(in.warnings.empty());

  BeamRequest g;
  g.alpha2 = 2.0;
  g.boundary = "fixed";
  g.tip_x = 0.9;
  g.tip_angle = "0.1";
  const BeamInput fixed = make_beam_input(g);
  EXPECT_EQ(fixed.problem.boundary, EndCondition::kFixed);
  EXPECT_EQ(fixed.problem.prescribed.x, 0.9);
  EXPECT_EQ(fixed.problem.prescribed.theta, 0.1);
  EXPECT_FALSE(fixed.problem.prescribed.y.has_value());
}

TEST(BeamRequest, AnAngleAboveAFullTurnInRadiansIsAUnitsWarning) {
  BeamRequest r;
  r.theta0 = "45";
  const BeamInput in = make_beam_input(r, BeamRequestNames::command_line());
  ASSERT_EQ(in.warnings.size(), 1u);
  EXPECT_EQ(in.warnings[0].kind, WarningKind::kUnits);
  EXPECT_EQ(in.warnings[0].text,
            "--theta0 (tip angle) = 45 rad is more than a full turn: plain angles are radians; "
            "for degrees write 45deg");
  r.theta0 = "6.2";
  EXPECT_TRUE(make_beam_input(r).warnings.empty());
}

TEST(BeamRequest, ABeamGivenWholeKeepsTheSettings) {
  BeamRequest r;
  r.physical = true;
  r.method = "chain";
  r.elements = 40;
  BeamInput in = make_beam_input(r);
  PhysicalCantilever beam;
  beam.length = 0.1;
  beam.material.E = 200e9;
  beam.section = Section::general(1e-12);
  beam.Fy = 1.0;
  add_physical_beam(in, beam);
  ASSERT_TRUE(in.physical.has_value());
  EXPECT_TRUE(in.is_physical());
  EXPECT_EQ(in.problem.elements, 40);
  // alpha2 = Fy L^2/EI of the given beam (Howell eq. 2.67).
  EXPECT_NEAR(in.problem.value, 1.0 * 0.01 / (200e9 * 1e-12), 1e-12);

  BeamRequest c;
  c.chain = true;
  BeamInput chained = make_beam_input(c);
  PhysicalChain chain;
  chain.chain = uniform_cantilever(EndLoad{0.0, 1.0, 0.0});
  chain.chain.end = EndCondition::kGuided;
  add_chain(chained, chain, false);
  EXPECT_FALSE(chained.is_physical());
  EXPECT_EQ(chained.problem.boundary, EndCondition::kGuided);
  ASSERT_TRUE(chained.problem.chain.has_value());
}

// A chain file holds its own end condition and tip: a tip flag beside it is refused naming the file
// option and the flag, not the default boundary (which used to be blamed: "--tip-y is not
// prescribed by --boundary free" for a fixed chain).
TEST(BeamRequest, ATipValueBesideAChainFileNamesTheFile) {
  BeamRequest r;
  r.chain = true;
  r.tip_y = 0.2;
  const std::string message = refusal(r, BeamRequestNames::command_line());
  EXPECT_NE(message.find("--chain FILE.toml prescribes the tip itself"), std::string::npos)
      << message;
  EXPECT_NE(message.find("--tip-y"), std::string::npos) << message;
  EXPECT_EQ(message.find("--boundary free"), std::string::npos) << message;
  r.tip_y.reset();
  r.tip_angle = "0.1";
  EXPECT_NE(refusal(r, BeamRequestNames::command_line()).find("--tip-angle"), std::string::npos);
}

TEST(BeamRequest, AnswerWarningsNameTheCallersOptions) {
  BeamProblem p;
  p.value = 30.0;
  const BeamSolution prbm = solve_beam(BeamMethod::kPrbm, p);
  ASSERT_FALSE(prbm.prbm_inside_validity);
  const std::vector<Warning> cli = beam_answer_warnings(p, prbm, BeamRequestNames::command_line());
  ASSERT_FALSE(cli.empty());
  EXPECT_EQ(cli[0].kind, WarningKind::kOutsideValidity);
  EXPECT_EQ(cli[0].text.rfind("the PRB angle Theta = ", 0), 0u) << cli[0].text;
  EXPECT_NE(cli[0].text.find("(--method elliptic or shooting is exact)"), std::string::npos);
  const std::vector<Warning> lib = beam_answer_warnings(p, prbm);
  EXPECT_NE(lib[0].text.find("(method elliptic or shooting is exact)"), std::string::npos);

  p.value = 0.5;
  const BeamSolution inside = solve_beam(BeamMethod::kPrbm, p);
  ASSERT_TRUE(inside.prbm_inside_validity);
  EXPECT_TRUE(beam_answer_warnings(p, inside).empty());

  BeamSolution unstable;
  unstable.stability.kind = StabilityKind::kUnstable;
  unstable.stability.index = 1;
  unstable.stability.margin = -0.25;
  const std::vector<Warning> u =
      beam_answer_warnings(p, unstable, BeamRequestNames::command_line());
  ASSERT_EQ(u.size(), 1u);
  EXPECT_EQ(u[0].text,
            "the returned equilibrium is UNSTABLE (index 1, stability margin -0.25): it is the "
            "equilibrium reached by proportional loading, but the beam cannot stay there under "
            "these loads and supports (a small disturbance makes it buckle or snap away); --stable "
            "returns a stable equilibrium");
  unstable.stability.kind = StabilityKind::kCritical;
  unstable.stability.margin = 1e-12;
  EXPECT_EQ(beam_answer_warnings(p, unstable)[0].text,
            "the returned equilibrium is CRITICAL (stability margin 1e-12): a buckling or limit "
            "point, where the slightest further load makes the beam buckle or snap");
}

std::string incomplete(const BeamProblem& p, const BeamSolution& s, const PhysicalResults* r) {
  try {
    require_complete_answer(p, s, r);
  } catch (const NoConvergence& e) {
    return e.what();
  }
  return "";
}

TEST(BeamRequest, AnAnswerMissingWhatWasAskedIsRefused) {
  BeamProblem p;
  p.value = 2.0;
  p.shape_points = 11;
  const BeamSolution good = solve_beam(BeamMethod::kElliptic, p);
  ASSERT_TRUE(good.converged()) << good.message;
  ASSERT_EQ(good.shape.size(), 11u);
  EXPECT_EQ(incomplete(p, good, nullptr), "");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  BeamSolution s = good;
  s.tip.b_over_l = nan;
  EXPECT_EQ(incomplete(p, s, nullptr), "b/l came out as nan; no converged solution to report");
  s = good;
  s.alpha2 = nan;
  EXPECT_EQ(incomplete(p, s, nullptr), "alpha2 came out as nan; no converged solution to report");
  s = good;
  s.shape.pop_back();
  EXPECT_EQ(incomplete(p, s, nullptr), "method 'elliptic' returned 10 shape points instead of 11");
  PhysicalResults r;
  r.max_moment = 1.0;
  r.max_stress = std::numeric_limits<double>::infinity();
  EXPECT_EQ(incomplete(p, good, &r), "max_stress came out as inf; no converged solution to report");
}

}  // namespace
}  // namespace flexure
