#pragma once
// The displacement-controlled equilibrium path of the chained BCM and of the BCM (ladder_models.h;
// docs/models.md "Paths under displacement control"): `flexure path --method cbcm|bcm --control
// tip-x|tip-y|tip-angle`, the problem Ma and Chen made the CBCM for (inclined and bistable beams
// whose guided end is moved along a path).
//
// As the shooting method's controlled path (shooting_solver.h, docs/paths.md): the chain's loads
// and prescribed coordinates are applied first by proportional loading (stage 1, recorded only
// when there is something to apply); then the controlled coordinate moves from its value there to
// the target as the path parameter lambda goes from 0 to 1 (stage 2). The moving stage is followed
// by pseudo-arclength continuation in the unknowns (every element's y_j, theta_j and the
// prescribed coordinates' reactions) and lambda, with a secant-free tangent from the augmented
// Jacobian [dr/dz dr/dlambda; t'] (forward differences) and Keller's corrector on the hyperplane
// normal to the tangent. Special points, located by bisection on the chord between the two path
// points around them (the corrector on the hyperplane through the chord point, normal to the
// chord):
//   * a limit point (fold of lambda): the tangent's lambda component changes sign;
//   * a bifurcation: the sign of det of the augmented Jacobian changes while lambda keeps its
//     direction (a simple branch point; the determinant of dr/dz alone changes sign at both).
// At the k-th bifurcation (branch = k) the path leaves onto the other branch: its direction is the
// null vector of [dr/dz dr/dlambda] there orthogonal to the path's tangent (the two smallest
// singular vectors span the null space), on the side (branch_side) where the tip's y increases,
// or its angle when y is held, or the clamp's bending moment m(0) when both are.
// Force points: zeros of the support's load on the moved coordinate (Brent-free: bisection on the
// chord) and its local extrema along the path (golden section on the two chords around a sampled
// extremum), each on the path to the corrector's tolerance.
//
// The BCM (one element) is valid to a transverse deflection of about 0.1 of its length (Awtar et
// al. 2007): its path stops, completed == false and left_domain == true, at the first point past
// that, the message naming where and the CBCM that goes on.
#include <string>
#include <vector>

#include "flexure/elements/ladder_models.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {

struct CbcmPathOptions {
  int elements = 20;         // N (1: the BCM)
  double slenderness = 0.0;  // as ChainedBcmSolver::Options
  // The largest change of lambda in one step (e.g. 1/(min_points - 1)), and of any element node's
  // angle (rad).
  double max_load_step = 0.02;
  double max_angle_step = 0.05;
  int branch = 0;            // k > 0: switch onto the other branch at the k-th bifurcation
  int branch_side = 1;       // +1 or -1 (see above)
  double tolerance = 1e-11;  // max |residual| (the segment's EI/L^2, EI/L; per L)
  int max_steps = 20000;     // accepted and rejected steps together
  // Throws InvalidInput naming the field.
  void validate() const;
};

struct CbcmPathPoint {
  double lambda = 0.0;
  ChainPose tip;      // the chain's units
  Reaction reaction;  // the clamp on the chain
  Reaction tip_load;  // total load on the tip (a prescribed coordinate's: its reaction)
  double max_element_deflection = 0.0;  // largest |y_j| per element length
  int status = 1;  // as PathStatus: 0 start, 1 accepted, 2 limit point, 3 end, 4 bifurcation
  int stage = 1;
  int branch = 0;
};

struct CbcmSpecialPoint {
  SpecialPointKind kind = SpecialPointKind::kLimitPoint;  // as the shooting path's (to_string)
  CbcmPathPoint point;
  int index = -1, index_after = -1;
  bool located = true;
  bool switched = false;
};

struct CbcmForcePoint {
  ForcePointKind kind = ForcePointKind::kZero;  // as the shooting path's (to_string)
  CbcmPathPoint point;
  double coordinate = 0.0, force = 0.0;
  double slope = 0.0;  // at a zero: d force / d coordinate on the path; 0 at an extremum
  int index_before = -1;
  bool located = true;
};

struct CbcmPathResult : SolveStatus {
  std::vector<CbcmPathPoint> points;
  std::vector<CbcmSpecialPoint> special_points;
  std::vector<CbcmForcePoint> force_points;
  double lambda_reached = 0.0;
  int limit_points = 0, bifurcation_points = 0;
  bool switched_branch = false;
  int steps = 0, rejected_steps = 0, newton_iterations = 0, location_corrections = 0;
  bool left_domain = false;  // the BCM's path stopped where it left its stated range
  int elements = 0;
  double axial_stiffness = 0.0;  // d = EA L^2/EI solved with (infinity: inextensible)
};

// The path of `chain` with `control.coordinate` moved to `control.target` (root frame, the chain's
// units; rad). Throws InvalidInput for a chain the CBCM does not model (ladder_models.h), a one-way
// control (shooting only), or bad options. A path that stops early returns completed == false
// (SolveStatus) with the message; the points up to there are kept.
CbcmPathResult trace_cbcm_controlled_path(const SegmentChain& chain,
                                          const DisplacementControl& control,
                                          const CbcmPathOptions& options);

}  // namespace flexure
