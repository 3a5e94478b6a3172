#include "cli/beam_methods.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <utility>
#include <vector>

#include "cli/cli_common.h"
#include "flexure/beam/beam_keys.h"
#include "flexure/solver/common/names.h"
#include "flexure/solver/common/status.h"

namespace flexure::cli {

void add_method_option(CLI::App& command, std::string& method) {
  command
      .add_option(
          "--method",
          method,
          "Solution method: auto (the cheapest within --tol: a model of the ladder, the PRBM, "
          "elliptic or shooting), "
          "elliptic, shooting, chain, prbm; the cheaper models linear, prbm3r, bcm, cbcm "
          "(docs/models.md)")
      ->default_str("auto")
      ->transform(
          CLI::IsMember(std::vector<std::string>(kBeamMethodNames.begin(), kBeamMethodNames.end()),
                        CLI::ignore_case));
}

std::string failure_hint(const BeamProblem& problem, const BeamSolution& failed) {
  const BeamFailureAdvice advice = advise_after_failure(problem, failed, failed.methods_tried);
  if (advice.methods.empty()) {
    return advice.load_path_helps
               ? advice.text + " (flexure path with the same loads and --out FILE writes it)"
               : advice.text;
  }
  // The library's advice with the flag of each method.
  std::string hint = "Try ";
  for (std::size_t i = 0; i < advice.methods.size(); ++i) {
    hint += fmt::format("{}{} (--method {}): {}",
                        i > 0 ? "; or " : "",
                        advice.names[i],
                        to_string(advice.methods[i]),
                        advice.reasons[i]);
  }
  return hint + ".";
}

CLI::Option* add_tolerance_option(CLI::App& command, double& tolerance) {
  return command
      .add_option(
          "--tol", tolerance, "--method auto: relative tip error allowed (error / tip deflection)")
      ->default_str("1e-6")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            char* end = nullptr;
            const double value = std::strtod(text.c_str(), &end);
            if (end == text.c_str() || *end != '\0' || !std::isfinite(value) || value <= 0.0) {
              return "--tol must be a finite relative error > 0, e.g. 1e-6 (got " + text + ")";
            }
            return {};
          },
          "TOL > 0"));
}

void refuse_tol_with_named_method(const CLI::Option* tol_option, const std::string& method) {
  if (tol_option == nullptr || tol_option->count() == 0 || same_name(method, "auto")) return;
  throw InvalidInput(fmt::format(
      "--tol is the error --method auto allows when it chooses a method; --method {} works to its "
      "own tolerance, so --tol does not apply (drop it, or use --method auto)",
      method));
}

void refuse_tolerance_below_reach(const bench::ToleranceBelowReach& e, double tolerance) {
  // Rather than an answer that misses the tolerance (docs/cli.md, "--tol").
  throw InvalidInputReport(
      fmt::format("--tol: {} (--tol {:.0e}, or drop --tol for the default 1e-6)",
                  e.what(),
                  e.best_tolerance()),
      Json{{"tolerance", tolerance},
           {"best_tolerance", e.best_tolerance()},
           {"best_method", e.best_method()}});
}

void throw_beam_failure(const BeamProblem& problem, const BeamSolution& failed) {
  // What was reached, for the JSON error object (null where it is not a number), with the
  // methods the message suggests (failure_advice.h), most capable first; empty when none is
  // measured to reach further (the message then says what to change).
  Json reached = beam_keys::failure<Json>(
      problem, failed, advise_after_failure(problem, failed, failed.methods_tried).methods);
  if (problem.stable && !failed.stable_search.empty()) {
    // The answer was reached; no stable equilibrium was found from it.
    throw NoConvergenceReport(failed.message, std::move(reached));
  }
  throw NoConvergenceReport(
      fmt::format("method '{}' found no converged solution after {} iterations: {}. {}",
                  to_string(failed.method),
                  failed.iterations,
                  failed.message.empty() ? "no message" : failed.message,
                  failure_hint(problem, failed)),
      std::move(reached));
}

}  // namespace flexure::cli
