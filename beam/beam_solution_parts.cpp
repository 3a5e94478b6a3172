#include "flexure/beam/beam_solution_parts.h"

#include <cmath>
#include <limits>

namespace flexure {

// Interior sign changes of the curvature along a sampled shape (numerical methods).
int count_curvature_sign_changes(const std::vector<ShapePoint>& shape) {
  int changes = 0;
  double previous = 0.0;
  for (std::size_t i = 1; i < shape.size(); ++i) {
    const double d = shape[i].theta - shape[i - 1].theta;
    if (std::fabs(d) < 1e-12) continue;
    if (previous != 0.0 && (d > 0.0) != (previous > 0.0)) ++changes;
    previous = d;
  }
  return changes;
}

// Linear interpolation of a shape given at increasing s onto `count` equally spaced points.
std::vector<ShapePoint> resample(const std::vector<ShapePoint>& nodes, int count) {
  std::vector<ShapePoint> out;
  if (nodes.size() < 2 || count < 2) return out;
  const double s0 = nodes.front().s;
  const double s1 = nodes.back().s;
  std::size_t j = 0;
  for (int i = 0; i < count; ++i) {
    const double s = s0 + (s1 - s0) * i / (count - 1);
    while (j + 2 < nodes.size() && nodes[j + 1].s < s) ++j;
    const ShapePoint& a = nodes[j];
    const ShapePoint& b = nodes[j + 1];
    const double t = b.s > a.s ? (s - a.s) / (b.s - a.s) : 0.0;
    out.push_back(
        {s, a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.theta + t * (b.theta - a.theta)});
  }
  return out;
}

// The constant EI of a uniform straight chain of flexible segments, or nullopt.
std::optional<double> uniform_EI(const SegmentChain& chain) {
  std::optional<double> EI;
  for (const Segment& segment : chain.segments) {
    const auto* flexible = std::get_if<FlexibleSegment>(&segment);
    if (flexible == nullptr || !flexible->EI_profile.empty() || flexible->kappa0 != 0.0 ||
        flexible->beyond_elastica()) {
      return std::nullopt;
    }
    if (EI && *EI != flexible->EI) return std::nullopt;
    EI = flexible->EI;
  }
  return EI;
}

// A chain given as a whole: keeps its loads in its own units and states them in Howell's
// parameters where the chain has them (BeamSolution::alpha2).
void describe_chain_loads(const SegmentChain& chain, BeamSolution& s) {
  const TipLoad& tip = chain.tip_load;
  s.chain_tip_load = {tip.Fx, tip.Fy, tip.M};
  s.chain_root_moment = s.root_moment;
  s.chain_reactions = s.reactions;
  const std::optional<double> EI = uniform_EI(chain);
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  if (!EI || tip.follower != 0.0) {
    s.alpha2 = s.load_ratio_n = s.mu = s.root_moment = kNaN;
    s.reactions = {kNaN, kNaN, kNaN};
    return;
  }
  const double L = chain.total_length();
  const double force_scale = L * L / *EI, moment_scale = L / *EI;
  s.alpha2 = tip.Fy * force_scale;
  // + 0.0: no -0. An axial load alone (Fy = 0, Fx != 0) has no Howell's n (eq. 2.67).
  s.load_ratio_n = tip.Fy != 0.0   ? -tip.Fx / tip.Fy + 0.0
                   : tip.Fx == 0.0 ? 0.0
                                   : std::numeric_limits<double>::quiet_NaN();
  s.mu = tip.M * moment_scale;
  s.root_moment *= moment_scale;
  s.reactions = {
      s.reactions.Fx * force_scale, s.reactions.Fy * force_scale, s.reactions.M * moment_scale};
}

BeamSolution missed_inverse_solution(BeamMethod method, const TipTargetSolution& found) {
  BeamSolution missed;
  missed.method = method;
  missed.termination = found.termination;
  missed.alpha2 = found.alpha2;
  missed.iterations = found.forward_solves;
  missed.target_residual = found.residual;
  missed.message = found.message;
  return missed;
}

}  // namespace flexure
