// What is checked against what (docs/chain-toml.md, limits): the TOML pre-check
// (io::check_toml_limits) refuses, before toml++ recurses, nesting deeper than kMaxTomlNesting and
// text longer than kMaxTomlBytes, naming the source, the line (counted here by hand from the text
// the test builds) and the limit; the depth it counts is the depth of the TOML tree (a text built
// exactly at the limit passes, one level more fails); brackets and dots inside strings and
// comments, and dots in numbers, are not nesting. The example files in docs/examples pass. Through
// the binary: a 50 000-level [a.a.a...] header (it crashed with SIGSEGV) and a 2 MB file exit 2 for
// both `beam --chain` and `mechanism analyze`; a node index of 1e300 (cast to int out of range,
// reported as -2147483648) is refused quoting the value as written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "flexure/io/toml_files.h"
#include "flexure/io/toml_support.h"
#include "flexure/solver/common/status.h"
#include "tests/support/cli_test_support.h"

namespace flexure::io {
namespace {

using test::run_flexure;
using test::ScratchDir;

std::string limit_message(const std::string& text) {
  try {
    check_toml_limits(text, "t.toml");
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

std::string repeat(const std::string& s, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += s;
  return out;
}

// [a.a...a] with `parts` parts: a table `parts` levels deep.
std::string dotted(int parts) {
  std::string key = "a";
  for (int i = 1; i < parts; ++i) key += ".a";
  return key;
}

TEST(TomlLimits, TableHeadersDeeperThanTheLimitAreRefusedNamingLineAndLimit) {
  const int limit = kMaxTomlNesting;
  EXPECT_EQ(limit_message("[" + dotted(limit) + "]\n"), "");
  const std::string too_deep = "# comment\nx = 1\n[" + dotted(limit + 1) + "]\n";
  const std::string message = limit_message(too_deep);
  EXPECT_NE(message.find("t.toml:3:"), std::string::npos) << message;
  EXPECT_NE(message.find(std::to_string(limit)), std::string::npos) << message;
  // An array of tables is one level more than the table header with the same key.
  EXPECT_EQ(limit_message("[[" + dotted(limit - 1) + "]]\n"), "");
  EXPECT_NE(limit_message("[[" + dotted(limit) + "]]\n"), "");
  // The input: 50 000 levels.
  EXPECT_NE(limit_message("[" + dotted(50000) + "]\n").find("t.toml:1:"), std::string::npos);
}

TEST(TomlLimits, DottedKeysAddToTheirTablesDepth) {
  const int limit = kMaxTomlNesting;
  // [a.a] is 2 levels; a key of limit - 2 parts puts its value at depth limit.
  EXPECT_EQ(limit_message("[a.a]\n" + dotted(limit - 2) + " = 1\n"), "");
  EXPECT_NE(limit_message("[a.a]\n" + dotted(limit - 1) + " = 1\n").find("t.toml:2:"),
            std::string::npos);
  // The key's depth is measured from the latest header, not accumulated over the file.
  EXPECT_EQ(
      limit_message("[a]\n" + dotted(limit - 1) + " = 1\n[b]\n" + dotted(limit - 1) + " = 2\n"),
      "");
}

TEST(TomlLimits, InlineArraysAndTablesCountEveryLevel) {
  const int limit = kMaxTomlNesting;
  // x = [[...[1]...]]: x is level 1, the outer array too, each further bracket one level more.
  EXPECT_EQ(limit_message("x = " + repeat("[", limit) + "1" + repeat("]", limit) + "\n"), "");
  EXPECT_NE(limit_message("x = " + repeat("[", limit + 1) + "1" + repeat("]", limit + 1) + "\n"),
            "");
  // x = {b = {b = ... 1}}: x and every b are one level each.
  EXPECT_EQ(limit_message("x = " + repeat("{b = ", limit - 1) + "1" + repeat("}", limit - 1)), "");
  EXPECT_NE(limit_message("x = " + repeat("{b = ", limit) + "1" + repeat("}", limit)), "");
  // A multi-line array: the depth (and the line reported) follows the brackets across lines.
  const std::string multi = "x = [\n" + repeat("[\n", limit) + "1" + repeat("]", limit + 1);
  EXPECT_NE(limit_message(multi).find("t.toml:" + std::to_string(limit + 1) + ":"),
            std::string::npos)
      << limit_message(multi);
  // Siblings do not add up: many arrays side by side are each shallow.
  EXPECT_EQ(limit_message("x = [" + repeat("[[1]], ", 1000) + "]\n"), "");
}

TEST(TomlLimits, StringsCommentsAndNumbersAreNotNesting) {
  const std::string brackets = repeat("[{", 1000);
  EXPECT_EQ(limit_message("x = \"" + brackets + "\"\n"), "");
  EXPECT_EQ(limit_message("x = '" + brackets + "'\n"), "");
  EXPECT_EQ(limit_message("x = \"\"\"\n" + brackets + "\n\"\"\"\n"), "");
  EXPECT_EQ(limit_message("x = '''" + brackets + "'''\n"), "");
  EXPECT_EQ(limit_message("# " + brackets + "\n"), "");
  EXPECT_EQ(limit_message("x = \"\\\"" + brackets + "\"\n"), "") << "an escaped quote";
  EXPECT_EQ(limit_message("\"" + repeat("a.", 1000) + "\" = 1\n"), "") << "a quoted key";
  EXPECT_EQ(limit_message("x = [" + repeat("1.5, ", 1000) + "]\n"), "") << "dots in numbers";
  // Lines inside a multi-line string are counted: the deep header below is on line 5.
  const std::string after = "x = \"\"\"\na\nb\n\"\"\"\n[" + dotted(kMaxTomlNesting + 1) + "]\n";
  EXPECT_NE(limit_message(after).find("t.toml:5:"), std::string::npos) << limit_message(after);
}

TEST(TomlLimits, TextLongerThanTheLimitIsRefusedNamingTheLine) {
  std::string text(kMaxTomlBytes, '#');
  for (std::size_t i = 99; i < text.size(); i += 100) text[i] = '\n';
  EXPECT_EQ(limit_message(text), "") << "exactly the limit is allowed";
  text += "\n";
  const std::string message = limit_message(text);
  // The limit is crossed after kMaxTomlBytes bytes, that is after this many newlines:
  const std::size_t lines_before = kMaxTomlBytes / 100;
  EXPECT_NE(message.find("t.toml:" + std::to_string(lines_before + 1) + ":"), std::string::npos)
      << message;
  EXPECT_NE(message.find(std::to_string(kMaxTomlBytes)), std::string::npos) << message;
}

TEST(TomlLimits, TheExampleFilesPass) {
  int files = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(FLEXURE_SOURCE_DIR) + "/docs/examples")) {
    if (entry.path().extension() != ".toml") continue;
    ++files;
    EXPECT_EQ(limit_message(test::read_text(entry.path())), "") << entry.path();
  }
  EXPECT_GE(files, 5);
}

TEST(TomlLimits, LargeIntegersAreNumbers) {
  // node.value<double>() refuses 2^63 - 1 (not exactly representable); it is still a number.
  const toml::table t = toml::parse("x = 9223372036854775807\ny = 'text'\nz = 2.5\n");
  EXPECT_EQ(toml_number(*t.get("x")), 9223372036854775807.0);
  EXPECT_EQ(toml_number(*t.get("z")), 2.5);
  EXPECT_FALSE(toml_number(*t.get("y")).has_value());
}

// --- through the binary --------------------------------------------------------------------------

void write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

TEST(TomlLimitsCli, DeeplyNestedHeaderExitsTwoForChainsAndMechanisms) {
  ScratchDir dir;
  const auto file = dir / "deep.toml";
  write(file, "# 50 000 levels\n[" + dotted(50000) + "]\n");
  for (const std::string command : {"beam --chain ",
                                    "mechanism analyze ",
                                    "path --alpha2 1 "
                                    "--out x.h5 --chain "}) {
    for (const std::string json : {"", " --json"}) {
      const test::CommandResult r = run_flexure(command + file.string() + json, dir.path());
      EXPECT_EQ(r.exit_code, 2) << command << json << "\n" << r.err;
      EXPECT_NE(r.err.find(file.string() + ":2:"), std::string::npos) << r.err;
      EXPECT_NE(r.err.find(std::to_string(kMaxTomlNesting)), std::string::npos) << r.err;
      EXPECT_TRUE(test::no_result_on_stdout(r)) << r.out;
    }
  }
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"deep.toml"}) << "path wrote a file";
}

