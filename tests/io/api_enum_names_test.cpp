// What is checked against what (issue 28: methods and models are enums in the C++ API, their text
// the old strings): for every enum that replaced a string field -- the contact event and contact
// kinds (solver/shooting/rigid_contact.h), a flexure's geometric kind (mechanism.h), the
// dynamics' spring rule (dynamics.h), the general analysis's --model
// (io/general_mechanism_file.h) -- each value's name is the text the field held before, written
// out here, and the parser returns the value for it; an unknown name is refused with InvalidInput
// naming every valid one. The beam sweep's method is a BeamMethod, whose names beam_method_test
// checks; here only the HDF5 text it gives.
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "flexure/io/general_mechanism_file.h"
#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/dynamics/dynamics.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/rigid_contact.h"

namespace flexure {
namespace {

// Each value's name is `names[i]` and parses back to the value; `parse` refuses "bogus" with a
// message naming every name.
template <class Enum, class Parse>
void expect_names(const std::vector<std::pair<Enum, std::string>>& names, Parse parse) {
  for (const auto& [value, name] : names) {
    EXPECT_EQ(std::string(to_string(value)), name);
    EXPECT_EQ(parse(name), value) << name;
  }
  try {
    parse("bogus");
    FAIL() << "'bogus' was accepted";
  } catch (const InvalidInput& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'bogus'"), std::string::npos) << what;
    for (const auto& [value, name] : names) {
      EXPECT_NE(what.find(name), std::string::npos) << what << " does not name " << name;
    }
  }
  // Names are exact: another case is a different name (the tool lower-cases flags first).
  EXPECT_THROW(parse(std::string("X") + names.front().second), InvalidInput);
}

TEST(ApiEnumNames, ContactEventKind) {
  expect_names<ContactEventKind>({{ContactEventKind::kLanding, "landing"},
                                  {ContactEventKind::kLiftOff, "lift-off"},
                                  {ContactEventKind::kLineContact, "line-contact"},
                                  {ContactEventKind::kTipContact, "tip-contact"}},
                                 contact_event_kind_from_string);
}

TEST(ApiEnumNames, ContactKind) {
  expect_names<ContactKind>({{ContactKind::kNone, "none"},
                             {ContactKind::kWrap, "wrap"},
                             {ContactKind::kTip, "tip"},
                             {ContactKind::kPoint, "point"},
                             {ContactKind::kLine, "line"}},
                            contact_kind_from_string);
  EXPECT_EQ(ContactResult{}.kind, ContactKind::kNone);  // the free beam's, as "none" was
}

TEST(ApiEnumNames, FlexureKind) {
  using mechanism::FlexureKind;
  expect_names<FlexureKind>({{FlexureKind::kSmall, "small"},
                             {FlexureKind::kLong, "long"},
                             {FlexureKind::kFixedFixed, "fixed-fixed"}},
                            mechanism::flexure_kind_from_string);
}

TEST(ApiEnumNames, FlexureKindOfEachPivotOfADesign) {
  // 1A-lpp: a long (fixed-pinned) segment at pivot 1, pins at 2 and 3; 3A-sss: three small ones.
  const mechanism::MechanismDesign lpp = mechanism::find_builtin_mechanism("1A-lpp");
  EXPECT_EQ(mechanism::flexure_kind(lpp, 1), mechanism::FlexureKind::kLong);
  EXPECT_FALSE(mechanism::flexure_kind(lpp, 2).has_value());
  EXPECT_FALSE(mechanism::flexure_kind(lpp, 3).has_value());
  const mechanism::MechanismDesign sss = mechanism::find_builtin_mechanism("3A-sss");
  for (int p = 1; p <= 3; ++p) {
    EXPECT_EQ(mechanism::flexure_kind(sss, p), mechanism::FlexureKind::kSmall) << p;
  }
}

TEST(ApiEnumNames, DynamicsSpringRule) {
  using dynamics::DynamicsSpringRule;
  expect_names<DynamicsSpringRule>({{DynamicsSpringRule::kTable5Printed, "table5-printed"},
                                    {DynamicsSpringRule::kPureBending, "pure-bending"},
                                    {DynamicsSpringRule::kTable2, "table2"},
                                    {DynamicsSpringRule::kTable5, "table5"},
                                    {DynamicsSpringRule::kGiven, "given"}},
                                   dynamics::dynamics_spring_rule_from_string);
  // A mechanism's rule has the same name in the dynamics.
  for (mechanism::SpringRule r : {mechanism::SpringRule::kPureBending,
                                  mechanism::SpringRule::kTable2,
                                  mechanism::SpringRule::kTable5}) {
    EXPECT_EQ(std::string(to_string(dynamics::dynamics_spring_rule(r))),
              mechanism::spring_rule_name(r));
  }
}

TEST(ApiEnumNames, DynamicsDesignsReportTheirRule) {
  // The printed Table 5 springs by default, a computed rule when given one.
  const dynamics::DynamicsDesign printed =
      dynamics::builtin_dynamics_design("2B-lplm", std::nullopt);
  EXPECT_EQ(printed.spring_rule, dynamics::DynamicsSpringRule::kTable5Printed);
  const dynamics::DynamicsDesign table2 =
      dynamics::builtin_dynamics_design("2B-lplm", mechanism::SpringRule::kTable2);
  EXPECT_EQ(table2.spring_rule, dynamics::DynamicsSpringRule::kTable2);
}

TEST(ApiEnumNames, GeneralAnalysisModel) {
  using io::GeneralAnalysisModel;
  expect_names<GeneralAnalysisModel>({{GeneralAnalysisModel::kPrbm, "prbm"},
                                      {GeneralAnalysisModel::kExact, "exact"},
                                      {GeneralAnalysisModel::kBoth, "both"},
                                      {GeneralAnalysisModel::kMixed, "mixed"}},
                                     io::general_analysis_model_from_string);
}

}  // namespace
}  // namespace flexure
