#pragma once
// The top-level commands of the tool, in the order `flexure --help` lists them, and their
// registration. A process registers in full only the commands its arguments name; every other
// command is a stub (name and description, nothing else), so that `flexure --help`, "A subcommand
// is required" and the hints of a parse error read exactly as with every command registered, while
// `flexure beam --alpha2 2` does not pay for building the options of the other twelve (a third of
// its instructions did: docs/performance.md "Start-up").
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace flexure::cli {

struct CommandEntry {
  const char* name;         // "beam", "design", ...
  const char* description;  // the text `flexure --help` lists; the same as the full registration's
                            // (tests/cli/cli_registration_test.cpp)
  std::vector<void (*)(CLI::App&)> registrars;  // design: design cfm and design mechanism
};

// The 12 top-level commands (13 registration functions), help last.
const std::vector<CommandEntry>& command_table();

// Adds every command to `app`: in full each one that a word of `args` (the command line without
// the program name) names, in any case, wherever it stands (`help beam` names help and beam); a
// stub for the others. Also the --version flag, "one subcommand required" and the examples that
// end each registered command's --help. A word never names a stub that CLI11 would select: CLI11
// selects a subcommand only by a word equal to its name.
void register_commands_for(CLI::App& app, const std::vector<std::string>& args);

}  // namespace flexure::cli
