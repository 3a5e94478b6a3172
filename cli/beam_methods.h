#pragma once
// Command-line options shared by the beam commands (`flexure beam`, `flexure sweep beam`,
// `flexure path`): --method and --tol, and the hint printed when a method fails. The problem and
// its solution are the library's (beam/beam_problem.h).
#include <CLI/CLI.hpp>
#include <string>

#include "flexure/beam/beam_problem.h"
#include "flexure/benchmarks/studies/failure_advice.h"

namespace flexure::cli {

// Adds `--method` (default "auto", restricted to kBeamMethodNames) to a subcommand.
void add_method_option(CLI::App& command, std::string& method);
// Adds `--tol` (relative error allowed to `--method auto`, default 1e-6, > 0).
CLI::Option* add_tolerance_option(CLI::App& command, double& tolerance);

// --tol means one thing: the error `--method auto` allows when it chooses a method. With a named
// method it does not apply (each method works to its own tolerance): InvalidInput saying so.
void refuse_tol_with_named_method(const CLI::Option* tol_option, const std::string& method);

// `--method auto` with a --tol that no method meets (bench::ToleranceBelowReach): the refusal as
// InvalidInputReport (exit 2), with the flag to give and the JSON keys tolerance, best_tolerance,
// best_method.
[[noreturn]] void refuse_tolerance_below_reach(const bench::ToleranceBelowReach& e,
                                               double tolerance);

// Sentences for non-convergence messages: the library's advice (failure_advice.h: a method only
// where it is measured to reach further than those tried, else what to change) with the flags.
std::string failure_hint(const BeamProblem& problem, const BeamSolution& failed);

// A beam solve that did not converge, as `flexure beam` and the Python module's flexure.beam
// report it: NoConvergenceReport (exit 3) with the message (the method, its iterations and
// message, failure_hint; or the stable search's message when the answer was reached but no stable
// equilibrium found from it) and the `reached` keys (beam/beam_keys.h failure, with the methods
// the advice suggests).
[[noreturn]] void throw_beam_failure(const BeamProblem& problem, const BeamSolution& failed);

}  // namespace flexure::cli
