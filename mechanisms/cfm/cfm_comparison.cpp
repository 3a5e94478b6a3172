#include "flexure/mechanisms/cfm/cfm_comparison.h"

#include <algorithm>
#include <cmath>
#include <functional>

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

}  // namespace flexure::cfm
