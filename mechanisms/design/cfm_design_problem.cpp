#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/design/cfm_synthesis.h"
#include "flexure/solver/common/names.h"
#include "flexure/solver/common/status.h"

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

char to_char(OrientationRule rule) {
  switch (rule) {
    case OrientationRule::kInPlane:
      return 'I';
    case OrientationRule::kOutOfPlane:
      return 'O';
    case OrientationRule::kPossiblyOutOfPlane:
      return 'o';
  }
  return '?';
}

std::vector<OrientationRule> orientation_rules_from_string(const std::string& flags) {
  std::vector<OrientationRule> rules;
  for (char f : flags) {
    if (f == 'I') {
      rules.push_back(OrientationRule::kInPlane);
    } else if (f == 'O') {
      rules.push_back(OrientationRule::kOutOfPlane);
    } else if (f == 'o') {
      rules.push_back(OrientationRule::kPossiblyOutOfPlane);
    } else {
      throw InvalidInput(fmt::format("orientation '{}': use the thesis's flags I, O and o", flags));
    }
  }
  return rules;
}

std::string to_string(const std::vector<OrientationRule>& rules) {
  std::string flags;
  for (OrientationRule r : rules) flags.push_back(to_char(r));
  return flags;
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
  // Near d = 100 % only R = 1 reaches the stroke: no interval is left to search.
  if (std::log(std::min(R.upper, hi) / std::max(R.lower, lo)) < 1e-9) {
    throw InvalidInput(fmt::format(
        "stroke d = {} % leaves R no room: the toggle position allows only R in [{:.10g}, "
        "{:.10g}]; use a smaller d",
        stroke_percent,
        lo,
        hi));
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
  const OrientationLimits& l = orientation_limits;
  if (!(l.I_D_min_max > 0.0 && l.C_min > 0.0 && l.O_D_equal.lower > 0.0 &&
        l.O_D_equal.lower <= l.O_D_equal.upper && l.o_D_equal.lower > 0.0 &&
        l.o_D_equal.lower <= l.o_D_equal.upper && std::isfinite(l.I_D_min_max) &&
        std::isfinite(l.C_min) && std::isfinite(l.O_D_equal.upper) &&
        std::isfinite(l.o_D_equal.upper))) {
    throw InvalidInput("orientation limits must be finite and positive with lower <= upper");
  }
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

double ConstraintValue::normalised_violation() const {
  switch (kind) {
    case ConstraintKind::kRatio: {
      // Ratios are positive; a zero (a flexure that never bends against the primary one) is far
      // from any bound but must stay finite for the optimiser.
      const double v = std::log(std::max(value, 1e-300) / bound);
      return upper ? v : -v;
    }
    case ConstraintKind::kPcf:
      return violation() / std::max(100.0 - bound, 1e-3);
    case ConstraintKind::kToggle:
      break;
  }
  return violation();
}

bool CfmDesignEvaluation::feasible() const {
  return std::all_of(constraints.begin(), constraints.end(), [](const NamedConstraint& c) {
    return c.satisfied();
  });
}

double objective_value(const CfmDesignProblem& problem, const cfm::CfmResult& r) {
  switch (problem.objective) {
    case DesignObjective::kMinXi:
      return r.Xi;
    case DesignObjective::kMaxPcf:
      return r.percent_constant_force;
    case DesignObjective::kMaxPsi:
      return r.Psi_raw;
    case DesignObjective::kMinDn:
      return r.d_N_max;
  }
  return r.Xi;
}

OrientationRatios orientation_ratios(const cfm::CfmResult& r, int primary) {
  OrientationRatios o;
  if (primary == r.primary_pivot) {
    o.C = r.C;
    o.D_equal = r.D_equal;
    o.D_min = r.D_min;
    return o;
  }
  // As cfm_model.cpp computes them for the primary pivot p (eqs. 5.35, 5.36).
  const int p = primary - 1;
  const std::array<double, 3> K_prev = {1.0, r.K1, r.K2};
  for (int i = 0; i < 3; ++i) {
    if (r.kappa[i] <= 0.0) continue;
    o.C[i] = i == p ? 1.0 : r.alpha_ratio_min[p][i];
    o.D_equal[i] = K_prev[i] * r.kappa[p] / (K_prev[p] * r.kappa[i]);
    o.D_min[i] = *o.D_equal[i] / std::pow(*o.C[i], 3);
  }
  return o;
}

void constraint_values(const CfmDesignProblem& problem,
                       const cfm::CfmResult& r,
                       int primary,
                       std::vector<ConstraintValue>& out) {
  out.clear();
  // The stroke ends before the toggle position (the model would clamp it: eq. 2.16).
  out.push_back({problem.stroke_percent, r.toggle_stroke_percent, true, ConstraintKind::kToggle});
  if (problem.pcf_min) {
    out.push_back({r.percent_constant_force, *problem.pcf_min, false, ConstraintKind::kPcf});
  }
  if (problem.orientation.empty()) return;
  const OrientationLimits& limits = problem.orientation_limits;
  const OrientationRatios o = orientation_ratios(r, primary);
  // Orientation rules (Table 5.4, eqs. 6.10-6.11) on every pivot; a pin or the primary pivot
  // meets them (C = D = 1 there, or no flexure), so the constraint count stays fixed.
  const auto value = [](const std::optional<double>& v) { return v.value_or(1.0); };
  for (int i = 0; i < 3; ++i) {
    for (OrientationRule f : problem.orientation) {
      if (f == OrientationRule::kInPlane) {
        out.push_back({value(o.D_min[i]), limits.I_D_min_max, true, ConstraintKind::kRatio});
      } else {
        const Bounds& D = f == OrientationRule::kOutOfPlane ? limits.O_D_equal : limits.o_D_equal;
        out.push_back({value(o.C[i]), limits.C_min, false, ConstraintKind::kRatio});
        out.push_back({value(o.D_equal[i]), D.lower, false, ConstraintKind::kRatio});
        out.push_back({value(o.D_equal[i]), D.upper, true, ConstraintKind::kRatio});
      }
    }
  }
}

CfmDesignEvaluation evaluate_design(const CfmDesignProblem& problem,
                                    const cfm::CfmModel& model,
                                    const std::vector<double>& x) {
  CfmDesignEvaluation e;
  e.result = model.evaluate(parameters_at(problem, x));
  e.objective = objective_value(problem, e.result);
  std::vector<ConstraintValue> values;
  constraint_values(problem, e.result, e.result.primary_pivot, values);
  // The names, in constraint_values' order.
  std::vector<std::string> names{"stroke <= toggle stroke (eq. 2.16)"};
  if (problem.pcf_min) names.push_back(fmt::format("Xi' >= {:g} (eq. 6.8)", *problem.pcf_min));
  const OrientationLimits& limits = problem.orientation_limits;
  for (int i = 0; !problem.orientation.empty() && i < 3; ++i) {
    const std::string pivot = fmt::format("pivot {}", i + 1);
    for (OrientationRule rule : problem.orientation) {
      const char f = to_char(rule);
      if (rule == OrientationRule::kInPlane) {
        names.push_back(fmt::format("{} I: D_min <= {:g}", pivot, limits.I_D_min_max));
      } else {
        const Bounds& D =
            rule == OrientationRule::kOutOfPlane ? limits.O_D_equal : limits.o_D_equal;
        names.push_back(fmt::format("{} {}: C >= {:g}", pivot, f, limits.C_min));
        names.push_back(fmt::format("{} {}: D_equal >= {:g}", pivot, f, D.lower));
        names.push_back(fmt::format("{} {}: D_equal <= {:g}", pivot, f, D.upper));
      }
    }
  }
  e.constraints.reserve(values.size());
  for (std::size_t k = 0; k < values.size(); ++k) {
    NamedConstraint c;
    static_cast<ConstraintValue&>(c) = values[k];
    c.name = names[k];
    e.constraints.push_back(std::move(c));
  }
  return e;
}

}  // namespace flexure::design
