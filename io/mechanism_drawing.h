#pragma once
// Drawings of a mechanism's buildable geometry (mechanisms/mechanism.h) to scale in
// millimetres: SVG (renders in a browser; viewBox in mm, one <g id=LAYER> per layer) and DXF
// (ASCII R12, POLYLINE entities on named layers, $INSUNITS = mm) for CAD programs and laser
// cutters. Layers: LINKS (rigid link centrelines), FLEXURES (each flexure's outline, its real
// length by its real thickness, at rest), PINS (pin joints as circles), SLIDER (slider block and
// its guide), GROUND (the ground body's face), DIMENSIONS (principal dimensions: dimension lines
// and text), DEFORMED (the end of the stroke: the exact model's bent flexures and its links where
// MechanismGeometry::exact_stroke_end (mechanisms/mechanism_exact_geometry.h), else the flexures
// as PRBM pseudo-rigid polylines; the slider) and, in the SVG, NOTES. docs/drawings.md.
#include <string>
#include <vector>

#include "flexure/mechanisms/mechanism.h"

namespace flexure::io {

enum class DrawingFormat { kSvg, kDxf };

// The format a path's extension names (.svg, .dxf, case-insensitive). Throws InvalidInput naming
// the path and the accepted extensions otherwise.
DrawingFormat drawing_format(const std::string& path);

// One principal dimension: its name ("r2", "flexure 1 length", "stroke", ...), its value in m and
// the two points it spans (m, the drawing's frame); `offset` is how far (m, +y up) the dimension
// line is drawn from the points.
struct DrawingDimension {
  std::string name;
  double value = 0.0;
  mechanism::GeometryPoint from, to;
  double offset = 0.0;
};

// The dimensions a drawing shows: r2, r3, every flexure's length (its thickness and width as
// text), every rigid link's length, the overall length and the stroke.
std::vector<DrawingDimension> principal_dimensions(const mechanism::MechanismGeometry& g);

struct DrawingOptions {
  bool stroke_end = true;  // draw the DEFORMED layer (the end of the stroke)
};

std::string mechanism_svg(const mechanism::MechanismGeometry& g, const DrawingOptions& options);
std::string mechanism_dxf(const mechanism::MechanismGeometry& g, const DrawingOptions& options);

// Writes the drawing in the format of `path`'s extension, whole or not at all (write_text_file).
// Throws InvalidInput for an unknown extension or a path that cannot be written, naming `option`.
void write_mechanism_drawing(const std::string& path,
                             const mechanism::MechanismGeometry& g,
                             const DrawingOptions& options,
                             const std::string& option = "--out");

}  // namespace flexure::io
