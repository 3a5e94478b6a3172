#include "flexure/mechanisms/design/cfm_synthesis.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <nlopt.hpp>

#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/design/halton.h"
#include "flexure/solver/common/status.h"

namespace flexure::design {
namespace {

// The value NLopt sees where the model refuses a point (never NaN), and the cap of a normalised
// constraint violation.
constexpr double kPenalty = 1e6;
constexpr double kMaxViolation = 1e3;
// A local run whose chunk of evaluations (run_local) improved its best by less than this has
// converged as far as designs differ: 1e-4 of Psi or d_N (their logs are minimised), 1e-4 of
// Xi or Xi' (0.01 points).
constexpr double kProgress = 1e-4;
// A restarted local run that met its tolerance having gained more than this (0.1 % of Psi) is
// crawling along a narrow band and restarts again (run_local).
constexpr double kCrawlGain = 1e-3;
// The smallest initial step (log units) a stalled local run retries with (run_local).
constexpr double kSmallestStep = 1e-3;
// A region's optimum keeps its pivot the primary one by this much of log Psi (Search::regions):
// the model's choice of the primary pivot at a tie is then not in question.
constexpr double kRegionMargin = 1e-8;

// The primary pivot decides which flexures the orientation rules apply to (Table 5.4: every one
// but the primary) and which pivot's stress Psi counts (eq. 5.19): both jump where it changes,
// and local optima sit on those jumps. So the search also poses the problem in each region of the
// design space where pivot j is the primary one: there the rules are taken relative to j, Psi is
// Psi_j, and "j is primary" is a smooth constraint (Psi_j <= Psi_i for every sprung i; the primary
// pivot has the highest stress, i.e. the smallest Psi_i). Index 0 is the problem as posed, index j
// (1..3) the problem in region j.
constexpr int kViews = 4;

// One evaluated design as the search sees it.
struct Sample {
  std::vector<double> y;  // log variables
  cfm::CfmResult result;
  // Per view (0: as posed, j: region j): the minimised objective (Xi, -Xi', -log Psi or
  // log d_N,max), the largest normalised constraint violation (with the coarse margin), and
  // feasibility.
  std::array<double, kViews> f{};
  std::array<double, kViews> violation{};
  std::array<bool, kViews> feasible{};
  std::array<bool, kViews> has_view{};  // which views are computed (Search::fill_views)
  double objective = 0.0;               // the minimised objective as posed
  std::array<double, 3> log_psi{};      // log Psi_i (log_psi_of), with regions
  int run = -1;                         // the local run that met it (-1: the scan)
};

// In view v: feasible before infeasible; then the objective, or the smaller violation.
bool ranks_before(const Sample& a, const Sample& b, int v) {
  if (a.feasible[v] != b.feasible[v]) return a.feasible[v];
  if (a.feasible[v]) return a.f[v] < b.f[v];
  return a.violation[v] < b.violation[v];
}

// `a` better than `b` in view v by more than a relative `tol` (the minimised objective is log Psi
// or log d_N for those, so there an absolute one).
bool improves_on(const Sample& a, const Sample& b, int v, double tol, bool log_objective) {
  if (a.feasible[v] != b.feasible[v]) return a.feasible[v];
  const double scale = log_objective ? 1.0 : std::max(1.0, std::abs(b.f[v]));
  if (a.feasible[v]) return a.f[v] < b.f[v] - tol * scale;
  return a.violation[v] < b.violation[v] - tol;
}

// log Psi_i of every pivot (+inf for a pin): the stiffness parameter (eq. 5.19) were pivot i the
// primary one, from the model's beta, kappa, lambda and end-of-stroke alpha_i as cfm_model.cpp
// computes Psi_raw for the primary pivot.
std::array<double, 3> log_psi_of(const cfm::CfmResult& r, bool class_1B) {
  const std::array<double, 3> K_prev = {1.0, r.K1, r.K2};
  const double kappa_ref = r.kappa[class_1B ? 1 : 0];
  std::array<double, 3> out{};
  for (int i = 0; i < 3; ++i) {
    const bool sprung = r.kappa[i] > 0.0 && K_prev[i] > 0.0 && r.alpha_end[i] > 0.0;
    out[i] = sprung ? std::log(r.beta * r.kappa[i] / (r.lambda * kappa_ref * K_prev[i])) -
                          3.0 * std::log(r.alpha_end[i])
                    : std::numeric_limits<double>::infinity();
  }
  return out;
}

// The model on one sampling, with a cache of the last point (NLopt asks for the objective and
// the constraints at the same point one after the other), the best sample met in all (as posed)
// and in the local run under way (in its view).
class Search {
 public:
  Search(const CfmDesignProblem& problem,
         cfm::CfmOptions options,
         std::vector<double> lower_bounds,
         std::vector<double> upper_bounds,
         std::vector<int> region_pivots,
         double pcf_margin)
      : lower(std::move(lower_bounds)),
        upper(std::move(upper_bounds)),
        regions(std::move(region_pivots)),
        log_objective(problem.objective == DesignObjective::kMaxPsi ||
                      problem.objective == DesignObjective::kMinDn),
        problem_(problem),
        model_(options),
        class_1B_(cfm::find_cfm_configuration(problem.config).is_class_1B()),
        pcf_margin_(pcf_margin) {
    // The free variables' values come from at(); the held ones are set once.
    const std::vector<std::string> names = problem.variables();
    parameters_ = parameters_at(problem, std::vector<double>(names.size(), 1.0));
    for (const std::string& name : names) {
      if (name == "R") variable_.push_back(&parameters_.R);
      if (name == "K1") variable_.push_back(&*parameters_.K1);
      if (name == "K2") variable_.push_back(&*parameters_.K2);
    }
  }

