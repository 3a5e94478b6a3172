#pragma once
// A stable equilibrium of a segment chain near an unstable (or critical) one: what `flexure beam
// --stable` returns when the equilibrium reached by proportional loading is not stable
// (docs/stability.md, "A stable answer on request").
//
// Method: a descent of the total potential energy of a discrete model of the chain, then the
// shooting method's Newton iteration from the discrete minimum, then the verdict.
//   1. The discrete model: the tangent angle at the nodes of equal elements on every flexible
//      segment (the element counts of stability_stations(), at least `min_elements` each), the
//      bending energy sum k_e/2 (dtheta - kappa0 h)^2 with k_e = int_e EI ds / h^2 (exact for a
//      tapered EI with linear theta), positions by the trapezoid rule r = sum h/2 (t_a + t_b)
//      (second order), rigid links exactly. Its Hessian is the bending matrix B (tridiagonal) plus
//      a diagonal W = (h/2) N . t: the discrete second variation of the verdict
//      (second_variation.h), so the verdict's inertia and eigenvalue routines apply to it. The
//      prescribed tip coordinates are constraints (x(L), y(L): nonlinear, kept by a projection in
//      the B^{-1} metric after every step; theta(L): the last node's angle is fixed).
//   2. The descent: from the start (the unstable equilibrium sampled at the nodes), a step along
//      the eigenvector of the lowest constrained eigenvalue of the second variation (both signs
//      are tried), then Newton steps on the constraint manifold with the Hessian shifted by tau B
//      where its lowest eigenvalue is not positive, plus the negative-curvature direction while one
//      exists; every step is accepted only where the energy decreases (backtracking). It ends at a
//      point where the gradient vanishes and the second variation is positive definite: a strict
//      local minimum of the discrete energy.
//   3. Newton from the minimum: the root unknowns (m(0) from the statics of the discrete shape,
//      N(0) from the loads and the multipliers of the constraints, which are the support's
//      reactions) start ShootingSolver::solve_from(); where it does not converge the elements are
//      doubled (from the interpolated minimum) up to `refinements` times.
//   4. The verdict of the converged equilibrium (equilibrium_stability with the shooting shape)
//      must be stable. Of the candidates (the two signs), the one of lower energy is returned.
// Dead loads only: a follower force has no potential energy (InvalidInput).
#include <string>
#include <vector>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {

struct StableEquilibriumOptions {
  // Elements of the discrete model on each flexible segment: those of stability_stations() for
  // the start's support reaction, at least this many.
  int min_elements = 64;
  int max_elements = 4096;           // per flexible segment
  int max_iterations = 400;          // descent steps per start
  int refinements = 2;               // doublings of the elements when Newton does not converge
  double max_step = 0.5;             // largest change of a node angle in one descent step, rad
  double unstable_step = 0.25;       // length of the step along an unstable direction, rad
  ShootingSolver::Options shooting;  // the Newton iteration and the shape (its defaults)
  StabilityOptions stability;        // the verdict

  // Throws InvalidInput naming the first field outside its range.
  void validate() const;
};

struct StableEquilibrium : SolveStatus {
  // message: what was done, or why no stable equilibrium was found (converged() false)
  // iterations: descent steps in all, over every candidate
  ShootingResult equilibrium;  // the stable equilibrium (converged)
  Stability stability;         // its verdict (stable when converged())
  // Total potential energy of the discrete model (chain units) at the start (after the start was
  // made to meet the constraints of the model) and at the returned equilibrium's minimum.
  double start_energy = 0.0;
  double energy = 0.0;
  int candidates = 0;  // descents that reached a stable equilibrium (of 2)
  int elements = 0;    // flexible elements of the discrete model that gave the answer
};

// From the equilibrium `start` (a function of arc length, as for the verdict; e.g. the shooting
// or elliptic shape) with the support reaction `start_support_reaction` (sizes the elements; zeros
// for a free end). Never throws for a search that fails (converged() false with the reason);
// throws InvalidInput for an invalid chain or options, a follower force, or a start that is not a
// shape of this chain.
StableEquilibrium find_stable_equilibrium(const SegmentChain& chain,
                                          const ShapeAtStations& start,
                                          const Reaction& start_support_reaction,
                                          const StableEquilibriumOptions& options = {});

// A shape given at samples (increasing s, e.g. the chain algorithm's nodes) as a function of arc
// length: linear interpolation of x, y and theta between the samples (the angle taken on the far
// side of a node where two samples share one s).
ShapeAtStations interpolated_shape(std::vector<ShapePoint> samples);

}  // namespace flexure
