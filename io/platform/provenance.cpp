#include "flexure/io/platform/provenance.h"

#include <fmt/format.h>

#include <chrono>
#include <ctime>
#include <fstream>
#include <iterator>
#include <mutex>
#include <string_view>
#include <utility>

#include "flexure/io/platform/mpi_world.h"
#include "flexure/version.h"

namespace flexure::io {
namespace {

std::mutex g_mutex;
std::vector<std::string> g_arguments;  // recorded by record_command_line
bool g_recorded = false;
// A command run in-process (CommandLineScope): this thread's files record it instead.
thread_local const std::vector<std::string>* t_scoped = nullptr;

// The arguments of this process from /proc/self/cmdline (NUL-separated); empty where there is
// no /proc.
std::vector<std::string> proc_arguments() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  const std::string raw((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::string> arguments;
  std::string current;
  for (char c : raw) {
    if (c == '\0') {
      arguments.push_back(current);
      current.clear();
    } else {
      current += c;
    }
  }
  if (!current.empty()) arguments.push_back(current);
  return arguments;
}

bool shell_safe(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
         std::string_view("@%+=:,./_-").find(c) != std::string_view::npos;
}

}  // namespace

void record_command_line(int argc, const char* const* argv) {
  const std::lock_guard lock(g_mutex);
  g_arguments.assign(argv, argv + argc);
  g_recorded = true;
}

CommandLineScope::CommandLineScope(std::vector<std::string> arguments)
    : arguments_(std::move(arguments)), previous_(t_scoped) {
  t_scoped = &arguments_;
}

CommandLineScope::~CommandLineScope() { t_scoped = previous_; }

std::string command_line() {
  std::vector<std::string> arguments;
  if (t_scoped != nullptr) {
    arguments = *t_scoped;
  } else {
    const std::lock_guard lock(g_mutex);
    arguments = g_recorded ? g_arguments : proc_arguments();
  }
  if (arguments.empty()) return "unknown";
  std::string line;
  for (const std::string& argument : arguments) {
    if (!line.empty()) line += ' ';
    line += shell_quote(argument);
  }
  return line;
}

std::string shell_quote(const std::string& argument) {
  bool safe = !argument.empty();
  for (char c : argument) safe = safe && shell_safe(c);
  if (safe) return argument;
  // Inside single quotes nothing is special except the quote itself: ' becomes '\''.
  std::string quoted = "'";
  for (char c : argument) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string utc_now_iso8601() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&now, &tm);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buffer;
}

const std::vector<std::string>& provenance_attribute_names() {
  static const std::vector<std::string> names = {
      "tool", "tool_version", "git_commit", "command_line", "creation_time", "status_meanings"};
  return names;
}

void write_provenance(Hdf5Group& root, const std::vector<CodeMeaning>& codes) {
  std::string meanings;
  for (const CodeMeaning& c : codes) {
    if (c.meaning.find('\n') != std::string::npos) {
      throw Hdf5Error(fmt::format(
          "HDF5: the meaning of {} {} in {} must be one line", c.dataset, c.code, root.where()));
    }
    if (!meanings.empty()) meanings += '\n';
    meanings += fmt::format("{} {}: {}", c.dataset, c.code, c.meaning);
  }
  root.set_attribute("tool", "flexure");
  root.set_attribute("tool_version", kVersion);
  root.set_attribute("git_commit", kGitCommit);
  // Attributes of a collective file are written by every rank with the same value: rank 0's.
  const auto same = [&](const std::string& value) {
    return root.collective() ? parallel::world().broadcast(value) : value;
  };
  root.set_attribute("command_line", same(command_line()));
  root.set_attribute("creation_time", same(utc_now_iso8601()));
  root.set_attribute("status_meanings", meanings);
}

}  // namespace flexure::io
