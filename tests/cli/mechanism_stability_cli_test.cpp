// What is checked against what: the stroke points' stability verdicts of `flexure mechanism
// analyze` and `validate` as the user reads them (docs/stability.md "Mechanisms"; the verdicts
// themselves are checked in tests/mechanisms/mechanism_stability_test.cpp):
//  - --json: per model and control one verdict per stroke point, the counts equal to the arrays,
//    the PRBM held at its slider stable with margin 1, force control never more stable than
//    displacement control, and under force control one more negative direction exactly where the
//    exact force array falls (central differences, away from its extremum);
//  - --out: the same verdicts as integer codes, indices and margins, equal to the JSON's, with the
//    codes' meanings on the root and a summary per model;
//  - the text output prints the summaries; stderr warns for 3A-lssm, whose exact stroke is
//    unstable with the slider held;
//  - validate: the column and the counts, without the per-point arrays; --out's columns.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

using nlohmann::json;

constexpr int kPoints = 24;

TEST(MechanismStabilityCli, JsonHasAVerdictPerStrokePoint) {
  const CommandResult r = run_flexure("mechanism analyze 2A-ssp --method exact --json --points " +
                                      std::to_string(kPoints));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  const std::vector<double> F = j["force_exact"].get<std::vector<double>>();
  for (const char* control : {"stability_displacement_control", "stability_force_control"}) {
    for (const char* model : {"prbm", "exact"}) {
      const json& v = j[control][model];
      ASSERT_TRUE(v.is_object()) << control << " " << model;
      ASSERT_EQ(v["stability"].size(), static_cast<std::size_t>(kPoints));
      ASSERT_EQ(v["stability_index"].size(), static_cast<std::size_t>(kPoints));
      ASSERT_EQ(v["stability_margin"].size(), static_cast<std::size_t>(kPoints));
      int unstable = 0;
      for (int i = 0; i < kPoints; ++i) {
        unstable += v["stability"][i] == "unstable" ? 1 : 0;
        EXPECT_EQ(v["stability"][i] == "unstable", v["stability_index"][i].get<int>() > 0);
      }
      EXPECT_EQ(v["unstable_points"].get<int>(), unstable);
      EXPECT_EQ(v["not_checked_points"].get<int>(), 0);
      EXPECT_TRUE(v["not_checked"].empty());
      EXPECT_NE(
          v["summary"].get<std::string>().find(model == std::string("prbm") ? "PRBM" : "exact"),
          std::string::npos);
    }
  }
  const json& pdc = j["stability_displacement_control"]["prbm"];
  for (int i = 0; i < kPoints; ++i) {
    EXPECT_EQ(pdc["stability"][i], "stable");
    EXPECT_EQ(pdc["stability_margin"][i].get<double>(), 1.0);
  }
  const json& dc = j["stability_displacement_control"]["exact"];
  const json& fc = j["stability_force_control"]["exact"];
  int compared = 0, falling = 0;
  for (int i = 1; i + 1 < kPoints; ++i) {
    EXPECT_LE(fc["stability_margin"][i].get<double>(),
              dc["stability_margin"][i].get<double>() + 1e-8);
    const double left = F[i] - F[i - 1], right = F[i + 1] - F[i];
    if ((left > 0) != (right > 0)) continue;
    EXPECT_EQ(fc["stability_index"][i].get<int>(),
              dc["stability_index"][i].get<int>() + (left < 0 ? 1 : 0))
        << "point " << i;
    ++compared;
    falling += left < 0 ? 1 : 0;
  }
  EXPECT_GT(compared, kPoints - 6);
  EXPECT_GT(falling, 2);  // 2A-ssp's exact force falls over the last quarter of its stroke
  EXPECT_GT(fc["unstable_points"].get<int>(), 2);
}

TEST(MechanismStabilityCli, PrbmOnlyHasNoExactVerdicts) {
  const CommandResult r = run_flexure("mechanism analyze 1A-lpp --method prbm --json --points 8");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_TRUE(j["stability_force_control"]["exact"].is_null());
  EXPECT_EQ(j["stability_force_control"]["prbm"]["stability"].size(), 8u);
}

