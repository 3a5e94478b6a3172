#include "flexure/elements/chained_bcm_model.h"

#include <fmt/format.h>

#include <algorithm>

#include "flexure/solver/chain_model/tip_reach.h"
#include "flexure/solver/common/status.h"

namespace flexure::detail::cbcm {

Prepared prepare(const SegmentChain& chain, const std::string& model, int controlled) {
  chain.validate();
  int flexible_index = -1;
  int flexible_count = 0;
  for (int i = 0; i < chain.segment_count(); ++i) {
    if (std::holds_alternative<FlexibleSegment>(chain.segments[static_cast<std::size_t>(i)])) {
      ++flexible_count;
      flexible_index = i;
    }
  }
  if (flexible_count != 1) {
    throw InvalidInput(fmt::format(
        "the {} model solves a chain of one flexible segment with rigid links or kinks at either "
        "end (this chain has {} flexible segments); the shooting method or the chain algorithm "
        "solves it",
        model,
        flexible_count));
  }
  const auto& flexible =
      std::get<FlexibleSegment>(chain.segments[static_cast<std::size_t>(flexible_index)]);
  if (flexible.kappa0 != 0.0 || !flexible.EI_profile.empty()) {
    throw InvalidInput(fmt::format(
        "the {} model's elements are straight and uniform: the flexible segment has {}; the "
        "shooting method or the chain algorithm solves it",
        model,
        flexible.kappa0 != 0.0 ? "an initial curvature kappa0" : "an EI profile"));
  }
  if (flexible.has_distributed_load()) {
    throw InvalidInput(fmt::format(
        "the {} model's elements carry end loads only: the flexible segment has a distributed "
        "load (qx, qy, q_profile or q_follower); the shooting method solves it",
        model));
  }
  if (chain.tip_load.follower != 0.0) {
    throw InvalidInput(fmt::format(
        "the {} model takes dead loads; the shooting method solves a follower force", model));
  }
  require_reachable_tip(chain);
  Prepared p;
  p.L = flexible.length;
  p.EI = flexible.EI;
  p.EA = flexible.EA;
  p.GAs = flexible.GAs;
  const double force_scale = p.L * p.L / p.EI, moment_scale = p.L / p.EI;
  const std::vector<ChainPose> unloaded = chain.unloaded_nodes();
  const ChainPose& root = unloaded[static_cast<std::size_t>(flexible_index)];
  p.root = {root.x / p.L, root.y / p.L, root.theta};
  for (int i = flexible_index + 1; i < chain.segment_count(); ++i) {
    RigidSegment link = std::get<RigidSegment>(chain.segments[static_cast<std::size_t>(i)]);
    link.length /= p.L;
    p.tip_links.push_back(link);
  }
  p.distal_loads.resize(p.tip_links.size() + 1);
  const auto scaled = [&](double Fx, double Fy, double M) {
    return PointLoad{Fx * force_scale, Fy * force_scale, M * moment_scale};
  };
  for (const NodeLoad& load : chain.node_loads) {
    const PointLoad l = scaled(load.Fx, load.Fy, load.M);
    if (load.node <= flexible_index) {
      const ChainPose& at = unloaded[static_cast<std::size_t>(load.node)];
      p.root_loads.push_back({{at.x / p.L, at.y / p.L, at.theta}, l});
    } else {
      PointLoad& d = p.distal_loads[static_cast<std::size_t>(load.node - flexible_index - 1)];
      d.Fx += l.Fx;
      d.Fy += l.Fy;
      d.M += l.M;
    }
  }
  PointLoad& tip = p.distal_loads.back();
  const PointLoad t = scaled(chain.tip_load.Fx, chain.tip_load.Fy, chain.tip_load.M);
  tip.Fx += t.Fx;
  tip.Fy += t.Fy;
  tip.M += t.M;
  p.mask = prescribed_mask(chain.end);
  p.controlled = controlled;
  if (controlled >= 0) {
    bool* coordinate = controlled == 0 ? &p.mask.x : controlled == 1 ? &p.mask.y : &p.mask.theta;
    p.controlled_by_end = *coordinate;
    *coordinate = true;
  }
  p.prescribed = int(p.mask.x) + int(p.mask.y) + int(p.mask.theta);
  const ChainPose target = chain.prescribed_tip();
  const ChainPose free_tip = chain.unloaded_tip();
  p.target = {target.x / p.L, target.y / p.L, target.theta};
  p.unloaded = {free_tip.x / p.L, free_tip.y / p.L, free_tip.theta};
  double scale = 1.0;
  for (const PointLoad& l : p.distal_loads) {
    scale = std::max({scale, std::fabs(l.Fx), std::fabs(l.Fy), std::fabs(l.M)});
  }
  scale = std::max({scale,
                    std::fabs(p.target.x - p.unloaded.x),
                    std::fabs(p.target.y - p.unloaded.y),
                    std::fabs(p.target.theta - p.unloaded.theta)});
  p.load_scale = scale;
  return p;
}

double axial_stiffness(const Prepared& p, double slenderness, const std::string& model) {
  if (std::isfinite(p.EA)) {
    const double d = p.EA * p.L * p.L / p.EI;
    if (slenderness > 0.0) {
      throw InvalidInput(fmt::format(
          "the {} model takes its axial stiffness from the flexible segment's EA = {:g} (d = EA "
          "L^2/EI = {:g}) and from a slenderness L/t = {:g} (d = 12 (L/t)^2 = {:g}): give one "
          "(leave "
          "out the slenderness to use EA)",
          model,
          p.EA,
          d,
          slenderness,
          12.0 * slenderness * slenderness));
    }
    return d;
  }
  if (slenderness > 0.0) return 12.0 * slenderness * slenderness;
  return std::numeric_limits<double>::infinity();
}

}  // namespace flexure::detail::cbcm
