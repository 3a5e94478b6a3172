#include "flexure/mechanisms/design/cfm_synthesis.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlopt.hpp>

#include "flexure/mechanisms/cfm/cfm_subclasses.h"
#include "flexure/solver/common/errors.h"

namespace flexure::design {
namespace {

// The value NLopt sees where the model refuses a point (never NaN).
constexpr double kPenalty = 1e6;

// The i-th point of the Halton sequence in base `base`, in (0, 1).
double halton(int i, int base) {
  double f = 1.0, r = 0.0;
  for (int n = i; n > 0; n /= base) {
    f /= base;
    r += f * (n % base);
  }
  return r;
}

struct Search {
  const CfmDesignProblem& problem;
  cfm::CfmModel model;
  int evaluations = 0;
  std::vector<double> lower, upper;  // log bounds

  // The design at log-variables y, or nullopt where the model refuses it.
  std::optional<CfmDesignEvaluation> at(const std::vector<double>& y) {
    ++evaluations;
    std::vector<double> x(y.size());
    std::transform(y.begin(), y.end(), x.begin(), [](double v) { return std::exp(v); });
    try {
      CfmDesignEvaluation e = evaluate_design(problem, model, x);
      if (!std::isfinite(e.objective)) return std::nullopt;
      return e;
    } catch (const InvalidInput&) {
      return std::nullopt;
    }
  }
  // Minimised by NLopt: the objective in its minimising sense.
  double minimised(const CfmDesignEvaluation& e) const {
    const bool maximise = problem.objective == DesignObjective::kMaxPcf ||
                          problem.objective == DesignObjective::kMaxPsi;
    return maximise ? -e.objective : e.objective;
  }
};

struct ConstraintSlot {
  Search* search;
  std::size_t index;
};

double objective_of(const std::vector<double>& y, std::vector<double>&, void* data) {
  auto* s = static_cast<Search*>(data);
  const auto e = s->at(y);
  return e ? s->minimised(*e) : kPenalty;
}

double constraint_of(const std::vector<double>& y, std::vector<double>&, void* data) {
  auto* slot = static_cast<ConstraintSlot*>(data);
  const auto e = slot->search->at(y);
  return e ? e->constraints[slot->index].violation() : kPenalty;
}

struct LocalRun {
  std::vector<double> y;
  std::optional<CfmDesignEvaluation> e;
  bool stopped_by_test = false;
};

LocalRun run_local(Search& s,
                   nlopt::algorithm algorithm,
                   std::vector<double> y,
                   std::size_t constraint_count,
                   const SynthesisOptions& options) {
  const unsigned n = static_cast<unsigned>(y.size());
  nlopt::opt opt(algorithm, n);
  opt.set_lower_bounds(s.lower);
  opt.set_upper_bounds(s.upper);
  opt.set_min_objective(objective_of, &s);
  std::vector<ConstraintSlot> slots;
  slots.reserve(constraint_count);
  if (algorithm == nlopt::LN_COBYLA) {
    for (std::size_t k = 0; k < constraint_count; ++k) {
      slots.push_back({&s, k});
      opt.add_inequality_constraint(constraint_of, &slots.back(), 1e-10);
    }
  }
  opt.set_xtol_rel(options.xtol_rel);
  opt.set_maxeval(options.max_evaluations);
  // Initial steps of a tenth of each log range: the optimum of Table 2.1 rows is narrow in R.
  std::vector<double> step(n);
  for (unsigned i = 0; i < n; ++i) step[i] = 0.1 * (s.upper[i] - s.lower[i]);
  opt.set_initial_step(step);
  LocalRun run;
  double value = 0.0;
  try {
    const nlopt::result r = opt.optimize(y, value);
    run.stopped_by_test = r == nlopt::XTOL_REACHED || r == nlopt::FTOL_REACHED ||
                          r == nlopt::SUCCESS || r == nlopt::STOPVAL_REACHED;
  } catch (const nlopt::roundoff_limited&) {
    run.stopped_by_test = true;  // as far as double precision goes
  } catch (const std::runtime_error&) {
    // NLopt's generic failure: keep the last point.
  }
  run.y = y;
  run.e = s.at(y);
  return run;
}

std::optional<std::string> nearest_subclass(const CfmDesignProblem& p, const cfm::CfmResult& r) {
  for (const cfm::CfmSubclass& row : cfm::thesis_subclasses()) {
    if (row.config != p.config || std::abs(row.stroke_percent - p.stroke_percent) > 1e-9) continue;
    const auto close = [](double a, double b) {
      return std::abs(a - b) <= 0.01 * std::max(std::abs(b), 0.1);
    };
    if (close(r.R, row.R) && close(r.K1, row.K1) && close(r.K2, row.K2)) return row.name;
  }
  return std::nullopt;
}

bool better(const LocalRun& a, const LocalRun& b, const Search& s) {
  if (!a.e) return false;
  if (!b.e) return true;
  if (a.e->feasible() != b.e->feasible()) return a.e->feasible();
  return s.minimised(*a.e) < s.minimised(*b.e);
}

}  // namespace

void SynthesisOptions::validate() const {
  if (starts < 0 || starts > 10000) {
    throw InvalidInput(fmt::format("starts = {} must lie in [0, 10000] (0: automatic)", starts));
  }
  if (max_evaluations < 10) {
    throw InvalidInput(fmt::format("max_evaluations = {} must be >= 10", max_evaluations));
  }
  if (!(xtol_rel > 0.0 && xtol_rel < 0.1)) {
    throw InvalidInput(fmt::format("xtol_rel = {} must lie in (0, 0.1)", xtol_rel));
  }
}

CfmSynthesisResult synthesize_cfm(const CfmDesignProblem& problem,
                                  const SynthesisOptions& options) {
  problem.validate();
  options.validate();
  Search s{problem, cfm::CfmModel(problem.model)};
  CfmSynthesisResult out;
  out.variables = problem.variables();
  const auto [R_lo, R_hi] = toggle_R_interval(problem.stroke_percent);
  for (const std::string& v : out.variables) {
    const Bounds b = v == "R"
                         ? Bounds{std::max(problem.R.lower, R_lo), std::min(problem.R.upper, R_hi)}
                         : (v == "K1" ? problem.K1 : problem.K2);
    s.lower.push_back(std::log(b.lower));
    s.upper.push_back(std::log(b.upper));
  }
  const std::size_t n = out.variables.size();
  const int starts = options.starts > 0 ? options.starts : (n == 1 ? 8 : (n == 2 ? 16 : 32));
  nlopt::srand(options.seed);
  // One constraint per rule and pivot (cfm_design_problem.cpp): a count fixed by the problem.
  std::size_t constraint_count = 1 + (problem.pcf_min ? 1 : 0);
  for (char f : problem.orientation) constraint_count += f == 'I' ? 3 : 9;
  // Nelder-Mead polishes min-xi's kinked optimum where only the bounds constrain it (the toggle
  // limit is in the bounds of R).
  const bool polish = problem.objective == DesignObjective::kMinXi && problem.orientation.empty() &&
                      !problem.pcf_min;
  constexpr int kBases[] = {2, 3, 5};
  LocalRun best;
  for (int k = 0; k < starts; ++k) {
    std::vector<double> y(n);
    for (std::size_t i = 0; i < n; ++i) {
      y[i] = s.lower[i] + halton(k + 1, kBases[i]) * (s.upper[i] - s.lower[i]);
    }
    LocalRun run = run_local(s, nlopt::LN_COBYLA, y, constraint_count, options);
    if (polish && run.e) {
      LocalRun polished = run_local(s, nlopt::LN_NELDERMEAD, run.y, 0, options);
      if (polished.e && s.minimised(*polished.e) <= s.minimised(*run.e)) run = polished;
    }
    if (run.e && run.e->feasible()) ++out.feasible_starts;
    if (k == 0 || better(run, best, s)) best = run;
  }
  out.starts = starts;
  out.evaluations = s.evaluations;
  out.iterations = s.evaluations;
  if (!best.e) {
    out.termination = Termination::kNoConvergence;
    out.message = fmt::format("the model refused every one of the {} starts", starts);
    return out;
  }
  out.best = *best.e;
  out.x.resize(n);
  std::transform(best.y.begin(), best.y.end(), out.x.begin(), [](double v) { return std::exp(v); });
  const NamedConstraint* worst = nullptr;
  for (const NamedConstraint& c : out.best.constraints) {
    if (worst == nullptr || c.violation() > worst->violation()) worst = &c;
  }
  out.residual = worst != nullptr ? std::max(0.0, worst->violation()) : 0.0;
  out.nearest_subclass = nearest_subclass(problem, out.best.result);
  if (!out.best.feasible()) {
    out.termination = Termination::kNoConvergence;
    out.message = fmt::format(
        "no start reached a feasible design; the best violates '{}' ({:.6g} against {:g})",
        worst->name,
        worst->value,
        worst->bound);
  } else if (!best.stopped_by_test) {
    out.termination = Termination::kNoConvergence;
    out.message =
        fmt::format("the best local run stopped at its evaluation limit ({}) before its tolerance",
                    options.max_evaluations);
  } else {
    out.termination = Termination::kConverged;
    out.message = fmt::format("best of {} local runs ({} feasible), {} model evaluations",
                              starts,
                              out.feasible_starts,
                              out.evaluations);
  }
  return out;
}

}  // namespace flexure::design
