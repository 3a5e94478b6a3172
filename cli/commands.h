#pragma once
// One registration function per subcommand, each defined in its own file (see main.cpp).
#include <CLI/CLI.hpp>

namespace flexure::cli {

void register_beam_command(CLI::App& app);       // beam_command.cpp
void register_sweep_command(CLI::App& app);      // sweep_command.cpp
void register_validate_command(CLI::App& app);   // validate_command.cpp
void register_prbm_command(CLI::App& app);       // prbm_command.cpp
void register_cfm_command(CLI::App& app);        // cfm_command.cpp
void register_path_command(CLI::App& app);       // path_command.cpp
void register_mechanism_command(CLI::App& app);  // mechanism_command.cpp
void register_dynamics_command(CLI::App& app);   // dynamics_command.cpp
void register_bench_command(CLI::App& app);      // bench_command.cpp
void register_design_command(CLI::App& app);     // design_command.cpp
void register_design_mechanism_command(CLI::App& app);
void register_models_command(CLI::App& app);     // models_command.cpp
void register_materials_command(CLI::App& app);  // materials_command.cpp
void register_plot_command(CLI::App& app);       // plot_command.cpp
void register_map_command(CLI::App& app);        // map_command.cpp  // design_mechanism_command.cpp
void register_help_command(CLI::App& app);       // help_command.cpp (register last)
// Ends every registered command's --help with its examples (command_examples.cpp); call after
// registering (commands registered as stubs, command_table.h, have none).
void add_command_examples(CLI::App& app);

// `flexure mechanism draw` (mechanism_draw_command.cpp), registered with the mechanism command.
void register_mechanism_draw_command(CLI::App& app);
// `flexure mechanism export` (mechanism_export_command.cpp), registered with the mechanism command.
void register_mechanism_export_command(CLI::App& app);

}  // namespace flexure::cli
