// What is checked, through the built tool:
//  * `flexure help [COMMAND ...]` prints the same text as `flexure [COMMAND ...] --help`, exit 0;
//    an unknown command is exit 2 naming the commands there are;
//  * names match case-insensitively everywhere: methods, end conditions, segments,
//    configurations and mechanisms give the same result in any case.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/cli_test_support.h"

namespace flexure {
namespace {

using test::run_flexure;
using Json = nlohmann::json;

TEST(CliHelp, HelpCommandPrintsTheCommandsHelp) {
  for (const std::string command : {"", "beam", "mechanism analyze", "prbm compare"}) {
    const test::CommandResult help = run_flexure("help " + command);
    const test::CommandResult flag = run_flexure(command + " --help");
    ASSERT_EQ(help.exit_code, 0) << command << ": " << help.err;
    EXPECT_EQ(help.out, flag.out) << command;
    EXPECT_FALSE(help.out.empty());
  }
  const test::CommandResult unknown = run_flexure("help bean");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("beam"), std::string::npos) << unknown.err;
}

TEST(CliHelp, ParseErrorsSuggestTheNearestFlagAndNameTheCommandsHelp) {
  const test::CommandResult alpha = run_flexure("beam --alpha 2");
  EXPECT_EQ(alpha.exit_code, 2);
  EXPECT_NE(alpha.err.find("did you mean --alpha2"), std::string::npos) << alpha.err;
  EXPECT_NE(alpha.err.find("'flexure beam --help'"), std::string::npos) << alpha.err;
  const test::CommandResult points = run_flexure("mechanism analyze 1A-lpp --point 5");
  EXPECT_EQ(points.exit_code, 2);
  EXPECT_NE(points.err.find("did you mean --points"), std::string::npos) << points.err;
  EXPECT_NE(points.err.find("'flexure mechanism analyze --help'"), std::string::npos);
  // Nothing near: no guess, only the help.
  const test::CommandResult far = run_flexure("beam --alpha2 1 --zzzzzzzz 3");
  EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;
}

// The JSON of `args` with exit 0, without the keys that echo the request.
Json result(const std::string& args) {
  const test::CommandResult r = run_flexure(args + " --json");
  EXPECT_EQ(r.exit_code, 0) << args << ": " << r.err;
  Json j = Json::parse(r.out.empty() ? "{}" : r.out);
  j.erase("method_reason");
  return j;
}

TEST(CliNames, MatchInAnyCase) {
  EXPECT_EQ(result("beam --alpha2 2 --method ELLIPTIC"),
            result("beam --alpha2 2 --method elliptic"));
  EXPECT_EQ(result("beam --alpha2 2 --boundary Guided --method Shooting"),
            result("beam --alpha2 2 --boundary guided --method shooting"));
  EXPECT_EQ(result("prbm compare --segment End-Moment --mu 1"),
            result("prbm compare --segment end-moment --mu 1"));
  EXPECT_EQ(result("cfm --config LPP --R 1 --d 40")["Phi"],
            result("cfm --config lpp --R 1 --d 40")["Phi"]);
  EXPECT_EQ(result("mechanism analyze 1a-LPP --points 5 --prbm-only")["prbm"],
            result("mechanism analyze 1A-lpp --points 5 --prbm-only")["prbm"]);
}

TEST(CliNames, DynamicsFindsTheDesignInAnyCase) {
  test::ScratchDir dir;
  const auto out = [&](const char* name) {
    return run_flexure(
               std::string("dynamics --mechanism ") + name + " --omega 1:2:2 --out d.h5 --json",
               dir.path())
        .exit_code;
  };
  EXPECT_EQ(out("2b-lplm"), 0);
  EXPECT_EQ(out("2B-LPLM"), 0);
}

}  // namespace
}  // namespace flexure
