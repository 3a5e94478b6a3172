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
