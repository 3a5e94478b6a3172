// What is checked against what: the stability verdict of every point of `flexure path` (JSON
// `stability*`, the file's /stability datasets; docs/stability.md "Points of a path") and the
// special points `flexure beam --method shooting` reports (JSON `special_points`):
//  * a physical column under a pure axial force (--Fx): every point on the straight path against
//    the closed form of the straight column, margin = 1 - P/P_1 with P = lambda |Fx| and the
//    cantilever's Euler load P_1 = pi^2/4 (1e-8 relative), index = the number of Euler loads
//    (2k - 1)^2 pi^2/4 below P (0, 1, 2 at Fx = -30), the first located bifurcation critical; the
//    buckled branch after --branch 1 stable (the first mode's post-buckling is stable: Timoshenko
//    & Gere §2.7);
//  * the same state judged under another control: --control tip-y holds the tip's y in the moving
//    stage, and the straight column under P = 3 is then a clamped-pinned column, stable with
//    margin 1 - 3/20.1907 (P_cr = 4.4934^2 EI/L^2, the root of tan(bL) = bL), to O(y^2);
//  * a fold under load control (n = 0, alpha2 = 10, mu = -2 pi): stable before it, critical at the
//    located fold, one negative direction right after it (the index changes by one where the load
//    factor turns: Morse theory of the energy in the load factor);
//  * the clamped-clamped beam of issue 27 (tip (0.9, 0.001)): its last point is the second mode
//    (unstable, index 1) with tip angle 0, the first mode (stable) with 0.01;
//  * beam --method shooting --Fx -3 / -30: special_points at pi^2/12 and pi^2/120, 9 pi^2/120;
//  * --stability off and the chain method: not_checked with null index and margin.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "tests/support/cli_test_support.h"

