#pragma once
// Howell §7.2: a segment chain cut into beam elements, each to be treated as a cantilever clamped
// to the deflected end of the previous one (Fig. 7.2). Flexible segments share the requested
// element count in proportion to their length; a rigid segment is one element that never deflects.
#include <vector>

#include "flexure/solver/chain_model/segment_chain.h"

namespace flexure {

struct ChainElement {
  double length = 0.0;  // arc length L_i
  double EI = 1.0;      // flexural rigidity at the element midpoint (flexible elements)
  // Linear compliances of the element with its EI varying along it (Simpson's rule on 1/EI at
  // both ends and the midpoint) minus those of the midpoint EI: zero for a uniform segment.
  double d_f22 = 0.0, d_f23 = 0.0, d_f33 = 0.0;
  double kappa0 = 0.0;        // stress-free curvature; the unloaded element is an arc
  bool rigid = false;         // rigid link: no elastic deflection
  double angle_offset = 0.0;  // rigid links only: kink between incoming tangent and link direction
  int segment = 0;            // index of the SegmentChain segment the element belongs to
  double s_start = 0.0;       // arc length of the element's near node from the root
};

// Loads on the element nodes 0..E at load factor 1 (root frame, dead) plus the tip follower.
struct ChainNodeLoads {
  std::vector<double> fx, fy, m;  // size E + 1; index 0 (the clamp) is unused
  double follower = 0.0;          // force along the tip normal (-sin theta, cos theta)
};

struct ChainDiscretisation {
  std::vector<ChainElement> elements;  // E elements, root to tip
  std::vector<int> model_node;         // element-node index of SegmentChain node k (size n + 1)
  ChainNodeLoads loads;                // full given loads (reactions not included)
  int flexible_elements = 0;           // N, the count requested for the flexible segments

  int element_count() const { return static_cast<int>(elements.size()); }
};

// Throws InvalidInput when `flexible_elements` is smaller than the number of flexible segments.
ChainDiscretisation discretise(const SegmentChain& chain, int flexible_elements);

}  // namespace flexure
