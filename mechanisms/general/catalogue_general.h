#pragma once
// A built-in constant-force slider design (half mechanism, mechanism.h) as a general mechanism
// (general_mechanism.h), so that the general models -- the mixed model with a model per flexure
// above all (solve_general_mixed) -- analyse it (docs/mechanisms.md "A model per flexure").
//
// Built from Table 8.1 of Weight's thesis: pivot 1 at the ground (s: a flexure from the ground
// clamp at x = 0, its pivot at f1/2; l: a fixed-pinned segment r2/gamma long clamped at 0 and
// pinned to the coupler; p: a pin at 0), pivot 2 r2 further, pivot 3 r3 further, the slider on the
// x axis carrying pivot 3's far end. Flexures are named f1, f2, f3 by pivot, pins p1, p2, p3. The
// input is the slider's x, moved inwards over the catalogue's stroke points
// (stroke_displacements); the straight position is a dead point, so the crank's start rotation
// picks the branch with pivot 2 above the axis. Its input load is minus the catalogue's slider
// force (it holds x where the catalogue's force pushes the slider inwards). Its PRBM gives the
// catalogue's PRBM force to 1e-9 and its exact model the catalogue's exact force to 1e-8
// (tests/mechanisms/general_mechanism_test.cpp). Every flexure's model is kPrbm.
#include "flexure/mechanisms/general/general_mechanism.h"
#include "flexure/mechanisms/mechanism.h"

namespace flexure::mechanism::general {

// Throws InvalidInput for a long segment at pivot 2 or 3 (slp, plp: no general form yet) and
// points < 2.
GeneralMechanism general_from_design(const MechanismDesign& design, int points);

}  // namespace flexure::mechanism::general
