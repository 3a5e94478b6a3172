// `flexure beam` and `flexure sweep beam` report the stability of every answer (issue 27; keys
// `stability`, `stability_index`, `stability_margin`, `stability_message`, `stable_search`,
// `warnings`; docs/cli.md), run as a process. Each verdict is recomputed here independently of
// the tool:
//  * the straight column (a physical beam L = 1 m, EI = 1 N m^2, Fx = -3 N or -30 N): margin
//    1 - 4P/pi^2 and index 1 (P = 3), 2 (P = 30) in closed form (critical loads
//    ((2k - 1) pi / 2)^2 = 2.47, 22.2, 61.7);
//  * the clamped-clamped beam of the issue (tip at (0.9, 0.001), angle 0 or 0.01): the verdict of
//    the continuous Jacobi count (JacobiSecondVariation, which integrates its own elastica from
//    the reactions the tool prints) against the tool's discrete one;
//  * --stable: the clamped-clamped beam returns its first mode (the perfect beam's 16 K(k)^2 with
//    2 E(k)/K(k) - 1 = 0.9, within the 0.001 offset's 1e-4), stable by the Jacobi count; the
//    column returns the buckled cantilever (P L^2/EI = K(k)^2, k = sin(theta0/2): tip angle to
//    1e-8); a critical column (P = pi^2/4 exactly) has no strictly stable equilibrium: exit 3;
//  * the sweep's /stability_margin against the Jacobi count with the elliptic closed form's
//    root moment (margins to 1e-6, the sweep's margin accuracy).
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "flexure/solver/chain_model/jacobi_stability.h"
#include "flexure/solver/elliptic/elliptic_solver.h"
#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

using nlohmann::json;
constexpr double kPi = std::numbers::pi;

// Runs with --json; exit code 0 and one JSON object expected (warnings on stderr allowed).
json run_json(const std::string& args, int expected_exit = 0) {
  const CommandResult r = run_flexure(args + " --json");
  EXPECT_EQ(r.exit_code, expected_exit) << args << "\nstderr: " << r.err;
  EXPECT_EQ(count_lines(r.out), 1) << "exactly one JSON object on one line: " << r.out;
  return json::parse(r.out);
}

void expect_stability_keys(const json& j) {
  for (const char* key :
       {"stability", "stability_index", "stability_margin", "stability_message", "warnings"}) {
    EXPECT_TRUE(j.contains(key)) << "missing key " << key << " in " << j.dump();
  }
}

const char* kColumn = "beam --length 1 --E 1 --I 1";

TEST(CliBeamStability, StraightColumnIsUnstableWithTheClosedFormMargin) {
  for (const std::string method : {"auto", "shooting"}) {
    for (const double P : {3.0, 30.0}) {
      const std::string args =
          std::string(kColumn) + " --Fx -" + std::to_string(P) + " --method " + method;
      const json j = run_json(args);
      expect_stability_keys(j);
      EXPECT_EQ(j["method"], "shooting");
      EXPECT_EQ(j["converged"], true);
      EXPECT_EQ(j["stability"], "unstable") << args;
      EXPECT_EQ(j["stability_index"], P < 22.0 ? 1 : 2) << args;
      EXPECT_NEAR(j["stability_margin"].get<double>(), 1.0 - 4.0 * P / (kPi * kPi), 1e-8) << args;
      EXPECT_TRUE(j["stable_search"].is_null());
      ASSERT_EQ(j["warnings"].size(), 1u) << j["warnings"].dump();
      EXPECT_NE(j["warnings"][0].get<std::string>().find("UNSTABLE"), std::string::npos);
    }
  }
}

TEST(CliBeamStability, UnstableAnswerExitsZeroWithAWarningInTheTextOutput) {
  const CommandResult r = run_flexure(std::string(kColumn) + " --Fx -3");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("stability: unstable, index 1, stability margin -0.21585"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.err.find("warning: the returned equilibrium is UNSTABLE"), std::string::npos)
      << r.err;
  const CommandResult stable = run_flexure("beam --alpha2 1");
  EXPECT_NE(stable.out.find("stability: stable, index 0"), std::string::npos) << stable.out;
  EXPECT_TRUE(stable.err.empty()) << stable.err;
}

