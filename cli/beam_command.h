#pragma once
// What `flexure beam` shares with the Python module's beam (python/flexure_module.cpp): the
// warnings of an answer in the tool's words.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli/command_runner.h"
#include "flexure/beam/beam_problem.h"
#include "flexure/beam/beam_request.h"

namespace flexure::cli {

// The warnings of an answer that `flexure beam` prints on stderr and lists under the JSON key
// `warnings`: a PRBM outside its validity limits, an unstable or critical equilibrium.
std::vector<std::string> beam_warnings(const BeamProblem& problem, const BeamSolution& solution);

}  // namespace flexure::cli
