#pragma once
// One pass of Howell's chain algorithm (§7.2, eqs. 7.10-7.23) over all elements, root to tip.
//
// Element i is clamped to the already deflected end of element i-1. The part of the chain beyond
// node i is taken from a previous geometry (the previous increment or the previous pass) rigidly
// rotated by the change of the clamp angle, which gives the "most up-to-date" moment arms of
// eqs. 7.14-7.15 (with the bracket erratum of 7.15 corrected). Internal loads follow from statics
// (eqs. 7.10-7.12), element deflections from the flexibility of eq. 7.30, and the element tip is
// placed with the transverse deflection perpendicular to the clamp tangent psi_i (eqs. 7.17-7.18;
// eq. 7.6 for element 1 uses theta_1 + delta_theta_1 instead, which differs by O(L^3) per
// element (erratum 7.6 vs 7.17, docs/theory-chain.md); this code uses psi_i for every element).
// Rigid-body motion of the elements (eqs. 7.19-7.22) is implicit: node positions are accumulated
// directly in the root frame.
//
// Cost: O(E) per pass. The moment arms of all downstream loads are rotated by one angle per
// element, so suffix sums of p x f and p . f give every moment in constant time.
#include <vector>

#include "flexure/solver/chain/chain_discretisation.h"

namespace flexure {

// Deformed configuration at the element nodes 0..E (node 0 is the clamp at the origin).
struct ChainGeometry {
  std::vector<double> x, y;
  std::vector<double> theta;  // tangent angle at the far end of element i (theta[0] = 0)
};

// Stress-free geometry of the discretised chain.
ChainGeometry unloaded_geometry(const ChainDiscretisation& d);

struct ChainPassOptions {
  // Subtract from the chord the second-order shortening 1/2 * integral(w'^2) of the element's
  // cubic deflection shape (the quantity whose Hessian is the geometric stiffness of eq. 7.28),
  // so that the deflected element keeps its arc length. Howell's eqs. 7.17-7.18 omit it.
  bool foreshortening = false;
  // Terms that keep curved (kappa0) and tapered (EI profile) elements as accurate as straight
  // uniform ones: the stress-free arc's offset from its chord in the moment arms and lever arms,
  // and Simpson-rule compliances for a varying EI (ChainElement::d_f22...). Without them such
  // elements are second order in 1/N.
  bool curved_and_tapered_terms = false;
  // Rotate the downstream moment arms also by the element's own new rotation (one Newton step of
  // the scalar element equation, linearised about the previous geometry) instead of by the clamp
  // angle alone (Howell's Delta Theta_{i-1}, eq. 7.13). Same fixed point; faster convergence when
  // the loads are large (about 2x fewer passes at alpha2 = 50, docs/theory-chain.md).
  bool implicit_rotation = false;
};

struct ChainPassReport {
  bool ok = true;                // false when an element buckled (eq. 7.30 has no valid inverse)
  int failed_element = -1;       // the buckled element (0-based) when !ok
  double position_change = 0.0;  // max |new - old| over node coordinates
  double angle_change = 0.0;     // max |new - old| over node angles (rad)
};

// Loads: dead forces/moments at the element nodes (already scaled by the load factor and with any
// tip reactions added) and the tip follower force magnitude.
ChainPassReport chain_pass(const ChainDiscretisation& d,
                           const ChainNodeLoads& loads,
                           const ChainGeometry& previous,
                           const ChainPassOptions& options,
                           ChainGeometry& next);

}  // namespace flexure