  // The design at log variables y[0..n), or nullptr where the model refuses it.
  const Sample* at(const double* y, std::size_t n) {
    if (has_last_ && std::equal(y, y + n, last_.y.begin(), last_.y.end())) {
      if (!last_valid_) return nullptr;
      fill_views(last_);
      note(last_);
      return &last_;
    }
    ++evaluations;
    has_last_ = true;
    last_valid_ = false;
    last_.y.assign(y, y + n);
    for (std::size_t i = 0; i < n; ++i) *variable_[i] = std::exp(y[i]);
    try {
      last_.result = model_.evaluate(parameters_);
    } catch (const InvalidInput&) {
      record(nullptr);
      return nullptr;
    }
    const cfm::CfmResult& r = last_.result;
    const double objective = objective_value(problem_, r);
    if (!std::isfinite(objective) || !r.converged()) {
      record(nullptr);
      return nullptr;
    }
    last_.has_view.fill(false);
    last_.objective = minimised(objective);
    if (!regions.empty()) last_.log_psi = log_psi_of(r, class_1B_);
    fill_views(last_);
    last_.run = run;
    last_valid_ = true;
    record(&last_);
    note(last_);
    return &last_;
  }
  const Sample* at(const std::vector<double>& y) { return at(y.data(), y.size()); }

  // Starts local run `id` in view `v`: its best starts afresh.
  void begin_run(int id, int v) {
    run = id;
    view = v;
    run_best.reset();
  }

  // NLopt's inequality constraints g <= 0 in the view under way: the normalised violations of
  // the problem's constraints (the toggle limit, in the bounds of R, left out), then in a region
  // those that keep its pivot primary.
  std::size_t constraint_count() const {
    const std::size_t rules = constraint_count_;
    return view > 0 ? rules + regions.size() - 1 : rules;
  }
  void set_constraint_count(std::size_t m) { constraint_count_ = m; }
  void constraints_of(const Sample* s, double* g) {
    const std::size_t count = constraint_count();
    if (s == nullptr) {
      std::fill(g, g + count, kPenalty);
      return;
    }
    constraint_values(problem_, s->result, view > 0 ? view : s->result.primary_pivot, values_);
    std::size_t k = 0;
    for (std::size_t c = 1; c < values_.size(); ++c) g[k++] = normalised(values_[c]);
    if (view > 0) {
      for (int i : regions) {
        if (i != view) g[k++] = region_violation(s->log_psi, view, i);
      }
    }
  }

