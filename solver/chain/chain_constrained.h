#pragma once
// Chain passes that meet prescribed tip coordinates as they go: the fixed point of Howell's passes
// (§7.2) together with the unknown tip reactions of the shooting method (§7.2.1, eq. 7.37),
// found in one iteration instead of a Newton iteration on the reactions around fully converged
// passes.
//
// Why (docs/theory-chain.md §5): the shooting method of §7.2.1 applies a guess of the reactions
// as dead tip loads and converges the passes of that *free-ended* chain before each Newton step.
// Under a large compressive load with a guided end (n = 3.66, alpha2 = 12.5: an axial load 18
// times the free cantilever's Euler load) that free-ended chain is far past its own buckling
// load: its equilibrium under the guessed loads is unstable, and the passes, a relaxation towards
// it, converge only slowly (Anderson's extrapolation) or not at all, some 30 000 passes per load
// step in all, 1.4 million for the answer. The guided chain itself is stable; its reaction is what
// holds it. So here every iteration is one pass at the current reactions z and one more per
// unknown at z + h e_k, and the new geometry and reactions are the combination of these passes
// whose tip meets the prescribed coordinates (to first order in the correction):
//     y_0 = pass(x; z),  y_k = pass(x; z + h_k e_k),  J_ck = (tip_c(y_k) - tip_c(y_0)) / h_k,
//     dz = J^+ (wanted - tip(y_0)),  x' = y_0 + sum_k dz_k (y_k - y_0) / h_k,  z' = z + dz.
// A fixed point has dz = 0, so tip(x) = wanted and x = pass(x; z): exactly the discrete
// equilibrium of the shooting method, now reached at the rate of the constrained chain. Anderson
// acceleration (chain_fixed_point.h) acts on (x, z / scale) together.
//
// The passes stop early, with the reason, when the measured rate of convergence says that the
// remaining pass budget cannot reach the tolerance (a budget from the rate, not a timeout).
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "flexure/solver/chain/chain_fixed_point.h"
#include "flexure/solver/common/status.h"

namespace flexure {

struct ConstrainedTip {
  std::vector<int> unknowns;            // tip reaction components solved for: 0 Fx, 1 Fy, 2 M
  double wanted[3] = {0, 0, 0};         // prescribed x, y, theta at this load factor
  double unknown_scale[3] = {1, 1, 1};  // EI/l^2, EI/l^2, EI/l
  double tolerance = 1e-10;             // |tip - wanted| (positions over length, angles)
};

struct ConstrainedReport : SolveStatus {
  // iterations: constrained iterations, each a correction of the reactions
  int passes = 0;       // chain passes (1 + unknowns per iteration)
  double change = 0.0;  // scaled change of the last iteration
  double boundary_residual = 0.0;
  int failed_element = -1;  // an element buckled on the first pass
  double rate = 0.0;        // measured convergence rate per iteration when it stopped early
  std::string failure;      // why it stopped, when not converged
};

// `loads` are the given loads at the load factor (without reactions); `z` the starting reactions
// (in/out); `geometry` the starting geometry (in) and the last iterate (out).
ConstrainedReport converge_constrained_chain(const ChainDiscretisation& d,
                                             const ChainNodeLoads& loads,
                                             const ConstrainedTip& tip,
                                             Eigen::Vector3d& z,
                                             ChainGeometry& geometry,
                                             const FixedPointOptions& options);

}  // namespace flexure
