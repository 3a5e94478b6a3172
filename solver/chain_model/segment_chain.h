#pragma once
// A planar segment chain and the stability verdict of its equilibria, in one header.
//
// ================================================================================================
// Planar serial segment chain: the problem description shared by the shooting solver
// (solver/shooting/) and Howell's chain algorithm (solver/chain/). This header is the contract
// between the two; keep changes backward compatible.
//
// Geometry and frame
//   * Node 0 (the root) is clamped at the origin, tangent along +x (theta = 0). Segments are listed
//     from the root to the tip; node k (1 <= k <= n) is the far end of segment k-1, node n the tip.
//   * Arc length s runs from the root; x' = cos(theta), y' = sin(theta).
//   * FlexibleSegment: Euler-Bernoulli beam, inextensible and shear-rigid by default. Bending
//     moment m = EI (theta' - kappa0), kappa0 the stress-free curvature (constant on the segment;
//     positive bends toward +theta). EI is constant, or tabulated at equally spaced stations from
//     the near end (s = 0) to the far end (s = length) and interpolated linearly. With a finite EA
//     and/or GAs it is Reissner's geometrically exact planar beam: axial strain N.t / EA, shear
//     strain N.n / GAs, r' = (1 + eps) t + gamma n (docs/extensible.md). Shooting solver only.
//   * Distributed loads on a flexible segment (docs/distributed-loads.md): a dead load q per unit
//     (undeformed) length in the root frame, constant or tabulated at equally spaced stations like
//     EI_profile, and a follower pressure q_follower per unit deformed length along the deflected
//     normal n = (-sin theta, cos theta) (positive toward the left of the tangent). The shooting
//     solver integrates them; the chain algorithm lumps dead loads on its element nodes and refuses
//     followers.
//   * RigidSegment: a straight link. Its direction is the incoming tangent angle plus angle_offset
//     (a rigid kink at its near end); the next segment leaves along the link. A RigidSegment of
//     length 0 is a pure kink, e.g. a clamp at an angle.
//
// Loads (dead loads are fixed in the root frame; moments counter-clockwise positive)
//   * NodeLoad: dead force (Fx, Fy) and moment M at an intermediate node 1 <= node <= n-1.
//   * TipLoad: dead force (Fx, Fy), moment M and a follower force of magnitude `follower` that
//     always acts along the tip normal (-sin theta_tip, cos theta_tip), i.e. perpendicular to the
//     deflected tip tangent (positive: toward +y for an undeflected straight beam).
//
// End condition at the tip: each of x, y, theta is either prescribed or its conjugate load
// (Fx, Fy, M) is given. The load components conjugate to prescribed coordinates are the unknown
// tip reactions; the given values for those components must be zero (validate() enforces it).
//     kFree   : Fx, Fy, M given (cantilever)
//     kGuided : theta prescribed, Fx and Fy given (Howell's fixed-guided beam)
//     kPinned : x and y prescribed, M given
//     kSlider : y prescribed, Fx and M given
//     kFixed  : x, y, theta prescribed
// A prescribed value left unset (std::nullopt) means "the stress-free tip value", e.g. the guided
// beam keeps its initial tip angle (theta = 0 for an initially straight chain).
//
// Internal force convention (both solvers): N(s) is the force the distal part exerts on the
// proximal part across the section at s; m(s) is the bending moment, same sense. At the root the
// reaction the clamp exerts on the chain is -N(0) and the reaction moment is -m(0).
// Equilibrium of the distal part: N' = 0 on segments, dm/ds = -(t x N) = N_x sin(theta) -
// N_y cos(theta) (Howell eq. 2.67 differentiated); across node k, N and m drop by that node's load.
//
// Proportional loading (load factor lambda in [0, 1], used by continuation and by the chain
// algorithm's load increments, Howell eqs. 7.24-7.27): every given load is multiplied by lambda
// and every prescribed tip coordinate moves linearly from its stress-free value (lambda = 0) to its
// prescribed value (lambda = 1). See SegmentChain::at_load_factor().
//
// Units: any consistent set; the solvers are dimensionless in the sense that nothing assumes
// l = 1 or EI = 1, but uniform_cantilever() builds Howell's nondimensional beam (l = 1, EI = 1).
// ================================================================================================
//
// Stability of an equilibrium of a segment chain, for any end condition, from its shape: the
// verdict of the second variation of the total potential energy (docs/stability.md).
//
// The energy of the chain under dead loads, with the prescribed tip coordinates as constraints,
//     Pi = int EI (theta' - kappa0)^2 / 2 ds - sum F_k . r(s_k) - sum M_k theta(s_k)
//          - R . (r(L) - r*) - R_M (theta(L) - theta*),
// has the support's reactions (R, R_M) as Lagrange multipliers; they act like dead loads. Its
// second variation in a direction eta = delta theta (eta(0) = 0 at the clamp) is
//     Q[eta] = int EI eta'^2 ds + int (N(s) . t(s)) eta^2 ds,
// N(s) the force the distal part exerts across s (above), *including the support's
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
//     return shooting_shape_at(chain, shooting_result, s);  // solver/shooting/shooting_solver.h
//   });
// or with samples at stability_stations(chain, support) (or any samples that include the nodes,
// e.g. the chain algorithm's nodes with ChainResult::tip_reaction).
#include <array>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/status.h"

