#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <exception>
#include <nlopt.hpp>
#include <optional>
#include <string>
#include <utility>

#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/design/cfm_synthesis.h"
#include "flexure/mechanisms/design/halton.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/solver/common/status.h"

namespace flexure::design {
namespace {

// What NLopt sees where a point cannot be evaluated (never NaN).
constexpr double kPenalty = 1e3;

struct ExactSearch {
  const CfmDesignProblem& problem;
  CfmDesignProblem constraints_problem;  // the PRBM constraints without Xi' >= pcf_min
  const ExactRefinementOptions& options;
  cfm::CfmModel model;
  int evaluations = 0;
  // The last point's values: COBYLA asks for the objective and every constraint at one point.
  std::vector<double> last_y;
  double last_pcf = 0.0;
  std::optional<CfmDesignEvaluation> last_prbm;
  int run = 0;  // the local run under way
  std::vector<SynthesisEvaluation> history;
  // options.progress: strokes counted (the budget of the runs before this one plus this run's
  // strokes, at most its limit), the budget, and an exception it threw inside NLopt (whose C++
  // wrapper would turn it into a generic failure), rethrown when NLopt returns.
  std::size_t done = 0, total = 0, run_base = 0;
  int run_strokes = 0;  // evaluations (exact strokes) of the local run under way
  std::exception_ptr stopped;

  void report(std::size_t next_done) {
    if (!options.progress) return;
    done = std::max(done, std::min(next_done, total));
    options.progress(done, total);
  }
  // Moves the count to the end of the local run just finished (its confirmation counted).
  void end_run() {
    run_base += static_cast<std::size_t>(options.max_evaluations) + 1;
    report(run_base);
  }

  ExactSearch(const CfmDesignProblem& p,
              CfmDesignProblem constraints,
              const ExactRefinementOptions& o,
              cfm::CfmModel m)
      : problem(p), constraints_problem(std::move(constraints)), options(o), model(std::move(m)) {}

