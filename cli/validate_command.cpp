// `flexure validate`: every available method against the built-in reference problems.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/validation_problems.h"
#include "flexure/io/beam_sweep.h"
#include "flexure/io/hdf5_file.h"
#include "flexure/io/output_path.h"
#include "flexure/solver/common/errors.h"

namespace flexure::cli {
namespace {

struct ValidateArgs {
  std::string out = "validation.h5";
  bool json = false;
};

// One row of the results table.
struct Check {
  std::string problem;
  std::string method;
  std::string quantity;
  double computed = std::numeric_limits<double>::quiet_NaN();  // NaN: the solve failed
  double reference = 0.0;
  double rel_error = std::numeric_limits<double>::quiet_NaN();
  double tolerance = 0.0;
  bool passed = false;
  double seconds_per_solve = 0.0;
  std::string message;  // the method's message when the solve failed or did not converge
};

// Timing: repeat a solve until this much time has passed (or kMaxRepeats), for a stable mean.
constexpr double kMinTimingSeconds = 2e-3;
constexpr int kMaxRepeats = 1000;

struct TimedSolve {
  BeamSolution solution;
  bool solved = false;
  std::string error;
  double seconds_per_solve = 0.0;
};

TimedSolve timed_solve(const ValidationMethod& method, const BeamProblem& problem) {
  TimedSolve timed;
  using Clock = std::chrono::steady_clock;
  try {
    const auto start = Clock::now();
    timed.solution = method.solve(problem);
    int repeats = 1;
    double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    while (elapsed < kMinTimingSeconds && repeats < kMaxRepeats) {
      method.solve(problem);
      ++repeats;
      elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    }
    timed.seconds_per_solve = elapsed / repeats;
    timed.solved = timed.solution.converged();
    if (!timed.solved) timed.error = "not converged: " + timed.solution.message;
  } catch (const std::exception& e) {
    // A reference problem the method rejects or cannot solve is a failed check, not a crash.
    timed.error = e.what();
  }
  return timed;
}

std::vector<Check> run_checks() {
  std::vector<Check> checks;
  const std::vector<ReferenceProblem> problems = reference_problems();
  for (const ValidationMethod& method : validation_methods()) {
    for (const ReferenceProblem& problem : problems) {
      if (!method.applies(problem)) continue;
      const TimedSolve timed = timed_solve(method, problem.problem);
      for (const ReferenceValue& expected : problem.expected) {
        Check check;
        check.problem = problem.name;
        check.method = method.name;
        check.quantity = expected.quantity;
        check.reference = expected.reference;
        // A numerical method passes within its own stated accuracy or the reference's rounding.
        check.tolerance = std::max(expected.tolerance, method.accuracy);
        check.seconds_per_solve = timed.seconds_per_solve;
        check.message = timed.error;
        if (timed.solved) {
          const double computed = quantity_value(timed.solution, expected.quantity);
          if (std::isfinite(computed)) {
            check.computed = computed;
            check.rel_error = std::abs(computed - expected.reference) /
                              std::max(std::abs(expected.reference), expected.scale_floor);
            check.passed = check.rel_error <= check.tolerance;
          } else {
            check.message = fmt::format("{} is not finite", expected.quantity);
          }
        }
        checks.push_back(std::move(check));
      }
    }
  }
  return checks;
}

void write_checks(io::Hdf5Group& root, const std::vector<Check>& checks, bool all_passed) {
  const auto column = [&](auto field) {
    using T = std::decay_t<decltype(field(checks.front()))>;
    std::vector<T> values;
    values.reserve(checks.size());
    for (const Check& check : checks) values.push_back(field(check));
    return values;
  };
  root.write_dataset("problem", column([](const Check& c) { return c.problem; }));
  root.write_dataset("method", column([](const Check& c) { return c.method; }));
  root.write_dataset("quantity", column([](const Check& c) { return c.quantity; }));
  root.write_dataset("message", column([](const Check& c) { return c.message; }));
  const auto doubles = [&](const char* name, auto field) {
    const std::vector<double> values = column(field);
    root.write_dataset(name, std::span<const double>(values));
  };
  doubles("computed", [](const Check& c) { return c.computed; });
  doubles("reference", [](const Check& c) { return c.reference; });
  doubles("rel_error", [](const Check& c) { return c.rel_error; });
  doubles("tolerance", [](const Check& c) { return c.tolerance; });
  doubles("seconds_per_solve", [](const Check& c) { return c.seconds_per_solve; });
  const std::vector<int> passed = column([](const Check& c) { return c.passed ? 1 : 0; });
  root.write_dataset("passed", std::span<const int>(passed));
  // Same convention as sweeps: status 1 flags rows whose computed value is NaN (no solution).
  const std::vector<int> status =
      column([](const Check& c) { return std::isfinite(c.computed) ? 0 : 1; });
  root.write_dataset("status", std::span<const int>(status));
  root.set_attribute("all_passed", static_cast<std::int64_t>(all_passed ? 1 : 0));
  root.set_attribute("count", static_cast<std::int64_t>(checks.size()));
  root.set_attribute(
      "rel_error_definition",
      "|computed - reference| / max(|reference|, scale_floor); scale_floor = 1 (one beam length) "
      "for end-moment lengths that vanish, else 0");
  io::write_provenance(root);
}

void print_table(const std::vector<Check>& checks, const std::string& out, bool all_passed) {
  fmt::print("{:<42} {:<9} {:<9} {:>16} {:>16} {:>9} {:>7} {:<4} {:>9}\n",
             "problem",
             "method",
             "quantity",
             "computed",
             "reference",
             "rel.err",
             "tol",
             "pass",
             "us/solve");
  for (const Check& c : checks) {
    fmt::print("{:<42} {:<9} {:<9} {:>16.10g} {:>16.10g} {:>9.2e} {:>7.0e} {:<4} {:>9.2f}\n",
               c.problem,
               c.method,
               c.quantity,
               c.computed,
               c.reference,
               c.rel_error,
               c.tolerance,
               c.passed ? "ok" : "FAIL",
               c.seconds_per_solve * 1e6);
    if (!c.message.empty()) fmt::print("    ({})\n", c.message);
  }
  const auto passed =
      std::count_if(checks.begin(), checks.end(), [](const Check& c) { return c.passed; });
  fmt::print("{} of {} checks passed{}; results written to {}\n",
             passed,
             checks.size(),
             all_passed ? "" : " -- SOME FAILED",
             out);
}

Json to_json(const std::vector<Check>& checks, const std::string& out, bool all_passed) {
  Json result;
  result["out"] = out;
  result["all_passed"] = all_passed;
  Json rows = Json::array();
  for (const Check& c : checks) {
    Json row;
    row["problem"] = c.problem;
    row["method"] = c.method;
    row["quantity"] = c.quantity;
    // A failed solve has no number: JSON null (never NaN), with the method's message.
    row["computed"] = std::isfinite(c.computed) ? Json(c.computed) : Json(nullptr);
    row["reference"] = c.reference;
    row["rel_error"] = std::isfinite(c.rel_error) ? Json(c.rel_error) : Json(nullptr);
    row["tolerance"] = c.tolerance;
    row["passed"] = c.passed;
    row["seconds_per_solve"] = c.seconds_per_solve;
    if (!c.message.empty()) row["message"] = c.message;
    rows.push_back(std::move(row));
  }
  result["checks"] = std::move(rows);
  return result;
}

void run_validate(const ValidateArgs& args) {
  io::check_output_path(args.out);
  std::unique_ptr<io::AtomicHdf5File> file;
  try {
    file = std::make_unique<io::AtomicHdf5File>(args.out);
  } catch (const io::Hdf5Error& e) {
    throw InvalidInput(fmt::format("--out: {}", e.what()));
  }
  const std::vector<Check> checks = run_checks();
  const bool all_passed =
      std::all_of(checks.begin(), checks.end(), [](const Check& c) { return c.passed; });
  write_checks(file->root(), checks, all_passed);
  file->commit();
  if (args.json) {
    print_json(to_json(checks, args.out, all_passed));
  } else {
    print_table(checks, args.out, all_passed);
  }
  if (!all_passed) set_exit_code(kExitCheckFailed);
}

}  // namespace

void register_validate_command(CLI::App& app) {
  auto args = std::make_shared<ValidateArgs>();
  CLI::App* validate = app.add_subcommand(
      "validate", "Check every available method against built-in reference problems");
  validate->add_option("--out", args->out, "Results file (HDF5, written atomically)")
      ->default_str("validation.h5");
  validate->add_flag("--json", args->json, "Print one JSON object on stdout");
  validate->callback([args] { run_validate(*args); });
}

}  // namespace flexure::cli
