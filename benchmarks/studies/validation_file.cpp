#include "flexure/benchmarks/studies/validation_file.h"

#include <cmath>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "flexure/io/platform/hdf5_file.h"
#include "flexure/io/platform/provenance.h"
#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

void write_checks(io::Hdf5Group& root, const ValidationReport& report) {
  const std::vector<ValidationCheck>& checks = report.checks;
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
  root.set_attribute("all_passed", static_cast<std::int64_t>(report.all_passed ? 1 : 0));
  root.set_attribute("count", static_cast<std::int64_t>(checks.size()));
  root.set_attribute(
      "rel_error_definition",
      "|computed - reference| / max(|reference|, scale_floor); scale_floor = 1 (one beam length) "
      "for end-moment lengths that vanish, else 0");
  io::write_provenance(root,
                       {{"status", 0, "the method gave a finite value"},
                        {"status", 1, "no solution: computed and rel_error are NaN"}});
}

}  // namespace

ValidationFile::ValidationFile(const std::string& path) : path_(path) {
  try {
    file_ = std::make_unique<io::AtomicHdf5File>(path);
  } catch (const io::Hdf5Error& e) {
    throw InvalidInput(e.what());
  }
}

ValidationFile::~ValidationFile() = default;
ValidationFile::ValidationFile(ValidationFile&&) noexcept = default;
ValidationFile& ValidationFile::operator=(ValidationFile&&) noexcept = default;

void ValidationFile::write(const ValidationReport& report) {
  if (!file_ || file_->committed()) {
    throw std::logic_error(path_ + ": a ValidationFile is written once only");
  }
  write_checks(file_->root(), report);
  file_->commit();
}

}  // namespace flexure
