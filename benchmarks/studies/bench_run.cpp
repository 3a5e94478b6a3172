#include "flexure/benchmarks/studies/bench_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>

#include "flexure/benchmarks/studies/bench_hdf5.h"
#include "flexure/benchmarks/studies/bench_problems.h"
#include "flexure/benchmarks/studies/bench_solve.h"
#include "flexure/io/platform/hdf5_file.h"
#include "flexure/io/platform/output_path.h"
#include "flexure/mechanisms/mechanism_exact.h"
#include "flexure/solver/common/status.h"

namespace flexure::bench {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Below this tip displacement (per l) the relative error is not meaningful; it is taken relative
// to this floor instead (the unloaded beam would otherwise divide by zero).
constexpr double kDisplacementFloor = 1e-9;
// The same for the slider force of a mechanism problem, N.
constexpr double kForceFloor = 1e-12;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Times solves of one load: the first result is kept, repeats give the median. Slow solves are
// repeated less so that the full run stays within minutes.
template <typename Solve>
PointSolution timed_solve(Solve&& solve, bool quick, double& seconds, int& repeats) {
  std::vector<double> times;
  auto t0 = std::chrono::steady_clock::now();
  const PointSolution first = solve();
  times.push_back(seconds_since(t0));
  int target = quick ? 3 : 7;
  if (times[0] > 0.5) {
    target = 1;
  } else if (times[0] > 0.05) {
    target = 3;
  }
  while (static_cast<int>(times.size()) < target) {
    t0 = std::chrono::steady_clock::now();
    (void)solve();
    times.push_back(seconds_since(t0));
  }
  seconds = median(times);
  repeats = static_cast<int>(times.size());
  return first;
}

PointSolution timed_solve(const BenchMethod& method,
                          const BenchProblem& problem,
                          const LoadPoint& load,
                          bool quick,
                          double& seconds,
                          int& repeats) {
  return timed_solve([&] { return solve_point(method, problem, load); }, quick, seconds, repeats);
}

void push_point(MethodRun& run,
                const BenchProblem& problem,
                const LoadPoint& load,
                const PointSolution& s,
                double seconds,
                int repeats) {
  const bool beam = !problem.is_mechanism();
  run.load_ratio_n.push_back(beam ? load.load_ratio_n : kNaN);
  run.alpha2.push_back(beam ? load.alpha2 : kNaN);
  run.mu.push_back(beam ? load.mu : kNaN);
  const bool ok = s.status == kStatusConverged;
  run.a_over_l.push_back(ok && beam ? s.tip.a_over_l : kNaN);
  run.b_over_l.push_back(ok && beam ? s.tip.b_over_l : kNaN);
  run.theta0.push_back(ok && beam ? s.tip.theta0 : kNaN);
  if (!beam) {
    run.displacement.push_back(load.displacement);
    run.force.push_back(ok ? s.force : kNaN);
    run.error_force.push_back(kNaN);
  }
  run.seconds.push_back(seconds);
  run.repeats.push_back(repeats);
  run.status.push_back(s.status);
  run.iterations.push_back(s.iterations);
  run.inside_validity.push_back(s.inside_validity);
  run.message.push_back(s.message);
  run.error_position.push_back(kNaN);
  run.error_relative.push_back(kNaN);
  run.error_theta0.push_back(kNaN);
}

void fill_errors(MethodRun& run, const MethodRun& reference) {
  for (std::size_t i = 0; i < run.size(); ++i) {
    if (run.status[i] != kStatusConverged) continue;
    if (reference.status[i] != kStatusConverged) {
      run.status[i] = kStatusNoReference;
      continue;
    }
    if (!run.force.empty()) {
      // Mechanism: relative slider-force error (the stroke never reaches F = 0 for a
      // constant-force design; the floor only guards the division).
      const double e = std::fabs(run.force[i] - reference.force[i]) /
                       std::max(std::fabs(reference.force[i]), kForceFloor);
      run.error_force[i] = e;
      run.error_relative[i] = e;
      continue;
    }
    const double da = run.a_over_l[i] - reference.a_over_l[i];
    const double db = run.b_over_l[i] - reference.b_over_l[i];
    const double e = std::hypot(da, db);
    // Relative to the tip displacement from the unloaded tip (1, 0), as Howell's 0.5 % criterion
    // for the PRBM (eq. 5.47).
    const double displacement = std::hypot(reference.a_over_l[i] - 1.0, reference.b_over_l[i]);
    run.error_position[i] = e;
    run.error_relative[i] = e / std::max(displacement, kDisplacementFloor);
    run.error_theta0[i] = std::fabs(run.theta0[i] - reference.theta0[i]);
  }
}

bool same_points(const MethodRun& run, const BenchProblem& problem) {
  if (run.size() != problem.points.size()) return false;
  if (problem.is_mechanism()) {
    if (run.displacement.size() != problem.points.size()) return false;
    for (std::size_t i = 0; i < run.size(); ++i) {
      if (run.displacement[i] != problem.points[i].displacement) return false;
    }
    return true;
  }
  for (std::size_t i = 0; i < run.size(); ++i) {
    const LoadPoint& p = problem.points[i];
    if (run.load_ratio_n[i] != p.load_ratio_n || run.alpha2[i] != p.alpha2 || run.mu[i] != p.mu) {
      return false;
    }
  }
  return true;
}

}  // namespace

