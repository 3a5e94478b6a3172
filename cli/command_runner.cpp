#include "cli/command_runner.h"

#include <fmt/format.h>

#include <utility>

#include "cli/command_table.h"
#include "cli/slow_progress.h"
#include "flexure/io/platform/provenance.h"

namespace flexure::cli {

void register_all_commands(CLI::App& app) {
  std::vector<std::string> names;
  for (const CommandEntry& entry : command_table()) names.emplace_back(entry.name);
  register_commands_for(app, names);
}

CommandOutput run_command(const std::vector<std::string>& args,
                          std::function<void(std::size_t done, std::size_t total)> progress) {
  CLI::App app{"flexure: exact large-deflection beams and compliant mechanisms", "flexure"};
  register_commands_for(app, args);
  std::vector<std::string> words{"flexure"};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  OutputCapture capture;
  // Files written by the command record the command line it stands for.
  const io::CommandLineScope command_line(words);
  // The run's progress, like its output capture, belongs to this thread for the call.
  const ProgressSink sink(std::move(progress));
  reset_exit_code();
  try {
    parse_and_run(app, static_cast<int>(words.size()), argv.data());
  } catch (const CLI::Success&) {
    // --help or --version: nothing to return as data.
    throw InvalidInput(fmt::format("'{}' asks for help text, which run_command does not return",
                                   fmt::join(args, " ")));
  }
  CommandOutput out;
  out.json = std::move(capture.json);
  out.warnings = std::move(capture.warnings);
  out.exit_code = exit_code();
  return out;
}

}  // namespace flexure::cli
