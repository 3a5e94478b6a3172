// `flexure validate`: every available method against the built-in reference problems.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "flexure/benchmarks/studies/validation_checks.h"
#include "flexure/io/hdf5_file.h"
#include "flexure/io/output_path.h"
#include "flexure/io/provenance.h"
#include "flexure/solver/common/errors.h"

namespace flexure::cli {
namespace {

struct ValidateArgs {
  std::string out = "validation.h5";
  bool json = false;
};

void write_checks(io::Hdf5Group& root,
                  const std::vector<ValidationCheck>& checks,
                  bool all_passed) {
  const auto column = [&](auto field) {
    using T = std::decay_t<decltype(field(checks.front()))>;
    std::vector<T> values;
    values.reserve(checks.size());
    for (const ValidationCheck& check : checks) values.push_back(field(check));
    return values;
  };
  root.write_dataset("problem",
                     column([](const ValidationCheck& c) { return c.problem; }),
                     "text",
                     "reference problem of the row");
  root.write_dataset(
      "method", column([](const ValidationCheck& c) { return c.method; }), "text", "method solved");
  root.write_dataset("quantity",
                     column([](const ValidationCheck& c) { return c.quantity; }),
                     "text",
                     "compared quantity: alpha, alpha2, a_over_l, b_over_l or theta0");
  root.write_dataset("message",
                     column([](const ValidationCheck& c) { return c.message; }),
                     "text",
                     "empty, or why the method gave no number");
  // theta0 is an angle, the other quantities are nondimensional (l = 1, EI = 1): the unit differs
  // by row, so each row names it.
  root.write_dataset("quantity_units",
                     column([](const ValidationCheck& c) {
                       return std::string(c.quantity == "theta0" ? "rad" : "1");
                     }),
                     "text",
                     "units of computed and reference in this row");
  const auto doubles = [&](const char* name, auto field, const char* units, const char* what) {
    const std::vector<double> values = column(field);
    root.write_dataset(name, std::span<const double>(values), units, what);
  };
  doubles(
      "computed",
      [](const ValidationCheck& c) { return c.computed; },
      "per row: quantity_units",
      "the method's value; NaN where status is 1");
  doubles(
      "reference",
      [](const ValidationCheck& c) { return c.reference; },
      "per row: quantity_units",
      "independent reference value (docs/validation.md)");
  doubles(
      "rel_error",
      [](const ValidationCheck& c) { return c.rel_error; },
      "1",
      "relative error (root attribute rel_error_definition); NaN where status is 1");
  doubles(
      "tolerance",
      [](const ValidationCheck& c) { return c.tolerance; },
      "1",
      "largest rel_error that passes");
  doubles(
      "seconds_per_solve",
      [](const ValidationCheck& c) { return c.seconds_per_solve; },
      "s",
      "wall time of one solve");
  const std::vector<int> passed = column([](const ValidationCheck& c) { return c.passed ? 1 : 0; });
  root.write_dataset(
      "passed", std::span<const int>(passed), "1", "1 rel_error <= tolerance, 0 failed");
  // Same convention as sweeps: status 1 flags rows whose computed value is NaN (no solution).
  const std::vector<int> status =
      column([](const ValidationCheck& c) { return std::isfinite(c.computed) ? 0 : 1; });
  root.write_dataset("status",
                     std::span<const int>(status),
                     "1",
                     "0 solved, 1 no solution (root status_meanings)");
  root.set_attribute("all_passed", static_cast<std::int64_t>(all_passed ? 1 : 0));
  root.set_attribute("count", static_cast<std::int64_t>(checks.size()));
  root.set_attribute(
      "rel_error_definition",
      "|computed - reference| / max(|reference|, scale_floor); scale_floor = 1 (one beam length) "
      "for end-moment lengths that vanish, else 0");
  io::write_provenance(root,
                       {{"status", 0, "the method gave a finite value"},
                        {"status", 1, "no solution: computed and rel_error are NaN"}});
}

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
  io::check_output_path(args.out);
  std::unique_ptr<io::AtomicHdf5File> file;
  try {
    file = std::make_unique<io::AtomicHdf5File>(args.out);
  } catch (const io::Hdf5Error& e) {
    throw InvalidInput(fmt::format("--out: {}", e.what()));
  }
  const std::vector<ValidationCheck> checks = run_validation_checks();
  const bool all_passed =
      std::all_of(checks.begin(), checks.end(), [](const ValidationCheck& c) { return c.passed; });
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
