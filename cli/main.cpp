// flexure: command-line tool for large-deflection beams and compliant mechanisms.
//
// How to add a subcommand (the pattern every command follows):
//  1. Create cli/<name>_command.cpp with `void register_<name>_command(CLI::App& app)` in
//     namespace flexure::cli; declare it in cli/commands.h and add it, with the description it
//     gives its subcommand, to command_table() (command_table.cpp), which the tool and the
//     Python module share.
//  2. In it, keep the parsed arguments in a std::shared_ptr<Args> captured by the subcommand's
//     callback (CLI11 runs the callback after a successful parse). Add `--json`.
//  3. The callback validates input and throws flexure::InvalidInput (exit 2) naming the flag and
//     the allowed range (require_finite_input, require_in_range, parse_range in cli_common.h);
//     throws flexure::NoConvergence (exit 3) when a method does not converge, saying how far it
//     got and which method may work; calls set_exit_code() only for other non-zero outcomes
//     (validate: 1 = a reference check failed).
//  4. With --json print exactly one object with print_json() (it refuses NaN/Inf); otherwise a
//     short readable report on stdout. Errors never go to stdout: run_app() prints them as one
//     line on stderr.
//  5. Output files are written by the library's writers (io/, benchmarks/studies/; a command
//     makes no HDF5 call itself): a temporary name renamed into place, so whole or not at all,
//     checked or opened BEFORE the solve so that an unwritable path fails fast with exit 2. Every
//     dataset gets units and a description, and the root the provenance (io/platform/provenance.h;
//     docs/hdf5-schema.md).
//  6. Beam problems are solved by the library's solve_beam (beam/beam_problem.h); a
//     new method is plugged in there (docs/architecture.md), not in the commands.
// Nested commands (`sweep beam`) use get_or_add_subcommand() so that several files can add
// children to the same parent.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "cli/cli_common.h"
#include "cli/command_table.h"
#include "flexure/io/platform/provenance.h"
#include "flexure/solver/common/gsl_guard.h"

int main(int argc, char** argv) {
  flexure::disable_gsl_abort();
  // HDF5 is initialised by the first file opened (hdf5_file.h), not here: a command that writes
  // no file does not pay for it (docs/performance.md "Start-up").
  // Every HDF5 file written by this run records the command line that made it.
  flexure::io::record_command_line(argc, argv);

  CLI::App app{"flexure: exact large-deflection beams and compliant mechanisms", "flexure"};
  // Only the command the arguments name is registered in full (command_table.h): start-up.
  flexure::cli::register_commands_for(app, std::vector<std::string>(argv + 1, argv + argc));

  return flexure::cli::run_app(app, argc, argv);
}
