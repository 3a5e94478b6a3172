// Contact with a rigid surface through the tool (docs/contact.md, docs/cli.md):
//   * the flexure-on-a-cylinder example (SI): the curvature condition at the separation point
//     from the statics of the printed free span, m(s_c) = F x (r_tip - r_c) = EI/R with
//     EI = E b t^3/12, to 1e-9; clamp reaction + tip load + contact force = 0 to 1e-10;
//   * the HDF5 file of --out holds the same numbers as the JSON;
//   * a stop left along a load continuation from a start tip load: one lift-off event;
//   * a leaf spring lying on a stop (line contact): the clamp moment sqrt(2 EI q d) exactly,
//   balances;
//     sweep beam --chain and path --chain refuse a [[contact]];
//   * refusals (exit 2) for other methods, several contacts, unknown keys and types, path --chain;
//     a compressed wrap is exit 3 with what was reached.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/cli_test_support.h"

namespace flexure {
namespace {

using test::run_flexure;
using Json = nlohmann::json;

const std::string kExample =
    std::string(FLEXURE_SOURCE_DIR) + "/docs/examples/flexure_on_cylinder.toml";

Json run_json(const std::string& args) {
  const test::CommandResult r = run_flexure(args + " --json");
  EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err << r.out;
  return r.exit_code == 0 ? Json::parse(r.out) : Json::object();
}

TEST(CliContact, FlexureOnACylinderMeetsTheCurvatureConditionAndBalances) {
  test::ScratchDir dir;
  const std::string h5 = (dir / "cylinder.h5").string();
  const Json j = run_json("beam --chain " + kExample + " --out " + h5 + " --shape 51");
  ASSERT_FALSE(j.empty());
  EXPECT_EQ(j["units"], "SI");
  EXPECT_EQ(j["surface"], "circle");
  ASSERT_TRUE(j["in_contact"].get<bool>());
  const double E = 200e9, b = 0.01, t = 0.0002, R = 0.04;
  const double EI = E * b * t * t * t / 12.0;
  const Json& c = j["contact"];
  const Json& sep = c["separation_points"][0];
  const double Fx = j["tip_load"]["Fx"], Fy = j["tip_load"]["Fy"];
  const double m_sc = (j["tip"]["x"].get<double>() - sep["x"].get<double>()) * Fy -
                      (j["tip"]["y"].get<double>() - sep["y"].get<double>()) * Fx;
  EXPECT_NEAR(m_sc, EI / R, 1e-9 * EI / R);
  EXPECT_NEAR(j["reaction"]["M"].get<double>(), -EI / R, 1e-12 * EI / R);
  EXPECT_NEAR(j["reaction"]["Fx"].get<double>() + Fx + c["contact_force"]["Fx"].get<double>(),
              0.0,
              1e-10 * Fy);
  EXPECT_NEAR(j["reaction"]["Fy"].get<double>() + Fy + c["contact_force"]["Fy"].get<double>(),
              0.0,
              1e-10 * Fy);
  EXPECT_DOUBLE_EQ(c["s_end"].get<double>(), sep["s"].get<double>());
  EXPECT_GE(c["point_force_normal"].get<double>(), 0.0);
  EXPECT_GE(c["line_pressure"].get<double>(), 0.0);
  ASSERT_EQ(j["events"].size(), 1u);
  EXPECT_EQ(j["events"][0]["kind"], "landing");
  EXPECT_EQ(j["shape"].size(), 51u);
  EXPECT_EQ(j["path"].size(), 21u);  // steps = 20 in the file, and lambda = 0
  // The verdict (docs/contact.md "Stability"): the free span clamped at s_c, pulled by a tip
  // force that it turns toward, is nowhere compressed: stable with margin 1 (the energy check of
  // contact verdicts is tests/solver/contact_stability_test.cpp).
  EXPECT_EQ(j["stability"], "stable");
  EXPECT_EQ(j["stability_index"], 0);
  EXPECT_NEAR(j["stability_margin"].get<double>(), 1.0, 1e-9);
  // The HDF5 file: the same numbers.
  const hid_t f = test::open_read_only(h5);
  ASSERT_GE(f, 0);
  EXPECT_DOUBLE_EQ(test::read_doubles(f, "/contact/separation_s").at(0), sep["s"].get<double>());
  EXPECT_DOUBLE_EQ(test::read_doubles(f, "/contact/contact_force").at(1),
                   c["contact_force"]["Fy"].get<double>());
  EXPECT_EQ(test::read_strings(f, "/events/kind").at(0), "landing");
  EXPECT_EQ(test::read_doubles(f, "/shape/x").size(), 51u);
  EXPECT_EQ(test::read_ints(f, "/path/in_contact").size(), 21u);
  EXPECT_EQ(test::read_string_attribute(f, "/", "surface"), "circle");
  EXPECT_EQ(test::read_string_attribute(f, "/", "stability"), "stable");
  H5Fclose(f);
}

TEST(CliContact, AStopLeftAlongTheContinuationReportsLiftOff) {
  test::ScratchDir dir;
  const std::string file = (dir / "stop.toml").string();
  std::ofstream(file) << "[[segment]]\ntype = \"flexible\"\nlength = 1.0\nEI = 1.0\n"
                         "[tip_load]\nFy = 1.0\n[[contact]]\ntype = \"line\"\n"
                         "point = [0.0, -0.3]\nnormal = [0.0, 1.0]\n"
                         "start_tip_load = { Fy = -5.0 }\nsteps = 10\n";
  const Json j = run_json("beam --chain " + file);
  ASSERT_FALSE(j.empty());
  ASSERT_EQ(j["events"].size(), 1u);
  EXPECT_EQ(j["events"][0]["kind"], "lift-off");
  EXPECT_FALSE(j["in_contact"].get<bool>());
  EXPECT_TRUE(j["path"][0]["in_contact"].get<bool>());
  EXPECT_GT(j["contact"]["tip_gap"].get<double>(), 0.0);
}

TEST(CliContact, APinTouchedAtOnePoint) {
  // A pin of radius 0.1 under the beam: one interior contact point, tangent, the force along the
  // pin's radius; clamp reaction + tip load + contact force = 0 and the moments about the clamp.
  test::ScratchDir dir;
  const std::string file = (dir / "pin.toml").string();
  std::ofstream(file) << "[[segment]]\ntype = \"flexible\"\nlength = 1.0\nEI = 1.0\n"
                         "[tip_load]\nFx = 0.5\nFy = -3.0\n[[contact]]\ntype = \"circle\"\n"
                         "center = [0.5, -0.15]\nradius = 0.1\n";
  const Json j = run_json("beam --chain " + file);
  ASSERT_FALSE(j.empty());
  EXPECT_EQ(j["contact_kind"], "point");
  // An interior point contact is not judged: not_checked, saying why.
  EXPECT_EQ(j["stability"], "not_checked");
  EXPECT_TRUE(j["stability_index"].is_null());
  EXPECT_NE(j["stability_message"].get<std::string>().find("interior point contact"),
            std::string::npos);
  const Json& p = j["contact"]["separation_points"][0];
  const double x = p["x"], y = p["y"], theta = p["theta"];
  EXPECT_NEAR(std::hypot(x - 0.5, y + 0.15), 0.1, 1e-12);
  EXPECT_NEAR(std::cos(theta) * (x - 0.5) + std::sin(theta) * (y + 0.15), 0.0, 1e-11);
  const double fx = j["contact"]["contact_force"]["Fx"], fy = j["contact"]["contact_force"]["Fy"];
  EXPECT_NEAR(j["reaction"]["Fx"].get<double>() + 0.5 + fx, 0.0, 1e-10);
  EXPECT_NEAR(j["reaction"]["Fy"].get<double>() - 3.0 + fy, 0.0, 1e-10);
  const double tx = j["tip"]["x"], ty = j["tip"]["y"];
  EXPECT_NEAR(
      j["reaction"]["M"].get<double>() + (tx * -3.0 - ty * 0.5) + (x * fy - y * fx), 0.0, 1e-10);
}

TEST(CliContact, ALeafSpringLyingOnAStop) {
  // docs/examples/leaf_spring_on_stop.toml: EI = E b t^3/12 = 4.5e-3 N m^2, q = 40 N/m, the stop
  // d = 5 mm below. The clamp moment is sqrt(2 EI q d) exactly at any deflection (the first
  // integral m^2/(2 EI) + N . t + q . r = const of the free span, from the clamp to the
  // separation point where m = 0 and the beam is level); balance of forces to 1e-10; the lying
  // part carries q to the stop (line pressure 40 N/m); the HDF5 file holds the same numbers.
  test::ScratchDir dir;
  const std::string h5 = (dir / "stop.h5").string();
  const std::string example =
      std::string(FLEXURE_SOURCE_DIR) + "/docs/examples/leaf_spring_on_stop.toml";
  const Json j = run_json("beam --chain " + example + " --out " + h5 + " --shape 41");
  ASSERT_FALSE(j.empty());
  EXPECT_EQ(j["contact_kind"], "line");
  EXPECT_EQ(j["units"], "SI");
  const double EI = 200e9 * 0.01 * std::pow(0.3e-3, 3) / 12.0, q = 40.0, d = 0.005;
  EXPECT_NEAR(j["reaction"]["M"].get<double>(), std::sqrt(2.0 * EI * q * d), 1e-12);
  const Json& c = j["contact"];
  EXPECT_NEAR(j["reaction"]["Fy"].get<double>() - q * 0.1 + c["contact_force"]["Fy"].get<double>(),
              0.0,
              1e-10);
  EXPECT_NEAR(c["line_pressure"].get<double>(), q, 1e-12);
  EXPECT_EQ(c["tip_reaction_normal"].get<double>(), 0.0);
  const double a = c["s_start"];
  EXPECT_EQ(c["s_end"].get<double>(), 0.1);
  const Json& sep = c["separation_points"][0];
  EXPECT_EQ(sep["s"].get<double>(), a);
  EXPECT_NEAR(sep["y"].get<double>(), -d, 1e-13);
  EXPECT_NEAR(sep["theta"].get<double>(), 0.0, 1e-12);
  // Contact force: point force at a plus q over the lying part.
  EXPECT_NEAR(c["contact_force"]["Fy"].get<double>(),
              c["point_force_normal"].get<double>() + q * (0.1 - a),
              1e-12);
  ASSERT_EQ(j["events"].size(), 2u);
  EXPECT_EQ(j["events"][1]["kind"], "line-contact");
  EXPECT_EQ(j["stability"], "not_checked");
  EXPECT_NE(j["stability_message"].get<std::string>().find("line contact"), std::string::npos);
  EXPECT_EQ(j["shape"].size(), 41u);
  const hid_t f = test::open_read_only(h5);
  ASSERT_GE(f, 0);
  EXPECT_EQ(test::read_string_attribute(f, "/", "contact_kind"), "line");
  EXPECT_DOUBLE_EQ(test::read_doubles(f, "/contact/s_start").at(0), a);
  EXPECT_DOUBLE_EQ(test::read_doubles(f, "/contact/line_pressure").at(0),
                   c["line_pressure"].get<double>());
  EXPECT_DOUBLE_EQ(test::read_doubles(f, "/contact/tip_reaction_normal").at(0), 0.0);
  EXPECT_EQ(test::read_strings(f, "/events/kind").at(1), "line-contact");
  H5Fclose(f);
  // A sweep or a path of a file with a [[contact]]: refused (exit 2), never the free beam.
  test::expect_refused(
      "sweep beam --chain " + example + " --Fy 0:1:3 --csv " + (dir / "s.csv").string(),
      {"sweep beam --chain", "[[contact]]"});
  test::expect_refused("path --chain " + example + " --control tip-y --tip-y \"-3 mm\"",
                       {"contact"});
  EXPECT_FALSE(std::filesystem::exists(dir / "s.csv"));
}

TEST(CliContact, TwoSurfacesOneTouched) {
  // A pin above the beam and a stop below: the stop (table 2) is touched; its JSON says which.
  // A pin under the span as well: exit 3 naming both tables.
  test::ScratchDir dir;
  const std::string head =
      "[[segment]]\ntype = \"flexible\"\nlength = 1.0\nEI = 1.0\n[tip_load]\nFy = -8.0\n";
  const std::string stop =
      "[[contact]]\ntype = \"line\"\npoint = [0.0, -0.3]\nnormal = [0.0, 1.0]\n";
  const std::string file = (dir / "two.toml").string();
  std::ofstream(file) << head
                      << "[[contact]]\ntype = \"circle\"\ncenter = [0.5, 0.3]\nradius = 0.1\n"
                      << stop;
  const Json j = run_json("beam --chain " + file);
  ASSERT_FALSE(j.empty());
  EXPECT_EQ(j["contact_table"], 2);
  EXPECT_EQ(j["contact_kind"], "tip");
  EXPECT_NEAR(j["tip"]["y"].get<double>(), -0.3, 1e-12);
  const std::string both = (dir / "both.toml").string();
  std::ofstream(both) << head << stop
                      << "[[contact]]\ntype = \"circle\"\ncenter = [0.6, -0.22]\nradius = 0.1\n";
  const test::CommandResult r = run_flexure("beam --chain " + both + " --json");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  const Json e = Json::parse(r.out);
  const std::string message = e["error"];
  EXPECT_NE(message.find("contact 1"), std::string::npos) << message;
  EXPECT_NE(message.find("contact 2"), std::string::npos) << message;
}

TEST(CliContact, UnsupportedCombinationsAreRefused) {
  test::ScratchDir dir;
  auto write = [&](const std::string& name, const std::string& contact) {
    const std::string path = (dir / name).string();
    std::ofstream(path) << "[[segment]]\ntype = \"flexible\"\nlength = 1.0\nEI = 1.0\n"
                           "[tip_load]\nFx = -1.0\nFy = 8.0\n"
                        << contact;
    return path;
  };
  const std::string circle = "[[contact]]\ntype = \"circle\"\ncenter = [0.0, 0.5]\nradius = 0.5\n";
  const std::string ok = write("ok.toml", circle);
  test::expect_refused("beam --chain " + ok + " --method chain", {"shooting"});
  test::expect_refused("beam --chain " + ok + " --stable", {"--stable"});
  test::expect_refused("path --chain " + ok, {"contact"});
  test::expect_refused(
      "beam --chain " + write("two.toml", circle + "steps = 4\n" + circle + "steps = 5\n"),
      {"steps differs"});
  test::expect_refused("beam --chain " + write("key.toml", circle + "friction = 0.3\n"),
                       {"friction"});
  test::expect_refused("beam --chain " + write("type.toml", "[[contact]]\ntype = \"sphere\"\n"),
                       {"sphere"});
  test::expect_refused(
      "beam --chain " +
          write("off.toml", "[[contact]]\ntype = \"circle\"\ncenter = [0.2, 0.5]\nradius = 0.5\n"),
      {"tangent"});
  test::expect_refused("beam --alpha2 1 --out x.h5", {"--out"});
  // Fx = -1 compresses the wrap: exit 3 with what was reached, never an answer.
  const test::CommandResult r = run_flexure("beam --chain " + ok + " --json");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  const Json e = Json::parse(r.out);
  EXPECT_EQ(e["exit_code"], 3);
  EXPECT_TRUE(e.contains("load_factor"));
  EXPECT_NE(e["error"].get<std::string>().find("compressed"), std::string::npos);
}

}  // namespace
}  // namespace flexure
