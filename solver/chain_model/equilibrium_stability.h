#pragma once
// Stability of an equilibrium of a segment chain, for any end condition, from its shape: the
// verdict of the second variation of the total potential energy (docs/stability.md).
//
// The energy of the chain under dead loads, with the prescribed tip coordinates as constraints,
//     Pi = int EI (theta' - kappa0)^2 / 2 ds - sum F_k . r(s_k) - sum M_k theta(s_k)
//          - R . (r(L) - r*) - R_M (theta(L) - theta*),
// has the support's reactions (R, R_M) as Lagrange multipliers; they act like dead loads. Its
// second variation in a direction eta = delta theta (eta(0) = 0 at the clamp) is
//     Q[eta] = int EI eta'^2 ds + int (N(s) . t(s)) eta^2 ds,
// N(s) the force the distal part exerts across s (segment_chain.h), *including the support's
// reaction*: tension (N . t > 0) stiffens, compression softens; a moment (given or a reaction) is
// linear in theta and adds nothing. The admissible variations satisfy the linearised constraints
//     x(L) prescribed: int sin(theta) eta ds = 0,  y(L): int cos(theta) eta ds = 0,  theta(L):
//     eta(L) = 0;
// eta is constant along a rigid link. The equilibrium is stable when Q is positive definite on
// them. Reported (solver/common/status.h):
//   index  = the number of constrained eigenvalues of Q eta = lambda B eta below -tolerance,
//   margin = the lowest of them, B[eta] = int EI eta'^2 ds the unloaded bending stiffness:
//            1 for an unloaded chain, 1 - P/P_cr for a straight column under an axial load P,
//            0 at a buckling or limit point, negative when unstable; never above 1 (the spectrum
//            accumulates at 1; a chain with no compressed part has margin exactly 1).
// A follower tip force is not conservative: kNotConservative.
//
// Method (docs/stability.md, "Method 1"): linear elements in eta on the sampled shape, the bending
// term integrated exactly (also for a tapered EI), the axial term lumped at the nodes with the
// tangent of each element from its chord; the constrained inertia by the bordered-matrix formula
// and the eigenvalue by Newton's method on the bordered determinant inside a bracket given by the
// inertia (second_variation.h). The error of the discrete eigenvalues is O(h^2) with an expansion
// in powers of h^2, so when every flexible segment is sampled at equal elements in a number
// divisible by 4 the eigenvalues of the grid and of the grids of every 2nd and every 4th sample are
// extrapolated (Romberg, O(h^6); by 2 only: Richardson, O(h^4)): on the stations of
// stability_stations() the margin is accurate to about 1e-9 on smooth shapes (measured: 2.5e-10
// on columns, docs/stability.md).
//
// Usage with a solver's result (the tip reaction is needed whenever a tip coordinate is
// prescribed; for a free end it is zero), preferably with the shape as a function of the arc
// lengths, which lets the verdict refine its stations where it needs to:
//   const Reaction support = tip_support_reaction(chain, shooting_result.tip_load);
//   const Stability v = equilibrium_stability(chain, support, [&](const std::vector<double>& s) {
//     return shooting_shape_at(chain, shooting_result, s);  // solver/shooting/shooting_shape.h
//   });
// or with samples at stability_stations(chain, support) (or any samples that include the nodes,
// e.g. the chain algorithm's nodes with ChainResult::tip_reaction).
#include <functional>
#include <string>
#include <vector>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/status.h"

namespace flexure {

struct DiscreteSecondVariation;  // second_variation.h (internal)

struct StabilityOptions {
  // |margin| <= this is critical (status.h says why 1e-6).
  double critical_tolerance = kCriticalMarginTolerance;
  // Each discrete eigenvalue is found to this times max(1, |lambda|).
  double eigenvalue_tolerance = 1e-12;
  // Stations: each flexible segment gets n equal elements, n = length * q / element_resolution
  // within [min_elements, max_elements], rounded up to a multiple of 4 (the extrapolation uses the
  // grids of every 2nd and 4th sample too) and of the EI profile's intervals (its kinks fall on
  // nodes); q bounds the segment's wavenumber from the loads: sqrt(|N| / EI) + |m| / EI +
  // |kappa0| (stability_stations() says how |m| is bounded).
  int min_elements = 32;
  double element_resolution = 0.1;
  int max_elements = 20000;
  // The ShapeAtStations variant doubles the elements (up to max_elements) until the estimated
  // error of the margin (the last Romberg correction) is below this times max(1, |margin|).
  double margin_accuracy = 1e-9;