TEST(CliBeamStability, ChainRefusesTheUnstableColumnAndSaysWhy) {
  const CommandResult r = run_flexure(std::string(kColumn) + " --Fx -3 --method chain --json");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["exit_code"], 3);
  EXPECT_EQ(j["stability"], "unstable");
  EXPECT_EQ(j["stability_index"], 1);
  EXPECT_NEAR(j["stability_margin"].get<double>(), 1.0 - 12.0 / (kPi * kPi), 1e-3);
  EXPECT_NE(j["error"].get<std::string>().find("unstable equilibrium"), std::string::npos);
}

// The clamped-clamped beam of the issue with its reactions checked by the Jacobi count.
SegmentChain clamped_clamped(double tip_angle) {
  SegmentChain chain = uniform_cantilever(EndLoad{});
  chain.end = EndCondition::kFixed;
  chain.prescribed = {0.9, 0.001, tip_angle};
  return chain;
}

Stability jacobi_of(const SegmentChain& chain, const json& j) {
  const Reaction clamp{j["reactions"]["Fx"].get<double>(),
                       j["reactions"]["Fy"].get<double>(),
                       j["reactions"]["M"].get<double>()};
  return JacobiSecondVariation(chain, clamp).verdict();
}

const char* kClamped = "beam --boundary fixed --alpha2 0 --tip-x 0.9 --tip-y 0.001";

TEST(CliBeamStability, ClampedClampedModesAreJudgedLikeTheJacobiCount) {
  const json second = run_json(std::string(kClamped) + " --tip-angle 0");
  expect_stability_keys(second);
  EXPECT_NEAR(second["reactions"]["Fx"].get<double>(), 83.75, 0.01);  // the antisymmetric mode
  EXPECT_EQ(second["stability"], "unstable");
  EXPECT_EQ(second["stability_index"], 1);
  const Stability j2 = jacobi_of(clamped_clamped(0.0), second);
  EXPECT_EQ(j2.index, 1);
  EXPECT_NEAR(second["stability_margin"].get<double>(), j2.margin, 1e-8);

  const json first = run_json(std::string(kClamped) + " --tip-angle 0.01");
  EXPECT_NEAR(first["reactions"]["Fx"].get<double>(), 41.36, 0.01);
  EXPECT_EQ(first["stability"], "stable");
  EXPECT_EQ(first["stability_index"], 0);
  EXPECT_TRUE(first["warnings"].empty());
  const Stability j1 = jacobi_of(clamped_clamped(0.01), first);
  EXPECT_EQ(j1.kind, StabilityKind::kStable);
  EXPECT_NEAR(first["stability_margin"].get<double>(), j1.margin, 1e-8);
}

TEST(CliBeamStability, StableGivesTheClampedClampedFirstMode) {
  const json j = run_json(std::string(kClamped) + " --tip-angle 0 --stable");
  expect_stability_keys(j);
  EXPECT_EQ(j["stability"], "stable");
  EXPECT_EQ(j["method"], "shooting");
  EXPECT_NE(j["stable_search"].get<std::string>().find("unstable (index 1"), std::string::npos)
      << j["stable_search"];
  EXPECT_NE(j["method_reason"].get<std::string>().find("stable equilibrium"), std::string::npos);
  double lo = 1e-9, hi = 0.999;  // 2 E(k)/K(k) - 1 = 0.9
  for (int i = 0; i < 200; ++i) {
    const double k = 0.5 * (lo + hi);
    (2.0 * std::comp_ellint_2(k) / std::comp_ellint_1(k) - 1.0 > 0.9 ? lo : hi) = k;
  }
  const double K = std::comp_ellint_1(0.5 * (lo + hi));
  EXPECT_NEAR(j["reactions"]["Fx"].get<double>(), 16.0 * K * K, 1e-4 * 16.0 * K * K);
  EXPECT_NEAR(j["a_over_l"].get<double>(), 0.9, 1e-10);
  EXPECT_NEAR(j["b_over_l"].get<double>(), 0.001, 1e-10);
  const Stability jacobi = jacobi_of(clamped_clamped(0.0), j);
  EXPECT_EQ(jacobi.kind, StabilityKind::kStable) << jacobi.message;
  EXPECT_NEAR(j["stability_margin"].get<double>(), jacobi.margin, 1e-8);
  // Already stable: nothing to do.
  const json kept = run_json(std::string(kClamped) + " --tip-angle 0.01 --stable");
  EXPECT_EQ(kept["stable_search"].get<std::string>().rfind("not needed", 0), 0u);
  EXPECT_NEAR(kept["reactions"]["Fx"].get<double>(), 41.36, 0.01);
}

