// The TOML writer (io/toml_files.h mechanism_toml) against the reader: every built-in design
// -- the nine thesis configurations, Howell's designs, the modified designs of paper 004 and
// every thesis sub-class -- written and read back gives the same design, bit for bit, and the
// same PRBM stroke.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "flexure/io/toml_files.h"
#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {
namespace {

void expect_same(const MechanismDesign& a, const MechanismDesign& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.config, b.config) << a.name;
  EXPECT_EQ(a.paper_config, b.paper_config) << a.name;
  EXPECT_EQ(a.note, b.note) << a.name;
  EXPECT_EQ(a.r2, b.r2) << a.name;
  EXPECT_EQ(a.r3, b.r3) << a.name;
  EXPECT_EQ(a.material.E, b.material.E) << a.name;
  EXPECT_EQ(a.material.yield_strength, b.material.yield_strength) << a.name;
  EXPECT_EQ(a.stroke, b.stroke) << a.name;
  EXPECT_EQ(a.spring_rule, b.spring_rule) << a.name;
  for (int p = 0; p < 3; ++p) {
    const JointDesign &x = a.joints[p], &y = b.joints[p];
    EXPECT_EQ(x.type, y.type) << a.name << " pivot " << p + 1;
    if (x.type == PivotType::kPin) continue;  // a pin has no section (some designs carry one)
    EXPECT_EQ(x.segment, y.segment) << a.name << " pivot " << p + 1;
    EXPECT_EQ(x.thickness, y.thickness) << a.name << " pivot " << p + 1;
    EXPECT_EQ(x.width, y.width) << a.name << " pivot " << p + 1;
    EXPECT_EQ(x.length, y.length) << a.name << " pivot " << p + 1;
    if (x.segment == SegmentKind::kFixedFixed) {
      EXPECT_EQ(x.table2_factor, y.table2_factor) << a.name;
    }
  }
}

TEST(MechanismTomlWriter, EveryBuiltInDesignReadsBackUnchanged) {
  std::vector<MechanismDesign> designs = builtin_mechanisms();
  for (const auto& d : howell_mechanisms()) designs.push_back(d);
  for (const auto& d : modified_designs()) designs.push_back(d);
  for (const cfm::CfmSubclass& row : cfm::thesis_subclasses()) {
    designs.push_back(find_builtin_mechanism(row.name));
  }
  ASSERT_GT(designs.size(), 80u);
  for (const MechanismDesign& d : designs) {
    const std::string text = mechanism_toml(d, "written by the round-trip test\nsecond line");
    SCOPED_TRACE(text);
    const MechanismDesign back = parse_mechanism_toml(text, d.name);
    expect_same(d, back);
    const PrbmStrokeResult s1 = prbm_stroke(d, 10), s2 = prbm_stroke(back, 10);
    EXPECT_EQ(s1.mean_force, s2.mean_force) << d.name;
  }
}

TEST(MechanismTomlWriter, EscapesQuotesAndBackslashesInTexts) {
  MechanismDesign d = builtin_mechanisms().front();
  d.name = "a \"quoted\" name \\ with a backslash";
  d.note = "line one\ttab";
  const MechanismDesign back = parse_mechanism_toml(mechanism_toml(d), "test");
  EXPECT_EQ(back.name, d.name);
  EXPECT_EQ(back.note, d.note);
}

// force_of (what `mechanism analyze` reports for the file) is written only when set and reads
// back; an unknown value is refused naming the key and the line.
TEST(MechanismTomlWriter, ForceOfReadsBackAndAnUnknownValueIsRefused) {
  MechanismDesign d = builtin_mechanisms().front();
  EXPECT_EQ(mechanism_toml(d).find("force_of"), std::string::npos);
  EXPECT_FALSE(parse_mechanism_toml(mechanism_toml(d), "test").force_of.has_value());
  for (ForceOf of : {ForceOf::kWholeMechanism, ForceOf::kOneHalf}) {
    d.force_of = of;
    const MechanismDesign back = parse_mechanism_toml(mechanism_toml(d), "test");
    ASSERT_TRUE(back.force_of.has_value());
    EXPECT_EQ(*back.force_of, of);
  }
  std::string text = mechanism_toml(d);
  text.replace(text.find("force_of = 'half'"), 17, "force_of = 'both'");
  try {
    parse_mechanism_toml(text, "bad.toml");
    ADD_FAILURE() << "force_of = 'both' was accepted";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("bad.toml:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("force_of = 'both' is unknown"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace flexure::mechanism
