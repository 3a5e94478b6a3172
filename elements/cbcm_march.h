#pragma once
// The chained BCM integrated from its root loads (ladder_models.h; docs/mechanisms.md "A model per
// flexure"): the CBCM's initial-value form, as the shooting method integrates the elastica from
// the loads at its root.
//
// The segment (length 1, EI 1) is N equal BCM elements of length h = 1/N. Given the force F =
// (Fx, Fy) that the distal part carries (the load on the tip; per EI/L^2) and the moment m0 of the
// distal loads about the root (the bending moment at the clamp, m(s) = m0 + Fx y(s) - Fy x(s);
// per EI/L), element j's tip loads in its own frame (its root turned Phi_j) are known up to its
// own displacement: p = F . t_j, f = F . n_j (both times h^2) and the moment about its tip node,
//   m_j h = M_j h - (1 + x_j) f + y_j p,   M_j the moment about its root node,
// since the tip node lies h [(1 + x_j) t_j + y_j n_j] beyond the root node. With the BCM relations
// [f; m_j] = K(p) [y_j; theta_j] and x_j = p/d_e - u'Pu/2 - p u'Qu (ladder_models.h,
// d_e = d/N^2) that is two equations in (y_j, theta_j), solved by Newton from the linear solution
// (at most a few iterations: the quadratic term is O(f h^2 y^2)). The next element starts at the
// tip node, turned theta_j, with M_{j+1} = m_j. The equations are those of ChainedBcmSolver (the
// same element relations, the same moment bookkeeping), so a march and a tip-loaded CBCM solve
// with the march's tip loads meet at one equilibrium; unlike the load path from the unloaded
// chain, the march needs no path (each element's 2x2 system is regular while its own load stays
// far from its buckling load, |p| << 10 N^2 for the segment's p), which a mechanism's Newton
// system needs where the flexure under dead tip loads would snap (the inclined bistable beam).
#include <vector>

#include "flexure/solver/chain_model/segment_chain.h"

namespace flexure {

struct CbcmMarchResult {
  double x = 1.0, y = 0.0, theta = 0.0;  // the tip in the root frame (per L, rad)
  double m = 0.0;                        // the distal loads' moment about the tip (per EI/L)
  double max_element_deflection = 0.0;   // largest |y_j| per element length
  std::vector<ChainPose> nodes;          // the N + 1 nodes (node 0 the root), when asked for
  std::vector<double> node_moments;      // M_j at every node, when asked for
};

// Marches `elements` BCM elements from the root loads (m0, Fx, Fy) (per EI/L and EI/L^2); the
// segment's axial stiffness is 1/inverse_d, d = EA L^2/EI (0: inextensible). False when an
// element's Newton does not converge (its load near its own buckling load) or a value is not
// finite. `keep_nodes` fills nodes and node_moments.
bool cbcm_march(int elements,
                double inverse_d,
                double m0,
                double Fx,
                double Fy,
                CbcmMarchResult& out,
                bool keep_nodes = false);

}  // namespace flexure
