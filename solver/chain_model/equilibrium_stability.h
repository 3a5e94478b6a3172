#pragma once
// Stability of an equilibrium of a segment chain under dead loads, from its shape.
//
// Why: along proportional loading from the stress-free chain every equilibrium is stable up to the
// first limit point. A solver that reports an unstable equilibrium without having passed a limit
// point has left the load path (a natural-parameter iteration such as the chain algorithm's passes
// can converge to an unstable equilibrium near an imperfect bifurcation). This is a self-check
// that needs no second method.
//
// The second variation of the potential energy (the energy of a free end under dead loads,
// Pi = int EI (theta' - kappa0)^2 / 2 ds - sum F_k . r(s_k) - sum M_k theta(s_k)) in the direction
// eta = delta theta, eta(0) = 0, is
//     Q[eta] = int EI eta'^2 ds + int (N(s) . t(s)) eta^2 ds,
// N(s) the sum of the dead forces applied beyond s, t = (cos theta, sin theta): tension (N.t > 0)
// stiffens, compression softens. On a rigid segment eta is constant (EI infinite). The equilibrium
// is stable when Q is positive definite. Q is discretised on the shape's sample points (linear
// eta, lumped axial term) into a tridiagonal matrix K; Sylvester's law of inertia counts its
// negative eigenvalues as the negative pivots of K = L D L^T, after the shift K + eps M (M the
// lumped mass of int eta^2, eps = 1e-6 min EI / L^2), so that a state within rounding of a limit
// point is not called unstable.
//
// Only a free end with dead loads (no follower force) is covered; other ends return kNotChecked.
#include <string>
#include <vector>

#include "flexure/solver/chain_model/segment_chain.h"

namespace flexure {

struct StabilityVerdict {
  enum class Kind { kStable, kUnstable, kNotChecked };
  Kind kind = Kind::kNotChecked;
  int unstable_directions = 0;  // negative eigenvalues of the discretised second variation
  std::string message;
};

// `shape`: samples (s, x, y, theta) from the root (s = 0) to the tip (s = total length), in
// increasing s, that include every node between segments; the chain's loads are the full loads.
StabilityVerdict equilibrium_stability(const SegmentChain& chain,
                                       const std::vector<ShapePoint>& shape);

}  // namespace flexure
