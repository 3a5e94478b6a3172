#include "cli/cli_common.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <vector>

#include "cli/mpi_launch.h"
#include "flexure/io/platform/mpi_world.h"
#include "flexure/solver/common/evenly_spaced.h"
#include "flexure/solver/common/status.h"

namespace flexure::cli {
namespace {

// Per thread: run_command (command_runner.h) runs commands in-process, possibly on several
// threads at once (the Python module releases its lock while a command runs).
thread_local int g_exit_code = kExitOk;
thread_local bool g_json_printed = false;  // print_json ran: a failure prints no second object
thread_local OutputCapture* g_capture = nullptr;  // run_command: collect instead of printing

// Error messages must stay on one line even when they quote user input or library text.
std::string one_line(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

void report(const std::string& message) { std::cerr << "flexure: " << one_line(message) << '\n'; }

// Levenshtein distance between two short names.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1] ? 1 : 0)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// For a parse error: the command the arguments were meant for, the nearest flag to each unknown
// one ("did you mean --alpha2?"), and where its help is.
std::string parse_error_hint(CLI::App& app, int argc, char** argv) {
  CLI::App* target = &app;
  std::string command = app.get_name();
  std::vector<std::string> flags;
  for (int i = 1; i < argc; ++i) {
    const std::string token = argv[i];
    if (token.empty()) continue;
    if (token.rfind("--", 0) == 0) {
      flags.push_back(token.substr(
          2, token.find('=') == std::string::npos ? std::string::npos : token.find('=') - 2));
      continue;
    }
    for (CLI::App* child : target->get_subcommands([](CLI::App*) { return true; })) {
      if (child->get_name() == token) {
        target = child;
        command += " " + token;
        break;
      }
    }
  }
  std::vector<std::string> known;
  const auto add_names = [&known](const CLI::App& from) {
    for (const CLI::Option* option : from.get_options()) {
      for (const std::string& name : option->get_lnames()) known.push_back(name);
    }
  };
  add_names(*target);
  // Options in option groups (e.g. beam's exactly-one-of --alpha2, --theta0, --b-over-l).
  for (CLI::App* child : target->get_subcommands([](CLI::App*) { return true; })) {
    if (dynamic_cast<CLI::Option_group*>(child) != nullptr) add_names(*child);
  }
  std::string hint;
  for (const std::string& flag : flags) {
    if (flag.empty() || std::find(known.begin(), known.end(), flag) != known.end()) continue;
    const std::string* nearest = nullptr;
    std::size_t best = std::max<std::size_t>(2, flag.size() / 3) + 1;
    for (const std::string& name : known) {
      const std::size_t d = edit_distance(flag, name);
      if (d < best || (d == best && nearest == nullptr && name.rfind(flag, 0) == 0)) {
        best = d;
        nearest = &name;
      }
    }
    if (nearest != nullptr) hint += fmt::format("did you mean --{} for --{}? ", *nearest, flag);
  }
  return fmt::format("{}run '{} --help' for the allowed arguments", hint, command);
}

bool wants_json(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--json") return true;
  }
  return false;
}

// The JSON error object of a failed command run with --json (one line on stdout).
void report_json(const std::string& message, int code, const Json& reached = Json::object()) {
  if (g_json_printed) return;
  Json error;
  error["error"] = one_line(message);
  error["exit_code"] = code;
  for (const auto& [key, value] : reached.items()) error[key] = value;
  std::cout << error.dump() << '\n';
  std::cout.flush();
}

// Depth-first search for the first non-finite number; returns its JSON pointer or "".
std::string find_non_finite(const Json& node, const std::string& where) {
  if (node.is_number_float()) {
    return std::isfinite(node.get<double>()) ? std::string() : (where.empty() ? "/" : where);
  }
  if (node.is_object()) {
    for (const auto& [key, value] : node.items()) {
      std::string found = find_non_finite(value, where + "/" + key);
      if (!found.empty()) return found;
    }
  } else if (node.is_array()) {
    for (std::size_t i = 0; i < node.size(); ++i) {
      std::string found = find_non_finite(node[i], where + "/" + std::to_string(i));
      if (!found.empty()) return found;
    }
  }
  return {};
}

}  // namespace

void warn(const std::string& text) {
  // Under mpirun rank 0 alone prints (docs/scaling.md): the ranks meet the same input, and the
  // distributed commands bring the warnings of their items to rank 0.
  if (text.empty() || parallel::launched_rank() != 0) return;
  if (g_capture != nullptr) {
    g_capture->warnings.push_back(text);
  } else {
    std::cerr << "flexure: warning: " << text << "\n";
  }
}

OutputCapture::OutputCapture() : previous_(g_capture) { g_capture = this; }
OutputCapture::~OutputCapture() { g_capture = previous_; }

void warn(const std::vector<std::string>& texts) {
  for (const std::string& text : texts) warn(text);
}

// Strict decimal parse of a whole token (no trailing characters); accepts "nan"/"inf" so that the
// caller can reject them with a message naming the quantity.
bool parse_double(const std::string& token, double& value) {
  if (token.empty()) return false;
  char* end = nullptr;
  value = std::strtod(token.c_str(), &end);
  return end == token.c_str() + token.size();
}

CLI::App& get_or_add_subcommand(CLI::App& parent,
                                const std::string& name,
                                const std::string& description) {
  for (CLI::App* child : parent.get_subcommands([](CLI::App*) { return true; })) {
    if (child->get_name() == name) return *child;
  }
  return *parent.add_subcommand(name, description);
}

void set_exit_code(int code) { g_exit_code = code; }
void reset_exit_code() {
  g_exit_code = kExitOk;
  g_json_printed = false;
}
int exit_code() { return g_exit_code; }

void parse_and_run(CLI::App& app, int argc, char** argv) {
  // CLI11 reads an empty value as the option's default (--alpha2 '' as 0): refuse it instead.
  for (int i = 1; i < argc; ++i) {
    const std::string token = argv[i];
    const bool empty_after_flag =
        token.empty() && i > 1 && std::string(argv[i - 1]).rfind("--", 0) == 0;
    if (empty_after_flag || (token.rfind("--", 0) == 0 && token.back() == '=')) {
      const std::string flag = empty_after_flag ? argv[i - 1] : token.substr(0, token.size() - 1);
      throw InvalidInput(
          fmt::format("{} has an empty value ({})", flag, parse_error_hint(app, argc, argv)));
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    throw;
  } catch (const CLI::CallForAllHelp&) {
    throw;
  } catch (const CLI::CallForVersion&) {
    throw;
  } catch (const CLI::ParseError& e) {
    // CLI11 reports missing, conflicting, unknown and non-numeric arguments here.
    throw InvalidInput(fmt::format("{} ({})", e.what(), parse_error_hint(app, argc, argv)));
  }
}

namespace {

// The exit code of an exception's type (the table in cli_common.h).
int exit_code_of(const std::exception_ptr& cause) {
  try {
    std::rethrow_exception(cause);
  } catch (const InvalidInput&) {
    return kExitInvalidInput;
  } catch (const NoConvergence&) {
    return kExitNoConvergence;
  } catch (...) {
    return kExitInternal;
  }
}

}  // namespace

namespace {

// Under mpirun, the end of a run on every rank (docs/scaling.md "Failures"): the ranks agree on
// the exit code, the largest of theirs, so that an error one rank met after the shared work (rank
// 0 printing its report, say) ends the others with it. `message` is this rank's error, if any: rank
// 0 prints its own; another rank prints its own only where rank 0 did not meet the same. A rank
// that does not arrive within `seconds` (negative: no limit) would leave the others waiting:
// the run then ends with MPI_Abort, never a hang.
int end_together(
    int code, double seconds, const std::string& message, bool json, const Json& reached) {
  const bool mpi = parallel::world_started() && parallel::world().parallel();
  // The JSON error object from rank 0 alone: stdout holds one object (a rank's own error goes to
  // stderr as text).
  const auto print = [&](const std::string& text) {
    report(text);
    if (json && parallel::launched_rank() == 0) report_json(text, code, reached);
  };
  if (!mpi) {
    if (!message.empty() && parallel::launched_rank() == 0) print(message);
    return code;
  }
  const parallel::World& w = parallel::world();
  report_balance();
  const std::optional<parallel::World::AgreedCode> agreed = w.agree(code, seconds);
  if (!message.empty() && (w.root() || !agreed || agreed->root != code)) {
    print(w.root() ? message : fmt::format("rank {}: {}", w.rank(), message));
  }
  if (!agreed) w.abort(code == 0 ? kExitInternal : code);
  if (w.root() && agreed->largest != code && code == 0) {
    report(fmt::format("another rank failed (exit code {}); it prints its own message",
                       agreed->largest));
  }
  return agreed->largest;
}

}  // namespace

int run_app(CLI::App& app, int argc, char** argv) {
  reset_exit_code();
  const bool json = wants_json(argc, argv);
  // Under mpirun (docs/scaling.md): rank 0 prints the report and the errors every rank meets
  // alike; a rank prints a failure of its own (RankFailure) and ends the run at once with
  // MPI_Abort; otherwise the ranks end together with one exit code (end_together): never a hang.
  silence_stdout_of_other_ranks();
  parallel::set_rank_failure_handler([json](const parallel::RankFailure& e) {
    const int code = exit_code_of(e.cause());
    restore_stdout();
    report(e.what());
    if (json) report_json(e.what(), code, Json::object());
    parallel::world().abort(code);
  });
  const auto fail = [&](const std::string& message, int code, const Json& reached) {
    return end_together(code, 10.0, message, json, reached);
  };
  try {
    check_mpi_launch(argc, argv);
    parse_and_run(app, argc, argv);
  } catch (const parallel::RankFailure& e) {
    // Not reached in the tool (the handler above ends the run); kept for a caller without it.
    const int code = exit_code_of(e.cause());
    restore_stdout();
    report(e.what());
    if (json) report_json(e.what(), code, Json::object());
    parallel::world().abort(code);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const InvalidInputReport& e) {
    return fail(e.what(), kExitInvalidInput, e.keys());
  } catch (const InvalidInput& e) {
    return fail(e.what(), kExitInvalidInput, Json::object());
  } catch (const NoConvergenceReport& e) {
    return fail(e.what(), kExitNoConvergence, e.reached());
  } catch (const NoConvergence& e) {
    return fail(e.what(), kExitNoConvergence, Json::object());
  } catch (const std::exception& e) {
    return fail(fmt::format("error: {}", e.what()), kExitInternal, Json::object());
  }
  // Outside the try: each rank agrees once, on this path or on a failure's.
  return end_together(g_exit_code, -1.0, "", json, Json::object());
}

void require_finite_json(const Json& object) {
  const std::string bad = find_non_finite(object, "");
  if (!bad.empty()) {
    throw NoConvergence(
        fmt::format("result '{}' is not a finite number; no converged solution to report", bad));
  }
}

void print_json(const Json& object) {
  require_finite_json(object);
  if (g_capture != nullptr) {
    g_capture->json = object;
  } else {
    std::cout << object.dump() << '\n';
    std::cout.flush();
  }
  g_json_printed = true;
}

void require_finite_result(double value, const std::string& what) {
  if (!std::isfinite(value)) {
    throw NoConvergence(
        fmt::format("{} came out as {}; no converged solution to report", what, value));
  }
}

void require_finite_input(double value, const std::string& what) {
  if (!std::isfinite(value)) {
    throw InvalidInput(fmt::format(
        "{} = {} is not allowed: it must be a finite number (not NaN or Inf)", what, value));
  }
}

void require_in_range(double value, const std::string& what, double lo, double hi) {
  if (!std::isfinite(value) || value < lo || value > hi) {
    throw InvalidInput(
        fmt::format("{} = {} is outside the allowed range [{}, {}]", what, value, lo, hi));
  }
}

double Range::at(long i) const { return evenly_spaced(start, stop, count, i); }

Range parse_range(const std::string& text, const std::string& what, long max_count) {
  const auto fail = [&](const std::string& why) {
    return InvalidInput(fmt::format(
        "{} = '{}' is not a valid range: {} (expected START:STOP:COUNT with finite START, STOP "
        "and an integer COUNT in [1, {}])",
        what,
        text,
        why,
        max_count));
  };
  const auto first = text.find(':');
  const auto second = first == std::string::npos ? std::string::npos : text.find(':', first + 1);
  if (second == std::string::npos || text.find(':', second + 1) != std::string::npos) {
    throw fail("it needs exactly two ':'");
  }
  Range range;
  if (!parse_double(text.substr(0, first), range.start) || !std::isfinite(range.start)) {
    throw fail("START is not a finite number");
  }
  if (!parse_double(text.substr(first + 1, second - first - 1), range.stop) ||
      !std::isfinite(range.stop)) {
    throw fail("STOP is not a finite number");
  }
  const std::string count_text = text.substr(second + 1);
  long count = 0;
  const auto [ptr, ec] =
      std::from_chars(count_text.data(), count_text.data() + count_text.size(), count);
  if (count_text.empty() || ec != std::errc() || ptr != count_text.data() + count_text.size()) {
    throw fail("COUNT is not an integer");
  }
  if (count < 1 || count > max_count) throw fail("COUNT is out of range");
  range.count = count;
  return range;
}

}  // namespace flexure::cli