TEST(CliBeamStability, StableGivesTheBuckledCantilever) {
  for (const std::string method : {"auto", "chain"}) {
    const json j = run_json(std::string(kColumn) + " --Fx -3 --stable --method " + method);
    EXPECT_EQ(j["stability"], "stable");
    EXPECT_TRUE(j["warnings"].empty()) << j["warnings"].dump();
    double lo = 0.0, hi = 1.0 - 1e-15;  // P L^2/EI = 3 = K(k)^2
    for (int i = 0; i < 200; ++i) {
      const double k = 0.5 * (lo + hi), K = std::comp_ellint_1(k);
      (K * K < 3.0 ? lo : hi) = k;
    }
    const double k = 0.5 * (lo + hi);
    EXPECT_NEAR(std::fabs(j["theta0"].get<double>()), 2.0 * std::asin(k), 1e-8) << method;
    EXPECT_NEAR(
        j["tip_x"].get<double>(), 2.0 * std::comp_ellint_2(k) / std::comp_ellint_1(k) - 1.0, 1e-8);
  }
}

TEST(CliBeamStability, StableFailsWithExitThreeOrRefusesBadRequests) {
  // Exactly at the Euler load the straight column is critical and the buckled branch only starts.
  const CommandResult critical =
      run_flexure(std::string(kColumn) + " --Fx -2.4674011002723395 --stable --json");
  EXPECT_EQ(critical.exit_code, 3) << critical.err;
  const json j = json::parse(critical.out);
  EXPECT_EQ(j["stability"], "critical");
  EXPECT_NE(j["error"].get<std::string>().find("no stable equilibrium found"), std::string::npos)
      << j["error"];
  for (const std::string args : {"beam --theta0 0.5 --stable",
                                 "beam --alpha2 1 --follower 1 "
                                 "--stable"}) {
    const CommandResult r = run_flexure(args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find("stable equilibrium"), std::string::npos) << r.err;
  }
}

TEST(CliBeamStability, FollowerForceIsNotConservative) {
  const json j = run_json("beam --alpha2 0 --follower 2 --method shooting");
  EXPECT_EQ(j["stability"], "not_conservative");
  EXPECT_TRUE(j["stability_index"].is_null());
  EXPECT_TRUE(j["stability_margin"].is_null());
}

TEST(CliSweepStability, StoredVerdictsAgreeWithTheJacobiCount) {
  ScratchDir dir;
  const auto path = dir / "sweep.h5";
  const CommandResult r =
      run_flexure("sweep beam --alpha2 0:12:7 --n 2 --out '" + path.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const hid_t file = open_read_only(path);
  ASSERT_GE(file, 0);
  const std::vector<double> alpha2 = read_doubles(file, "alpha2");
  const std::vector<double> margin = read_doubles(file, "stability_margin");
  const std::vector<int> code = read_ints(file, "stability");
  const std::vector<int> index = read_ints(file, "stability_index");
  const std::string meanings = read_string_attribute(file, "/", "status_meanings");
  H5Fclose(file);
  EXPECT_NE(meanings.find("not_conservative"), std::string::npos) << meanings;
  ASSERT_EQ(margin.size(), 7u);
  for (std::size_t i = 0; i < alpha2.size(); ++i) {
    const EndLoad load = EndLoad::howell(2.0, alpha2[i], 0.0);
    const EllipticResult e = EllipticSolver().solve(load);
    const Stability j = JacobiSecondVariation(uniform_cantilever(load),
                                              Reaction{-load.Fx, -load.Fy, -e.root_moment})
                            .verdict();
    EXPECT_EQ(code[i], static_cast<int>(j.kind)) << "alpha2 = " << alpha2[i];
    EXPECT_EQ(index[i], j.index);
    EXPECT_NEAR(margin[i], j.margin, 1e-6) << "alpha2 = " << alpha2[i];
  }
  const auto off = dir / "off.h5";
  ASSERT_EQ(run_flexure("sweep beam --alpha2 0:12:7 --stability off --out '" + off.string() + "'")
                .exit_code,
            0);
  const hid_t f2 = open_read_only(off);
  ASSERT_GE(f2, 0);
  for (int c : read_ints(f2, "stability")) EXPECT_EQ(c, 4);
  for (int i : read_ints(f2, "stability_index")) EXPECT_EQ(i, -1);
  for (double m : read_doubles(f2, "stability_margin")) EXPECT_TRUE(std::isnan(m));
  H5Fclose(f2);
}

}  // namespace
}  // namespace flexure::test
