#pragma once
// The exact (elastica) shapes of a mechanism's flexures at the end of the stroke, for drawings
// (io/mechanism_drawing.h, docs/drawings.md): the exact model's solved point at Delta x = stroke
// (mechanism_exact.h, the stroke `mechanism analyze` solves) is integrated again from its unknowns
// at chosen arc lengths (solver/shooting/shooting_solver.h) -- every flexible segment's two ends
// and `samples` points along it, every rigid piece's two ends -- and placed in the drawing frame
// of mechanism.h: the chain's root at the ground attachment (the ground clamp of an s or
// l pivot 1, pin 1), +x along the slider axis; a middle-pin coupler chain from the displaced
// slider clamp back to pivot 2 (its frame turned by pi, mechanism_exact_pin.cpp); a two-force
// coupler as the straight line from the crank's tip to the slider pin.
//
// Where the PRBM pseudo-rigid polylines of mechanism_geometry() place the pivots by the PRBM
// kinematics, these are the exact model's positions: the pivots of the two models differ by the
// PRBM's own error (docs/validation.md).
#include <string>

#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_exact.h"

namespace flexure::mechanism {

// Fills the exact fields of `g` (FlexureGeometry::stroke_end_exact, RigidLinkGeometry's and
// PivotGeometry's, MechanismGeometry::exact_stroke_end) from `end`, a converged exact point of
// `design` at Delta x = design.stroke. `samples` (>= 2) points per flexible segment, equally
// spaced in arc length, ends included. Throws InvalidInput for a point that is not converged or
// not at the end of the stroke, NoConvergence when the re-integration fails.
void add_exact_stroke_end(MechanismGeometry& g,
                          const MechanismDesign& design,
                          const ExactPoint& end,
                          int samples = 101);

// The geometry of `design` (mechanism_geometry) with the exact fields filled, as above, for
// `point`, a converged exact point at any Delta x of the stroke (the fields named stroke_end*
// and exact_end* then hold that point's shapes): a stroke's deformed shapes point by point
// (io/mechanism_stroke_shapes.h). Throws InvalidInput for a point that is not converged,
// NoConvergence when the re-integration fails.
MechanismGeometry exact_geometry_at(const MechanismDesign& design,
                                    const ExactPoint& point,
                                    int samples = 101);

// Solves the exact model's stroke as `mechanism analyze` does (`points` stroke points) and adds its
// last point's shapes to `g`. Returns "" when added, else why not (a PRBM-only configuration, a
// stroke the exact model did not finish): the drawing then keeps the PRBM pseudo-rigid shapes.
std::string add_exact_stroke_end(MechanismGeometry& g,
                                 const MechanismDesign& design,
                                 int points = 50,
                                 int samples = 101);

}  // namespace flexure::mechanism
