// What is checked against what: a process registers in full only the commands its arguments
// name, the others as stubs (cli/command_table.h), and nobody can tell from the outside:
//  * every table description equals the one the full registration gives its subcommand (the
//    stub's text is a copy);
//  * with the command named, its help is the full registration's (same options, subcommands,
//    examples); the other commands are stubs (no option besides --help, no subcommand);
//  * the top-level help with stubs equals the one with every command registered;
//  * parse errors (unknown command, misspelt flag, missing subcommand, an unknown command beside
//    a real one, `help` of an unknown name) give the same message either way.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_common.h"
#include "cli/command_runner.h"
#include "cli/command_table.h"

namespace flexure::cli {
namespace {

std::unique_ptr<CLI::App> new_app() {
  return std::make_unique<CLI::App>(
      "flexure: exact large-deflection beams and compliant mechanisms", "flexure");
}

std::unique_ptr<CLI::App> full_app() {
  auto app = new_app();
  register_all_commands(*app);
  return app;
}

std::unique_ptr<CLI::App> app_for(const std::vector<std::string>& args) {
  auto app = new_app();
  register_commands_for(*app, args);
  return app;
}

std::string help_of(CLI::App& app, const std::string& path) {
  CLI::App* command = &app;
  std::string usage = "flexure";
  std::istringstream words(path);
  for (std::string word; words >> word;) {
    command = command->get_subcommand(word);
    usage += " " + word;
  }
  return command->get_formatter()->make_help(command, usage, CLI::AppFormatMode::Normal);
}

// CLI11 lists an option's "Excludes:" in the order of the options' addresses (a std::set of
// pointers), which depends on what else the process allocated: compared as sets.
std::string sorted_excludes(const std::string& help) {
  std::istringstream in(help);
  std::string out;
  for (std::string line; std::getline(in, line);) {
    const std::size_t at = line.find(" Excludes: ");
    if (at != std::string::npos) {
      std::istringstream words(line.substr(at + 11));
      std::vector<std::string> names;
      std::string rest;
      for (std::string w; words >> w;) {
        if (rest.empty() && w.rfind("--", 0) == 0) {
          names.push_back(w);
        } else {
          rest += " " + w;
        }
      }
      std::sort(names.begin(), names.end());
      line = line.substr(0, at) + " Excludes:";
      for (const std::string& n : names) line += " " + n;
      line += rest;
    }
    out += line + "\n";
  }
  return out;
}

bool is_stub(CLI::App& command) {
  return command.get_options().size() == 1 &&  // --help
         command.get_subcommands([](CLI::App*) { return true; }).empty();
}

TEST(CliRegistration, TableDescriptionsAreTheRegisteredOnes) {
  auto full = full_app();
  ASSERT_EQ(full->get_subcommands([](CLI::App*) { return true; }).size(), command_table().size());
  for (const CommandEntry& entry : command_table()) {
    EXPECT_EQ(full->get_subcommand(entry.name)->get_description(), entry.description) << entry.name;
  }
}

TEST(CliRegistration, OnlyTheNamedCommandIsRegisteredInFull) {
  auto full = full_app();
  for (const CommandEntry& entry : command_table()) {
    auto app = app_for({entry.name});
    for (const CommandEntry& other : command_table()) {
      CLI::App* command = app->get_subcommand(other.name);
      if (other.name == entry.name) {
        EXPECT_FALSE(is_stub(*command)) << other.name;
        EXPECT_EQ(sorted_excludes(help_of(*app, other.name)),
                  sorted_excludes(help_of(*full, other.name)))
            << other.name;
        for (CLI::App* child : command->get_subcommands([](CLI::App*) { return true; })) {
          if (dynamic_cast<CLI::Option_group*>(child) != nullptr) continue;
          const std::string path = std::string(other.name) + " " + child->get_name();
          EXPECT_EQ(sorted_excludes(help_of(*app, path)), sorted_excludes(help_of(*full, path)))
              << path;
        }
      } else {
        EXPECT_TRUE(is_stub(*command)) << other.name << " registered for " << entry.name;
      }
    }
  }
  // `help beam` names both; names match in any case, as `flexure help BEAM` does.
  auto help = app_for({"help", "BEAM"});
  EXPECT_FALSE(is_stub(*help->get_subcommand("help")));
  EXPECT_FALSE(is_stub(*help->get_subcommand("beam")));
  EXPECT_TRUE(is_stub(*help->get_subcommand("cfm")));
  // Flag values are words too: registering more than needed is harmless.
  EXPECT_TRUE(is_stub(*app_for({"--json"})->get_subcommand("beam")));
}

TEST(CliRegistration, TopLevelHelpIsTheSameWithStubs) {
  auto full = full_app();
  auto stubs = app_for({});
  EXPECT_EQ(help_of(*stubs, ""), help_of(*full, ""));
  EXPECT_FALSE(help_of(*stubs, "").empty());
}

// The message of the InvalidInput that parsing `args` throws (empty when it does not throw).
std::string parse_error(CLI::App& app, const std::vector<std::string>& args) {
  std::vector<std::string> words{"flexure"};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  try {
    parse_and_run(app, static_cast<int>(words.size()), argv.data());
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return {};
}

TEST(CliRegistration, ParseErrorsAreTheSameWithStubs) {
  const std::vector<std::vector<std::string>> cases = {
      {},
      {"beem"},
      {"beam", "--alpah2", "3"},
      {"beam", "--alpha2", ""},
      {"mechanism"},
      {"mechanism", "analyz"},
      {"beem", "beam", "--alpha2", "2"},
      {"sweep", "beam", "--alpha", "1:2:3"},
      {"--alpha2", "2"},
      {"help", "bean"},
      {"help", "sweep", "bean"},
      {"design", "cfm", "--confg", "lpp"},
  };
  for (const std::vector<std::string>& args : cases) {
    auto full = full_app();
    auto stubs = app_for(args);
    const std::string expected = parse_error(*full, args);
    std::string text;
    for (const std::string& a : args) text += a + " ";
    EXPECT_FALSE(expected.empty()) << text;
    EXPECT_EQ(parse_error(*stubs, args), expected) << text;
  }
}

}  // namespace
}  // namespace flexure::cli
