#pragma once
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
#include <array>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "flexure/solver/common/end_load.h"

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
