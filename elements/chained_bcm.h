#pragma once
// The chained beam-constraint model, CBCM (Ma and Chen, "Chained beam-constraint-model (CBCM): a
// powerful tool for modeling large and complicated deflections of flexible beams in compliant
// mechanisms", J. Mechanisms Robotics 8:021018, 2016; docs/models.md).
//
// The flexible segment (length L, EI) is divided into N equal elements of length h = L/N. Element
// j is a BCM (beam_constraint_model.h) in the frame of its own deflected root, the tip of element
// j-1 (angle Phi_j = the root's angle + theta_1 + ... + theta_{j-1}). Its tip loads are those of
// everything distal, in that frame: with F the force the distal part carries (the tip force, the
// node forces beyond the segment and the supports' reactions; no load acts inside the segment),
//   p_j = Fx cos Phi_j + Fy sin Phi_j,  f_j = -Fx sin Phi_j + Fy cos Phi_j,
//   m_j = the moment of the distal loads about the element's tip node,
// normalised by the element: p h^2/EI, f h^2/EI, m h/EI. The element displacements (y_j, theta_j,
// x_j) chain the nodes: node_{j+1} = node_j + h [(1 + x_j) t_j + y_j n_j] (t, n: the element
// frame's axes). Unknowns: y_j, theta_j of every element and the reactions of the prescribed tip
// coordinates; equations: every element's BCM relations and the prescribed coordinates. They are
// solved along proportional loading from the unloaded chain (load_path_newton.h).
//
// N = 1 is the BCM itself in the chain's setting (rigid links, any end). As N grows the CBCM
// converges to the elastica: the tip error falls as h^3, measured on seeded random loads
// (tests/elements/ladder_models_test.cpp; docs/models.md, "Convergence"). Each element's relation
// is correct to second order in its displacements, which are O(h) (theta_j) and O(h^2) (y_j).
//
// Axial stiffness: the segment's d = E A L^2/EI = 12 (L/t)^2 for a rectangle; element j's is
// d h^2/L^2 = d/N^2. It comes from the segment's own EA (FlexibleSegment::EA, set in a chain file
// by `EA` or by `extensible = true` with a section; docs/extensible.md) or, for a segment without
// one, from `slenderness` (L/t); without either it is the inextensible limit d -> infinity, which
// the exact elastica describes. A segment with EA and a slenderness is refused (two values for one
// stiffness). The BCM has no shear deformation: a segment's GAs is not modelled (a warning says
// so).
//
// Chains: one flexible segment (straight, constant EI) with rigid links and kinks before it (they
// only place its root) and after it (they carry the tip), any end condition (segment_chain.h),
// dead node loads on the rigid parts. Not: several flexible segments, an initial curvature, an EI
// profile, a follower force (the shooting method solves those).
#include <limits>
#include <string>
#include <vector>

#include "flexure/elements/cantilever_case.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/end_load.h"
#include "flexure/solver/common/status.h"

namespace flexure {

struct CbcmResult : SolveStatus {
  // iterations: Newton iterations over all load steps
  // residual: max |BCM relation residual| (in the segment's EI/L^2 and EI/L) and |prescribed
  // coordinate - target| (per L) at the returned state
  int elements = 0;
  int load_steps = 0;
  double load_factor = 0.0;  // the proportional-loading factor reached (1 when converged)
  ChainPose tip;             // the chain's tip, root frame, the chain's units
  Reaction reaction;         // loads the clamp applies to the chain: -N(0), -m(0)
  Reaction tip_load;  // total load on the tip: given + the reaction of a prescribed coordinate
  double root_moment = 0.0;  // bending moment at the clamp, m(0) = -reaction.M
  // The clamp, every joint of the chain and every element node, with the arc length s of the
  // undeformed chain (a kink of length 0 gives two points at one s).
  std::vector<ShapePoint> nodes;
  // The largest element transverse deflection |y_j| (per element length): the BCM's stated range
  // is about 0.1.
  double max_element_deflection = 0.0;
  bool inside_validity = false;
  // The axial stiffness d = EA L^2/EI solved with (infinity: the inextensible segment).
  double axial_stiffness = std::numeric_limits<double>::infinity();
  // The tip of the cantilever as Howell writes it (a/l, b/l per `length`, theta0).
  TipPose tip_pose(double length = 1.0) const {
    return {tip.x / length, tip.y / length, tip.theta};
  }
};

class ChainedBcmSolver {
 public:
  struct Options {
    int elements = 6;  // N equal BCM elements (1: the BCM)
    // Slenderness L/t of the flexible segment (rectangle): d = 12 (L/t)^2. 0 (the default): the
    // segment's own EA when it has one, else the inextensible limit d -> infinity. A chain whose
    // flexible segment has EA refuses a slenderness > 0 (InvalidInput): give one of them.
    double slenderness = 0.0;
    double tolerance = 1e-12;  // max |residual|, relative to max(1, |loads|)
    int max_iterations = 30;   // Newton iterations per load step
    int max_load_steps = 2000;
    // Throws InvalidInput naming the first bad field: elements in [1, 2000], slenderness 0 or
    // finite > 0, tolerance finite > 0, the counts >= 1.
    void validate() const;
  };

  ChainedBcmSolver();
  explicit ChainedBcmSolver(Options options);

  // Howell's cantilever (free or guided end). Throws InvalidInput for what
  // CantileverCase::validate refuses.
  CbcmResult solve(const CantileverCase& problem) const;
  // A chain of one flexible segment with rigid links at either end (see above). Throws
  // InvalidInput for a chain outside that class (several flexible segments, a curved or tapered
  // one, a distributed or follower load), naming the method that solves it, and for a segment with
  // EA given a slenderness too.
  CbcmResult solve(const SegmentChain& chain) const;

  // "bcm" for one element, else "cbcm": the name messages use.
  std::string model_name() const;
  const Options& options() const { return options_; }

 private:
  Options options_;
};

}  // namespace flexure
