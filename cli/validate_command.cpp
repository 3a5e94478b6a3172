// `flexure validate`: every available method against the built-in reference problems.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/csv_output.h"
#include "flexure/benchmarks/studies/validation_checks.h"
#include "flexure/benchmarks/studies/validation_file.h"
#include "flexure/io/platform/output_path.h"
#include "flexure/solver/common/status.h"

namespace flexure::cli {
namespace {

struct ValidateArgs {
  std::string out = "validation.h5";
  bool json = false;
};

void print_table(const std::vector<ValidationCheck>& checks,
                 const std::string& out,
                 bool all_passed) {
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
  for (const ValidationCheck& c : checks) {
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
  const auto passed = std::count_if(
      checks.begin(), checks.end(), [](const ValidationCheck& c) { return c.passed; });
  fmt::print("{} of {} checks passed{}; results written to {}\n",
             passed,
             checks.size(),
             all_passed ? "" : " -- SOME FAILED",
             out);
}

Json to_json(const std::vector<ValidationCheck>& checks, const std::string& out, bool all_passed) {
  Json result;
  result["out"] = out;
  result["all_passed"] = all_passed;
  Json rows = Json::array();
  for (const ValidationCheck& c : checks) {
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
  refuse_csv_out(args.out, "the checks with their attributes; --json prints them");
  io::check_output_path(args.out);
  std::optional<ValidationFile> file;
  try {
    file.emplace(args.out);
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("--out: {}", e.what()));
  }
  const ValidationReport report = run_validation();
  file->write(report);
  if (args.json) {
    print_json(to_json(report.checks, args.out, report.all_passed));
  } else {
    print_table(report.checks, args.out, report.all_passed);
  }
  if (!report.all_passed) set_exit_code(kExitCheckFailed);
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
