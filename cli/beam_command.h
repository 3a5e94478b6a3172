#pragma once
// `flexure beam` without the solve: the problem the command would solve for these arguments,
// validated exactly as the tool validates them (the Python module's vectorised beam solves it
// at many loads; python/flexure_module.cpp).
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli/command_runner.h"
#include "flexure/beam/beam_problem.h"

namespace flexure::cli {

struct BeamCommandProblem {
  BeamProblem problem;
  BeamMethod method = BeamMethod::kAuto;
  bool physical = false;  // a beam in SI units or a chain file
  bool json = false;
};

// `flexure beam ... --json` for values already parsed (the Python module's scalar flexure.beam):
// the same checks, messages, warnings and JSON object as the command, without a command line to
// parse or commands to register. Each field is the flag of that name, unset when not given; the
// string values of --method, --boundary, --integrator, --chain-variant and --stability must be
// the canonical lower-case names (the command's own parser maps other spellings to them). The
// options not listed here (--tol, --chain, a physical beam, fatigue, the ladder's settings) go
// through run_command.
struct BeamKeywords {
  std::optional<double> n, mu, alpha2, b_over_l, tip_x, tip_y, follower;
  std::optional<std::string> theta0, tip_angle;  // radians, or text with a unit ("30deg")
  std::optional<std::string> method, boundary, integrator, chain_variant, stability;
  std::optional<int> shape, elements, increments;
  bool stable = false;
};
CommandOutput run_beam_keywords(const BeamKeywords& keywords);

// `args` are those of `flexure beam` (without "beam"). Throws InvalidInput with the tool's message
// for anything the tool refuses.
BeamCommandProblem beam_problem_of(const std::vector<std::string>& args);

// The warnings of an answer that `flexure beam` prints on stderr and lists under the JSON key
// `warnings`: a PRBM outside its validity limits, an unstable or critical equilibrium.
// The JSON key `special_points` of an answer: the limit and bifurcation points the shooting
// method's continuation passed (null for the other methods).
nlohmann::ordered_json special_points_json(const BeamProblem& problem,
                                           const BeamSolution& solution);

std::vector<std::string> beam_warnings(const BeamProblem& problem, const BeamSolution& solution);

}  // namespace flexure::cli
