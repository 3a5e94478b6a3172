#include "flexure/mechanisms/design/cfm_design_problem.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "flexure/mechanisms/cfm/cfm_configuration.h"
#include "flexure/solver/common/errors.h"
#include "flexure/solver/common/names.h"

namespace flexure::design {
namespace {

constexpr std::array<std::pair<DesignObjective, const char*>, 4> kObjectives = {{
    {DesignObjective::kMinXi, "min-xi"},
    {DesignObjective::kMaxPcf, "max-pcf"},
    {DesignObjective::kMaxPsi, "max-psi"},
    {DesignObjective::kMinDn, "min-dn"},
}};

void check_bounds(const Bounds& b, const char* name) {
  if (!(std::isfinite(b.lower) && std::isfinite(b.upper) && b.lower > 0.0 && b.lower <= b.upper)) {
    throw InvalidInput(fmt::format(
        "{} bounds [{}, {}] must be finite with 0 < lower <= upper", name, b.lower, b.upper));
  }
}

}  // namespace

const char* to_string(DesignObjective objective) {
  for (const auto& [o, name] : kObjectives) {
    if (o == objective) return name;
  }
  return "?";
}

DesignObjective design_objective_from_string(const std::string& name) {
  for (const auto& [o, text] : kObjectives) {
    if (same_name(name, text)) return o;
  }
  throw InvalidInput(
      fmt::format("objective '{}' is unknown; allowed: min-xi, max-pcf, max-psi, min-dn", name));
}

std::pair<double, double> toggle_R_interval(double d) {
  if (!(d > 0.0 && d < 100.0)) {
    throw InvalidInput(fmt::format("stroke d = {} % must lie in (0, 100)", d));
  }
  // Inverse of toggle_stroke_percent (slider_crank.h): 100 (1 - sqrt(|1 - R|/(1 + R))) = d.
  const double q = (1.0 - d / 100.0) * (1.0 - d / 100.0);
  return {(1.0 - q) / (1.0 + q), (1.0 + q) / (1.0 - q)};
}

cfm::CfmOptions default_model_options(DesignObjective objective) {
  cfm::CfmOptions o;
  if (objective == DesignObjective::kMinXi) {
    o.sampling = cfm::StrokeSampling::kUniform;
    o.points = 50;
  }
  return o;
}

void CfmDesignProblem::validate() const {
  const cfm::CfmConfiguration& c = cfm::find_cfm_configuration(config);
  toggle_R_interval(stroke_percent);
  check_bounds(R, "R");
  check_bounds(K1, "K1");
  check_bounds(K2, "K2");
  const auto [lo, hi] = toggle_R_interval(stroke_percent);
  if (std::max(R.lower, lo) > std::min(R.upper, hi)) {
    throw InvalidInput(fmt::format(
        "no R in [{}, {}] reaches a stroke of {} % before the toggle position (that needs R in "
        "[{:.4f}, {:.4f}])",
        R.lower,
        R.upper,
        stroke_percent,
        lo,
        hi));
  }
  for (char f : orientation) {
    if (f != 'I' && f != 'O' && f != 'o') {
      throw InvalidInput(
          fmt::format("orientation '{}': use the thesis's flags I, O and o", orientation));
    }
  }
  const bool needs_pcf =
      objective == DesignObjective::kMaxPsi || objective == DesignObjective::kMinDn;
  if (needs_pcf && !pcf_min) {
    throw InvalidInput(
        fmt::format("--objective {} trades constant force away: give --pcf-min (the thesis's Xi' "
                    ">= 99, 95, 90)",
                    to_string(objective)));
  }
  if (pcf_min && !(*pcf_min > 0.0 && *pcf_min < 100.0)) {
    throw InvalidInput(fmt::format("--pcf-min = {} must lie in (0, 100)", *pcf_min));
  }
  const auto check_fixed = [&](const std::optional<double>& k, int pivot, const char* name) {
    if (!k) return;
    if (!c.has_spring(pivot) || (pivot == 2 && c.is_class_1B())) {
      throw InvalidInput(fmt::format("{} is not a variable of configuration {}", name, config));
    }
    if (!(std::isfinite(*k) && *k > 0.0)) {
      throw InvalidInput(fmt::format("fixed {} = {} must be a finite positive number", name, *k));
    }
  };
  check_fixed(fixed_K1, 2, "K1");
  check_fixed(fixed_K2, 3, "K2");
  model.validate();
}

std::vector<std::string> CfmDesignProblem::variables() const {
  const cfm::CfmConfiguration& c = cfm::find_cfm_configuration(config);
  std::vector<std::string> v{"R"};
  if (c.has_spring(2) && !c.is_class_1B() && !fixed_K1) v.emplace_back("K1");
  if (c.has_spring(3) && !fixed_K2) v.emplace_back("K2");
  return v;
}

cfm::CfmParameters parameters_at(const CfmDesignProblem& problem, const std::vector<double>& x) {
  const cfm::CfmConfiguration& c = cfm::find_cfm_configuration(problem.config);
  cfm::CfmParameters p;
  p.config = problem.config;
  p.stroke_percent = problem.stroke_percent;
  const std::vector<std::string> names = problem.variables();
  for (std::size_t i = 0; i < names.size() && i < x.size(); ++i) {
    if (names[i] == "R") p.R = x[i];
    if (names[i] == "K1") p.K1 = x[i];
    if (names[i] == "K2") p.K2 = x[i];
  }
  if (c.has_spring(2) && !c.is_class_1B() && problem.fixed_K1) p.K1 = problem.fixed_K1;
  if (c.has_spring(3) && problem.fixed_K2) p.K2 = problem.fixed_K2;
  return p;
}

bool CfmDesignEvaluation::feasible() const {
  return std::all_of(constraints.begin(), constraints.end(), [](const NamedConstraint& c) {
    return c.satisfied();
  });
}

CfmDesignEvaluation evaluate_design(const CfmDesignProblem& problem,
                                    const cfm::CfmModel& model,
                                    const std::vector<double>& x) {
  CfmDesignEvaluation e;
  e.result = model.evaluate(parameters_at(problem, x));
  const cfm::CfmResult& r = e.result;
  switch (problem.objective) {
    case DesignObjective::kMinXi:
      e.objective = r.Xi;
      break;
    case DesignObjective::kMaxPcf:
      e.objective = r.percent_constant_force;
      break;
    case DesignObjective::kMaxPsi:
      e.objective = r.Psi_raw;
      break;
    case DesignObjective::kMinDn:
      e.objective = r.d_N_max;
      break;
  }
  // The stroke ends before the toggle position (the model would clamp it: eq. 2.16).
  e.constraints.push_back({"stroke <= toggle stroke (eq. 2.16)",
                           problem.stroke_percent,
                           r.toggle_stroke_percent,
                           true});
  if (problem.pcf_min) {
    e.constraints.push_back({fmt::format("Xi' >= {:g} (eq. 6.8)", *problem.pcf_min),
                             r.percent_constant_force,
                             *problem.pcf_min,
                             false});
  }
  // Orientation rules (Table 5.4, eqs. 6.10-6.11) on every pivot; a pin or the primary pivot
  // meets them (C = D = 1 there, or no flexure), so the constraint count stays fixed.
  for (int i = 0; i < 3; ++i) {
    const auto value = [&](const std::optional<double>& v) { return v.value_or(1.0); };
    const std::string pivot = fmt::format("pivot {}", i + 1);
    for (char f : problem.orientation) {
      if (f == 'I') {
        e.constraints.push_back({pivot + " I: D_min <= 1", value(r.D_min[i]), 1.0, true});
      } else {
        const double D_low = f == 'O' ? 0.5 : 0.1, D_high = f == 'O' ? 2.0 : 10.0;
        e.constraints.push_back({pivot + " " + f + ": C >= 1", value(r.C[i]), 1.0, false});
        e.constraints.push_back({fmt::format("{} {}: D_equal >= {:g}", pivot, f, D_low),
                                 value(r.D_equal[i]),
                                 D_low,
                                 false});
        e.constraints.push_back({fmt::format("{} {}: D_equal <= {:g}", pivot, f, D_high),
                                 value(r.D_equal[i]),
                                 D_high,
                                 true});
      }
    }
  }
  return e;
}

}  // namespace flexure::design
