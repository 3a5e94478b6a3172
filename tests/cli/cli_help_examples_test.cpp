// What is checked, through the built tool: every command's --help ends with two or three examples,
// and every example runs as printed (exit 0, in a scratch directory; a --json example prints one
// JSON object), so the examples cannot go stale.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/cli_test_support.h"

namespace flexure {
namespace {

using test::run_flexure;

const std::vector<std::string> kCommands = {"beam",
                                            "sweep beam",
                                            "validate",
                                            "prbm derive",
                                            "prbm table",
                                            "prbm compare",
                                            "cfm",
                                            "design mechanism",
                                            "path",
                                            "mechanism list",
                                            "mechanism analyze",
                                            "mechanism validate",
                                            "mechanism export",
                                            "dynamics",
                                            "models map",
                                            "models prbm3r-constants",
                                            "bench",
                                            "help"};

// The lines after "Examples:" in `help`, without the leading "flexure ".
std::vector<std::string> examples_in(const std::string& help) {
  std::vector<std::string> examples;
  const std::size_t at = help.find("\nExamples:\n");
  if (at == std::string::npos) return examples;
  std::istringstream lines(help.substr(at + 11));
  for (std::string line; std::getline(lines, line);) {
    const std::string prefix = "  flexure ";
    if (line.rfind(prefix, 0) == 0) examples.push_back(line.substr(prefix.size()));
  }
  return examples;
}

class HelpExamples : public ::testing::TestWithParam<std::string> {};

TEST_P(HelpExamples, EndTheHelpAndRunAsPrinted) {
  const test::CommandResult help = run_flexure(GetParam() + " --help");
  ASSERT_EQ(help.exit_code, 0);
  const std::vector<std::string> examples = examples_in(help.out);
  EXPECT_GE(examples.size(), 2u) << help.out;
  EXPECT_LE(examples.size(), 3u) << help.out;
  for (const std::string& example : examples) {
    test::ScratchDir dir;
    const test::CommandResult r = run_flexure(example, dir.path());
    EXPECT_EQ(r.exit_code, 0) << "flexure " << example << "\n" << r.err;
    if (example.find("--json") != std::string::npos) {
      EXPECT_EQ(test::count_lines(r.out), 1) << example;
      EXPECT_TRUE(nlohmann::json::parse(r.out, nullptr, false).is_object()) << example;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Commands,
                         HelpExamples,
                         ::testing::ValuesIn(kCommands),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           for (char& c : name) {
                             if (c == ' ' || c == '-') c = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace flexure
