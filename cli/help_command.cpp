// `flexure help [COMMAND [SUBCOMMAND]]`: the same text as `flexure [COMMAND ...] --help`.
#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "flexure/solver/common/names.h"
#include "flexure/solver/common/status.h"

namespace flexure::cli {
namespace {

// The child of `parent` named `name` (any case), or null.
CLI::App* find_command(CLI::App& parent, const std::string& name) {
  for (CLI::App* child : parent.get_subcommands([](CLI::App*) { return true; })) {
    if (same_name(child->get_name(), name)) return child;
  }
  return nullptr;
}

std::string command_names(CLI::App& parent) {
  std::string names;
  for (CLI::App* child : parent.get_subcommands([](CLI::App*) { return true; })) {
    names += (names.empty() ? "" : ", ") + child->get_name();
  }
  return names;
}

}  // namespace

void register_help_command(CLI::App& app) {
  auto path = std::make_shared<std::vector<std::string>>();
  CLI::App* help =
      app.add_subcommand("help", "Help for flexure or one command: flexure help [COMMAND]");
  help->add_option("command", *path, "The command (and subcommand), e.g. 'mechanism analyze'");
  help->callback([&app, path] {
    CLI::App* target = &app;
    std::string usage_name = app.get_name();  // "flexure mechanism analyze", as --help prints it
    for (const std::string& name : *path) {
      CLI::App* next = find_command(*target, name);
      if (next == nullptr) {
        throw InvalidInput(fmt::format("'{}' is not a command of '{}' (commands: {})",
                                       name,
                                       target->get_name(),
                                       command_names(*target)));
      }
      target = next;
      usage_name += " " + target->get_name();
    }
    // make_help, not help(): App::help() of a parent shows its selected subcommand (this one).
    std::cout << target->get_formatter()->make_help(target, usage_name, CLI::AppFormatMode::Normal);
  });
}

}  // namespace flexure::cli
