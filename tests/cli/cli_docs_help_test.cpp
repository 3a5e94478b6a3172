// docs/cli.md matches `--help`: every command (found by walking the help's subcommand lists, so a
// new command is covered without editing this test) has a section in docs/cli.md ("## `flexure
// CMD`", or its parent's section), every flag its --help lists is documented in that section, and
// every flag the section documents exists in the help of one of the section's commands (so a
// removed or renamed flag cannot stay documented).
#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/cli_test_support.h"

namespace flexure {
namespace {

using test::run_flexure;

// Lines between "Subcommands:" and the next blank line: "  name   description".
std::vector<std::string> subcommands(const std::string& help) {
  std::vector<std::string> names;
  std::istringstream in(help);
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line.rfind("Subcommands:", 0) == 0) {
      inside = true;
      continue;
    }
    if (!inside) continue;
    if (line.empty()) break;
    std::istringstream words(line);
    std::string name;
    words >> name;
    if (!name.empty() && name != "help") names.push_back(name);
  }
  return names;
}

// Long flags of the "Options:" lines (and option groups), e.g. "  -h,--help", "  --alpha2 FLOAT".
std::set<std::string> help_flags(const std::string& help) {
  std::set<std::string> flags;
  const std::regex option_line(R"(^\s+(?:-[A-Za-z],)?(--[A-Za-z0-9][A-Za-z0-9-]*))");
  std::istringstream in(help);
  std::string line;
  std::smatch m;
  while (std::getline(in, line)) {
    if (std::regex_search(line, m, option_line)) flags.insert(m[1]);
  }
  flags.erase("--help");
  return flags;
}

std::set<std::string> documented_flags(const std::string& section) {
  std::set<std::string> flags;
  const std::regex flag(R"((?:^|[^A-Za-z0-9-])(--[A-Za-z][A-Za-z0-9-]*))");
  for (std::sregex_iterator it(section.begin(), section.end(), flag), end; it != end; ++it) {
    flags.insert((*it)[1]);
  }
  return flags;
}

// The text of "## `flexure NAME`" up to the next "## " heading, or empty.
std::string section(const std::string& doc, const std::string& name) {
  const std::string heading = "## `flexure " + name + "`";
  std::size_t at = doc.find(heading + "\n");
  if (at == std::string::npos) return "";
  const std::size_t end = doc.find("\n## ", at + heading.size());
  return doc.substr(at, end == std::string::npos ? std::string::npos : end - at);
}

// Leaf commands: "beam", "sweep beam", "mechanism analyze", ...
void collect(const std::string& path, std::map<std::string, std::string>& helps) {
  const test::CommandResult r = run_flexure(path + " --help");
  ASSERT_EQ(r.exit_code, 0) << path;
  const std::vector<std::string> children = subcommands(r.out);
  if (children.empty()) {
    helps[path] = r.out;
    return;
  }
  for (const std::string& child : children) collect(path + " " + child, helps);
}

TEST(CliDocs, EveryFlagOfEveryCommandIsDocumentedAndNoOther) {
  const std::string doc = test::read_text(std::string(FLEXURE_SOURCE_DIR) + "/docs/cli.md");
  ASSERT_FALSE(doc.empty());
  std::map<std::string, std::string> helps;
  for (const std::string& top : subcommands(run_flexure("--help").out)) collect(top, helps);
  ASSERT_GE(helps.size(), 10u);
  // Flags per documented section, over the commands it covers.
  std::map<std::string, std::set<std::string>> section_flags;
  for (const auto& [command, help] : helps) {
    std::string name = command;
    std::string text = section(doc, name);
    if (text.empty()) {
      name = command.substr(0, command.find(' '));
      text = section(doc, name);
    }
    ASSERT_FALSE(text.empty()) << "docs/cli.md has no section '## `flexure " << command << "`'";
    const std::set<std::string> documented = documented_flags(text);
    for (const std::string& flag : help_flags(help)) {
      EXPECT_TRUE(documented.count(flag))
          << "flexure " << command << " " << flag << " is in --help but not in docs/cli.md";
      section_flags[name].insert(flag);
    }
  }
  for (const auto& [name, flags] : section_flags) {
    for (const std::string& flag : documented_flags(section(doc, name))) {
      EXPECT_TRUE(flags.count(flag) || flag == "--help" || flag == "--version")
          << "docs/cli.md documents " << flag << " under `flexure " << name
          << "`, but no command there has it";
    }
  }
}

}  // namespace
}  // namespace flexure
