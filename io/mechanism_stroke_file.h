#pragma once
// The HDF5 file of one constant-force stroke (`flexure mechanism analyze NAME|FILE.toml --out`;
// docs/hdf5-schema.md "flexure mechanism analyze --out"): the slider force of the PRBM and the
// exact model, the stresses, the PRBM's validity, the stability of every stroke point under both
// controls, the fatigue check, /design (the analysed half mechanism in its described form) and
// /shapes (io/mechanism_stroke_shapes.h), with the provenance. `flexure plot` draws it.
#include <memory>
#include <string>

#include "flexure/io/platform/hdf5_file.h"
#include "flexure/mechanisms/materials_fatigue.h"
#include "flexure/mechanisms/mechanism_analysis.h"

namespace flexure::io {

// Writes the stroke into `root` (the caller commits the file). `fatigue`: the check of the stroke
// (null where the material lacks S_ut or S_e'); `stable`, `stable_search`: --stable and what it
// did (the JSON keys; `stable_search` empty where the JSON has null).
void write_mechanism_stroke(Hdf5Group& root,
                            const mechanism::MechanismAnalysis& analysis,
                            const mechanism::MechanismFatigue* fatigue,
                            bool stable,
                            const std::string& stable_search);

// The same file for a caller that sees no HDF5 type: opened when made (a path that cannot be
// written fails before the stroke is solved: InvalidInput "--out: <why>"), written and renamed
// into place by write(), once; dropped without write() it leaves nothing behind.
class MechanismStrokeFile {
 public:
  explicit MechanismStrokeFile(const std::string& path);
  ~MechanismStrokeFile();
  MechanismStrokeFile(const MechanismStrokeFile&) = delete;
  MechanismStrokeFile& operator=(const MechanismStrokeFile&) = delete;

  void write(const mechanism::MechanismAnalysis& analysis,
             const mechanism::MechanismFatigue* fatigue,
             bool stable,
             const std::string& stable_search);

 private:
  std::unique_ptr<AtomicHdf5File> file_;
};

}  // namespace flexure::io
