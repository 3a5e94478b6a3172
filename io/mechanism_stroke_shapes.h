#pragma once
// The deformed shapes of a mechanism's stroke in a `mechanism analyze --out` file (the group
// /shapes, docs/hdf5-schema.md): at every stroke point the exact model solved, the half
// mechanism's centreline from the ground attachment to the slider attachment -- each flexure's
// bent centreline and each rigid link's two ends, in the order they sit at rest -- placed as the
// drawings place the end of the stroke (mechanisms/mechanism_exact_geometry.h), and the same
// stations at rest. `flexure plot` draws them and animates the stroke (python/flexure_plot).
#include "flexure/io/platform/hdf5_file.h"
#include "flexure/mechanisms/mechanism_analysis.h"

namespace flexure::io {

// Writes /shapes into `root` where the exact stroke has converged points; returns how many stroke
// points it holds (0: the group is not written: a PRBM-only configuration or no converged exact
// point). `samples` (>= 2) stations along each flexure. Where a point's shapes cannot be placed
// (InvalidInput, NoConvergence of the re-integration) nothing is written but the root attribute
// `shapes_note` saying why.
int write_stroke_shapes(Hdf5Group& root, const mechanism::MechanismAnalysis& a, int samples = 41);

}  // namespace flexure::io
