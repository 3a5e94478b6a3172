#pragma once
// The second variation of the total potential energy of a mechanism's elastic path, from the
// ground to the slider through pins: the discretisation of the chain's stability verdict
// (solver/chain_model/segment_chain.h, docs/stability.md) extended to the exact models of
// mechanisms whose elastic system is not one segment chain (docs/stability.md "Mechanisms").
//
// A mechanism of docs/mechanisms.md is, seen from the ground, one path of flexures and rigid links
// to the slider: the ground clamp (or pin), the crank, pivot 2 (a flexure, or a pin), the coupler,
// the slider joint. A pin is a hinge of the path: the rotation on either side is independent and
// no bending energy is stored across it. With eta = delta theta the variation of the path's
// tangent angle (eta = 0 at a clamped root, free at a pinned one; constant along a rigid link),
//     Q[eta] = int EI eta'^2 ds + int (N . t) eta^2 ds,   B[eta] = int EI eta'^2 ds,
// where N is the force the distal part of the path exerts on the proximal part across a section,
// constant along these paths (no loads between the ends; the slider's force and the supports'
// reactions act like dead loads, as in the chain's Lagrangian). A compressed rigid coupler between
// two pins enters through its own (N . t) r3 eta^2: the geometric stiffness -Q/r3 of a compressed
// pin-ended link. The admissible variations keep the slider where its guide holds it:
//     slider x held (displacement control):  int sin(theta) eta ds = 0,
//     slider y held (always):                 int cos(theta) eta ds = 0,
//     slider angle held (a flexure clamped into the slider): eta(L) = 0.
// The margin is the lowest eigenvalue of Q = lambda B on them, the chain's scaling: 1 unloaded,
// 0 at a buckling or limit point, negative when unstable. B may be singular on the whole space (a
// pinned root, a rigid coupler: directions that bend nothing) but is positive definite on the
// admissible directions of every built-in design's path, where those motions move the slider.
//
// The linear algebra is the chain's: B tridiagonal (zero across a hinge), W = (N . t) lumped
// diagonal, at most two constraint rows, the bordered-matrix inertia and Newton's method on the
// bordered determinant of solver/chain_model/second_variation.h, Romberg over the grids of every
// node, every 2nd and every 4th (segment_chain.h). Only the eigenvalues' lower bracket
// differs: the chain's bound from B's flexibility does not exist where B is singular, so it is
// found by the inertia count (count(lo) = 0).
#include <array>
#include <string_view>
#include <vector>

#include "flexure/solver/chain_model/second_variation.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {

// One flexure or rigid link of the path, in path order.
struct PathPiece {
  double EI = 0.0;      // flexural rigidity of a flexible piece (> 0); 0: a rigid link
  double length = 0.0;  // arc length, > 0
  // Positions along the piece in path order, in the frame common to the path: a rigid link's two
  // ends; a flexible piece's n + 1 points at n equal elements (n divisible by 4 for three grids).
  std::vector<std::array<double, 2>> points;
  // A pin at the near end: the piece's rotation is independent of the piece before it. On the
  // first piece: a pinned root (else the root is clamped, eta = 0 there).
  bool hinge = false;
};

struct MechanismPath {
  std::vector<PathPiece> pieces;
  // The force the distal part exerts on the proximal part across every section of the path.
  double Nx = 0.0;
  double Ny = 0.0;
  // Which coordinates of the path's tip (the slider joint) are held.
  bool hold_x = false;
  bool hold_y = false;
  bool hold_theta = false;
};

// The discrete second variation on every `stride`-th point of each flexible piece (1, 2 or 4; the
// pieces' element counts must be divisible by it), with its independent constraint rows (a row
// whose root-mean-square over the path is below 1e-10 constrains nothing at first order and is
// dropped, as in the chain's). `compression_bound` is left 0: path_stability() brackets by the
// count. Throws InvalidInput for an empty path, a piece with non-finite or inconsistent points
// (a chord longer than its arc length by 5 %), or a stride that does not divide.
DiscreteSecondVariation path_second_variation(const MechanismPath& path, int stride = 1);

struct PathVerdict {
  Stability stability;
  double margin_error = 0.0;  // estimated error of the margin (the last Romberg correction)
};

// The verdict: index counted at -critical_tolerance on the finest grid (the extrapolated
// eigenvalues decide next to the threshold, as for a chain), margin the extrapolated lowest
// eigenvalue (1 when none lies below 1). kNotChecked when the path has no flexible piece or the
// energy is not bounded below relative to B on the admissible directions (a motion that bends
// nothing: not a mechanism of docs/mechanisms.md). `subject` names it in the message.
PathVerdict path_stability(const MechanismPath& path,
                           const StabilityOptions& options = {},
                           std::string_view subject = "the mechanism");

// The lowest `count` eigenvalues (extrapolated; 1 for those that do not exist below 1), for tests.
std::vector<double> path_eigenvalues(const MechanismPath& path,
                                     int count,
                                     const StabilityOptions& options = {});

}  // namespace flexure::mechanism
