#pragma once
// The XDMF sidecar of a `flexure path --shapes K --out FILE.h5` file (io/shapes_xdmf.h): one
// polyline per path point over the stations s, with theta and the moment as node attributes and
// the load factor as time (docs/hdf5-schema.md "flexure path").
#include <string>

#include "flexure/benchmarks/studies/load_path_study.h"

namespace flexure {

// Writes the sidecar of `h5_path` (io::xdmf_path_for) whole or not at all; nothing when the table
// has no shapes. Returns the sidecar's path (empty when none was written).
std::string write_path_shapes_xdmf(const std::string& h5_path, const PathTable& table);

}  // namespace flexure