RunStatistics run_statistics(const MethodRun& run) {
  RunStatistics s;
  s.points = static_cast<int>(run.size());
  std::vector<double> times;
  for (std::size_t i = 0; i < run.size(); ++i) {
    if (run.status[i] == kStatusConverged || run.status[i] == kStatusNoReference) ++s.converged;
    if (run.status[i] == kStatusConverged && std::isfinite(run.error_relative[i])) {
      s.max_relative_error = s.measured == 0
                                 ? run.error_relative[i]
                                 : std::max(s.max_relative_error, run.error_relative[i]);
      ++s.measured;
    }
    if (i < run.seconds.size() && std::isfinite(run.seconds[i])) times.push_back(run.seconds[i]);
  }
  if (!times.empty()) s.median_seconds = median(times);
  return s;
}

std::string summarize(const MethodRun& run) {
  const RunStatistics s = run_statistics(run);
  std::string error;
  if (s.measured > 0) {
    error = fmt::format("{:.2e}", s.max_relative_error);
  } else if (run.method == "reference") {
    error = "n/a (this is the reference)";
  } else if (s.converged > 0) {
    error = "n/a (no reference at the converged loads)";
  } else {
    error = "n/a (no converged load)";
  }
  return fmt::format(
      "{}/{} converged, max relative error {}, median time {}",
      s.converged,
      s.points,
      error,
      std::isfinite(s.median_seconds) ? fmt::format("{:.3g} s", s.median_seconds) : "n/a");
}

std::string checkpoint_path(const std::string& out) { return out + ".partial"; }

namespace {

// A mechanism problem: the stroke is traced point by point (the exact model continues from the
// previous point); each point is timed as the median of repeated solves of that point. The
// reference is the exact model itself.
MethodRun run_mechanism_method(const BenchProblem& problem,
                               const BenchMethod* method,
                               const MethodRun* reference,
                               bool quick) {
  MethodRun run;
  run.problem = problem.name;
  const MethodFamily family = method ? method->family : MethodFamily::kMechanismExact;
  run.method = method ? method->name : "reference";
  run.family = method ? to_string(family) : "reference";
  // ExactMechanismSolver::Options: inner shooting rtol 1e-12; the PRBM is closed form.
  run.tolerance = family == MethodFamily::kMechanismExact ? 1e-12 : 0.0;
  if (family == MethodFamily::kMechanismExact) {
    run.backend = to_string(mechanism::ExactMechanismSolver::Options{}.shooting.backend);
  }
  CfmStrokeSolver solver(problem.mechanism);
  for (const LoadPoint& load : problem.points) {
    double seconds = 0.0;
    int repeats = 0;
    const PointSolution s = timed_solve([&] { return solver.solve(family, load.displacement); },
                                        method ? quick : true,
                                        seconds,
                                        repeats);
    solver.accept_last();
    push_point(run, problem, load, s, seconds, repeats);
    if (method == nullptr) run.reference_source.push_back(2);
  }
  if (reference) fill_errors(run, *reference);
  return run;
}

}  // namespace

MethodRun run_method(const BenchProblem& problem,
                     const BenchMethod* method,
                     const MethodRun* reference,
                     bool quick) {
  if (problem.is_mechanism()) return run_mechanism_method(problem, method, reference, quick);
  MethodRun run;
  run.problem = problem.name;
  if (method == nullptr) {
    // The reference: exact elliptic where it applies, else shooting at its tightest tolerance.
    run.method = "reference";
    run.family = "reference";
    run.tolerance = 1e-12;
    const BenchMethod elliptic{"elliptic", MethodFamily::kElliptic};
    const BenchMethod shooting = reference_shooting_method();
    for (const LoadPoint& load : problem.points) {
      double seconds = 0.0;
      int repeats = 0;
      int source = 1;
      PointSolution s;
      if (problem.elliptic_applies()) {
        s = timed_solve(elliptic, problem, load, true, seconds, repeats);
        source = 0;
      }
      if (s.status != kStatusConverged) {
        s = timed_solve(shooting, problem, load, true, seconds, repeats);
        source = 1;
      }
      push_point(run, problem, load, s, seconds, repeats);
      run.reference_source.push_back(source);
    }
    return run;
  }
  run.method = method->name;
  run.family = to_string(method->family);
  if (method->family == MethodFamily::kShooting) {
    run.backend = to_string(method->backend);
    run.tolerance = method->rtol;
  } else if (method->family == MethodFamily::kChain) {
    run.tolerance = 1e-12;  // ChainAlgorithmSolver::Options::tolerance
    run.elements = method->elements;
    run.increments = method->increments;
  } else if (method->family == MethodFamily::kElliptic) {
    run.tolerance = 1e-14;  // EllipticSolver::Options::tolerance
  }
  for (const LoadPoint& load : problem.points) {
    double seconds = 0.0;
    int repeats = 0;
    const PointSolution s = timed_solve(*method, problem, load, quick, seconds, repeats);
    push_point(run, problem, load, s, seconds, repeats);
  }
  if (reference) fill_errors(run, *reference);
  return run;
}