namespace flexure {

struct FlexibleSegment {
  FlexibleSegment() = default;
  // The elastica's four fields in their order (the distributed loads and EA, GAs by name).
  FlexibleSegment(double length_,
                  double EI_,
                  std::vector<double> EI_profile_ = {},
                  double kappa0_ = 0.0)
      : length(length_), EI(EI_), EI_profile(std::move(EI_profile_)), kappa0(kappa0_) {}

  double length = 1.0;             // arc length of the segment, > 0
  double EI = 1.0;                 // flexural rigidity, > 0 (used when EI_profile is empty)
  std::vector<double> EI_profile;  // optional: EI at >= 2 equally spaced stations over the segment
  double kappa0 = 0.0;             // stress-free curvature (1/length), constant on the segment
  // Distributed loads (docs/distributed-loads.md). Dead load per unit length, root frame:
  double qx = 0.0;
  double qy = 0.0;
  // Optional: (qx, qy) at >= 2 equally spaced stations over the segment, interpolated linearly
  // (overrides qx, qy).
  std::vector<std::array<double, 2>> q_profile;
  // Follower pressure per unit deformed length along the deflected normal (-sin theta, cos theta).
  double q_follower = 0.0;
  // Axial and shear rigidity (docs/extensible.md); infinity = inextensible / shear-rigid.
  double EA = std::numeric_limits<double>::infinity();
  double GAs = std::numeric_limits<double>::infinity();  // k G A, k the shear coefficient