TEST(TomlLimitsCli, OversizedFileExitsTwoWithoutReadingItAll) {
  ScratchDir dir;
  const auto file = dir / "big.toml";
  write(file, std::string(2 * kMaxTomlBytes, '#'));
  for (const std::string command : {"beam --chain ", "mechanism analyze "}) {
    const test::CommandResult r = run_flexure(command + file.string());
    EXPECT_EQ(r.exit_code, 2) << command << r.err;
    EXPECT_NE(r.err.find(file.string() + ":1:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(std::to_string(kMaxTomlBytes)), std::string::npos) << r.err;
  }
  // An endless device is refused after the first MiB instead of filling memory.
  const test::CommandResult r = run_flexure("beam --chain /dev/zero");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("/dev/zero:1:"), std::string::npos) << r.err;
}

TEST(TomlLimitsCli, NodeIndexOutOfIntRangeIsRefusedQuotingTheValue) {
  ScratchDir dir;
  const std::string chain =
      "[[segment]]\ntype = \"flexible\"\nlength = 1\n"
      "[[segment]]\ntype = \"flexible\"\nlength = 1\n"
      "[[node_load]]\nFy = 1\nnode = ";
  const struct {
    const char* value;
    const char* quoted;
  } cases[] = {{"1e300", "got 1e+300"},
               {"-1e300", "got -1e+300"},
               {"2147483648", "got 2147483648"},
               {"9223372036854775807", "got 9223372036854775807"},
               {"-9223372036854775808", "got -9223372036854775808"},
               {"0", "got 0"},
               {"2", "got 2"},
               {"1.5", "got 1.5"}};
  for (const auto& c : cases) {
    write(dir / "node.toml", chain + c.value + "\n");
    const test::CommandResult r = run_flexure("beam --chain " + (dir / "node.toml").string());
    EXPECT_EQ(r.exit_code, 2) << c.value << "\n" << r.err;
    EXPECT_NE(r.err.find("node.toml:9:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.quoted), std::string::npos) << c.value << ": " << r.err;
    EXPECT_EQ(r.err.find("-2147483648"), std::string::npos) << r.err;
  }
  // The one valid joint of a two-segment chain, as an integer and as an integral float.
  for (const char* value : {"1", "1.0"}) {
    write(dir / "node.toml", chain + value + "\n");
    const SegmentChain parsed = read_chain_toml((dir / "node.toml").string());
    ASSERT_EQ(parsed.node_loads.size(), 1u);
    EXPECT_EQ(parsed.node_loads[0].node, 1) << value;
  }
}

}  // namespace
}  // namespace flexure::io
