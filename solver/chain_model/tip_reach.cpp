#include "flexure/solver/chain_model/tip_reach.h"

#include <fmt/format.h>

#include <cmath>
#include <variant>

#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

// Tip of the chain with every flexible segment straight and every rigid link as it is: the only
// configuration that can put the tip a full chain length from the root (a kink keeps it closer,
// unless it only turns the clamp, before any length).
ChainPose straightened_tip(const SegmentChain& chain) {
  ChainPose p;
  for (const Segment& segment : chain.segments) {
    if (const auto* rigid = std::get_if<RigidSegment>(&segment)) {
      p.theta += rigid->angle_offset;
      p.x += rigid->length * std::cos(p.theta);
      p.y += rigid->length * std::sin(p.theta);
    } else {
      const double length = std::get<FlexibleSegment>(segment).length;
      p.x += length * std::cos(p.theta);
      p.y += length * std::sin(p.theta);
    }
  }
  return p;
}

}  // namespace

double reachable_load_factor(const SegmentChain& chain) {
  const PrescribedMask mask = prescribed_mask(chain.end);
  if (!mask.x && !mask.y) return 1.0;
  // An extensible segment stretches: any point can be reached (at a large enough force).
  if (chain.has_extensible_segments()) return 1.0;
  const double L = chain.total_length();
  const ChainPose p0 = chain.unloaded_tip();
  const ChainPose p1 = chain.prescribed_tip();
  // The slider's free x is taken as 0, the most favourable value.
  const double ax = mask.x ? p0.x : 0.0, bx = mask.x ? p1.x - p0.x : 0.0;
  const double ay = mask.y ? p0.y : 0.0, by = mask.y ? p1.y - p0.y : 0.0;
  const ChainPose straight = straightened_tip(chain);
  auto outside = [&](double lam) {
    const double x = ax + lam * bx, y = ay + lam * by;
    const double d = std::hypot(x, y);
    if (d > L * (1.0 + 1e-12)) return true;
    if (d < L * (1.0 - 1e-12)) return false;
    // On the circle: only the straightened chain's own tip (for a slider, whose x is free, the
    // prescribed y must be that tip's y).
    const bool at_straight_tip =
        std::fabs(y - straight.y) <= 1e-9 * L && (!mask.x || std::fabs(x - straight.x) <= 1e-9 * L);
    return !at_straight_tip;
  };
  if (!outside(1.0)) return 1.0;
  // The start is a configuration of the chain; bisect the crossing.
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (outside(mid) ? hi : lo) = mid;
  }
  return lo;
}

void require_reachable_tip(const SegmentChain& chain) {
  const double reachable = reachable_load_factor(chain);
  if (reachable >= 1.0) return;
  const PrescribedMask mask = prescribed_mask(chain.end);
  const ChainPose target = chain.prescribed_tip();
  const double L = chain.total_length();
  const double distance = std::hypot(mask.x ? target.x : 0.0, mask.y ? target.y : 0.0);
  throw InvalidInput(fmt::format(
      "the prescribed tip {} lies {:.9g} from the root, and the chain is {:.9g} long: {} (the "
      "prescribed path of the tip leaves the reachable set at load factor {:.9g})",
      mask.x ? fmt::format("(x, y) = ({:.6g}, {:.6g})", target.x, target.y)
             : fmt::format("y = {:.6g}", target.y),
      distance,
      L,
      distance > L * (1.0 + 1e-12)
          ? "an inextensible chain cannot reach it"
          : "only the chain straightened along the clamp's tangent reaches that distance, so this "
            "point cannot be reached",
      reachable));
}

}  // namespace flexure
