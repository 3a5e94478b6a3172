#pragma once
// Shared by the two files of `flexure cfm` (cli/cfm_command.cpp: options, a configuration, a
// sub-class, --list; cli/cfm_table_command.cpp: --table and --table --exact, every printed row
// recomputed): the parsed arguments and the helpers both use.
#include <CLI/CLI.hpp>
#include <string>

#include "cli/cli_common.h"
#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/mechanism_analysis.h"

namespace flexure::cli {

struct CfmArgs {
  std::string config;
  double R = 0.0;
  double K1 = 0.0;
  double K2 = 0.0;
  double d = 0.0;
  std::string subclass;
  std::string sampling = "auto";
  int points = 50;
  bool curve = false;
  bool list = false;
  bool table = false;
  bool markdown = false;
  bool json = false;
  bool exact = false;
  int exact_points = 50;
  int exact_max_iterations = 0;
  std::string exact_rows = "a";
  CLI::Option* config_option = nullptr;
  CLI::Option* R_option = nullptr;
  CLI::Option* K1_option = nullptr;
  CLI::Option* K2_option = nullptr;
  CLI::Option* d_option = nullptr;
  CLI::Option* points_option = nullptr;
  CLI::Option* exact_points_option = nullptr;
  CLI::Option* exact_max_iterations_option = nullptr;
  CLI::Option* exact_rows_option = nullptr;
};

// Exact-model options from --exact-points / --exact-max-iterations (range-checked).
cfm::CfmExactOptions make_exact_options(const CfmArgs& args);
// The exact model's keys (Phi_exact, percent_constant_force_exact, max_force_error, ...).
void add_exact_json(Json& j, const cfm::CfmExactResult& e, bool curve);
// The PRBM model at p; throws NoConvergence, or InvalidInput for a non-finite result.
// The keys of `flexure cfm --json` for one evaluated design (also `flexure design cfm`).
Json cfm_result_json(const cfm::CfmResult& r, const cfm::CfmOptions& options);

cfm::CfmResult evaluate_or_throw(const cfm::CfmModel& model, const cfm::CfmParameters& p);

// --table: every printed row recomputed (exit 1 if one is outside its printed rounding).
void run_table(const CfmArgs& args);
// --table --exact: the thesis sub-classes solved with the exact model too.
void run_exact_table(const CfmArgs& args);

}  // namespace flexure::cli