namespace flexure {
namespace {

using test::run_flexure;
using Json = nlohmann::json;
constexpr double kPi = std::numbers::pi;

Json run_json(const std::string& args) {
  const test::CommandResult r = run_flexure(args + " --json");
  EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
  return Json::parse(r.out);
}

// Length 1 m, EI = 1 N m^2: loads in N are Howell's nondimensional ones.
const char* kUnitBeam = "--length 1 --E 1GPa --I 1e-9";

// The straight column: the number of the cantilever's Euler loads (2k - 1)^2 pi^2 / 4 below P.
int euler_loads_below(double P) {
  int k = 0;
  while ((2 * k + 1) * (2 * k + 1) * kPi * kPi / 4.0 < P) ++k;
  return k;
}

TEST(CliPathStability, StraightColumnAgainstItsClosedForm) {
  for (const double force : {3.0, 30.0}) {
    test::ScratchDir dir;
    const std::string out = (dir / "column.h5").string();
    const Json j = run_json(fmt::format("path {} --Fx -{} --out {}", kUnitBeam, force, out));
    const Json& kind = j["stability"];
    ASSERT_EQ(kind.size(), j["points"].get<std::size_t>());
    const hid_t file = test::open_read_only(out);
    ASSERT_GE(file, 0);
    const std::vector<double> lambda = test::read_doubles(file, "load_factor");
    const std::vector<double> y = test::read_doubles(file, "tip_y");
    const std::vector<int> status = test::read_ints(file, "status");
    const std::vector<int> code = test::read_ints(file, "stability");
    const std::vector<int> index = test::read_ints(file, "stability_index");
    const std::vector<double> margin = test::read_doubles(file, "stability_margin");
    H5Fclose(file);
    ASSERT_EQ(code.size(), lambda.size());
    int critical = 0;
    for (std::size_t i = 0; i < lambda.size(); ++i) {
      ASSERT_NEAR(y[i], 0.0, 1e-12);  // the path from zero stays straight
      const double P = lambda[i] * force;
      SCOPED_TRACE(fmt::format("force {}, point {}, P = {}", force, i, P));
      const double closed_form = 1.0 - P / (kPi * kPi / 4.0);
      EXPECT_NEAR(margin[i], closed_form, 1e-8 * std::max(1.0, std::fabs(closed_form)));
      EXPECT_NEAR(j["stability_margin"][i].get<double>(), margin[i], 0.0);
      if (status[i] == 4 && euler_loads_below(P * (1.0 - 1e-6)) == 0) {
        // The first located bifurcation, the Euler load: the lowest eigenvalue is zero.
        EXPECT_EQ(kind[i], "critical");
        EXPECT_EQ(code[i], 2);
        ++critical;
        continue;
      }
      // At a later bifurcation the next eigenvalue is zero, and the lowest already negative.
      const int expected = euler_loads_below(status[i] == 4 ? P * (1.0 - 1e-6) : P);
      EXPECT_EQ(index[i], expected);
      EXPECT_EQ(kind[i], expected == 0 ? "stable" : "unstable");
      EXPECT_EQ(j["stability_index"][i].get<int>(), expected);
    }
    EXPECT_EQ(critical, 1);
    // The stretches: stable, critical, unstable (index 1)[, unstable (index 2) past 9 pi^2/4].
    const Json& stretches = j["stability_stretches"];
    ASSERT_EQ(stretches.size(), force == 3.0 ? 3u : 4u);
    EXPECT_EQ(stretches[0]["stability"], "stable");
    EXPECT_EQ(stretches[0]["first_index"], 0);
    EXPECT_EQ(stretches[1]["stability"], "critical");
    EXPECT_NEAR(stretches[1]["first_load_factor"].get<double>() * force, kPi * kPi / 4.0, 1e-8);
    EXPECT_EQ(stretches[2]["stability"], "unstable");
    EXPECT_EQ(stretches[2]["stability_index"], 1);
    EXPECT_EQ(stretches.back()["last_index"].get<std::size_t>(), lambda.size() - 1);
    if (force == 30.0) EXPECT_EQ(stretches[3]["stability_index"], 2);
  }
}

TEST(CliPathStability, TextOutputNamesTheStretches) {
  test::ScratchDir dir;
  const test::CommandResult r =
      run_flexure(fmt::format("path {} --Fx -3 --out {}", kUnitBeam, (dir / "c.h5").string()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("stability under load control:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("critical at point"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("unstable (index 1) at points"), std::string::npos) << r.out;
}

TEST(CliPathStability, BuckledBranchIsStable) {
  test::ScratchDir dir;
  const std::string out = (dir / "buckled.h5").string();
  const Json j = run_json(fmt::format("path {} --Fx -3 --branch 1 --out {}", kUnitBeam, out));
  ASSERT_TRUE(j["switched_branch"].get<bool>());
  const hid_t file = test::open_read_only(out);
  const std::vector<int> branch = test::read_ints(file, "branch");
  const std::vector<double> margin = test::read_doubles(file, "stability_margin");
  H5Fclose(file);
  int on_branch = 0;
  for (std::size_t i = 0; i < branch.size(); ++i) {
    if (branch[i] != 1 || j["stability"][i] == "critical") continue;
    ++on_branch;
    EXPECT_EQ(j["stability"][i], "stable") << "point " << i;
    EXPECT_GT(margin[i], 0.0);
  }
  EXPECT_GE(on_branch, 3);
  EXPECT_EQ(j["stability"].back(), "stable");
}

TEST(CliPathStability, DisplacementControlHoldsTheControlledCoordinate) {
  // Stage 1: Fx = -3 applied with y free (load control): past pi^2/4 the straight column is
  // unstable. Stage 2 holds y (moved to 1e-3): the same straight column is now clamped-pinned.
  constexpr double kClampedPinned = 20.190728556426;  // (4.4934094579...)^2
  test::ScratchDir dir;
  const std::string out = (dir / "held.h5").string();
  const Json j = run_json(
      fmt::format("path {} --Fx -3 --control tip-y --tip-y 1e-3 --out {}", kUnitBeam, out));
  const hid_t file = test::open_read_only(out);
  const std::vector<int> stage = test::read_ints(file, "stage");
  const std::vector<double> margin = test::read_doubles(file, "stability_margin");
  H5Fclose(file);
  int moving = 0;
  for (std::size_t i = 0; i < stage.size(); ++i) {
    if (stage[i] == 1) continue;
    ++moving;
    EXPECT_EQ(j["stability"][i], "stable") << "point " << i;
    EXPECT_NEAR(margin[i], 1.0 - 3.0 / kClampedPinned, 1e-4) << "point " << i;
  }
  EXPECT_GE(moving, 2);
  // The last point of stage 1 (the same straight column under load control) is unstable.
  const auto last_load = std::find(stage.begin(), stage.end(), 2) - stage.begin() - 1;
  ASSERT_GE(last_load, 0);
  EXPECT_EQ(j["stability"][last_load], "unstable");
  EXPECT_NEAR(margin[last_load], 1.0 - 3.0 / (kPi * kPi / 4.0), 1e-8);
  EXPECT_EQ(j["control"], "tip-y");
}

TEST(CliPathStability, FoldChangesTheIndexByOne) {
  test::ScratchDir dir;
  const std::string out = (dir / "fold.h5").string();
  const Json j = run_json("path --alpha2 10 --mu -6.283185307179586 --out " + out);
  ASSERT_GE(j["limit_point_list"].size(), 1u);
  const int fold = j["limit_point_list"][0]["index"].get<int>();
  ASSERT_GT(fold, 0);
  for (int i = 0; i < fold; ++i) EXPECT_EQ(j["stability"][i], "stable") << "point " << i;
  EXPECT_EQ(j["stability"][fold], "critical");
  EXPECT_NEAR(j["stability_margin"][fold].get<double>(), 0.0, 1e-6);
  EXPECT_EQ(j["stability"][fold + 1], "unstable");
  EXPECT_EQ(j["stability_index"][fold + 1], 1);
}

TEST(CliPathStability, ClampedClampedModes) {
  test::ScratchDir dir;
  const std::string out = (dir / "cc.h5").string();
  const Json second =
      run_json("path --boundary fixed --tip-x 0.9 --tip-y 0.001 --tip-angle 0 --out " + out);
  EXPECT_EQ(second["stability"].back(), "unstable");
  EXPECT_EQ(second["stability_index"].back(), 1);
  const Json first =
      run_json("path --boundary fixed --tip-x 0.9 --tip-y 0.001 --tip-angle 0.01 --out " + out);
  EXPECT_EQ(first["stability"].back(), "stable");
  // The path's verdict of its end point is the beam's verdict of the same answer.
  const Json beam = run_json(
      "beam --boundary fixed --alpha2 0 --tip-x 0.9 --tip-y 0.001 --tip-angle 0 --method "
      "shooting");
  EXPECT_NEAR(second["stability_margin"].back().get<double>(),
              beam["stability_margin"].get<double>(),
              1e-6);
}

TEST(CliPathStability, OffAndChainAreNotChecked) {
  test::ScratchDir dir;
  const std::string out = (dir / "p.h5").string();
  const Json off = run_json("path --alpha2 3 --stability off --out " + out);
  for (const Json& k : off["stability"]) EXPECT_EQ(k, "not_checked");
  for (const Json& m : off["stability_margin"]) EXPECT_TRUE(m.is_null());
  const Json chain = run_json("path --alpha2 3 --method chain --out " + out);
  const Json& kind = chain["stability"];
  for (std::size_t i = 0; i + 1 < kind.size(); ++i) EXPECT_EQ(kind[i], "not_checked");
  EXPECT_EQ(kind.back(), "stable");  // the chain algorithm's own verdict of its answer
}

TEST(CliBeamSpecialPoints, ShootingReportsTheBifurcationsItPassed) {
  for (const double force : {3.0, 30.0}) {
    const Json j = run_json(fmt::format("beam {} --Fx -{} --method shooting", kUnitBeam, force));
    const Json& sp = j["special_points"];
    ASSERT_TRUE(sp.is_array());
    ASSERT_EQ(sp.size(), force == 3.0 ? 1u : 2u);
    for (std::size_t k = 0; k < sp.size(); ++k) {
      const double euler = (2.0 * k + 1.0) * (2.0 * k + 1.0) * kPi * kPi / 4.0;
      EXPECT_EQ(sp[k]["kind"], "bifurcation");
      EXPECT_NEAR(sp[k]["load_factor"].get<double>() * force / euler, 1.0, 1e-8);
      EXPECT_NEAR(sp[k]["b_over_l"].get<double>(), 0.0, 1e-12);
    }
  }
  // A fold: the elliptic solver's first limit point.
  const Json elliptic = run_json("beam --method elliptic --alpha2 10 --mu -6.283185307179586");
  const Json shooting = run_json("beam --method shooting --alpha2 10 --mu -6.283185307179586");
  ASSERT_GE(shooting["special_points"].size(), 1u);
  EXPECT_EQ(shooting["special_points"][0]["kind"], "limit_point");
  EXPECT_NEAR(shooting["special_points"][0]["load_factor"].get<double>(),
              elliptic["first_limit_load_factor"].get<double>(),
              1e-8);
  EXPECT_TRUE(elliptic["special_points"].is_null());  // the elliptic solver locates none
}

}  // namespace
}  // namespace flexure