  // Largest coordinate distance of two log points, in units of each variable's log range.
  double box_distance(const std::vector<double>& a, const std::vector<double>& b) const {
    double d = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      const double range = upper[i] - lower[i];
      if (range > 0.0) d = std::max(d, std::abs(a[i] - b[i]) / range);
    }
    return d;
  }

  std::vector<double> lower, upper;  // log bounds
  std::vector<int> regions;          // the sprung pivots (1..3) when regions are searched
  int evaluations = 0;               // distinct model evaluations
  std::vector<SynthesisEvaluation>* history = nullptr;  // where record() appends, if anywhere
  bool full_sampling = true;                            // for record()
  int run = -1;                                         // the local run under way (-1: the scan)
  int view = 0;                                         // its view: 0 as posed, j in region j
  bool log_objective = false;                           // Sample::f is a log (max-psi, min-dn)
  bool restoring = false;           // NLopt minimises the violation instead of the objective
  bool all_views = false;           // compute every view of each sample (the scan)
  std::optional<Sample> best;       // over every evaluation, as posed
  std::optional<Sample> run_best;   // over the run under way, in its view
  nlopt::opt* optimiser = nullptr;  // the local run under way
  std::vector<std::vector<double>> known_optima;  // the optima of the runs before, this view
  double duplicate_radius = 0.0;                  // box distance of the duplicate test
  bool duplicate = false;                         // the run under way was stopped as one

 private:
  // Sample::f, violation, feasible in view 0 (as posed), the view under way, or every view while
  // all_views (the scan ranks its points in each).
  void fill_views(Sample& s) {
    fill_view(s, 0);
    if (all_views) {
      for (int j : regions) fill_view(s, j);
    } else if (view > 0) {
      fill_view(s, view);
    }
  }
  void fill_view(Sample& s, int v) {
    if (s.has_view[v]) return;
    s.has_view[v] = true;
    const cfm::CfmResult& r = s.result;
    s.f[v] =
        problem_.objective == DesignObjective::kMaxPsi && v > 0 ? -s.log_psi[v - 1] : s.objective;
    // As posed the rules are relative to the model's primary pivot, in region j to j.
    constraint_values(problem_, r, v > 0 ? v : r.primary_pivot, values_);
    double worst = -kMaxViolation;
    for (const ConstraintValue& c : values_) worst = std::max(worst, normalised(c));
    if (v > 0) {
      for (int i : regions) {
        if (i != v) worst = std::max(worst, region_violation(s.log_psi, v, i));
      }
    }
    s.violation[v] = worst;
    // The full sampling's feasibility as posed is the problem's own test; the coarse one's
    // includes the margin.
    s.feasible[v] = v == 0 && pcf_margin_ == 0.0
                        ? std::all_of(values_.begin(),
                                      values_.end(),
                                      [](const ConstraintValue& c) { return c.satisfied(); })
                        : worst <= 0.0;
  }

  // Appends the evaluation at parameters_ to the history, if one is kept.
  void record(Sample* s) {
    if (history == nullptr) return;
    SynthesisEvaluation e;
    e.run = run;
    e.full_sampling = full_sampling;
    e.R = parameters_.R;
    e.K1 = parameters_.K1.value_or(0.0);
    e.K2 = parameters_.K2.value_or(0.0);
    if (s != nullptr) {
      fill_view(*s, 0);
      e.valid = true;
      e.objective = objective_value(problem_, s->result);
      e.max_violation = s->violation[0];
      e.feasible = s->feasible[0];
    }
    history->push_back(e);
  }

