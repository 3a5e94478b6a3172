#pragma once
// `flexure mechanism analyze FILE.toml` for the general form of a mechanism ([[body]] tables,
// io/toml_files.h; docs/mechanisms.md "General mechanisms"): parse, solve, print.
#include <optional>
#include <string>

#include "flexure/mechanisms/general/general_mechanism.h"

namespace flexure::cli {

struct GeneralAnalyzeRequest {
  std::string file;
  std::string model;  // "prbm" (default), "exact", "both", "mixed"; empty when --model is not given
  // --model mixed: --flexure-model SPEC ("MODEL" for every flexure, or "NAME=MODEL,..."), empty
  // when not given; --flexure-tol (auto's tolerance per length, 0 when not given);
  // --check-flexures (measure each flexure's model against the elastica under its loads).
  std::string flexure_models;
  double flexure_tol = 0.0;
  bool check_flexures = false;
  // A built-in design (or design file) in its general form (catalogue_general.h), analysed
  // instead of `file`; design_x0 is its slider's undeflected x (m), for the stroke Delta x.
  std::optional<mechanism::general::GeneralMechanism> mechanism;
  double design_x0 = 0.0;
  std::string input_range;  // --input START:STOP:COUNT, empty when not given
  // --out FILE.h5 (io/general_mechanism_file.h) or FILE.csv (the table only); --csv FILE (the
  // table beside an HDF5 --out, or alone). Empty when not given.
  std::string out;
  std::string csv;
  bool json = false;
  int points = 0;  // --points when given, else 0
  // --stable: at every grid value the equilibrium stable under the input's control
  // (mechanisms/general/stable_selection.h); exit 3 where none was found.
  bool stable = false;
  // The first flag of the constant-force analysis given on the command line (--method,
  // --material, ...), empty when none: refused for the general form, which does not use it.
  std::string foreign_flag;
};

// Whether `what` names a TOML file in the general form (reads and parses it).
bool is_general_mechanism_file(const std::string& what);

// Solves and prints; throws InvalidInput (exit 2) for a bad description or flag, NoConvergence
// (exit 3) when the path does not cover the input range.
void analyze_general_mechanism(const GeneralAnalyzeRequest& request);

}  // namespace flexure::cli
