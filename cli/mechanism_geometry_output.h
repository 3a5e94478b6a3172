#pragma once
// The buildable geometry of a mechanism design (mechanisms/mechanism.h) as the tool
// prints it: the JSON object under the key "geometry" (`mechanism analyze --json`, every design of
// `design mechanism --json`, `mechanism draw --json`) and the text block of the text outputs, in
// a length unit of the user's. docs/drawings.md.
#include <string>

#include "cli/cli_common.h"
#include "flexure/io/mechanism_drawing.h"
#include "flexure/mechanisms/mechanism.h"

namespace flexure::cli {

// SI (m, rad): flexures [{pivot, kind, length, width, thickness, rest: [[x,y],[x,y]],
// stroke_end: [[x,y] x3]}], links [{link, length, rest, stroke_end}], pivots [{pivot, type,
// rest, stroke_end}], overall_length, ground_attach_x, slider_attach_x_rest/_end, theta2_end,
// theta3_end, deformed_model.
Json geometry_json(const mechanism::MechanismGeometry& g);

// The principal dimensions of a drawing: [{name, value}] in m.
Json dimensions_json(const std::vector<io::DrawingDimension>& dims);

// Indented lines: each flexure's length, width and thickness, each rigid link's length, the
// pivots' positions at rest and at the end of the stroke, the overall length, in `unit` (a length
// unit solver/common/section.h knows, e.g. "mm", "in").
std::string geometry_text(const mechanism::MechanismGeometry& g,
                          const std::string& unit,
                          const std::string& indent = "  ");

// geometry_json of a design, or null when it has no geometry (a rejected design that is not
// finalised, a stroke past the toggle position).
Json design_geometry_json(const mechanism::MechanismDesign& design);

// "  buildable geometry of NAME ..." (geometry_text), or "" when the design has none.
std::string design_geometry_text(const mechanism::MechanismDesign& design, const std::string& unit);

// Throws InvalidInput "OPTION: ..." (exit 2) for a drawing path without .svg or .dxf, or one that
// cannot be written (io::check_output_path); called before any solving.
void check_drawing_path(const std::string& path, const std::string& option);

// The length unit a quantity was written in ("mm" when it had none or is not a length).
std::string length_unit_of(const std::string& quantity_text);

}  // namespace flexure::cli
