#pragma once
// Shared by the stability tests (tests/solver/stability_cross_check_test.cpp,
// tests/solver/stable_equilibrium_test.cpp): a seeded random mixed chain.
#include <random>

#include "flexure/solver/chain_model/segment_chain.h"

namespace flexure::test {

// A chain with a tapered, initially curved flexure, a rigid link with a kink, a second flexure and
// a node load, under the end condition `end`: prescribed tip coordinates near the unloaded tip,
// the other tip loads drawn from `rng`.
inline SegmentChain mixed_chain(EndCondition end, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  SegmentChain chain;
  FlexibleSegment tapered;
  tapered.length = 0.4;
  tapered.EI_profile = {1.6, 1.2, 1.0, 0.9};
  tapered.kappa0 = 0.6;
  RigidSegment link;
  link.length = 0.3;
  link.angle_offset = 0.25;
  FlexibleSegment second;
  second.length = 0.5;
  second.EI = 1.3;
  chain.segments = {tapered, link, second};
  chain.node_loads.push_back(NodeLoad{2, -1.0 + 2.0 * unit(rng), -1.0 + 2.0 * unit(rng), 0.3});
  chain.end = end;
  const PrescribedMask mask = prescribed_mask(end);
  const ChainPose free_tip = chain.unloaded_tip();
  if (mask.x) chain.prescribed.x = free_tip.x - 0.4 * unit(rng);
  if (mask.y) chain.prescribed.y = free_tip.y + (2.0 * unit(rng) - 1.0) * 0.3;
  if (mask.theta) chain.prescribed.theta = free_tip.theta + (2.0 * unit(rng) - 1.0) * 1.0;
  if (!mask.x) chain.tip_load.Fx = -25.0 + 30.0 * unit(rng);
  if (!mask.y) chain.tip_load.Fy = -6.0 + 12.0 * unit(rng);
  if (!mask.theta) chain.tip_load.M = (2.0 * unit(rng) - 1.0) * 1.5;
  return chain;
}

}  // namespace flexure::test
