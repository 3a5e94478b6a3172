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

// `args` are those of `flexure beam` (without "beam"). Throws InvalidInput with the tool's message
// for anything the tool refuses.
BeamCommandProblem beam_problem_of(const std::vector<std::string>& args);

// The warnings of an answer that `flexure beam` prints on stderr and lists under the JSON key
// `warnings`: a PRBM outside its validity limits, an unstable or critical equilibrium.
std::vector<std::string> beam_warnings(const BeamProblem& problem, const BeamSolution& solution);

}  // namespace flexure::cli