BenchSummary run_benchmark(const BenchOptions& options) {
  if (options.out.empty()) throw InvalidInput("--out: a results file name is required");
  const std::vector<BenchProblem> problems =
      select_problems(standard_problems(options.quick), options.problems);
  const std::vector<BenchMethod> methods =
      select_methods(standard_methods(options.quick), options.methods);
  auto say = [&](const std::string& line) {
    if (options.progress) options.progress(line);
  };

  // Finished groups from an interrupted run (checkpoint) or a previous complete file.
  std::vector<MethodRun> previous;
  const std::string checkpoint = checkpoint_path(options.out);
  if (options.resume) {
    std::string source;
    if (std::filesystem::exists(checkpoint)) {
      source = checkpoint;
    } else if (std::filesystem::exists(options.out)) {
      source = options.out;
    }
    if (!source.empty()) {
      if (read_bench_quick_flag(source) != options.quick) {
        throw InvalidInput(fmt::format(
            "--resume: {} was written {} --quick; run with the same flag or without --resume",
            source,
            options.quick ? "without" : "with"));
      }
      previous = read_bench_runs(source);
      say(fmt::format("resuming from {} ({} finished groups)", source, previous.size()));
    } else {
      say(fmt::format(
          "--resume: neither {} nor {} exists; starting afresh", checkpoint, options.out));
    }
  }
  if (!options.resume && std::filesystem::exists(checkpoint)) {
    // Never delete the finished groups of an interrupted run without being told to.
    throw InvalidInput(fmt::format(
        "{} holds the finished groups of an interrupted run: continue it with --resume, or delete "
        "the file to start afresh",
        checkpoint));
  }
  auto reuse = [&](const BenchProblem& p, const std::string& method) -> const MethodRun* {
    for (const MethodRun& r : previous) {
      if (r.problem == p.name && r.method == method && same_points(r, p)) return &r;
    }
    return nullptr;
  };

  BenchFileInfo info;
  info.machine = describe_machine();
  info.quick = options.quick;

  int total = 0;
  for (const BenchProblem& p : problems) {
    total += 1;
    for (const BenchMethod& m : methods) total += method_applies(m, p) ? 1 : 0;
  }

  BenchSummary summary;
  const auto start = std::chrono::steady_clock::now();
  int done = 0;
  auto finish_group = [&](MethodRun run, bool reused) -> bool {
    ++done;
    say(fmt::format("[{}/{}] {}: {}{} ({:.1f} s elapsed)",
                    done,
                    total,
                    run.key(),
                    summarize(run),
                    reused ? " (reused)" : "",
                    seconds_since(start)));
    summary.runs.push_back(std::move(run));
    if (reused) {
      ++summary.groups_reused;
      return true;
    }
    ++summary.groups_computed;
    info.complete = false;
    write_bench_file(checkpoint, info, problems, summary.runs);
    return options.stop_after_groups <= 0 || summary.groups_computed < options.stop_after_groups;
  };

  for (const BenchProblem& p : problems) {
    const MethodRun* old_reference = reuse(p, "reference");
    MethodRun reference =
        old_reference ? *old_reference : run_method(p, nullptr, nullptr, options.quick);
    if (!finish_group(reference, old_reference != nullptr)) return summary;
    for (const BenchMethod& m : methods) {
      if (!method_applies(m, p)) continue;
      const MethodRun* old = reuse(p, m.name);
      // A reused group keeps its errors only if the reference was reused too.
      if (old && old_reference) {
        if (!finish_group(*old, true)) return summary;
        continue;
      }
      if (!finish_group(run_method(p, &m, &reference, options.quick), false)) return summary;
    }
  }
  info.complete = true;
  write_bench_file(options.out, info, problems, summary.runs);
  std::error_code ignored;
  std::filesystem::remove(checkpoint, ignored);
  summary.complete = true;
  return summary;
}

int BenchSummary::solves() const {
  int count = 0;
  for (const MethodRun& run : runs) count += static_cast<int>(run.status.size());
  return count;
}

int BenchSummary::failed_solves() const {
  int count = 0;
  for (const MethodRun& run : runs) {
    for (int s : run.status) count += s == kStatusNotConverged || s == kStatusError ? 1 : 0;
  }
  return count;
}

void check_bench_outputs(const BenchOptions& options, const std::string& option) {
  io::check_output_path(options.out, option);
  io::check_output_path(checkpoint_path(options.out), option + " (its checkpoint)");
  try {
    io::AtomicHdf5File probe(options.out);
  } catch (const io::Hdf5Error& e) {
    throw InvalidInput(fmt::format("{} {}: {}", option, options.out, e.what()));
  }
}

}  // namespace flexure::bench
