#include "cli/beam_methods.h"

#include <fmt/format.h>

#include "solver/common/errors.h"
#include "solver/elliptic/elliptic_solver.h"

namespace flexure::cli {
namespace {

BeamSolution solve_elliptic(const BeamProblem& problem) {
  const EllipticSolver solver;
  EllipticResult result;
  switch (problem.given) {
    case BeamProblem::Given::kAlpha2:
      result = solver.solve(EndLoad::howell(problem.load_ratio_n, problem.value, problem.mu));
      break;
    case BeamProblem::Given::kTheta0:
      result = solver.solve_for_tip_angle(problem.load_ratio_n, problem.value, problem.mu);
      break;
    case BeamProblem::Given::kBOverL:
      result = solver.solve_for_deflection(problem.load_ratio_n, problem.value, problem.mu);
      break;
  }
  BeamSolution solution;
  solution.method = "elliptic";
  solution.converged = result.converged;
  solution.message = result.message;
  solution.iterations = result.iterations;
  // Howell's alpha2 is the transverse component P l^2/EI = Fy (eq. 2.83, EndLoad::howell).
  solution.alpha2 = result.load.Fy;
  solution.tip = result.tip;
  solution.branch = result.branch;
  solution.inflection_points = result.inflection_points;
  solution.root_moment = result.root_moment;
  solution.family = to_string(result.parameters.family);
  solution.tolerance = solver.options().tolerance;
  if (result.converged && problem.shape_points > 0) {
    solution.shape = solver.shape(result, problem.shape_points);
  }
  return solution;
}

}  // namespace

void add_method_option(CLI::App& command, std::string& method) {
  command
      .add_option("--method",
                  method,
                  "Solution method: auto (= elliptic in this build), elliptic, shooting, chain")
      ->default_str("auto")
      ->check(CLI::IsMember(
          std::vector<std::string>(kBeamMethodNames.begin(), kBeamMethodNames.end())));
}

std::string other_methods_hint(const std::string& failed_method) {
  // Shooting (Howell sec. 7.2.1) and the chain algorithm (sec. 7.2) follow a load path and can
  // reach branches the closed form does not; they are the fallback once they are built in.
  (void)failed_method;
  return "No other method is available in this build yet.";
}

std::string resolve_beam_method(const std::string& method) {
  // Only the exact elliptic solution exists in this build; when shooting and chain arrive, auto
  // should stay elliptic where it applies (it is exact and fastest) and fall back otherwise.
  return method == "auto" ? "elliptic" : method;
}

double beam_method_tolerance(const std::string& method) {
  const std::string used = resolve_beam_method(method);
  if (used == "elliptic") return EllipticSolver::Options{}.tolerance;
  throw InvalidInput(fmt::format("method '{}' is not available yet in this build", used));
}

BeamSolution solve_beam(const std::string& method, const BeamProblem& problem) {
  const std::string used = resolve_beam_method(method);
  if (used == "elliptic") return solve_elliptic(problem);
  if (used == "shooting" || used == "chain") {
    throw InvalidInput(fmt::format(
        "method '{}' is not available yet in this build (available: elliptic, auto)", used));
  }
  throw InvalidInput(
      fmt::format("--method '{}' is unknown (allowed: auto, elliptic, shooting, chain)", method));
}

}  // namespace flexure::cli