TEST(MechanismStabilityCli, Hdf5StoresTheJsonVerdicts) {
  ScratchDir dir;
  const CommandResult r = run_flexure(
      "mechanism analyze 1A-spp --method exact --json --points 12 --out m.h5", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  const hid_t file = open_read_only(dir / "m.h5");
  ASSERT_GE(file, 0);
  const std::vector<std::string> names = {
      "stable", "unstable", "critical", "not_conservative", "not_checked"};
  for (const char* control : {"displacement_control", "force_control"}) {
    for (const char* model : {"prbm", "exact"}) {
      const std::string group = std::string("/stability_") + control + "/" + model;
      const std::vector<int> codes = read_ints(file, (group + "/stability").c_str());
      const std::vector<int> index = read_ints(file, (group + "/stability_index").c_str());
      const std::vector<double> margin = read_doubles(file, (group + "/stability_margin").c_str());
      const json& v = j[std::string("stability_") + control][model];
      ASSERT_EQ(codes.size(), 12u) << group;
      for (std::size_t i = 0; i < codes.size(); ++i) {
        EXPECT_EQ(names.at(static_cast<std::size_t>(codes[i])), v["stability"][i]) << group;
        EXPECT_EQ(index[i], v["stability_index"][i].get<int>());
        EXPECT_EQ(margin[i], v["stability_margin"][i].get<double>());
      }
      EXPECT_EQ(read_string_attribute(file, group.c_str(), "summary"), v["summary"]);
      EXPECT_EQ(read_string_attribute(file, (group + "/stability_margin").c_str(), "units"), "1");
    }
  }
  const std::string meanings = read_string_attribute(file, "/", "status_meanings");
  EXPECT_NE(meanings.find("stability 0: stable"), std::string::npos);
  EXPECT_NE(meanings.find("stability 1: unstable"), std::string::npos);
  H5Fclose(file);
}

TEST(MechanismStabilityCli, TextPrintsTheStretchesAndWarnsOfAnUnstableExactStroke) {
  const CommandResult a = run_flexure("mechanism analyze 1A-spp --method exact --points 50");
  ASSERT_EQ(a.exit_code, 0) << a.err;
  for (const char* line : {"displacement control (PRBM): stable at all 50 points",
                           "displacement control (exact): stable at all 50 points",
                           "force control (PRBM): stable for Delta x in",
                           "(the force falls: snap-through under a dead load)",
                           "near-critical by design"}) {
    EXPECT_NE(a.out.find(line), std::string::npos) << line << "\n" << a.out;
  }
  EXPECT_EQ(a.err.find("unstable with the slider held"), std::string::npos) << a.err;
  // 3A-lssm's exact stroke (10 points) is unstable with its slider held: a warning, exit 0.
  const CommandResult b = run_flexure("mechanism analyze 3A-lssm --method exact --points 10");
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_NE(b.out.find("displacement control (exact): unstable (index 1) at all 10 points"),
            std::string::npos)
      << b.out;
  EXPECT_NE(b.err.find("3A-lssm: the exact model's equilibrium is unstable with the slider held "
                       "at 10 of 10 stroke points"),
            std::string::npos)
      << b.err;
  EXPECT_NE(b.err.find("--stable follows a stable branch instead"), std::string::npos) << b.err;
}

// --stable (docs/cli.md): 3A-lslm's exact stroke, unstable with the slider held at every point by
// default, is stable at every point with --stable; the JSON says what was done; the first force
// lies just above the lowest buckling load (10.55 N, docs/stability.md), far below the default
// stroke's; a design whose default stroke is stable keeps it ("not needed", same forces); a
// general mechanism file refuses the flag.
TEST(MechanismStabilityCli, StableFollowsAStableBranch) {
  const CommandResult a =
      run_flexure("mechanism analyze 3A-lslm --method exact --points 10 --stable --json");
  ASSERT_EQ(a.exit_code, 0) << a.err;
  const json j = json::parse(a.out);
  EXPECT_TRUE(j["stable"].get<bool>());
  const std::string search = j["stable_search"].get<std::string>();
  EXPECT_NE(search.find("lowest buckling mode"), std::string::npos) << search;
  const json& dc = j["stability_displacement_control"]["exact"];
  EXPECT_EQ(dc["unstable_points"].get<int>(), 0);
  for (const auto& v : dc["stability"]) EXPECT_EQ(v, "stable");
  EXPECT_EQ(a.err.find("unstable with the slider held"), std::string::npos) << a.err;
  const CommandResult d =
      run_flexure("mechanism analyze 3A-lslm --method exact --points 10 --json");
  ASSERT_EQ(d.exit_code, 0) << d.err;
  const json jd = json::parse(d.out);
  EXPECT_TRUE(jd["stable_search"].is_null());
  EXPECT_EQ(jd["stability_displacement_control"]["exact"]["unstable_points"].get<int>(), 10);
  // At 10 % of the stroke the sway branch carries far less than the default (PRBM-like) stroke.
  const double stable_first = j["force_exact"][0].get<double>();
  EXPECT_GT(stable_first, 10.55);
  EXPECT_LT(stable_first, 0.8 * jd["force_exact"][0].get<double>());
  // 2A-ssp: stable by default, so --stable changes nothing.
  const CommandResult s =
      run_flexure("mechanism analyze 2A-ssp --method exact --points 10 --stable --json");
  ASSERT_EQ(s.exit_code, 0) << s.err;
  const json js = json::parse(s.out);
  EXPECT_EQ(js["stable_search"].get<std::string>().rfind("not needed", 0), 0u);
  const CommandResult t = run_flexure("mechanism analyze 2A-ssp --method exact --points 10 --json");
  ASSERT_EQ(t.exit_code, 0) << t.err;
  EXPECT_EQ(js["force_exact"], json::parse(t.out)["force_exact"]);
  // The text output says it on a line of its own.
  const CommandResult x =
      run_flexure("mechanism analyze 3A-lslm --method exact --points 5 --stable");
  ASSERT_EQ(x.exit_code, 0) << x.err;
  EXPECT_NE(x.out.find("  --stable: the stroke from the PRBM start is unstable"), std::string::npos)
      << x.out;
}

// --stable in --out (issue 27): the root attributes `stable` (1/0) and `stable_search` equal the
// JSON keys of the same run; without --stable, stable = 0 and no stable_search (JSON null); the
// stored exact verdicts are the stable branch's (0 unstable points where the default has 10).
TEST(MechanismStabilityCli, Hdf5SaysWhatStableDid) {
  ScratchDir dir;
  const CommandResult a =
      run_flexure("mechanism analyze 3A-lslm --method exact --points 10 --stable --json --out s.h5",
                  dir.path());
  ASSERT_EQ(a.exit_code, 0) << a.err;
  const json j = json::parse(a.out);
  const hid_t file = open_read_only(dir / "s.h5");
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_int_attribute(file, "/", "stable"), 1);
  EXPECT_EQ(read_string_attribute(file, "/", "stable_search"), j["stable_search"]);
  const std::vector<int> codes = read_ints(file, "/stability_displacement_control/exact/stability");
  ASSERT_EQ(codes.size(), 10u);
  for (const int c : codes) EXPECT_EQ(c, 0);  // stable
  H5Fclose(file);
  const CommandResult d = run_flexure(
      "mechanism analyze 3A-lslm --method exact --points 10 --json --out d.h5", dir.path());
  ASSERT_EQ(d.exit_code, 0) << d.err;
  EXPECT_TRUE(json::parse(d.out)["stable_search"].is_null());
  const hid_t plain = open_read_only(dir / "d.h5");
  ASSERT_GE(plain, 0);
  EXPECT_EQ(read_int_attribute(plain, "/", "stable"), 0);
  EXPECT_LT(H5Aexists_by_name(plain, "/", "stable_search", H5P_DEFAULT), 1);
  int unstable = 0;
  for (const int c : read_ints(plain, "/stability_displacement_control/exact/stability")) {
    unstable += c == 1 ? 1 : 0;
  }
  EXPECT_EQ(unstable, 10);
  H5Fclose(plain);
}

