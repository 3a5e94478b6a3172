#include "flexure/mechanisms/cfm_comparison.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <string>

#include "flexure/solver/common/status.h"

namespace flexure::cfm {
namespace {

constexpr double kDecimalAllowance = 1e-12;  // binary representation of decimal data

double half_unit(int decimals) { return 0.5 * std::pow(10.0, -decimals); }

// Largest change of quantity(result) when each free design variable moves by half a unit of its
// printed (4th) decimal, summed over the variables.
double input_band(const CfmModel& model,
                  const CfmParameters& p,
                  const std::function<double(const CfmResult&)>& quantity) {
  const double h = half_unit(kPrintedDecimalsInputs);
  const double q0 = quantity(model.evaluate(p));
  double band = 0.0;
  auto vary = [&](auto&& set) {
    double worst = 0.0;
    for (double sign : {-1.0, 1.0}) {
      CfmParameters q = p;
      set(q, sign * h);
      worst = std::max(worst, std::abs(quantity(model.evaluate(q)) - q0));
    }
    band += worst;
  };
  vary([](CfmParameters& q, double dh) { q.R += dh; });
  if (p.K1) vary([](CfmParameters& q, double dh) { q.K1 = std::max(0.0, *q.K1 + dh); });
  if (p.K2) vary([](CfmParameters& q, double dh) { q.K2 = std::max(0.0, *q.K2 + dh); });
  return band;
}

PrintedComparison compare(const CfmModel& model,
                          const CfmParameters& p,
                          const CfmResult& result,
                          double printed,
                          int decimals,
                          const std::function<double(const CfmResult&)>& quantity,
                          double extra = 0.0) {
  PrintedComparison c;
  c.computed = quantity(result);
  c.printed = printed;
  c.tolerance = half_unit(decimals) + input_band(model, p, quantity) + extra;
  return c;
}

}  // namespace

bool PrintedComparison::within() const {
  return std::abs(deviation()) <= tolerance + kDecimalAllowance;
}

namespace {

// Both table row types carry (config, R, K1, K2, stroke_percent); only the springs the
// configuration has are inputs (class 1B has no K1).
template <typename Row>
CfmParameters parameters_of_row(const Row& row) {
  const CfmConfiguration& c = find_cfm_configuration(row.config);
  CfmParameters p;
  p.config = row.config;
  p.R = row.R;
  if (c.has_spring(2) && !c.is_class_1B()) p.K1 = row.K1;
  if (c.has_spring(3)) p.K2 = row.K2;
  p.stroke_percent = row.stroke_percent;
  return p;
}

}  // namespace

CfmParameters parameters_of(const CfmSubclass& row) { return parameters_of_row(row); }

CfmParameters parameters_of(const CfmClassRow& row) { return parameters_of_row(row); }

bool SubclassComparison::all_within() const {
  return Phi.within() && percent_constant_force.within() && beta.within() && lambda.within() &&
         Psi.within() && d_N_max.within() && primary_pivot_matches;
}

SubclassComparison compare_with_thesis(const CfmSubclass& row) {
  const CfmModel model;  // thesis-code sampling
  const CfmParameters p = parameters_of(row);
  SubclassComparison c;
  c.row = &row;
  c.result = model.evaluate(p);
  c.Phi = compare(
      model, p, c.result, row.Phi, kPrintedDecimalsPhi, [](const CfmResult& r) { return r.Phi; });
  c.percent_constant_force = compare(model,
                                     p,
                                     c.result,
                                     row.percent_constant_force,
                                     kPrintedDecimalsXiPrime,
                                     [](const CfmResult& r) { return r.percent_constant_force; });
  c.beta = compare(model, p, c.result, row.beta, kPrintedDecimalsBeta, [](const CfmResult& r) {
    return r.beta;
  });
  c.lambda =
      compare(model, p, c.result, row.lambda, kPrintedDecimalsLambda, [](const CfmResult& r) {
        return r.lambda;
      });
  c.Psi = compare(model, p, c.result, row.Psi, kPrintedDecimalsPsi, [](const CfmResult& r) {
    return r.Psi.value_or(0.0);
  });
  c.d_N_max = compare(model, p, c.result, row.d_N_max, kPrintedDecimalsDN, [](const CfmResult& r) {
    return r.d_N_max;
  });
  // Equal-width stress measure alpha_i (K_{i-1}/kappa_i)^(1/3) of the printed and the computed
  // primary pivot; a tie means the choice is rounding noise.
  c.primary_pivot_matches = c.result.primary_pivot == row.primary_pivot;
  if (!c.primary_pivot_matches) {
    const std::array<double, 3> K_prev = {1.0, c.result.K1, c.result.K2};
    auto stress = [&](int pivot) {
      const int i = pivot - 1;
      return c.result.kappa[i] > 0.0
                 ? c.result.alpha_end[i] * std::cbrt(K_prev[i] / c.result.kappa[i])
                 : 0.0;
    };
    const double a = stress(row.primary_pivot);
    const double b = stress(c.result.primary_pivot);
    c.primary_pivot_tie = std::abs(a - b) <= 1e-12 * std::max(a, b);
    c.primary_pivot_matches = c.primary_pivot_tie;
  }
  return c;
}

bool RatioComparison::all_within() const {
  bool ok = pins_agree;
  for (const auto* field : {&C, &D_equal, &D_min}) {
    for (const std::optional<PrintedComparison>& c : *field) ok = ok && (!c || c->within());
  }
  return ok;
}

RatioComparison compare_with_thesis_ratios(const CfmThicknessRatios& row) {
  const CfmModel model;
  const CfmParameters p = parameters_of(find_thesis_subclass(row.name));
  const CfmResult result = model.evaluate(p);
  RatioComparison c;
  c.row = &row;
  using Field = std::array<std::optional<double>, 3> CfmResult::*;
  const Field fields[3] = {&CfmResult::C, &CfmResult::D_equal, &CfmResult::D_min};
  const std::array<std::optional<double>, 3>* printed[3] = {&row.C, &row.D_equal, &row.D_min};
  std::array<std::optional<PrintedComparison>, 3>* out[3] = {&c.C, &c.D_equal, &c.D_min};
  for (int f = 0; f < 3; ++f) {
    const Field field = fields[f];
    for (int i = 0; i < 3; ++i) {
      const std::optional<double>& expected = (*printed[f])[i];
      if (expected.has_value() != (result.*field)[i].has_value()) c.pins_agree = false;
      if (!expected || !(result.*field)[i]) continue;
      (*out[f])[i] =
          compare(model, p, result, *expected, row.decimals, [field, i](const CfmResult& r) {
            return (r.*field)[i].value_or(0.0);
          });
    }
  }
  return c;
}

ClassRowComparison compare_with_class_row(const CfmClassRow& row, double extra_tolerance) {
  CfmOptions options;
  options.sampling = StrokeSampling::kUniform;
  options.points = 50;  // Howell §10.1: "50 equally spaced points"
  const CfmModel model(options);
  const CfmParameters p = parameters_of(row);
  ClassRowComparison c;
  c.row = &row;
  c.result = model.evaluate(p);
  c.Xi = compare(
      model, p, c.result, row.Xi, 4, [](const CfmResult& r) { return r.Xi; }, extra_tolerance);
  c.Phi = compare(
      model, p, c.result, row.Phi, 4, [](const CfmResult& r) { return r.Phi; }, extra_tolerance);
  return c;
}

namespace {

void update(WorstDeviation& worst, const PrintedComparison& c, const char* row) {
  const double r = std::abs(c.deviation()) / c.tolerance;
  if (r > worst.ratio) {
    worst.ratio = r;
    worst.row = row;
  }
}

// The PRBM at a printed row; a model failure or a non-finite result is no answer.
CfmResult evaluate_printed(const CfmSubclass& row) {
  CfmResult r = CfmModel().evaluate(parameters_of(row));
  if (!r.converged()) throw NoConvergence("cfm model: " + r.message);
  for (double v : {r.Phi, r.Xi, r.percent_constant_force, r.beta, r.lambda}) {
    if (!std::isfinite(v)) {
      throw NoConvergence(
          fmt::format("cfm result came out as {}; no converged solution to report", v));
    }
  }
  return r;
}

}  // namespace

PrintedTablesReport compare_printed_tables() {
  PrintedTablesReport report;
  const std::array<const char*, 6> quantities{"Phi", "Xi'", "beta", "lambda", "Psi", "d_N max"};
  for (std::size_t i = 0; i < quantities.size(); ++i) report.worst[i].quantity = quantities[i];
  int outside = 0;
  for (const CfmSubclass& row : thesis_subclasses()) {
    SubclassComparison c = compare_with_thesis(row);
    if (!c.all_within()) ++outside;
    update(report.worst[0], c.Phi, row.name);
    update(report.worst[1], c.percent_constant_force, row.name);
    update(report.worst[2], c.beta, row.name);
    update(report.worst[3], c.lambda, row.name);
    update(report.worst[4], c.Psi, row.name);
    update(report.worst[5], c.d_N_max, row.name);
    report.subclasses.push_back(std::move(c));
  }
  for (const CfmThicknessRatios& row : thesis_thickness_ratios()) {
    RatioComparison c = compare_with_thesis_ratios(row);
    if (!c.all_within()) ++outside;
    report.ratios.push_back(std::move(c));
  }
  for (const auto* table : {&thesis_table_2_1(), &howell_table_10_1()}) {
    for (const CfmClassRow& row : *table) {
      const double extra = std::string(row.class_name) == "1B" ? kClass1BSamplingAllowance : 0.0;
      ClassRowReport r{compare_with_class_row(row, extra), RowVerdict::kWithin};
      if (!(r.comparison.Xi.within() && r.comparison.Phi.within())) {
        r.verdict = row.reproducible ? RowVerdict::kOutside : RowVerdict::kOutsideIrreproducible;
        if (row.reproducible) ++outside;
      }
      report.class_rows.push_back(std::move(r));
    }
  }
  report.all_within = outside == 0;
  report.set_converged(report.all_within);
  report.message = report.all_within
                       ? "every printed row reproduced within its rounding"
                       : fmt::format("{} printed row(s) outside their rounding", outside);
  return report;
}

std::vector<const CfmSubclass*> exact_table_rows(ExactTableRows rows) {
  std::vector<const CfmSubclass*> selected;
  for (const CfmSubclass& row : thesis_subclasses()) {
    const std::string name = row.name;
    // Sub-class "a" of each configuration: "lpp-a", "slp-aIo" (not "lpp-a99", "slp-a90I").
    const std::size_t dash = name.find('-');
    const bool is_a = name.size() > dash + 1 && name[dash + 1] == 'a' &&
                      (name.size() == dash + 2 || !std::isdigit(name[dash + 2]));
    if (rows == ExactTableRows::kSubclassA && !is_a) continue;
    selected.push_back(&row);
  }
  return selected;
}

ExactTableReport compare_exact_table(ExactTableRows rows,
                                     CfmExactOptions options,
                                     const std::function<void(std::size_t, std::size_t)>& progress,
                                     const std::function<void(const ExactTableRow&)>& on_row) {
  ExactTableReport report;
  const std::vector<const CfmSubclass*> selected = exact_table_rows(rows);
  const std::size_t total = selected.size() * static_cast<std::size_t>(options.points);
  std::size_t reported = 0;
  int failed = 0;
  for (std::size_t i = 0; i < selected.size(); ++i) {
    if (progress) {
      const std::size_t before = i * static_cast<std::size_t>(options.points);
      options.progress = [&progress, &reported, before, total](std::size_t done, std::size_t) {
        reported = before + done;
        progress(reported, total);
      };
    }
    ExactTableRow row{selected[i], evaluate_printed(*selected[i]), {}};
    row.exact = solve_cfm_exact(row.prbm, options);
    if (!row.exact.converged()) ++failed;
    if (on_row) on_row(row);
    report.rows.push_back(std::move(row));
  }
  // A stroke that stopped early leaves the count short: end the progress all the same.
  if (progress && reported < total) progress(total, total);
  report.all_converged = failed == 0;
  report.set_converged(report.all_converged);
  report.message =
      report.all_converged
          ? fmt::format("{} rows solved", report.rows.size())
          : fmt::format(
                "the exact model did not converge on {} of {} rows", failed, report.rows.size());
  return report;
}

}  // namespace flexure::cfm
