#include "cli/command_table.h"

#include <fmt/format.h>

#include <stdexcept>

#include "cli/commands.h"
#include "flexure/solver/common/names.h"
#include "flexure/version.h"

namespace flexure::cli {

const std::vector<CommandEntry>& command_table() {
  static const std::vector<CommandEntry> table = {
      {"beam",
       "Initially straight cantilever with an end load (Howell sec. 2.9.2)",
       {register_beam_command}},
      {"sweep",
       "Solve a range of loads and write the results to an HDF5 file",
       {register_sweep_command}},
      {"validate",
       "Check every available method against built-in reference problems",
       {register_validate_command}},
      {"prbm",
       "Pseudo-rigid-body constants: derive, tables, compare with the exact solution",
       {register_prbm_command}},
      {"cfm",
       "Constant-force slider mechanism, nondimensional PRBM (Weight 2001, Howell §10.1)",
       {register_cfm_command}},
      {"path",
       "Equilibrium path from zero load (continuation: limit points and bifurcations located, "
       "branch switching, displacement control), written to HDF5",
       {register_path_command}},
      {"mechanism",
       "Constant-force slider mechanisms: PRBM and exact model of one design",
       {register_mechanism_command,
        register_mechanism_draw_command,
        register_mechanism_export_command}},
      {"dynamics",
       "Frequency sweep of a constant-force slider mechanism's input force (HDF5)",
       {register_dynamics_command}},
      {"bench",
       "Benchmark every method on the standard problems: error against the reference and median "
       "time per solve, written to HDF5 (docs/benchmarks.md)",
       {register_bench_command}},
      {"design",
       "Design constant-force mechanisms (docs/design.md)",
       {register_design_command, register_design_mechanism_command}},
      {"map", "Design-space maps (docs/design.md)", {register_map_command}},
      {"models",
       "The model ladder: every model's error and time against the exact solution",
       {register_models_command}},
      {"materials",
       "The material library (Howell Appendix C): E, nu, strengths, endurance limit, density, "
       "source",
       {register_materials_command}},
      {"plot",
       "Plot any HDF5 file flexure writes (matplotlib and h5py under /usr/bin/python3)",
       {register_plot_command}},
      {"help", "Help for flexure or one command: flexure help [COMMAND]", {register_help_command}},
  };
  return table;
}

void register_commands_for(CLI::App& app, const std::vector<std::string>& args) {
  app.set_version_flag("--version",
                       fmt::format("flexure {} (git commit {})", kVersion, kGitCommit));
  app.require_subcommand(1);
  for (const CommandEntry& entry : command_table()) {
    bool named = false;
    for (const std::string& word : args) {
      if (!word.empty() && word.front() != '-' && same_name(word, entry.name)) {
        named = true;
        break;
      }
    }
    if (!named) {
      CLI::App* stub = app.add_subcommand(entry.name, entry.description);
      // Unreachable (see command_table.h); a bug would otherwise pass silently with exit 0.
      stub->callback([name = entry.name] {
        throw std::logic_error(fmt::format("command '{}' was run unregistered", name));
      });
      continue;
    }
    for (void (*registrar)(CLI::App&) : entry.registrars) registrar(app);
  }
  add_command_examples(app);
}

}  // namespace flexure::cli
