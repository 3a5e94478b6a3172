#pragma once
// The HDF5 file and the CSV table of a general mechanism's analysis (`flexure mechanism analyze
// FILE.toml --out X.h5|X.csv`, and `--model mixed` on a built-in design; docs/hdf5-schema.md
// "flexure mechanism analyze (general form)", docs/cli.md "CSV output"). The same numbers as the
// command's JSON: the first model's arrays at the root, every model's in /models/<name>, with the
// equilibria of the unloaded mechanism, the limit points, the moving bodies' poses and, for the
// mixed model, the model of every flexure. `flexure plot` draws the file (python/flexure_plot).
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "flexure/io/csv_table.h"
#include "flexure/io/platform/hdf5_file.h"
#include "flexure/mechanisms/general/general_analysis.h"
#include "flexure/mechanisms/general/general_mechanism.h"

namespace flexure::io {

// The models `mechanism analyze --model` solves a general mechanism with: the PRBM, the exact
// model, both (PRBM first), or a model per flexure (mixed; general_analysis.h).
enum class GeneralAnalysisModel { kPrbm, kExact, kBoth, kMixed };
// "prbm", "exact", "both", "mixed" (the --model names, the JSON key and HDF5 attribute `model`).
const char* to_string(GeneralAnalysisModel model);
// The model of that name; throws InvalidInput listing the four.
GeneralAnalysisModel general_analysis_model_from_string(std::string_view name);

// One analysis: the models solved, in the command's order (the first one's arrays are the
// root's, as the JSON's top-level arrays are), and, for a constant-force design in its general
// form, the slider's undeflected x (m) that turns the input into the stroke Delta x.
struct GeneralAnalysisOutput {
  const mechanism::general::GeneralMechanism* mechanism = nullptr;
  GeneralAnalysisModel model = GeneralAnalysisModel::kPrbm;  // the --model given
  std::vector<std::pair<std::string, const mechanism::general::GeneralPrbmResult*>> results;
  std::optional<double> design_x0;  // set for a built-in design (its stroke and slider force)
  bool checked_flexures = false;    // --check-flexures: the mixed model's measured errors
};

// The stroke of a constant-force design in its general form, as `mechanism analyze` reports it:
// Delta x = x0 - x (the slider moves inwards) and the slider force of one half = -input load
// (the input load holds x; the catalogue's force pushes the slider inwards).
std::vector<double> design_stroke_displacement(const mechanism::general::GeneralPrbmResult& r,
                                               double x0);
std::vector<double> design_stroke_force(const mechanism::general::GeneralPrbmResult& r);

// "m" or "rad" (the input coordinate), "N" or "N m" (the load that holds it).
std::string general_input_unit(const mechanism::general::Input& input);
std::string general_input_load_unit(const mechanism::general::Input& input);

// Writes the analysis into `root` with its provenance (the file is committed by the caller).
void write_general_mechanism(Hdf5Group& root, const GeneralAnalysisOutput& out);

// Writes the analysis (write_general_mechanism) to the HDF5 file `path`, whole or not at all
// (AtomicHdf5File). Throws Hdf5Error when the file cannot be written.
void write_general_mechanism_hdf5(const std::string& path, const GeneralAnalysisOutput& out);

// The table of the analysis, one row per point of the first model: for a design, displacement
// [m] and force [N (half)]; then input, input_load, energy and the stability verdicts and margins
// under displacement and force control. A further model (--model both) adds its columns named
// <model>/input_load, ... when its points lie at the first model's inputs (the same grid, no
// limit point crossing it twice); `note` is set to why it is left out otherwise.
std::vector<CsvColumn> general_mechanism_csv_columns(const GeneralAnalysisOutput& out,
                                                     std::string* note = nullptr);

}  // namespace flexure::io
