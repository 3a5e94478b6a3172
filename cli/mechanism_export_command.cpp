// `flexure mechanism export NAME|FILE.toml [--out FILE.toml] [--points K]`: a constant-force design
// as a general mechanism TOML file (io/general_mechanism_toml_writer.h; docs/mechanisms.md "The
// catalogue as general mechanisms"), which `flexure mechanism analyze FILE --model prbm|exact`
// solves to the catalogue's numbers. Parses, calls the library, prints.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/mechanism_argument.h"
#include "flexure/io/general_mechanism_toml_writer.h"
#include "flexure/io/platform/output_path.h"
#include "flexure/io/toml_files.h"
#include "flexure/mechanisms/mechanism.h"

namespace flexure::cli {

void register_mechanism_export_command(CLI::App& app) {
  CLI::App& mech = get_or_add_subcommand(
      app, "mechanism", "Constant-force slider mechanisms: PRBM and exact model of one design");
  struct ExportArgs {
    std::string what;
    std::string out;
    int points = 50;
  };
  auto args = std::make_shared<ExportArgs>();
  CLI::App* cmd = mech.add_subcommand(
      "export",
      "A design as a general mechanism TOML file ([[body]] form) that `mechanism analyze FILE "
      "--model prbm|exact` solves to the design's numbers");
  cmd->add_option("mechanism",
                  args->what,
                  "Built-in name (1A-lpp, 2A-slp, 1A-lpp', 3A-lslm, howell-1A-spp-b, ...) or "
                  "FILE.toml (a constant-force design file)")
      ->required();
  cmd->add_option("--out",
                  args->out,
                  "Write the TOML to this file (whole or not at all); default: standard output");
  cmd->add_option("--points", args->points, "Stroke points of the input range (default 50)")
      ->default_str("50");
  cmd->callback([args] {
    require_in_range(args->points, "--points", 2, 100000);
    if (!args->out.empty()) io::check_output_path(args->out);
    const mechanism::MechanismDesign d = mechanism_design_argument(args->what);
    const std::string text = mechanism::general::design_as_general_toml(d, args->points);
    if (args->out.empty()) {
      std::cout << text;
      return;
    }
    io::write_text_file(args->out, text);
    std::cout << fmt::format("{}: general mechanism written to {} ({} stroke points)\n",
                             d.name,
                             args->out,
                             args->points);
  });
}

}  // namespace flexure::cli
