#pragma once
// The HDF5 file of one constant-force stroke (`flexure mechanism analyze NAME|FILE.toml --out`;
// docs/hdf5-schema.md "flexure mechanism analyze --out"): the slider force of the PRBM and the
// exact model, the stresses, the PRBM's validity, the stability of every stroke point under both
// controls, the fatigue check, /design (the analysed half mechanism in its described form) and
// /shapes (io/mechanism_stroke_shapes.h), with the provenance. `flexure plot` draws it.
#include <string>

#include "flexure/io/hdf5_file.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/mechanisms/mechanism_fatigue.h"

namespace flexure::io {

// Writes the stroke into `root` (the caller commits the file). `fatigue`: the check of the stroke
// (null where the material lacks S_ut or S_e'); `stable`, `stable_search`: --stable and what it
// did (the JSON keys; `stable_search` empty where the JSON has null).
void write_mechanism_stroke(Hdf5Group& root,
                            const mechanism::MechanismAnalysis& analysis,
                            const mechanism::MechanismFatigue* fatigue,
                            bool stable,
                            const std::string& stable_search);

}  // namespace flexure::io