  // Throws InvalidInput naming the first field outside its range.
  void validate() const;
};

// The reaction of the tip support: the components of the total tip load (ShootingResult::tip_load,
// the given load plus the reaction) conjugate to the coordinates the chain's end condition
// prescribes; the others zero.
Reaction tip_support_reaction(const SegmentChain& chain, const Reaction& total_tip_load);
// The same from the clamp's reaction (ShootingResult::reaction, PathPoint::reaction; the chain at
// the point's load, e.g. chain.at_load_factor(lambda)): the force at the tip is N(L) = -R_clamp -
// the node loads, of which the prescribed components are the support's. Its moment is left 0
// (the verdict does not use it; it needs the shape).
Reaction tip_support_reaction_from_root(const SegmentChain& chain, const Reaction& root_reaction);

// The arc lengths (root to tip, increasing, every node between segments included once, rigid
// segments only at their ends) at which equilibrium_stability wants the shape: each flexible
// segment cut into an even number of equal elements chosen from the loads (StabilityOptions).
// Throws InvalidInput for an invalid chain, reaction or options.
std::vector<double> stability_stations(const SegmentChain& chain,
                                       const Reaction& support_reaction,
                                       const StabilityOptions& options = {});

// The verdict. `chain`: the problem at the equilibrium's load (the full given loads);
// `support_reaction`: the force and moment the tip support exerts on the chain (zero components
// for coordinates that are not prescribed; the moment is not used); `shape`: the equilibrium at
// increasing arc lengths that include every node between segments (any others are allowed; at a
// node with a kink two samples with the same s are allowed). Only the positions x, y are used (the
// tangent of an element is the direction of its chord, which is unambiguous at kinks); s must be
// the arc length. stability_stations() gives the samples for the stated accuracy; other samples
// work at the accuracy they allow (not extrapolated unless every flexible segment has an even
// number of equal elements).
// Returns kNotConservative for a follower force, kNotChecked for a chain without a flexible
// segment. Throws InvalidInput when the reaction has a component conjugate to a free coordinate,
// the shape misses a node or is not ordered, or its samples are farther apart than the arc length
// between them (not a shape of this chain).
Stability equilibrium_stability(const SegmentChain& chain,
                                const Reaction& support_reaction,
                                const std::vector<ShapePoint>& shape,
                                const StabilityOptions& options = {});

// The same with the shape as a function that returns it at given arc lengths: called with
// stability_stations(), and again with twice the elements while the margin's estimated error
// exceeds StabilityOptions::margin_accuracy (which happens where the margin is close to 1: a weakly
// compressed chain's critical mode oscillates faster than the loads alone say). The preferred
// form where the shape can be evaluated anywhere (shooting, elliptic).
using ShapeAtStations = std::function<std::vector<ShapePoint>(const std::vector<double>& s)>;
Stability equilibrium_stability(const SegmentChain& chain,
                                const Reaction& support_reaction,
                                const ShapeAtStations& shape_at,
                                const StabilityOptions& options = {});

// The lowest `count` constrained eigenvalues of the second variation relative to the bending
// stiffness (extrapolated like the margin; 1 for those that do not exist below 1), e.g. to follow
// the second eigenvalue to a second bifurcation. Same arguments and errors as above; a follower
// force or a chain without a flexible segment throws InvalidInput.
std::vector<double> second_variation_eigenvalues(const SegmentChain& chain,
                                                 const Reaction& support_reaction,
                                                 const std::vector<ShapePoint>& shape,
                                                 int count,
                                                 const StabilityOptions& options = {});

// The discrete second variation on the shape's samples, every `stride`-th sample of each flexible
// segment (stride 2 needs an even number of elements in each), with its independent constraint
// rows: what the functions above solve, for tests and studies of the discretisation.
DiscreteSecondVariation discrete_second_variation(const SegmentChain& chain,
                                                  const Reaction& support_reaction,
                                                  const std::vector<ShapePoint>& shape,
                                                  int stride = 1);

// ---- Earlier interface, kept for its callers (the chain algorithm's self-check) ---------------
// A free end only (other ends: kNotChecked, since no reaction is given); stable includes critical.
struct StabilityVerdict {
  enum class Kind { kStable, kUnstable, kNotChecked };
  Kind kind = Kind::kNotChecked;
  int unstable_directions = 0;  // negative eigenvalues of the discretised second variation
  std::string message;
};
StabilityVerdict equilibrium_stability(const SegmentChain& chain,
                                       const std::vector<ShapePoint>& shape);

}  // namespace flexure
