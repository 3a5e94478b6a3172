#pragma once
// The buildable geometry (mechanisms/mechanism.h) as a TOML table `[geometry]` that
// `flexure design mechanism --out` appends to the design it writes (docs/drawings.md). The table
// is written for the builder and read back by nobody: parse_mechanism_toml accepts it and ignores
// it, since every number in it follows from the design's own keys.
#include <string>

#include "flexure/mechanisms/mechanism.h"

namespace flexure::io {

// "[geometry]" with the overall length, the attachments, the end-of-stroke angles, then one
// [[geometry.flexures]], [[geometry.links]] and [[geometry.pivots]] entry each (m, rad; numbers
// with 17 significant digits).
std::string geometry_toml(const mechanism::MechanismGeometry& g);

}  // namespace flexure::io
