// What is checked against what (command line: `beam --method shooting|chain`, boundaries,
// `--chain FILE.toml`, `path`):
// - shooting and chain tips for Howell's worked example (§2.9.2) against its exact values
//   (eqs. 2.90-2.98 recomputed: a/l = 0.7383564, b/l = 0.6103718 at alpha2 = 3.0870030);
// - `--boundary guided --alpha2 8` against the antisymmetry relation: two elliptic cantilevers of
//   length l/2 with the same end load (EllipticSolver, alpha2_half = 8/4);
// - root reactions against statics (the clamp holds -F and -M(0));
// - the TOML example chains: shooting and chain algorithm agree; unknown keys name key and line;
// - `path` writes the documented datasets and passes the limit points the elliptic solver reports;
// - invalid combinations exit 2.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "flexure/solver/elliptic/elliptic_solver.h"
#include "tests/support/cli_test_support.h"

namespace flexure {
namespace {

using test::run_flexure;
using Json = nlohmann::json;

Json run_json(const std::string& args) {
  const test::CommandResult r = run_flexure(args + " --json");
  EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
  return Json::parse(r.out);
}

TEST(CliMethods, ShootingAndChainReproduceHowellsWorkedExample) {
  constexpr double kHalfUnit = 5e-8;  // the reference is printed to 7 decimals
  const Json shooting = run_json("beam --alpha2 3.0870030 --method shooting");
  EXPECT_EQ(shooting["method"], "shooting");
  EXPECT_NEAR(shooting["a_over_l"].get<double>(), 0.7383564, kHalfUnit);
  EXPECT_NEAR(shooting["b_over_l"].get<double>(), 0.6103718, kHalfUnit);
  EXPECT_NEAR(shooting["theta0"].get<double>(), 1.0, 1e-7);
  // Chain algorithm, N = 100, corrected variant: third-order error ~1e-6 (docs/theory-chain.md).
  const Json chain = run_json("beam --alpha2 3.0870030 --method chain --elements 100");
  EXPECT_EQ(chain["elements"], 100);
  EXPECT_GE(chain["increments"].get<int>(), 1);
  EXPECT_NEAR(chain["a_over_l"].get<double>(), 0.7383564, 1e-5);
  EXPECT_NEAR(chain["b_over_l"].get<double>(), 0.6103718, 1e-5);
  // Statics: the clamp holds the tip force and the root moment.
  EXPECT_NEAR(shooting["reactions"]["Fy"].get<double>(), -3.0870030, 1e-12);
  EXPECT_NEAR(shooting["reactions"]["M"].get<double>(),
              -3.0870030 * shooting["a_over_l"].get<double>(),
              1e-8);
}

TEST(CliMethods, GuidedBeamMatchesTwoHalfCantilevers) {
  // A guided beam of length l under transverse load P is antisymmetric about its midpoint: two
  // cantilevers of length l/2 with end load P, i.e. alpha2_half = P (l/2)^2/EI = 8/4 = 2.
  const EllipticSolver elliptic;
  const EllipticResult half = elliptic.solve(EndLoad::howell(0.0, 2.0));
  for (const char* method : {"shooting", "chain --elements 200"}) {
    const Json guided =
        run_json(std::string("beam --boundary guided --alpha2 8 --method ") + method);
    const double tol = std::string(method) == "shooting" ? 1e-9 : 1e-6;
    EXPECT_NEAR(guided["a_over_l"].get<double>(), half.tip.a_over_l, tol) << method;
    EXPECT_NEAR(guided["b_over_l"].get<double>(), half.tip.b_over_l, tol) << method;
    EXPECT_NEAR(guided["theta0"].get<double>(), 0.0, 1e-9) << method;
    EXPECT_EQ(guided["boundary"], "guided");
    // Root moment = P l/2 * (a_half) ... = alpha2 * a/2 by antisymmetry (Howell eq. 5.102).
    EXPECT_NEAR(-guided["reactions"]["M"].get<double>(), 8.0 * half.tip.a_over_l / 2.0, 10 * tol);
  }
}

TEST(CliMethods, ShootingIntegratorIsSelectable) {
  // Howell's worked example (7 decimals) by both integrators; they agree with each other to 1e-9.
  const Json cvodes = run_json("beam --alpha2 3.0870030 --method shooting --integrator cvodes");
  const Json rk = run_json("beam --alpha2 3.0870030 --method shooting --integrator dormand-prince");
  for (const Json* j : {&cvodes, &rk}) {
    EXPECT_NEAR((*j)["a_over_l"].get<double>(), 0.7383564, 5e-8);
    EXPECT_NEAR((*j)["b_over_l"].get<double>(), 0.6103718, 5e-8);
  }
  EXPECT_NEAR(cvodes["b_over_l"].get<double>(), rk["b_over_l"].get<double>(), 1e-9);
  EXPECT_NE(run_flexure("beam --help").out.find("--integrator"), std::string::npos);
  const test::CommandResult refused =
      run_flexure("beam --alpha2 3 --method elliptic --integrator cvodes");
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("--method elliptic does not use one"), std::string::npos)
      << refused.err;
}

TEST(CliMethods, ChainKeysMeanWhatTheirNamesSay) {
  test::ScratchDir dir;
  // A strip in SI units: l = 0.05 m, EI = 0.02083 N m^2, Fx = -2.5 N, Fy = 4.33 N. Howell's
  // parameters (eqs. 2.67, 2.83): alpha2 = Fy l^2/EI = 0.51968, n = -Fx/Fy = 0.57737.
  std::ofstream(dir / "strip.toml") << "boundary = \"free\"\n[[segment]]\ntype = \"flexible\"\n"
                                       "length = 0.05\nEI = 0.02083\n[tip_load]\nFx = -2.5\n"
                                       "Fy = 4.33\n";
  const Json strip = run_json("beam --chain '" + (dir / "strip.toml").string() + "'");
  EXPECT_NEAR(strip["alpha2"].get<double>(), 4.33 * 0.05 * 0.05 / 0.02083, 1e-12);
  EXPECT_NEAR(strip["n"].get<double>(), 2.5 / 4.33, 1e-12);
  // The same beam nondimensionally: every Howell quantity agrees.
  const Json howell = run_json(fmt::format("beam --method shooting --n {:.17g} --alpha2 {:.17g}",
                                           2.5 / 4.33,
                                           4.33 * 0.05 * 0.05 / 0.02083));
  for (const char* key : {"a_over_l", "b_over_l", "theta0", "root_moment"}) {
    EXPECT_NEAR(strip[key].get<double>(), howell[key].get<double>(), 1e-9) << key;
  }
  EXPECT_NEAR(strip["reactions"]["M"].get<double>(), howell["reactions"]["M"].get<double>(), 1e-9);
  // In the file's units: M(0) = root_moment EI/l, N m.
  EXPECT_NEAR(strip["root_moment_chain_units"].get<double>(),
              howell["root_moment"].get<double>() * 0.02083 / 0.05,
              1e-9);
  EXPECT_EQ(strip["tip_load_chain_units"]["Fy"].get<double>(), 4.33);
  // Two flexures and a rigid link have no single alpha2: null, never the raw force.
  const Json two = run_json("beam --chain " + std::string(FLEXURE_SOURCE_DIR) +
                            "/docs/examples/two_flexures_rigid_link.toml");
  EXPECT_TRUE(two["alpha2"].is_null());
  EXPECT_TRUE(two["root_moment"].is_null());
  EXPECT_EQ(two["tip_load_chain_units"]["Fy"].get<double>(), 2.0);
  const test::CommandResult text = run_flexure("beam --chain " + std::string(FLEXURE_SOURCE_DIR) +
                                               "/docs/examples/two_flexures_rigid_link.toml");
  EXPECT_EQ(text.out.find("alpha2 = P l^2/EI"), std::string::npos) << text.out;
}

TEST(CliMethods, PrbmSolvesTheGuidedBeamAsBenchDoes) {
  // One PRBM dispatch for beam, bench and auto (elements/prbm_cantilever.h): the fixed-guided
  // segment of Howell §5.3 is two fixed-pinned halves, so its tip under alpha2 = 8 is the
  // fixed-pinned PRBM's tip under alpha2 = 2.
  const Json guided = run_json("beam --boundary guided --alpha2 8 --method prbm");
  const Json half = run_json("beam --alpha2 2 --method prbm");
  EXPECT_EQ(guided["method"], "prbm");
  EXPECT_EQ(guided["termination"], "converged");
  EXPECT_NE(guided["branch"].get<std::string>().find("fixed-guided"), std::string::npos);
  EXPECT_NEAR(guided["a_over_l"].get<double>(), half["a_over_l"].get<double>(), 1e-10);
  EXPECT_NEAR(guided["b_over_l"].get<double>(), half["b_over_l"].get<double>(), 1e-10);
  EXPECT_EQ(guided["theta0"].get<double>(), 0.0);
  // Ends no PRBM element models are refused with exit 2.
  EXPECT_EQ(run_flexure("beam --boundary pinned --alpha2 0 --tip-x 0.9 --method prbm").exit_code,
            2);
}

TEST(CliMethods, AutoPicksEllipticForTheFreeCantileverAndShootingOtherwise) {
  EXPECT_EQ(run_json("beam --alpha2 2")["method"], "elliptic");
  EXPECT_EQ(run_json("beam --alpha2 2 --boundary guided")["method"], "shooting");
}

TEST(CliMethods, InverseProblemsWithShooting) {
  // theta0 = 1 rad, n = 0 -> alpha2 = 3.0870030 (Howell §2.9.2 example, recomputed).
  const Json r = run_json("beam --theta0 1 --method shooting");
  EXPECT_NEAR(r["alpha2"].get<double>(), 3.0870030, 5e-7);
}

TEST(CliMethods, TomlChainsAgreeBetweenShootingAndChain) {
  for (const char* file : {"two_flexures_rigid_link.toml", "curved_tapered_cantilever.toml"}) {
    const std::string path = std::string(FLEXURE_SOURCE_DIR) + "/docs/examples/" + file;
    const Json shooting = run_json("beam --chain " + path + " --method shooting");
    const Json chain = run_json("beam --chain " + path + " --method chain --elements 200");
    EXPECT_NEAR(shooting["a_over_l"].get<double>(), chain["a_over_l"].get<double>(), 1e-6) << file;
    EXPECT_NEAR(shooting["b_over_l"].get<double>(), chain["b_over_l"].get<double>(), 1e-6) << file;
    EXPECT_NEAR(shooting["theta0"].get<double>(), chain["theta0"].get<double>(), 1e-6) << file;
  }
  // The guided example equals the command-line guided beam.
  const Json file_guided = run_json(std::string("beam --method shooting --chain ") +
                                    FLEXURE_SOURCE_DIR + "/docs/examples/fixed_guided_beam.toml");
  const Json flag_guided = run_json("beam --method shooting --boundary guided --alpha2 8");
  EXPECT_NEAR(file_guided["b_over_l"].get<double>(), flag_guided["b_over_l"].get<double>(), 1e-12);
}

TEST(CliMethods, TomlErrorsNameTheKeyAndLine) {
  test::ScratchDir dir;
  {
    std::ofstream f(dir / "typo.toml");
    f << "boundary = \"free\"\n[[segment]]\ntype = \"flexible\"\nlenght = 1.0\n";
  }
  test::CommandResult r = run_flexure("beam --chain " + (dir / "typo.toml").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("typo.toml:4"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("lenght"), std::string::npos) << r.err;
  {
    std::ofstream f(dir / "missing.toml");
    f << "[[segment]]\ntype = \"rigid\"\n";
  }
  r = run_flexure("beam --chain " + (dir / "missing.toml").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("'length'"), std::string::npos) << r.err;
  {
    std::ofstream f(dir / "negative.toml");
    f << "[[segment]]\ntype = \"flexible\"\nlength = -1\n";
  }
  r = run_flexure("beam --chain " + (dir / "negative.toml").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("length"), std::string::npos) << r.err;
  r = run_flexure("beam --chain " + (dir / "absent.toml").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("cannot read --chain file"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("absent.toml"), std::string::npos) << r.err;
}

TEST(CliMethods, PathFollowsLimitPointsTheEllipticSolverReports) {
  // alpha2 = 10, mu = -2 pi: the path folds near lambda = 0.5958. The elliptic solver follows it
  // through the fold and reports it; `flexure path` (shooting continuation) records every point
  // and ends where the elliptic solver does.
  const Json elliptic = run_json("beam --method elliptic --alpha2 10 --mu -6.283185307179586");
  EXPECT_TRUE(elliptic["converged"].get<bool>());
  EXPECT_GE(elliptic["limit_points"].get<int>(), 1);
  EXPECT_NEAR(elliptic["first_limit_load_factor"].get<double>(), 0.5958, 1e-3);
  test::ScratchDir dir;
  const std::string out = (dir / "path.h5").string();
  const Json summary = run_json("path --alpha2 10 --mu -6.283185307179586 --out " + out);
  EXPECT_TRUE(summary["completed"].get<bool>());
  EXPECT_GE(summary["limit_points"].get<int>(), 1);
  const hid_t file = test::open_read_only(out);
  const std::vector<double> lambda = test::read_doubles(file, "load_factor");
  const std::vector<int> status = test::read_ints(file, "status");
  const std::vector<double> x = test::read_doubles(file, "tip_x");
  H5Fclose(file);
  ASSERT_GE(lambda.size(), 3u);
  EXPECT_EQ(lambda.front(), 0.0);
  EXPECT_NEAR(lambda.back(), 1.0, 1e-12);
  EXPECT_NEAR(x.front(), 1.0, 1e-12);  // the unloaded tip
  EXPECT_NEAR(x.back(), elliptic["a_over_l"].get<double>(), 1e-9);
  EXPECT_EQ(status.size(), lambda.size());
  // The load factor rises, turns back at a limit point, and rises again.
  bool decreased = false;
  for (std::size_t i = 1; i < lambda.size(); ++i) decreased |= lambda[i] < lambda[i - 1];
  EXPECT_TRUE(decreased);
}

TEST(CliMethods, InvalidCombinationsExitTwo) {
  // Each refusal is for its own reason: exit 2 and key words of that reason on stderr.
  const struct {
    const char* args;
    std::vector<std::string> reason;
  } cases[] = {
      {"beam --alpha2 1 --method elliptic --boundary guided",
       {"elliptic method solves the uniform cantilever with a free end", "shooting or chain"}},
      // A free end prescribes nothing.
      {"beam --alpha2 1 --tip-x 0.9", {"--tip-x is not prescribed by --boundary free"}},
      {"beam --alpha2 1 --boundary slider --method shooting",
       {"slider end prescribes the tip y", "alpha2 must be 0"}},
      {"beam --alpha2 1 --method chain --elements 0", {"--elements", "= 0 is outside"}},
      {"beam --alpha2 1 --boundary sideways", {"--boundary", "sideways not in"}},
      {"beam", {"one of --alpha2, --theta0 or --b-over-l is required"}},
      {"path --alpha2 1 --out /nonexistent/dir/p.h5",
       {"--out", "directory '/nonexistent/dir' does not exist"}},
  };
  for (const auto& c : cases) {
    const test::CommandResult r = run_flexure(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args;
    for (const std::string& word : c.reason) {
      EXPECT_NE(r.err.find(word), std::string::npos) << c.args << ": " << r.err;
    }
  }
}

TEST(CliMethods, ShootingBranchSaysWhichPathWasTaken) {
  // A straight beam with both tip coordinates prescribed starts at a bifurcation, so the shooting
  // solver continues in two stages (docs/theory-shooting.md); `branch` used to say "direct Newton"
  // because the tool compared the solver's method text.
  const auto two_stage =
      run_json("beam --method shooting --boundary pinned --mu 1 --alpha2 0 --tip-x 0.95");
  ASSERT_EQ(two_stage["converged"], true) << two_stage.dump();
  EXPECT_NE(two_stage["branch"].get<std::string>().find("two-stage"), std::string::npos)
      << two_stage.dump();
  // A small load on a free cantilever is provably unique: direct Newton.
  const auto direct = run_json("beam --method shooting --alpha2 0.5");
  EXPECT_NE(direct["branch"].get<std::string>().find("direct Newton"), std::string::npos)
      << direct.dump();
}

}  // namespace
}  // namespace flexure