  void evaluate(const std::vector<double>& y) {
    if (y == last_y) return;
    last_y = y;
    std::vector<double> x(y.size());
    std::transform(y.begin(), y.end(), x.begin(), [](double v) { return std::exp(v); });
    ++evaluations;
    const int run_evaluations = ++run_strokes;
    try {
      last_prbm = evaluate_design(constraints_problem, model, x);
    } catch (const InvalidInput&) {
      last_prbm.reset();
    }
    last_pcf = last_prbm
                   ? exact_percent_constant_force(problem, x, options.points, options.work_budget)
                   : 0.0;
    // The history: the design's R, K1, K2 as the model took them (held values included).
    SynthesisEvaluation e;
    e.run = run;
    e.full_sampling = false;
    e.valid = last_prbm.has_value();
    const cfm::CfmParameters p = parameters_at(problem, x);
    e.R = p.R;
    e.K1 = p.K1.value_or(0.0);
    e.K2 = p.K2.value_or(0.0);
    e.objective = last_pcf;
    if (last_prbm) {
      double worst = problem.pcf_min ? *problem.pcf_min - last_pcf : -1.0;
      for (const NamedConstraint& c : last_prbm->constraints) {
        worst = std::max(worst, c.violation());
      }
      e.max_violation = worst;
      e.feasible = worst <= 1e-9;
    }
    history.push_back(e);
    report(run_base + static_cast<std::size_t>(std::min(run_evaluations, options.max_evaluations)));
  }
};

struct Slot {
  ExactSearch* search;
  std::size_t index;  // a PRBM constraint, or npos for Xi'_exact >= pcf_min
};

// evaluate() inside NLopt: an exception (from options.progress) is kept and NLopt told to stop.
void evaluate_in_nlopt(ExactSearch& s, const std::vector<double>& y) {
  try {
    s.evaluate(y);
  } catch (...) {
    s.stopped = std::current_exception();
    throw nlopt::forced_stop();
  }
}

double objective(const std::vector<double>& y, std::vector<double>&, void* data) {
  auto* s = static_cast<ExactSearch*>(data);
  evaluate_in_nlopt(*s, y);
  return -s->last_pcf;
}

double constraint(const std::vector<double>& y, std::vector<double>&, void* data) {
  auto* slot = static_cast<Slot*>(data);
  evaluate_in_nlopt(*slot->search, y);
  if (!slot->search->last_prbm) return kPenalty;
  if (slot->index == std::string::npos)
    return *slot->search->problem.pcf_min - slot->search->last_pcf;
  return slot->search->last_prbm->constraints[slot->index].violation();
}

}  // namespace

void ExactRefinementOptions::validate() const {
  if (points < 2 || points > 10000 || confirm_points < 2 || confirm_points > 10000) {
    throw InvalidInput(
        fmt::format("exact stroke points {} / {} must lie in [2, 10000]", points, confirm_points));
  }
  if (max_evaluations < 1) {
    throw InvalidInput(fmt::format("max_evaluations = {} must be >= 1", max_evaluations));
  }
  if (!(xtol_rel > 0.0 && xtol_rel < 0.1)) {
    throw InvalidInput(fmt::format("xtol_rel = {} must lie in (0, 0.1)", xtol_rel));
  }
  if (!(work_budget >= 1e3)) {
    throw InvalidInput(fmt::format("work_budget = {} must be >= 1000 steps", work_budget));
  }
}

double exact_percent_constant_force(const CfmDesignProblem& problem,
                                    const std::vector<double>& x,
                                    int points,
                                    double work_budget) {
  try {
    const cfm::CfmResult r = cfm::CfmModel(problem.model).evaluate(parameters_at(problem, x));
    cfm::CfmExactOptions o;
    o.points = points;
    o.solver.work_budget = work_budget;
    o.solver.work_budget_per_point = 0.0;
    const cfm::CfmExactResult e = cfm::solve_cfm_exact(r, o);
    return e.converged() ? e.percent_constant_force_exact : 0.0;
  } catch (const InvalidInput&) {
    return 0.0;
  }
}

namespace {

struct LocalResult {
  std::vector<double> y;
  bool stopped_by_test = false;
};

LocalResult run_local(ExactSearch& s,
                      std::vector<double> y,
                      const std::vector<double>& lower,
                      const std::vector<double>& upper,
                      const ExactRefinementOptions& options) {
  const std::size_t n = y.size();
  s.last_y.clear();
  s.run_strokes = 0;
  s.evaluate(y);
  const std::size_t count = s.last_prbm ? s.last_prbm->constraints.size() : 0;
  nlopt::opt opt(nlopt::LN_COBYLA, static_cast<unsigned>(n));
  opt.set_lower_bounds(lower);
  opt.set_upper_bounds(upper);
  opt.set_min_objective(objective, &s);  // -Xi'_exact
  std::vector<Slot> slots;
  slots.reserve(count + 1);
  for (std::size_t k = 0; k < count; ++k) {
    slots.push_back({&s, k});
    opt.add_inequality_constraint(constraint, &slots.back(), 1e-9);
  }
  if (s.problem.pcf_min) {
    slots.push_back({&s, std::string::npos});
    opt.add_inequality_constraint(constraint, &slots.back(), 1e-9);
  }
  opt.set_xtol_rel(options.xtol_rel);
  opt.set_maxeval(options.max_evaluations);
  // Steps of a twentieth of each log range: a local refinement of a good start.
  std::vector<double> step(n);
  for (std::size_t i = 0; i < n; ++i) step[i] = 0.05 * (upper[i] - lower[i]);
  opt.set_initial_step(step);
  LocalResult out;
  double value = 0.0;
  std::vector<double> best = y;
  try {
    const nlopt::result r = opt.optimize(best, value);
    out.stopped_by_test =
        r == nlopt::XTOL_REACHED || r == nlopt::FTOL_REACHED || r == nlopt::SUCCESS;
  } catch (const nlopt::roundoff_limited&) {
    out.stopped_by_test = true;
  } catch (const std::runtime_error&) {
    best = y;  // NLopt's generic failure: keep the start
  }
  if (s.stopped) std::rethrow_exception(s.stopped);  // options.progress threw: stop here
  out.y = best;
  return out;
}

std::vector<double> exp_of(const std::vector<double>& y) {
  std::vector<double> x(y.size());
  std::transform(y.begin(), y.end(), x.begin(), [](double v) { return std::exp(v); });
  return x;
}

}  // namespace

CfmExactRefinement refine_cfm_exact(const CfmDesignProblem& problem,
                                    const std::vector<std::vector<double>>& starts,
                                    const ExactRefinementOptions& options) {
  problem.validate();
  options.validate();
  CfmExactRefinement out;
  out.variables = problem.variables();
  const std::size_t n = out.variables.size();
  if (starts.empty()) throw InvalidInput("refine_cfm_exact needs at least one start");
  const auto [R_lo, R_hi] = toggle_R_interval(problem.stroke_percent);
  std::vector<double> lower, upper;
  for (std::size_t i = 0; i < n; ++i) {
    const std::string& v = out.variables[i];
    const Bounds b = v == "R"
                         ? Bounds{std::max(problem.R.lower, R_lo), std::min(problem.R.upper, R_hi)}
                         : (v == "K1" ? problem.K1 : problem.K2);
    lower.push_back(std::log(b.lower));
    upper.push_back(std::log(b.upper));
  }
  std::vector<std::vector<double>> ys;
  for (const std::vector<double>& start : starts) {
    if (start.size() != n) {
      throw InvalidInput(fmt::format(
          "a start has {} values; the problem's free variables are {}", start.size(), n));
    }
    std::vector<double> y(n);
    for (std::size_t i = 0; i < n; ++i) {
      y[i] = std::log(start[i]);
      if (!(y[i] >= lower[i] - 1e-12 && y[i] <= upper[i] + 1e-12)) {
        throw InvalidInput(fmt::format("start {} = {} lies outside its bounds [{:.6g}, {:.6g}]",
                                       out.variables[i],
                                       start[i],
                                       std::exp(lower[i]),
                                       std::exp(upper[i])));
      }
      y[i] = std::clamp(y[i], lower[i], upper[i]);
    }
    ys.push_back(y);
  }
  constexpr int kBases[] = {2, 3, 5};
  const int sequence_starts =
      options.sequence_starts < 0 ? static_cast<int>(2 * n) : options.sequence_starts;
  for (int k = 0; k < sequence_starts; ++k) {
    std::vector<double> y(n);
    for (std::size_t i = 0; i < n; ++i) {
      y[i] = lower[i] + halton(k + 1, kBases[i]) * (upper[i] - lower[i]);
    }
    ys.push_back(y);
  }
  CfmDesignProblem prbm_constraints = problem;
  prbm_constraints.pcf_min.reset();
  ExactSearch s(problem, prbm_constraints, options, cfm::CfmModel(problem.model));
  s.total = 1 + ys.size() * (static_cast<std::size_t>(options.max_evaluations) + 1);
  const auto feasible_at = [&](const std::vector<double>& x, double pcf) {
    try {
      const CfmDesignEvaluation e = evaluate_design(prbm_constraints, s.model, x);
      return e.feasible() && pcf > 0.0 && (!problem.pcf_min || pcf >= *problem.pcf_min - 1e-9);
    } catch (const InvalidInput&) {
      return false;
    }
  };
  out.start = starts.front();
  out.start_percent_constant_force_exact =
      exact_percent_constant_force(problem, out.start, options.confirm_points, options.work_budget);
  s.run_base = 1;
  s.report(1);
  out.x = out.start;
  out.percent_constant_force_exact = out.start_percent_constant_force_exact;
  bool best_feasible = feasible_at(out.x, out.percent_constant_force_exact);
  bool best_stopped = false;
  for (const std::vector<double>& y : ys) {
    s.run = static_cast<int>(&y - ys.data());
    const LocalResult local = run_local(s, y, lower, upper, options);
    const std::vector<double> x = exp_of(local.y);
    const double pcf =
        exact_percent_constant_force(problem, x, options.confirm_points, options.work_budget);
    s.end_run();
    const bool feasible = feasible_at(x, pcf);
    // Feasible beats infeasible; then the higher confirmed Xi'_exact.
    if ((feasible && !best_feasible) ||
        (feasible == best_feasible && pcf > out.percent_constant_force_exact)) {
      out.x = x;
      out.percent_constant_force_exact = pcf;
      best_feasible = feasible;
      best_stopped = local.stopped_by_test;
    }
  }
  out.starts = static_cast<int>(ys.size());
  out.history = std::move(s.history);
  out.evaluations = s.evaluations;
  out.iterations = s.evaluations;
  out.prbm = evaluate_design(prbm_constraints, s.model, out.x);
  double worst = 0.0;
  for (const NamedConstraint& c : out.prbm.constraints) worst = std::max(worst, c.violation());
  if (problem.pcf_min) {
    worst = std::max(worst, *problem.pcf_min - out.percent_constant_force_exact);
  }
  out.residual = worst;
  // The first start itself may remain the best (COBYLA found nothing better): converged too.
  const bool stopped = best_stopped || out.x == out.start;
  out.set_converged(best_feasible && stopped);
  out.message =
      !best_feasible ? "no start reached a feasible design with an exact solution"
      : !stopped
          ? fmt::format(
                "the best local run stopped at its evaluation limit "
                "({})",
                options.max_evaluations)
          : fmt::format("best of {} local runs, {} exact strokes", out.starts, out.evaluations);
  return out;
}

std::vector<std::vector<double>> exact_refinement_starts(const CfmDesignProblem& problem,
                                                         const std::vector<double>& prbm_x) {
  std::vector<std::vector<double>> starts{prbm_x};
  const auto [R_lo, R_hi] = toggle_R_interval(problem.stroke_percent);
  const std::vector<std::string> variables = problem.variables();
  for (const cfm::CfmSubclass& row : cfm::thesis_subclasses()) {
    if (row.config != problem.config || row.stroke_percent != problem.stroke_percent) continue;
    if (row.R < R_lo || row.R > R_hi) continue;  // toggle-clamped rows: outside the interval
    std::vector<double> x;
    bool inside = true;
    for (const std::string& v : variables) {
      const double value = v == "R" ? row.R : (v == "K1" ? row.K1 : row.K2);
      const Bounds& b = v == "R" ? problem.R : (v == "K1" ? problem.K1 : problem.K2);
      inside = inside && value >= b.lower && value <= b.upper;
      x.push_back(value);
    }
    if (inside) starts.push_back(x);
  }
  return starts;
}

CfmExactRefinement refine_cfm_exact_from_prbm(const CfmDesignProblem& problem,
                                              const CfmSynthesisResult& prbm,
                                              const ExactRefinementOptions& options) {
  if (prbm.x.empty()) {
    throw InvalidInput(
        "refine_cfm_exact_from_prbm: the PRBM synthesis found no design to start from");
  }
  return refine_cfm_exact(problem, exact_refinement_starts(problem, prbm.x), options);
}

}  // namespace flexure::design
