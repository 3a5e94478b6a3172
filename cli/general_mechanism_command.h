#pragma once
// `flexure mechanism analyze FILE.toml` for the general form of a mechanism ([[body]] tables,
// io/general_mechanism_toml.h; docs/mechanisms.md "General mechanisms"): parse, solve, print.
#include <string>

namespace flexure::cli {

struct GeneralAnalyzeRequest {
  std::string file;
  std::string model;        // "prbm" (default), "exact", "both"; empty when --model is not given
  std::string input_range;  // --input START:STOP:COUNT, empty when not given
  bool json = false;
  int points = 0;  // --points when given, else 0
  // The first flag of the constant-force analysis given on the command line (--method, --out,
  // ...), empty when none: refused for the general form, which does not use it.
  std::string foreign_flag;
};

// Whether `what` names a TOML file in the general form (reads and parses it).
bool is_general_mechanism_file(const std::string& what);

// Solves and prints; throws InvalidInput (exit 2) for a bad description or flag, NoConvergence
// (exit 3) when the path does not cover the input range.
void analyze_general_mechanism(const GeneralAnalyzeRequest& request);

}  // namespace flexure::cli
