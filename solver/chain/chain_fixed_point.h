#pragma once
// Repeated chain passes at one load until the geometry stops changing: Howell's "iteration ...
// until the desired accuracy is obtained" (§7.2, after eq. 7.27). The fixed point is the
// discretised equilibrium: every element's loads use moment arms of the geometry they produce.
//
// Optional Anderson acceleration (depth m) extrapolates from the last m passes. The plain passes
// converge linearly with a rate that approaches 1 as the load grows (about 0.6 per pass at
// alpha2 = 10 and 0.95 at alpha2 = 50 for N = 100, see docs/theory-chain.md); the fixed point is
// unchanged by the acceleration.
#include "flexure/solver/chain/chain_pass.h"
#include "flexure/solver/common/status.h"

namespace flexure {

struct FixedPointOptions {
  int max_passes = 2000;      // give up after this many passes
  double tolerance = 1e-12;   // on max(position change / length_scale, angle change)
  double length_scale = 1.0;  // total chain length
  int anderson_depth = 0;     // 0 = plain passes
  ChainPassOptions pass;
};

struct FixedPointReport : SolveStatus {
  int passes = 0;
  double change = 0.0;      // scaled change of the last pass
  int failed_element = -1;  // an element buckled (eq. 7.30 singular) on a plain pass
};

// `geometry` holds the starting geometry on entry and the last pass's output on return.
FixedPointReport converge_chain(const ChainDiscretisation& d,
                                const ChainNodeLoads& loads,
                                ChainGeometry& geometry,
                                const FixedPointOptions& options);

}  // namespace flexure