  void note(const Sample& s) {
    if (!best || ranks_before(s, *best, 0)) {
      best = s;
      best->run = run;
    }
    if (!run_best || ranks_before(s, *run_best, view)) {
      run_best = s;
      run_best->run = run;
    }
    // A run whose best comes within duplicate_radius of an optimum found before is heading for
    // it: it stops there (early exit for duplicate local optima).
    if (optimiser != nullptr && !restoring) {
      for (const std::vector<double>& o : known_optima) {
        if (box_distance(run_best->y, o) < duplicate_radius) {
          duplicate = true;
          optimiser->force_stop();
          break;
        }
      }
    }
  }
  double minimised(double objective) const {
    switch (problem_.objective) {
      case DesignObjective::kMinXi:
        return objective;
      case DesignObjective::kMaxPcf:
        return -objective;
      // Psi and d_N span decades between configurations: the log keeps the optimiser's scale.
      case DesignObjective::kMaxPsi:
        return objective > 0.0 ? -std::log(objective) : kPenalty;
      case DesignObjective::kMinDn:
        return objective > 0.0 ? std::log(objective) : -kPenalty;
    }
    return objective;
  }
  double normalised(const ConstraintValue& c) const {
    double v = c.normalised_violation();
    if (c.kind == ConstraintKind::kPcf) v += pcf_margin_ / std::max(100.0 - c.bound, 1e-3);
    return std::clamp(v, -kMaxViolation, kMaxViolation);
  }
  // Pivot j stays the primary one against pivot i: log Psi_j - log Psi_i + margin <= 0.
  static double region_violation(const std::array<double, 3>& log_psi, int j, int i) {
    const double v = log_psi[j - 1] - log_psi[i - 1] + kRegionMargin;
    return std::isfinite(v) ? std::clamp(v, -kMaxViolation, kMaxViolation) : kMaxViolation;
  }

