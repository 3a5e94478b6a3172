// What is checked against what: the PRBM validity of a mechanism stroke in `flexure mechanism
// analyze` (issue 27: a validity line at the first stroke point, "n = 16 is outside Table 5.1",
// while the PRBM's error stayed a steady 5 %, read as "the PRBM is never valid").
//  * lpp-a: the load ratio of its l segment is above Table 5.1's range at the first stroke point
//    (the pin force nearly along the beam). The JSON, text and HDF5 name the quantity, its value,
//    the table's range (-5 <= n <= 10, from the data file) and the points outside, and those are
//    the points flagged per point; the force error reported at the first point outside equals
//    |F_prbm - F_exact| / |F_exact| recomputed here from the two force curves of the same output,
//    and the largest error outside equals their maximum over the points flagged outside.
//  * 1B-plp: the pin force on the far side of the beam axis (load angle phi >= 180 deg, the table
//    covering 11.3 to 174.3 deg).
//  * 1A-lpp stays inside the table; 1A-spp (s pivots only) has none; without the exact model the
//    error there is said to be unknown (null), not 0.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/cli_test_support.h"

namespace flexure::test {
namespace {

nlohmann::json analyze(const std::string& args) {
  const CommandResult r = run_flexure("mechanism analyze " + args + " --json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return nlohmann::json::parse(r.out.empty() ? "{}" : r.out);
}

TEST(PrbmValidityCli, LoadRatioOutsideTheTableWithTheErrorThere) {
  const nlohmann::json j = analyze("lpp-a --points 50 --method exact");
  const nlohmann::json& v = j["prbm_validity"];
  ASSERT_TRUE(v.is_object()) << j.dump();
  EXPECT_EQ(v["quantity"], "load_ratio_n");
  EXPECT_EQ(v["unit"], "1");
  EXPECT_GT(v["value"].get<double>(), 10.0);
  EXPECT_EQ(v["table_range"], nlohmann::json::array({-5.0, 10.0}));
  EXPECT_EQ(v["pivot"], 1);
  EXPECT_EQ(v["points"], 50);
  const std::vector<double> prbm = j["force_prbm"].get<std::vector<double>>();
  const std::vector<double> exact = j["force_exact"].get<std::vector<double>>();
  const std::vector<int> inside = j["prbm_within_validity"].get<std::vector<int>>();
  ASSERT_EQ(inside.size(), 50u);
  int outside = 0;
  double worst = 0.0;
  int first = -1;
  for (std::size_t k = 0; k < inside.size(); ++k) {
    if (inside[k] != 0) continue;
    ++outside;
    if (first < 0) first = static_cast<int>(k);
    worst = std::max(worst, std::fabs(prbm[k] - exact[k]) / std::fabs(exact[k]));
  }
  EXPECT_EQ(v["points_outside"], outside);
  // Outside at the start of the stroke only: not "never valid".
  EXPECT_GE(outside, 1);
  EXPECT_LT(outside, 25);
  EXPECT_EQ(inside[0], 0);
  EXPECT_EQ(v["outside_ranges"][0][0], j["displacement"][0]);
  ASSERT_GE(first, 0);
  EXPECT_EQ(v["limit"], j["displacement"][first]);
  EXPECT_EQ(j["prbm_validity_limit"], j["displacement"][first]);
  EXPECT_NEAR(v["force_error_at_limit"].get<double>(),
              std::fabs(prbm[first] - exact[first]) / std::fabs(exact[first]),
              1e-12);
  EXPECT_NEAR(v["max_force_error_outside"].get<double>(), worst, 1e-12);
  // The error is a few percent there: not "invalid" in the sense of a wrong force.
  EXPECT_LT(v["force_error_at_limit"].get<double>(), 0.1);
  const std::string reason = j["prbm_validity_reason"];
  EXPECT_NE(reason.find("load ratio n = "), std::string::npos) << reason;
  EXPECT_NE(reason.find("(-5 <= n <= 10)"), std::string::npos) << reason;

  // The text output says the same, with the error.
  const CommandResult text = run_flexure("mechanism analyze lpp-a --points 50 --method exact");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("PRBM validity: left at "), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("load ratio n = "), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("the PRBM force error (against the exact model) is "), std::string::npos)
      << text.out;

  // And the file: the attributes and one flag per stroke point.
  ScratchDir dir;
  ASSERT_EQ(run_flexure("mechanism analyze lpp-a --points 50 --method exact --out v.h5", dir.path())
                .exit_code,
            0);
  const hid_t file = open_read_only(dir / "v.h5");
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_string_attribute(file, "/", "prbm_validity_quantity"), "load_ratio_n");
  EXPECT_EQ(read_double_attribute(file, "/", "prbm_validity_value"), v["value"].get<double>());
  EXPECT_EQ(read_double_attribute(file, "/", "prbm_validity_table_max"), 10.0);
  EXPECT_EQ(read_int_attribute(file, "/", "prbm_points_outside_validity"), outside);
  EXPECT_EQ(read_double_attribute(file, "/", "prbm_force_error_at_validity_limit"),
            v["force_error_at_limit"].get<double>());
  EXPECT_EQ(read_ints(file, "/prbm_within_validity"), inside);
  H5Fclose(file);
}

TEST(PrbmValidityCli, PinForceOnTheFarSideNamesTheLoadAngle) {
  const nlohmann::json v = analyze("1B-plp --points 8 --method exact")["prbm_validity"];
  EXPECT_EQ(v["quantity"], "load_angle_phi") << v.dump();
  EXPECT_EQ(v["unit"], "deg");
  EXPECT_GE(v["value"].get<double>(), 180.0);
  EXPECT_LT(v["value"].get<double>(), 360.0);
  EXPECT_NEAR(v["table_range"][0].get<double>(), 11.3, 1e-9);
  EXPECT_NEAR(v["table_range"][1].get<double>(), 174.3, 1e-9);
  EXPECT_TRUE(v["force_error_at_limit"].is_number()) << v.dump();
}

TEST(PrbmValidityCli, InsideNoTableAndNoExactModel) {
  const nlohmann::json inside = analyze("1A-lpp --points 8 --method exact")["prbm_validity"];
  EXPECT_EQ(inside["points_outside"], 0) << inside.dump();
  EXPECT_TRUE(inside["limit"].is_null());
  EXPECT_TRUE(inside["max_force_error_outside"].is_null());
  EXPECT_TRUE(inside["max_force_error_inside"].is_number());
  EXPECT_NE(inside["summary"].get<std::string>().find("inside Howell Table 5.1 at all 8"),
            std::string::npos);

  const nlohmann::json none = analyze("1A-spp --points 8")["prbm_validity"];
  EXPECT_TRUE(none["table"].is_null()) << none.dump();
  EXPECT_NE(none["no_table"].get<std::string>().find("small-length pivots"), std::string::npos);

  const nlohmann::json prbm_only = analyze("lpp-a --points 50 --method prbm")["prbm_validity"];
  EXPECT_EQ(prbm_only["quantity"], "load_ratio_n");
  EXPECT_TRUE(prbm_only["force_error_at_limit"].is_null()) << prbm_only.dump();
  EXPECT_NE(prbm_only["summary"].get<std::string>().find("the exact model was not solved"),
            std::string::npos);
}

}  // namespace
}  // namespace flexure::test
