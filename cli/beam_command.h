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
#include "flexure/beam/beam_request.h"

namespace flexure::cli {

struct BeamCommandProblem {
  BeamProblem problem;
  BeamMethod method = BeamMethod::kAuto;
  bool physical = false;  // a beam in SI units or a chain file
  bool json = false;
};

// `flexure beam ... --json` for a request already made of values (the Python module's scalar
// flexure.beam): the library's checks of the request (beam/beam_request.h) with the command's
// names, then the same solve, warnings and JSON object as the command, without a command line to
// parse or commands to register. A physical beam or a chain file (request.physical, .chain) goes
// through run_command.
CommandOutput run_beam_request(const BeamRequest& request);

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
