#pragma once
// The `flexure` commands as a library call: run_command({"beam", "--alpha2", "2", "--json"})
// parses and runs exactly what the tool would (the same registration, validation, defaults and
// messages) in this process, and returns the JSON object the tool would print instead of printing
// it. The Python module (python/, docs/python.md) is built on this, so its functions take the
// tool's flags and return the tool's keys by construction.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "cli/cli_common.h"

namespace flexure::cli {

// Adds every subcommand of the tool to `app`, each in full (tests, tools that walk the help).
// main.cpp and run_command register in full only the commands their arguments name
// (register_commands_for, command_table.h).
void register_all_commands(CLI::App& app);

struct CommandOutput {
  Json json;                          // the object the command prints with --json (null if none)
  std::vector<std::string> warnings;  // what it would print as "flexure: warning: ..."
  int exit_code = kExitOk;            // 0, or 1 when a check failed (validate)
};

// Runs one command line without the program name. Throws InvalidInput (exit code 2 of the tool:
// bad values, unknown flags and names, with the tool's message), NoConvergenceReport or
// NoConvergence (exit code 3), std::exception otherwise. Thread-safe: each thread has its own
// capture and exit code. Progress lines of long commands still go to stderr on a terminal.
// `progress`, when given, is called on this thread at every step of the command's long work that
// can stop between steps (stoppable_progress, cli/slow_progress.h: the dynamics study's
// frequencies, the exact CFM design's strokes, the PRBM synthesis's local runs, a mechanism's
// exact stroke, a sweep's points); it may throw to stop the command, and its exception leaves
// run_command with no output file written (the Python module's progress callables and Ctrl-C).
CommandOutput run_command(const std::vector<std::string>& args,
                          std::function<void(std::size_t done, std::size_t total)> progress = {});

}  // namespace flexure::cli
