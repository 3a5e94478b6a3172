// The general mechanism TOML writer (io/general_mechanism_toml_writer.h): every description it
// writes reads back (io/toml_files.h) as the same description to the bit -- the 40
// built-in designs' general forms (catalogue_general.h) and the shipped general examples -- and a
// read-back design solves to the same PRBM numbers.
#include "flexure/io/general_mechanism_toml_writer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "flexure/io/toml_files.h"
#include "flexure/mechanisms/general/catalogue_general.h"
#include "flexure/mechanisms/general/general_analysis.h"
#include "flexure/mechanisms/mechanism_catalogue.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism::general {
namespace {

std::vector<NamedPoint> sorted(std::vector<NamedPoint> points) {
  std::sort(points.begin(), points.end(), [](const NamedPoint& a, const NamedPoint& b) {
    return a.name < b.name;
  });
  return points;
}

// Exact equality of two descriptions (doubles compared with ==), a body's points in any order.
void expect_same(const GeneralMechanism& a, const GeneralMechanism& b) {
  EXPECT_EQ(a.name, b.name);
  ASSERT_EQ(a.bodies.size(), b.bodies.size());
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    EXPECT_EQ(a.bodies[i].name, b.bodies[i].name);
    const auto pa = sorted(a.bodies[i].points), pb = sorted(b.bodies[i].points);
    ASSERT_EQ(pa.size(), pb.size()) << a.bodies[i].name;
    for (std::size_t k = 0; k < pa.size(); ++k) {
      EXPECT_EQ(pa[k].name, pb[k].name);
      EXPECT_EQ(pa[k].position.x, pb[k].position.x) << pa[k].name;
      EXPECT_EQ(pa[k].position.y, pb[k].position.y) << pa[k].name;
    }
  }
  ASSERT_EQ(a.joints.size(), b.joints.size());
  for (std::size_t i = 0; i < a.joints.size(); ++i) {
    EXPECT_EQ(a.joints[i].name, b.joints[i].name);
    EXPECT_EQ(a.joints[i].kind, b.joints[i].kind);
    EXPECT_EQ(a.joints[i].a.text(), b.joints[i].a.text());
    EXPECT_EQ(a.joints[i].b.text(), b.joints[i].b.text());
    EXPECT_EQ(a.joints[i].axis_angle, b.joints[i].axis_angle);
  }
  ASSERT_EQ(a.flexures.size(), b.flexures.size());
  for (std::size_t i = 0; i < a.flexures.size(); ++i) {
    const Flexure &fa = a.flexures[i], &fb = b.flexures[i];
    EXPECT_EQ(fa.name, fb.name);
    EXPECT_EQ(fa.a.text(), fb.a.text());
    EXPECT_EQ(fa.b.text(), fb.b.text());
    EXPECT_EQ(fa.width, fb.width);
    EXPECT_EQ(fa.thickness, fb.thickness);
    EXPECT_EQ(fa.material.E, fb.material.E);
    EXPECT_EQ(fa.prbm, fb.prbm);
    EXPECT_EQ(fa.model, fb.model);
    EXPECT_EQ(fa.extensible, fb.extensible);
  }
  EXPECT_EQ(a.linear_springs.size(), b.linear_springs.size());
  EXPECT_EQ(a.torsion_springs.size(), b.torsion_springs.size());
  ASSERT_EQ(a.loads.size(), b.loads.size());
  for (std::size_t i = 0; i < a.loads.size(); ++i) {
    EXPECT_EQ(a.loads[i].fx, b.loads[i].fx);
    EXPECT_EQ(a.loads[i].fy, b.loads[i].fy);
    EXPECT_EQ(a.loads[i].moment, b.loads[i].moment);
  }
  EXPECT_EQ(a.has_input, b.has_input);
  EXPECT_EQ(a.input.body, b.input.body);
  EXPECT_EQ(a.input.point, b.input.point);
  EXPECT_EQ(a.input.point_to, b.input.point_to);
  EXPECT_EQ(a.input.coordinate, b.input.coordinate);
  EXPECT_EQ(a.input.control, b.input.control);
  EXPECT_EQ(a.input.start, b.input.start);
  EXPECT_EQ(a.input.stop, b.input.stop);
  EXPECT_EQ(a.input.count, b.input.count);
  auto rotations = [](std::vector<std::pair<std::string, double>> r) {
    std::sort(r.begin(), r.end());
    return r;
  };
  EXPECT_EQ(rotations(a.input.start_rotation), rotations(b.input.start_rotation));
}

TEST(GeneralMechanismTomlWriter, EveryBuiltInDesignReadsBackTheSame) {
  const std::vector<MechanismDesign> designs = mechanism_designs(DesignSet::kAll);
  ASSERT_EQ(designs.size(), 40u);
  for (const MechanismDesign& d : designs) {
    SCOPED_TRACE(d.name);
    const GeneralMechanism m = general_from_design(d, 12);
    const std::string text = design_as_general_toml(d, 12);
    expect_same(m, parse_general_mechanism_toml(text, d.name + ".toml"));
  }
}

TEST(GeneralMechanismTomlWriter, ShippedExamplesReadBackTheSame) {
  int files = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(FLEXURE_SOURCE_DIR) + "/docs/examples")) {
    const std::string path = entry.path().string();
    if (entry.path().extension() != ".toml") continue;
    const std::string text = [&] {
      std::ifstream in(path);
      std::stringstream s;
      s << in.rdbuf();
      return s.str();
    }();
    if (!is_general_mechanism_toml(text, path)) continue;
    SCOPED_TRACE(path);
    ++files;
    const GeneralMechanism m = load_general_mechanism_toml(path);
    GeneralMechanism back = parse_general_mechanism_toml(general_mechanism_to_toml(m), "back");
    back.name = m.name;
    expect_same(m, back);
  }
  EXPECT_GE(files, 9);
}

TEST(GeneralMechanismTomlWriter, ReadBackDesignSolvesToTheSamePrbm) {
  for (const char* name : {"2A-slp", "1B-plp'", "2B-lplm"}) {
    const MechanismDesign d = find_builtin_mechanism(name);
    const GeneralPrbmResult a = solve_general_prbm(general_from_design(d, 10));
    const GeneralPrbmResult b =
        solve_general_prbm(parse_general_mechanism_toml(design_as_general_toml(d, 10), name));
    ASSERT_TRUE(a.converged() && b.converged()) << name;
    ASSERT_EQ(a.points.size(), b.points.size());
    for (std::size_t k = 0; k < a.points.size(); ++k) {
      // Only the order of a body's points (its reference point, a sum) can differ.
      EXPECT_NEAR(
          a.points[k].input_load, b.points[k].input_load, 1e-12 * std::fabs(a.points[k].input_load))
          << name << " " << k;
    }
  }
}

TEST(GeneralMechanismTomlWriter, HeaderIsCommentAndBadDescriptionsThrow) {
  const std::string text = design_as_general_toml(find_builtin_mechanism("1A-lpp"), 5);
  EXPECT_EQ(text.rfind("# 1A-lpp (lpp) as a general mechanism", 0), 0u) << text.substr(0, 80);
  GeneralMechanism m = general_from_design(find_builtin_mechanism("1A-lpp"), 5);
  m.flexures[0].thickness = 0.0;
  EXPECT_THROW(general_mechanism_to_toml(m), InvalidInput);
}

}  // namespace
}  // namespace flexure::mechanism::general
