#pragma once
// The /shapes group of a file of many solutions (`flexure path --shapes`, `flexure sweep beam
// --shapes`; docs/hdf5-schema.md) and its XDMF sidecar (io/shapes_xdmf.h): one writer for both,
// so that the two files share one layout. Rows are the solutions (path points, sweep points),
// columns the shape points along s, row-major.
#include <span>
#include <string>
#include <vector>

#include "flexure/io/platform/hdf5_file.h"

namespace flexure {

struct ShapesView {
  long rows = 0;         // solutions
  int shape_points = 0;  // columns (>= 2)
  // s: shape_points values; the others rows x shape_points. axial/shear and the fibre stresses
  // may be empty (not stored).
  std::span<const double> s, x, y, theta, moment, axial, shear, stress_pos, stress_neg;
  std::string row_name = "path point";  // what a row is, in the descriptions
  std::string length_unit = "1", force_unit = "1", moment_unit = "1";
  std::string scaled;  // appended to the descriptions of scaled quantities, e.g. " (l = 1, EI = 1)"
};

// Writes the group "shapes" under `root`.
void write_shapes_group(io::Hdf5Group& root, const ShapesView& v);

// Writes the sidecar of `h5_path` (io::xdmf_path_for) whole or not at all, `times` one per row
// (the path's load factor, a sweep's swept value); nothing when there are no shapes. Returns the
// sidecar's path (empty when none was written).
std::string write_shapes_xdmf(const std::string& h5_path,
                              const ShapesView& v,
                              const std::vector<double>& times);

}  // namespace flexure
