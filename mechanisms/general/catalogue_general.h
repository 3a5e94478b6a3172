#pragma once
// A built-in constant-force slider design (half mechanism, mechanism.h) as a general mechanism
// (general_mechanism.h): the catalogue as data of the general description, so that the general
// models -- PRBM, exact, and the mixed model with a model per flexure (solve_general_mixed) --
// analyse it, and `flexure mechanism export` writes it as a general TOML file (docs/mechanisms.md
// "The catalogue as general mechanisms").
//
// Built from Table 8.1 of Weight's thesis, on the slider axis (x, the ground block's clamp or pin
// at 0): pivot 1 at the ground (s: a small-length flexure from the clamp at 0, its pivot at f1/2;
// l: link 2 a fixed-pinned segment r2/gamma long clamped at 0 and pinned to link 3 at pivot 2;
// p: a pin at 0), pivot 2 r2 further (s: centred on it; slp: link 3 a fixed-pinned segment
// r3/gamma long clamped into link 2 (1 - gamma) l before pivot 2 and pinned at the slider; plp:
// link 2 a fixed-pinned segment r2/gamma long pinned at the ground pin and clamped into link 3
// (1 - gamma) l after pivot 2; p: a pin), pivot 3 r3 further (s: centred on it, the slider at its
// far end; p: a pin), the slider on the x axis. A modified design's fixed-fixed segments are
// centred small-length flexures of their own length (builtin_designs.h). Bodies are ground,
// crank (link 2), coupler (link 3), slider -- a link that is a flexible segment is no body --,
// flexures f1, f2, f3 and pins p1, p2, p3 by pivot. An inversion (inversion.h) is described from
// its fixed block: mirrored along the axis (the fixed block at 0), the blocks' and links' roles
// swapped and pivot i named 4 - i, so that "ground" is the fixed slider block and "slider" the
// moving ground block.
//
// The input is the moving block's x, moved inwards over the catalogue's stroke points
// (stroke_displacements); the straight position is a dead point, so the links' start rotations
// pick the branch with pivot 2 above the axis. Its input load is minus the catalogue's slider
// force (it holds x where the catalogue's force pushes the slider inwards). Every flexure's model
// is kPrbm. Measured over all 40 designs of `flexure mechanism list`
// (tests/mechanisms/catalogue_general_test.cpp, docs/mechanisms.md): the PRBM forces, percent
// constant force and stresses agree with analyze_mechanism to 1e-9, the exact ones as stated there.
#include <string>

#include "flexure/mechanisms/general/general_mechanism.h"
#include "flexure/mechanisms/mechanism.h"

namespace flexure::mechanism::general {

// Throws InvalidInput for points < 2, for a design that does not finalise, and for fixed-fixed
// segments under a spring rule other than pure bending (the general small-length pivot is
// K = EI/l).
GeneralMechanism general_from_design(const MechanismDesign& design, int points);

// The flexure of the general form that models stored pivot `pivot` (1..3) of `design`: "f1",
// "f2", "f3" ("f3" for stored pivot 1 of an inversion); empty for a pin.
std::string general_flexure_name(const MechanismDesign& design, int pivot);

}  // namespace flexure::mechanism::general
