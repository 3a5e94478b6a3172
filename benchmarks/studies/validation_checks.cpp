#include "flexure/benchmarks/studies/validation_checks.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "flexure/benchmarks/studies/validation_problems.h"

namespace flexure {
namespace {

// Timing: repeat a solve until this much time has passed (or kMaxRepeats), for a stable mean.
constexpr double kMinTimingSeconds = 2e-3;
constexpr int kMaxRepeats = 1000;

struct TimedSolve {
  BeamSolution solution;
  bool solved = false;
  std::string error;
  double seconds_per_solve = 0.0;
};

TimedSolve timed_solve(const ValidationMethod& method, const BeamProblem& problem) {
  TimedSolve timed;
  using Clock = std::chrono::steady_clock;
  try {
    const auto start = Clock::now();
    timed.solution = method.solve(problem);
    int repeats = 1;
    double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    while (elapsed < kMinTimingSeconds && repeats < kMaxRepeats) {
      method.solve(problem);
      ++repeats;
      elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    }
    timed.seconds_per_solve = elapsed / repeats;
    timed.solved = timed.solution.converged();
    if (!timed.solved) timed.error = "not converged: " + timed.solution.message;
  } catch (const std::exception& e) {
    // A reference problem the method rejects or cannot solve is a failed check, not a crash.
    timed.error = e.what();
  }
  return timed;
}

}  // namespace

std::vector<ValidationCheck> run_validation_checks() {
  std::vector<ValidationCheck> checks;
  const std::vector<ReferenceProblem> problems = reference_problems();
  for (const ValidationMethod& method : validation_methods()) {
    for (const ReferenceProblem& problem : problems) {
      if (!method.applies(problem)) continue;
      const TimedSolve timed = timed_solve(method, problem.problem);
      for (const ReferenceValue& expected : problem.expected) {
        ValidationCheck check;
        check.problem = problem.name;
        check.method = method.name;
        check.quantity = expected.quantity;
        check.reference = expected.reference;
        // A numerical method passes within its own stated accuracy or the reference's rounding.
        check.tolerance = std::max(expected.tolerance, method.accuracy);
        check.seconds_per_solve = timed.seconds_per_solve;
        check.message = timed.error;
        if (timed.solved) {
          const double computed = quantity_value(timed.solution, expected.quantity);
          if (std::isfinite(computed)) {
            check.computed = computed;
            check.rel_error = std::abs(computed - expected.reference) /
                              std::max(std::abs(expected.reference), expected.scale_floor);
            check.passed = check.rel_error <= check.tolerance;
          } else {
            check.message = fmt::format("{} is not finite", expected.quantity);
          }
        }
        checks.push_back(std::move(check));
      }
    }
  }
  return checks;
}

ValidationReport run_validation() {
  ValidationReport report;
  report.checks = run_validation_checks();
  const auto failed = std::count_if(report.checks.begin(),
                                    report.checks.end(),
                                    [](const ValidationCheck& c) { return !c.passed; });
  report.all_passed = failed == 0;
  report.set_converged(report.all_passed);
  report.message = report.all_passed
                       ? fmt::format("all {} checks passed", report.checks.size())
                       : fmt::format("{} of {} checks failed", failed, report.checks.size());
  return report;
}

}  // namespace flexure
