#pragma once
// The problem every model of the ladder solves (docs/models.md): Howell's uniform cantilever
// (length l = 1, EI = 1), clamped at the origin with its tangent along +x, its far end either
//   * free, under the dead tip load EndLoad {Fx, Fy, mu} (Howell eq. 2.67: Fy = alpha2,
//     Fx = -n alpha2), or
//   * guided: the tip angle held at `guided_tip_angle` (0: Howell's fixed-guided beam, §5.3), the
//     tip force given, the tip moment the guide's reaction (so mu must be 0).
// Pinned, slider and fixed ends, rigid links and kinks are chains (segment_chain.h): the chained
// BCM (chained_bcm.h) and the exact shooting method solve those.
#include <string_view>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/end_load.h"

namespace flexure {

struct CantileverCase {
  EndLoad load;
  EndCondition end = EndCondition::kFree;  // kFree or kGuided
  double guided_tip_angle = 0.0;           // rad; guided end only

  // Throws InvalidInput naming `model` and what it cannot represent: a non-finite value, an end
  // other than free or guided (naming the models that solve it), an end moment on a guided end.
  void validate(std::string_view model) const;
  // The same problem as a segment chain (one flexible segment; the guided end's angle prescribed).
  SegmentChain to_chain() const;
};

// The statics every model's answer shares: the clamp's bending moment M(0) l/EI of the tip loads
// about the root, for a tip at (a/l, b/l) carrying the force (Fx, Fy) and the moment end_moment
// (mu on a free end, the guide's reaction on a guided one).
inline double root_moment_of(const TipPose& tip, const EndLoad& load, double end_moment) {
  return tip.a_over_l * load.Fy - tip.b_over_l * load.Fx + end_moment;
}

}  // namespace flexure