  const CfmDesignProblem& problem_;
  cfm::CfmModel model_;
  bool class_1B_ = false;
  double pcf_margin_ = 0.0;
  std::size_t constraint_count_ = 0;
  Sample last_;
  bool has_last_ = false;
  bool last_valid_ = false;
  std::vector<ConstraintValue> values_;  // scratch
  cfm::CfmParameters parameters_;        // the model's input, the free variables set by at()
  std::vector<double*> variable_;        // parameters_' R, K1 or K2 of each free variable
};

double objective_of(unsigned n, const double* y, double*, void* data) {
  auto* s = static_cast<Search*>(data);
  const Sample* p = s->at(y, n);
  if (p == nullptr) return kPenalty;
  return s->restoring ? p->violation[s->view] : p->f[s->view];
}

void constraints_of(unsigned, double* g, unsigned n, const double* y, double*, void* data) {
  auto* s = static_cast<Search*>(data);
  s->constraints_of(s->at(y, n), g);
}

struct LocalSettings {
  nlopt::algorithm algorithm = nlopt::LN_COBYLA;
  std::vector<double> steps;  // initial steps of each log variable
  double xtol = 1e-6;         // absolute on the log variables
  int max_evaluations = 2000;
  int chunk = 100;       // evaluations between the progress tests (run_local)
  bool restore = false;  // minimise the violation down to 0 (feasible) instead
};

// One local run from y; true when it ended by a stopping test (the tolerance, the progress test,
// a duplicate optimum, or feasibility reached while restoring), not by its evaluation limit.
//
// It runs in chunks of `chunk` evaluations. A chunk that uses them all while improving the run's
// best by more than kProgress restarts from that best with the initial steps: along a narrow
// feasible band or a jump of the constraints COBYLA's trust region shrinks to tiny steps and
// crawls, which restarts walk in a few. A chunk that improved it by less retries with smaller
// steps, down to kSmallestStep, where the run has converged.
bool run_local(Search& s, std::vector<double> y, const LocalSettings& settings) {
  const unsigned n = static_cast<unsigned>(y.size());
  nlopt::opt opt(settings.algorithm, n);
  opt.set_lower_bounds(s.lower);
  opt.set_upper_bounds(s.upper);
  opt.set_min_objective(objective_of, &s);
  s.restoring = settings.restore;
  if (settings.restore) {
    // The largest violation is <= 0 exactly where the design is feasible, and never below 0 with
    // an orientation rule (the primary pivot meets its own with equality); NLopt stops below
    // stopval.
    opt.set_stopval(1e-12);
  } else if (settings.algorithm == nlopt::LN_COBYLA && s.constraint_count() > 0) {
    opt.add_inequality_mconstraint(
        constraints_of, &s, std::vector<double>(s.constraint_count(), 1e-12));
  }
  opt.set_xtol_abs(settings.xtol);
  std::vector<double> steps(n);
  for (unsigned i = 0; i < n; ++i) {
    steps[i] = std::min(settings.steps[i], 0.5 * (s.upper[i] - s.lower[i]));
  }
  opt.set_initial_step(steps);
  s.optimiser = &opt;
  s.duplicate = false;
  bool by_test = false;
  bool restarted = false;
  for (int used = 0; used < settings.max_evaluations;) {
    opt.set_maxeval(std::min(settings.chunk, settings.max_evaluations - used));
    const std::optional<Sample> chunk_start = s.run_best;
    bool limit = false;
    by_test = false;
    double value = 0.0;
    try {
      const nlopt::result r = opt.optimize(y, value);
      by_test = r == nlopt::XTOL_REACHED || r == nlopt::FTOL_REACHED || r == nlopt::SUCCESS ||
                r == nlopt::STOPVAL_REACHED;
      limit = r == nlopt::MAXEVAL_REACHED;
    } catch (const nlopt::forced_stop&) {
      by_test = s.duplicate;  // the optimum found before stands for this run
    } catch (const nlopt::roundoff_limited&) {
      by_test = true;  // as far as double precision goes
    } catch (const std::runtime_error&) {
      // NLopt's generic failure: the run's best stands.
    }
    used += opt.get_numevals();
    if (s.duplicate || settings.restore || !s.run_best) break;
    if (!limit) {
      // Met its tolerance. A restart that still gained more than kCrawlGain is crawling along a
      // narrow band (see below) and goes on; a first chunk that met it has converged.
      if (!restarted || !chunk_start ||
          !improves_on(*s.run_best, *chunk_start, s.view, kCrawlGain, s.log_objective)) {
        break;
      }
    }
    restarted = true;
    // The chunk used up its evaluations: the run restarts from its best while the chunk gained
    // more than kProgress. One that gained less retries with a tenth of its steps (a feasible
    // band narrower than the steps, as Xi' >= 98 near the largest Xi' of sps at 40 %, defeats
    // COBYLA's linear models), and has converged as far as it matters at steps of 1e-3.
    if (chunk_start &&
        !improves_on(*s.run_best, *chunk_start, s.view, kProgress, s.log_objective)) {
      if (*std::max_element(steps.begin(), steps.end()) <= kSmallestStep) {
        by_test = true;
        break;
      }
      for (double& step : steps) step = std::max(0.1 * step, std::min(step, kSmallestStep));
      opt.set_initial_step(steps);
    }
    y = s.run_best->y;
  }
  s.optimiser = nullptr;
  s.restoring = false;
  return by_test;
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

// Up to `count` samples of `ranked` (best first), each at least `separation` from those taken.
std::vector<const Sample*> distinct_best(const std::vector<const Sample*>& ranked,
                                         std::size_t count,
                                         double separation,
                                         const Search& s) {
  std::vector<const Sample*> taken;
  for (const Sample* c : ranked) {
    if (taken.size() == count) break;
    const bool far = std::all_of(taken.begin(), taken.end(), [&](const Sample* t) {
      return s.box_distance(t->y, c->y) >= separation;
    });
    if (far) taken.push_back(c);
  }
  return taken;
}

}  // namespace

void SynthesisOptions::validate() const {
  if (starts < 0 || starts > 10000) {
    throw InvalidInput(fmt::format("starts = {} must lie in [0, 10000] (0: automatic)", starts));
  }
  if (scan_points < 0 || scan_points > 1000000) {
    throw InvalidInput(
        fmt::format("scan_points = {} must lie in [0, 1000000] (0: automatic)", scan_points));
  }
  if (polish < 0 || polish > 10000) {
    throw InvalidInput(fmt::format("polish = {} must lie in [0, 10000] (0: automatic)", polish));
  }
  if (coarse_stride < 1) {
    throw InvalidInput(fmt::format("coarse_stride = {} must be >= 1", coarse_stride));
  }
  if (!(pcf_margin >= 0.0 && pcf_margin < 10.0)) {
    throw InvalidInput(fmt::format("pcf_margin = {} must lie in [0, 10)", pcf_margin));
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
  CfmSynthesisResult out;
  out.variables = problem.variables();
  const auto [R_lo, R_hi] = toggle_R_interval(problem.stroke_percent);
  std::vector<double> lower, upper;
  for (const std::string& v : out.variables) {
    const Bounds b = v == "R"
                         ? Bounds{std::max(problem.R.lower, R_lo), std::min(problem.R.upper, R_hi)}
                         : (v == "K1" ? problem.K1 : problem.K2);
    lower.push_back(std::log(b.lower));
    upper.push_back(std::log(b.upper));
  }
  const std::size_t n = out.variables.size();
  nlopt::srand(options.seed);

  // Regions of the primary pivot (Search) where it matters: Psi, or orientation rules, with two
  // or more sprung pivots.
  const cfm::CfmConfiguration& configuration = cfm::find_cfm_configuration(problem.config);
  std::vector<int> regions;
  if (problem.objective == DesignObjective::kMaxPsi || !problem.orientation.empty()) {
    for (int i = 1; i <= 3; ++i) {
      if (configuration.has_spring(i)) regions.push_back(i);
    }
    if (regions.size() < 2) regions.clear();
  }
  std::vector<int> views;
  if (regions.empty()) views.push_back(0);
  views.insert(views.end(), regions.begin(), regions.end());

  // The full sampling decides; the coarse one (a subset of its points) searches, when the full
  // one has enough points for a subset to be worth it.
  const cfm::CfmOptions& full = problem.model;
  const long full_points =
      full.sampling == cfm::StrokeSampling::kThesisCode ? 1000 : static_cast<long>(full.points);
  const bool two_phase = options.coarse_stride > 1 && full_points >= 10L * options.coarse_stride;
  cfm::CfmOptions coarse_options = full;
  coarse_options.stride = two_phase ? options.coarse_stride : 1;
  Search fine(problem, full, lower, upper, regions, 0.0);
  Search coarse(problem, coarse_options, lower, upper, regions, options.pcf_margin);
  Search& global = two_phase ? coarse : fine;
  coarse.full_sampling = false;
  if (options.record_history) {
    fine.history = &out.history;
    coarse.history = &out.history;
  }

  // One NLopt constraint per rule and pivot (cfm_design_problem.cpp), a count fixed by the
  // problem; the toggle limit is in the bounds of R.
  std::size_t m = problem.pcf_min ? 1 : 0;
  for (OrientationRule f : problem.orientation) m += f == OrientationRule::kInPlane ? 3 : 9;
  fine.set_constraint_count(m);
  coarse.set_constraint_count(m);
  // Without constraints the objective (a max/min ratio over the stroke) has kinks at its optimum,
  // where COBYLA's linear models stall: Nelder-Mead instead.
  const bool constrained = m > 0 || !regions.empty();
  const nlopt::algorithm local = constrained ? nlopt::LN_COBYLA : nlopt::LN_NELDERMEAD;

  // Step 1: the scan.
  const int scan_points =
      options.scan_points > 0 ? options.scan_points : (n == 1 ? 32 : (n == 2 ? 256 : 1024));
  const int starts = options.starts > 0 ? options.starts : (n == 2 ? 4 : 3);
  const int polish = options.polish > 0 ? options.polish : 2;
  // Progress (SynthesisOptions::progress): one step per scan point and per local run.
  const std::size_t steps = static_cast<std::size_t>(scan_points) +
                            views.size() * static_cast<std::size_t>(starts) +
                            (two_phase ? static_cast<std::size_t>(polish) : 0);
  std::size_t steps_done = 0;
  const auto step_done = [&] {
    ++steps_done;
    if (options.progress) options.progress(steps_done, steps);
  };
  constexpr int kBases[] = {2, 3, 5};
  std::vector<Sample> scan;
  scan.reserve(static_cast<std::size_t>(scan_points));
  for (int k = 1; k <= scan_points; ++k) {
    std::vector<double> y(n);
    for (std::size_t i = 0; i < n; ++i) {
      y[i] = lower[i] + halton(k, kBases[i]) * (upper[i] - lower[i]);
    }
    global.all_views = true;
    if (const Sample* p = global.at(y)) scan.push_back(*p);
    global.all_views = false;
    step_done();
  }

  // One local run from a sample in view v: an infeasible start is first brought to feasibility
  // by Nelder-Mead on the largest violation (stopping as soon as it is feasible), then optimised.
  std::vector<bool> by_test;
  const auto local_run = [&](Search& s, const Sample& from, int v, const LocalSettings& settings) {
    s.begin_run(static_cast<int>(by_test.size()), v);
    const Sample* p = s.at(from.y);
    std::vector<double> y = from.y;
    if (constrained && p != nullptr && !p->feasible[v]) {
      LocalSettings restore = settings;
      restore.algorithm = nlopt::LN_NELDERMEAD;
      restore.restore = true;
      run_local(s, y, restore);
      if (s.run_best) y = s.run_best->y;
    }
    by_test.push_back(run_local(s, y, settings));
    step_done();
  };

  // Step 2: in each view, local runs from the best distinct scan points, with initial steps of
  // about the scan's spacing.
  const double spacing = 1.0 / std::pow(static_cast<double>(scan_points), 1.0 / n);
  LocalSettings coarse_settings;
  coarse_settings.algorithm = local;
  double smallest_range = upper[0] - lower[0];
  for (std::size_t i = 0; i < n; ++i)
    smallest_range = std::min(smallest_range, upper[i] - lower[i]);
  coarse_settings.steps.assign(n, spacing * smallest_range);
  coarse_settings.xtol = options.xtol_rel;
  coarse_settings.chunk = 40 * static_cast<int>(n + 1);
  // A coarse run only seeds the polish: a valley crawled for longer is not worth it.
  coarse_settings.max_evaluations =
      two_phase ? std::min(options.max_evaluations, 1000 * static_cast<int>(n + 1))
                : options.max_evaluations;
  global.duplicate_radius = 1e-3;
  struct Optimum {
    Sample sample;
    int view = 0;
  };
  std::vector<Optimum> optima;
  for (int v : views) {
    std::vector<const Sample*> ranked(scan.size());
    std::transform(scan.begin(), scan.end(), ranked.begin(), [](const Sample& a) { return &a; });
    std::stable_sort(ranked.begin(), ranked.end(), [v](const Sample* a, const Sample* b) {
      return ranks_before(*a, *b, v);
    });
    global.known_optima.clear();
    for (const Sample* start :
         distinct_best(ranked, static_cast<std::size_t>(starts), 2.0 * spacing, global)) {
      local_run(global, *start, v, coarse_settings);
      ++out.starts;
      if (global.run_best) {
        if (global.run_best->feasible[v]) ++out.feasible_starts;
        optima.push_back({*global.run_best, v});
        global.known_optima.push_back(global.run_best->y);
      }
    }
  }
  // The optima of all views ranked as posed would miss a region's optimum that sits on its edge
  // (as posed, the other side of the edge is another region): rank each by its own view.
  std::stable_sort(optima.begin(), optima.end(), [](const Optimum& a, const Optimum& b) {
    if (a.sample.feasible[a.view] != b.sample.feasible[b.view]) return a.sample.feasible[a.view];
    if (a.sample.feasible[a.view]) return a.sample.f[a.view] < b.sample.f[b.view];
    return a.sample.violation[a.view] < b.sample.violation[b.view];
  });

  // Step 3: the best distinct coarse optima polished on the full sampling, with small steps: the
  // coarse sampling agrees with the full one to about 3e-4 points of Xi' and 1e-5 of Psi at the
  // optima (measured on the 68 sub-classes), so a short run finishes.
  if (two_phase && !optima.empty()) {
    LocalSettings polish_settings = coarse_settings;
    polish_settings.steps.assign(n, 1e-3);
    polish_settings.chunk = 10 * static_cast<int>(n + 1);
    polish_settings.max_evaluations = std::min(options.max_evaluations, 4 * polish_settings.chunk);
    // Only optima that the coarse sampling can hardly tell from the best could overtake it on the
    // full one: within 0.1 % of Psi or d_N, 0.005 points of Xi', 5e-5 of Xi.
    const double window = problem.objective == DesignObjective::kMaxPcf
                              ? 0.005
                              : (problem.objective == DesignObjective::kMinXi ? 5e-5 : 1e-3);
    const Optimum& first = optima.front();
    std::vector<Optimum> chosen;
    for (const Optimum& o : optima) {
      if (static_cast<int>(chosen.size()) == polish) break;
      const bool close = o.sample.feasible[o.view] == first.sample.feasible[first.view] &&
                         o.sample.f[o.view] <= first.sample.f[first.view] + window;
      const bool distinct = std::all_of(chosen.begin(), chosen.end(), [&](const Optimum& c) {
        return coarse.box_distance(c.sample.y, o.sample.y) >= 1e-3;
      });
      if ((&o == &first || close) && distinct) chosen.push_back(o);
    }
    fine.duplicate_radius = 1e-3;
    for (const Optimum& o : chosen) {
      local_run(fine, o.sample, o.view, polish_settings);
      if (fine.run_best) fine.known_optima.push_back(fine.run_best->y);
    }
  }
  if (options.progress && steps_done < steps) options.progress(steps, steps);
  out.evaluations = coarse.evaluations + fine.evaluations;
  out.fine_evaluations = fine.evaluations;
  out.iterations = out.evaluations;
  // One phase: fine is the search itself. Two: its best over the polish (as posed).
  if (!fine.best) {
    out.termination = Termination::kNoConvergence;
    out.message = fmt::format("the model refused every one of the {} starts", out.starts);
    return out;
  }
  const Sample& best = *fine.best;
  out.x.resize(n);
  std::transform(best.y.begin(), best.y.end(), out.x.begin(), [](double v) { return std::exp(v); });
  out.best = evaluate_design(problem, cfm::CfmModel(full), out.x);
  const NamedConstraint* worst = nullptr;
  for (const NamedConstraint& c : out.best.constraints) {
    if (worst == nullptr || c.violation() > worst->violation()) worst = &c;
  }
  out.residual = worst != nullptr ? std::max(0.0, worst->violation()) : 0.0;
  out.nearest_subclass = nearest_subclass(problem, out.best.result);
  const bool run_converged = best.run < 0
                                 ? std::find(by_test.begin(), by_test.end(), true) != by_test.end()
                                 : by_test[static_cast<std::size_t>(best.run)];
  if (!out.best.feasible()) {
    out.termination = Termination::kNoConvergence;
    out.message = fmt::format(
        "no start reached a feasible design; the best violates '{}' ({:.6g} against {:g})",
        worst->name,
        worst->value,
        worst->bound);
  } else if (!run_converged) {
    out.termination = Termination::kNoConvergence;
    out.message = fmt::format(
        "the best local run stopped at its evaluation limit before its tolerance ({} model "
        "evaluations)",
        out.evaluations);
  } else {
    out.termination = Termination::kConverged;
    out.message = fmt::format(
        "best of {} local runs ({} feasible) from {} scan points, {} model evaluations ({} on "
        "the full sampling)",
        out.starts,
        out.feasible_starts,
        scan_points,
        out.evaluations,
        out.fine_evaluations);
  }
  return out;
}

}  // namespace flexure::design
