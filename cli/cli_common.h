#pragma once
// Shared plumbing for every `flexure` subcommand: exit codes, the exception -> exit-code mapping,
// JSON output that refuses NaN/Inf, and START:STOP:COUNT ranges.
//
// The contract (kept by all later subcommands):
//  * with --json a command prints exactly ONE JSON object on stdout (print_json); when it fails,
//    that object is {"error": message, "exit_code": 2|3|4, ...what was reached} (run_app), so
//    that scripts never parse stderr;
//  * errors go to stderr as ONE line naming the offending input and the allowed range;
//  * exit 0 success, 1 a check failed (validate), 2 invalid input (InvalidInput, CLI11 parse
//    errors), 3 no converged solution (NoConvergence, or a NaN/Inf about to be printed),
//    4 anything else (an I/O failure after solving, a bug);
//  * a command that writes a file and then finds some points unsolved (sweep) writes the file,
//    prints its normal output, then exits 3 with the one-line reason on stderr.
//
// A subcommand's callback does its work and either returns normally (exit 0), calls
// set_exit_code(...) for a non-error non-zero code (e.g. validate's "a check failed"), or throws
// InvalidInput / NoConvergence; run_app() in main.cpp maps the exceptions.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "flexure/solver/common/status.h"

namespace flexure::cli {

// Process exit codes of the tool.
enum ExitCode : int {
  kExitOk = 0,
  kExitCheckFailed = 1,    // validate: a reference check failed
  kExitInvalidInput = 2,   // bad input or a command-line parse error
  kExitNoConvergence = 3,  // a method produced no converged (finite) solution
  kExitInternal = 4,       // unexpected internal error (a bug, or an I/O failure after solving)
};

// Insertion order is kept so that printed objects read in the documented key order.
using Json = nlohmann::ordered_json;

// The child subcommand `name` of `parent`, created with `description` if it does not exist yet
// (lets several files add children to one parent, e.g. `sweep beam`, `sweep mechanism`).
CLI::App& get_or_add_subcommand(CLI::App& parent,
                                const std::string& name,
                                const std::string& description);

// Exit code a command wants when it finishes without throwing (default kExitOk). Per thread;
// reset_exit_code() before a command runs (run_app, run_command).
void set_exit_code(int code);
int exit_code();
void reset_exit_code();

// While one exists on this thread, print_json stores its object here instead of printing it and
// warn() collects its texts (run_command, command_runner.h). Nests: the innermost one collects.
class OutputCapture {
 public:
  OutputCapture();
  ~OutputCapture();
  OutputCapture(const OutputCapture&) = delete;
  OutputCapture& operator=(const OutputCapture&) = delete;
  nlohmann::ordered_json json;  // null until print_json runs
  std::vector<std::string> warnings;

 private:
  OutputCapture* previous_;
};

// NoConvergence that carries what was reached (load factor, method tried, ...): run_app adds these
// keys to the JSON error object printed with --json.
class NoConvergenceReport : public NoConvergence {
 public:
  NoConvergenceReport(const std::string& message, Json reached)
      : NoConvergence(message), reached_(std::move(reached)) {}
  const Json& reached() const { return reached_; }

 private:
  Json reached_;
};

// InvalidInput with keys for the JSON error object (e.g. the tolerance that can be met).
class InvalidInputReport : public InvalidInput {
 public:
  InvalidInputReport(const std::string& message, Json keys)
      : InvalidInput(message), keys_(std::move(keys)) {}
  const Json& keys() const { return keys_; }

 private:
  Json keys_;
};

// Parses argv with `app` and runs the selected subcommand's callback. Maps CLI11 parse errors and
// InvalidInput to 2, NoConvergence to 3, anything else to 4, each as one line on stderr prefixed
// "flexure: ". --help and --version print to stdout and return 0. When argv holds --json and the
// command has not printed its JSON object yet, a failure also prints the JSON error object on
// stdout: {"error": the message, "exit_code": the code, ...NoConvergenceReport::reached() or
// InvalidInputReport::keys()}.
int run_app(CLI::App& app, int argc, char** argv);

// Parses argv with `app` and runs the selected subcommand's callback, letting every failure
// through as an exception: a CLI11 parse error becomes InvalidInput with the message run_app
// prints (the nearest flag to an unknown one, where the help is); --help and --version stay
// CLI11's CallForHelp / CallForVersion.
void parse_and_run(CLI::App& app, int argc, char** argv);

// Prints `object` as one line of JSON on stdout. Throws NoConvergence naming the key if any
// number in it is NaN or Inf (a result is never printed as NaN).
void print_json(const Json& object);
// The check of print_json alone (for a JSON object handed to Python instead of printed).
void require_finite_json(const Json& object);

// Throws NoConvergence naming `what` unless `value` is finite. Used on results before printing.
void require_finite_result(double value, const std::string& what);

// Throws InvalidInput naming `what` (e.g. "--alpha2 (P l^2/EI)") unless `value` is finite.
void require_finite_input(double value, const std::string& what);

// Throws InvalidInput naming `what` and the allowed range unless lo <= value <= hi and finite.
void require_in_range(double value, const std::string& what, double lo, double hi);

// A range "START:STOP:COUNT": COUNT >= 1 equally spaced values from START to STOP inclusive
// (STOP may be below START; COUNT == 1 gives START only).
// "flexure: warning: TEXT" on stderr; nothing for an empty text. Warnings never change the exit
// code or stdout.
void warn(const std::string& text);
void warn(const std::vector<std::string>& texts);

// Strict decimal parse of a whole token (no trailing characters); "nan" and "inf" parse, so that
// the caller rejects them with a message naming the quantity.
bool parse_double(const std::string& token, double& value);

struct Range {
  double start = 0.0;
  double stop = 0.0;
  long count = 1;
  double at(long i) const;  // i-th value, exact at both ends
};
// Throws InvalidInput naming `what` unless `text` is START:STOP:COUNT with finite START and STOP
// and an integer 1 <= COUNT <= max_count.
Range parse_range(const std::string& text, const std::string& what, long max_count = 100'000'000);

}  // namespace flexure::cli