TEST(MechanismStabilityCli, ValidateCountsUnstablePoints) {
  ScratchDir dir;
  const CommandResult r =
      run_flexure("mechanism validate --designs thesis --points 10 --json --out v.h5", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  ASSERT_EQ(j["mechanisms"].size(), 9u);
  const hid_t file = open_read_only(dir / "v.h5");
  ASSERT_GE(file, 0);
  const std::vector<double> held =
      read_doubles(file, "/unstable_points_displacement_control_exact");
  const std::vector<double> dead = read_doubles(file, "/unstable_points_force_control_exact");
  const std::vector<double> prbm = read_doubles(file, "/unstable_points_force_control_prbm");
  ASSERT_EQ(held.size(), 9u);
  for (std::size_t i = 0; i < 9; ++i) {
    const json& m = j["mechanisms"][i];
    EXPECT_FALSE(m["stability_force_control"]["exact"].contains("stability"));
    EXPECT_EQ(held[i], m["stability_displacement_control"]["exact"]["unstable_points"].get<int>());
    EXPECT_EQ(dead[i], m["stability_force_control"]["exact"]["unstable_points"].get<int>());
    EXPECT_EQ(prbm[i], m["stability_force_control"]["prbm"]["unstable_points"].get<int>());
  }
  H5Fclose(file);
  const CommandResult md =
      run_flexure("mechanism validate --designs thesis --points 10 --markdown");
  ASSERT_EQ(md.exit_code, 0) << md.err;
  EXPECT_NE(md.out.find("unstable points: exact held / exact dead load / PRBM dead load"),
            std::string::npos);
}

}  // namespace
}  // namespace flexure::test
