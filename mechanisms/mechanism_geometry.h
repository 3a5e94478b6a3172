#pragma once
// The buildable geometry of a half constant-force slider mechanism (MechanismDesign): where every
// physical part sits, at rest and at the end of the stroke -- what a drawing, a CAD sketch or a
// laser cutter needs, as opposed to the PRBM link lengths r2, r3 the models compute with.
//
// Frame: PRB pivot 1 at the origin, the slider axis along +x, y up (docs/mechanisms.md). At rest
// the half mechanism is straight along the x axis; the parts follow thesis Table 8.1 as the exact
// model's physical chain does (mechanism_exact.h, physical_chain): an s flexure (or a fixed-fixed
// strip) of length f centred on its PRB pivot; an l segment l = r/gamma long, clamped (1 - gamma) l
// behind its characteristic pivot and pinned at its far end; rigid links fill the rest of r2, r3.
//
// At the end of the stroke (Delta x = stroke) the pivots are placed by the PRBM slider-crank
// kinematics (thesis eqs. 2.1-2.3, cfm/slider_crank.h): pivot 2 at r2 (cos theta2, sin theta2),
// pivot 3 at (r2 + r3 - Delta x, 0). Each rigid body moves rigidly (ground fixed, crank turned
// by theta2 about pivot 1, coupler along theta3 from pivot 2, slider translated by -Delta x). The
// deformed flexures are drawn in the PRBM's pseudo-rigid approximation: each flexure as the two
// pseudo-rigid pieces that meet at its characteristic pivot (a polyline of three points); the
// exact elastica shapes are added on request by mechanism_exact_geometry.h (drawings). An inverted
// design (inversion.h) is drawn in its original orientation. Units: SI (m) throughout; writers
// convert.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "flexure/mechanisms/mechanism.h"

namespace flexure::mechanism {

struct GeometryPoint {
  double x = 0.0;  // m
  double y = 0.0;  // m
};

// What a flexible segment is: a small-length flexure (s, centred on its pivot), a long one (l,
// fixed-pinned) or a fixed-fixed strip.
enum class FlexureKind { kSmall, kLong, kFixedFixed };
// "small", "long", "fixed-fixed" (the JSON and TOML key `kind` of a flexure's geometry).
const char* to_string(FlexureKind kind);
// The kind of that name; throws InvalidInput listing the three.
FlexureKind flexure_kind_from_string(std::string_view name);

// One flexible segment.
struct FlexureGeometry {
  int pivot = 0;  // PRB pivot it realises, 1..3
  FlexureKind kind = FlexureKind::kSmall;
  double length = 0.0;     // physical flexible length, m
  double width = 0.0;      // out-of-plane width b, m
  double thickness = 0.0;  // in-plane thickness h, m
  // Centreline at rest: from the end nearer the ground to the end nearer the slider.
  GeometryPoint rest_start, rest_end;
  // Pseudo-rigid polyline at the end of the stroke: rest_start's image, the characteristic
  // pivot, rest_end's image. The two pieces keep their lengths (|pivot - start| + |end - pivot|
  // = length).
  std::array<GeometryPoint, 3> stroke_end{};
  // The exact model's bent centreline at the end of the stroke (mechanism_exact_geometry.h), from
  // rest_start's image to rest_end's image; empty where it was not computed.
  std::vector<GeometryPoint> stroke_end_exact;
};

// One rigid link piece (what remains of r2 or r3 after the flexures; absent when an l segment is
// the whole link).
struct RigidLinkGeometry {
  int link = 0;         // 2 (crank, pivot 1 to 2) or 3 (coupler, pivot 2 to 3)
  double length = 0.0;  // m
  GeometryPoint rest_start, rest_end;
  GeometryPoint stroke_end_start, stroke_end_end;
  // The exact model's position of the same ends (valid when MechanismGeometry::exact_stroke_end).
  GeometryPoint exact_end_start, exact_end_end;
};

// One PRB pivot (characteristic pivot of a flexure, or a real pin joint).
struct PivotGeometry {
  int pivot = 0;  // 1..3
  PivotType type = PivotType::kPin;
  GeometryPoint rest;
  GeometryPoint stroke_end;
  GeometryPoint exact_end;  // the exact model's (valid when MechanismGeometry::exact_stroke_end)
};

struct MechanismGeometry {
  std::string name;
  std::string config;
  double r2 = 0.0, r3 = 0.0;  // PRBM link lengths, m
  double stroke = 0.0;        // m
  double theta2_end = 0.0;    // crank angle at the end of the stroke, rad
  double theta3_end = 0.0;    // principal coupler angle at the end of the stroke, rad (<= 0)
  bool inverted = false;      // drawn in the original orientation (slider block fixed in use)
  std::array<PivotGeometry, 3> pivots{};
  std::vector<FlexureGeometry> flexures;  // in pivot order
  std::vector<RigidLinkGeometry> links;   // crank piece first
  // Where the mechanism attaches to the ground body (the ground clamp of an s or l pivot 1, or
  // pin 1) and to the slider (the slider clamp of an s pivot 3, or pin 3), on the x axis, m.
  double ground_attach_x = 0.0;
  double slider_attach_x_rest = 0.0;
  double slider_attach_x_end = 0.0;
  // Overall length at rest, ground attachment to slider attachment, m.
  double overall_length() const { return slider_attach_x_rest - ground_attach_x; }
  // The model that placed the deformed flexures (for a drawing's notes).
  std::string deformed_model;
  // Whether the exact model's shapes at the end of the stroke were added (the fields *_exact,
  // exact_end_*; mechanism_exact_geometry.h); the drawing then draws those.
  bool exact_stroke_end = false;
  std::string exact_model;  // what placed them (for a drawing's notes)
};

// The geometry of a finalised design (MechanismDesign::finalise()). Throws InvalidInput for a
// design whose stroke is past the toggle position or whose lengths are not positive.
MechanismGeometry mechanism_geometry(const MechanismDesign& design);

// The kind of the flexure at pivot `pivot` (1..3) of a design; none for a pin.
std::optional<FlexureKind> flexure_kind(const MechanismDesign& design, int pivot);

}  // namespace flexure::mechanism