  // EI at local arc length s_local in [0, length] (clamped to that range).
  double EI_at(double s_local) const;
  // Dead load per unit length at s_local, and its integral from 0 to s_local (the resultant of
  // the segment's dead load on [0, s_local]).
  std::array<double, 2> q_at(double s_local) const;
  std::array<double, 2> q_resultant(double s_local) const;
  bool has_dead_load() const { return qx != 0.0 || qy != 0.0 || !q_profile.empty(); }
  bool has_distributed_load() const { return has_dead_load() || q_follower != 0.0; }
  bool extensible() const { return EA != std::numeric_limits<double>::infinity(); }
  bool shear_flexible() const { return GAs != std::numeric_limits<double>::infinity(); }
  // Any of the above: the segment needs the Reissner right-hand side of the shooting solver.
  bool beyond_elastica() const {
    return has_distributed_load() || extensible() || shear_flexible();
  }
};

struct RigidSegment {
  double length = 1.0;        // link length, >= 0 (0 = a pure kink)
  double angle_offset = 0.0;  // link direction minus incoming tangent angle (radians)
};

using Segment = std::variant<FlexibleSegment, RigidSegment>;

struct NodeLoad {
  int node = 1;     // joint index, 1 <= node <= n-1 (node k is the far end of segment k-1)
  double Fx = 0.0;  // dead force, root frame
  double Fy = 0.0;
  double M = 0.0;  // dead moment, counter-clockwise positive
};

struct TipLoad {
  double Fx = 0.0;  // dead force, root frame
  double Fy = 0.0;
  double M = 0.0;         // dead moment, counter-clockwise positive
  double follower = 0.0;  // force along the tip normal (-sin theta_tip, cos theta_tip)
};

enum class EndCondition { kFree, kGuided, kPinned, kSlider, kFixed };
const char* to_string(EndCondition end);
// Throws InvalidInput listing the allowed names ("free", "guided", "pinned", "slider", "fixed").
EndCondition end_condition_from_string(const std::string& name);

// Which tip coordinates an end condition prescribes.
struct PrescribedMask {
  bool x = false;
  bool y = false;
  bool theta = false;
};
PrescribedMask prescribed_mask(EndCondition end);

// Prescribed tip values, root frame. Unset = the stress-free tip value.
struct TipPrescription {
  std::optional<double> x;
  std::optional<double> y;
  std::optional<double> theta;
};

// Position and tangent angle of a point of the chain.
struct ChainPose {
  double x = 0.0;
  double y = 0.0;
  double theta = 0.0;
};

struct SegmentChain {
  std::vector<Segment> segments;     // root to tip, at least one
  std::vector<NodeLoad> node_loads;  // dead loads at intermediate joints
  TipLoad tip_load;
  EndCondition end = EndCondition::kFree;
  TipPrescription prescribed;

  int segment_count() const { return static_cast<int>(segments.size()); }
  double total_length() const;

  // Throws InvalidInput naming the segment/node load (counted from 1, root to tip) and the
  // field: empty chain, non-finite value, length <= 0 (flexible) or < 0 (rigid; 0 is a pure kink),
  // total length 0 (kinks only), a prescribed tip on a chain without a flexible segment, EI <= 0,
  // a bad EI_profile, a node index outside [1, n-1], a nonzero given load conjugate to a
  // prescribed coordinate. Every solver calls it before solving; the solvers' entry points also
  // refuse a prescribed tip the chain cannot reach (tip_reach.h).
  void validate() const;

  // Whether any flexible segment carries a distributed load (dead or follower), a follower
  // pressure, or is extensible / shear-flexible.
  bool has_distributed_loads() const;
  bool has_follower_pressure() const;
  bool has_extensible_segments() const;
  // Throws InvalidInput for a solver or analysis (`who`) that handles neither distributed loads
  // nor extensible segments, naming the first such segment and pointing to the shooting method.
  void require_elastica_only(const char* who) const;

  // Stress-free pose at every node 0..n (kappa0 arcs and rigid links, no loads).
  std::vector<ChainPose> unloaded_nodes() const;
  ChainPose unloaded_tip() const;

  // Resolved prescribed tip values at full load (unset values replaced by unloaded_tip()).
  ChainPose prescribed_tip() const;

  // The same chain under proportional loading: loads (distributed ones too) times lambda,
  // prescribed tip coordinates moved linearly from the stress-free tip (lambda = 0) to their
  // prescribed value (lambda = 1). The returned chain has every prescribed value set explicitly.
  SegmentChain at_load_factor(double lambda) const;
};

// Howell's nondimensional cantilever: one flexible segment, length 1, EI 1, straight, free end
// carrying the dead EndLoad {Fx, Fy, mu}.
SegmentChain uniform_cantilever(const EndLoad& load);

}  // namespace flexure

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
