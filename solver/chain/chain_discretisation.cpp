#include "flexure/solver/chain/chain_discretisation.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <variant>
#include <vector>

#include "flexure/solver/common/status.h"

namespace flexure {

namespace {

// Largest-remainder split of `total` elements over segment lengths, at least one per segment, so
// that element lengths stay as uniform as the segment lengths allow.
std::vector<int> split_elements(const std::vector<double>& lengths, int total) {
  const int count = static_cast<int>(lengths.size());
  const double sum = std::accumulate(lengths.begin(), lengths.end(), 0.0);
  std::vector<double> ideal(count);
  std::vector<int> n(count);
  int used = 0;
  for (int k = 0; k < count; ++k) {
    ideal[k] = lengths[k] / sum * total;
    n[k] = std::max(1, static_cast<int>(std::floor(ideal[k])));
    used += n[k];
  }
  while (used < total) {
    int best = 0;
    for (int k = 1; k < count; ++k) {
      if (ideal[k] - n[k] > ideal[best] - n[best]) best = k;
    }
    ++n[best];
    ++used;
  }
  while (used > total) {
    int best = -1;
    for (int k = 0; k < count; ++k) {
      if (n[k] > 1 && (best < 0 || ideal[k] - n[k] < ideal[best] - n[best])) best = k;
    }
    --n[best];
    --used;
  }
  return n;
}

}  // namespace

namespace {
double segment_start(const SegmentChain& chain, int segment) {
  double s = 0.0;
  for (int k = 0; k < segment; ++k) {
    s += std::visit([](const auto& seg) { return seg.length; }, chain.segments[k]);
  }
  return s;
}
}  // namespace

ChainDiscretisation discretise(const SegmentChain& chain, int flexible_elements) {
  for (int k = 0; k < chain.segment_count(); ++k) {
    const auto* f = std::get_if<FlexibleSegment>(&chain.segments[k]);
    if (f == nullptr) continue;
    if (f->q_follower != 0.0 || f->extensible() || f->shear_flexible()) {
      throw InvalidInput(fmt::format(
          "segment {} {}, which the chain algorithm does not model (it lumps dead distributed "
          "loads only); use the shooting method (--method shooting)",
          k + 1,
          f->q_follower != 0.0 ? "carries a follower pressure"
                               : "is extensible or shear-flexible (finite EA or GAs)"));
    }
  }
  std::vector<double> flexible_lengths;
  for (const Segment& seg : chain.segments) {
    if (const auto* f = std::get_if<FlexibleSegment>(&seg)) flexible_lengths.push_back(f->length);
  }
  const int flexible_count = static_cast<int>(flexible_lengths.size());
  if (flexible_elements < std::max(1, flexible_count)) {
    throw InvalidInput(fmt::format("elements must be >= {} (one per flexible segment) (got {})",
                                   std::max(1, flexible_count),
                                   flexible_elements));
  }
  const std::vector<int> per_segment =
      flexible_count > 0 ? split_elements(flexible_lengths, flexible_elements) : std::vector<int>{};

  ChainDiscretisation d;
  d.flexible_elements = flexible_count > 0 ? flexible_elements : 0;
  d.model_node.push_back(0);
  double s = 0.0;
  int flexible_index = 0;
  for (int k = 0; k < chain.segment_count(); ++k) {
    if (const auto* f = std::get_if<FlexibleSegment>(&chain.segments[k])) {
      const int n = per_segment[flexible_index++];
      const double L = f->length / n;
      for (int i = 0; i < n; ++i) {
        ChainElement e;
        e.length = L;
        // Midpoint value: a second-order quadrature of the compliance, matching the O(L^2)
        // accuracy of the element itself.
        e.EI = f->EI_at((i + 0.5) * L);
        // f33 = int c, f23 = int (L-s) c, f22 = int (L-s)^2 c with c = 1/EI, by Simpson's rule.
        const double c0 = 1.0 / f->EI_at(i * L);
        const double cm = 1.0 / e.EI;
        const double c1 = 1.0 / f->EI_at((i + 1) * L);
        e.d_f33 = L / 6.0 * (c0 + 4.0 * cm + c1) - L * cm;
        e.d_f23 = L * L / 6.0 * (c0 + 2.0 * cm) - 0.5 * L * L * cm;
        e.d_f22 = L * L * L / 6.0 * (c0 + cm) - L * L * L / 3.0 * cm;
        e.kappa0 = f->kappa0;
        e.segment = k;
        e.s_start = s + i * L;
        d.elements.push_back(e);
      }
    } else {
      const auto& r = std::get<RigidSegment>(chain.segments[k]);
      ChainElement e;
      e.length = r.length;
      e.rigid = true;
      e.angle_offset = r.angle_offset;
      e.segment = k;
      e.s_start = s;
      d.elements.push_back(e);
    }
    s += std::visit([](const auto& seg) { return seg.length; }, chain.segments[k]);
    d.model_node.push_back(d.element_count());
  }

  const int E = d.element_count();
  d.loads.fx.assign(E + 1, 0.0);
  d.loads.fy.assign(E + 1, 0.0);
  d.loads.m.assign(E + 1, 0.0);
  for (const NodeLoad& load : chain.node_loads) {
    const int j = d.model_node.at(load.node);
    d.loads.fx[j] += load.Fx;
    d.loads.fy[j] += load.Fy;
    d.loads.m[j] += load.M;
  }
  // Dead distributed loads lumped on the element nodes: each element's share of the load goes to
  // its two end nodes in the ratio of the load's first moment about them (the statically
  // equivalent split of a linear load: for a constant q, q L/2 each; on the clamp's node it is
  // carried by the clamp). The element's moment error is O(L^2) (docs/distributed-loads.md).
  for (int e = 0; e < E; ++e) {
    const ChainElement& el = d.elements[e];
    if (el.rigid) continue;
    const auto& f = std::get<FlexibleSegment>(chain.segments[el.segment]);
    if (!f.has_dead_load()) continue;
    const double s0 = el.s_start - segment_start(chain, el.segment);
    const double L = el.length;
    // Simpson's rule of q and q (s - s0)/L over the element (exact for a linear q on the element;
    // the element count is split at stations only approximately, so this is second order).
    const std::array<double, 2> qa = f.q_at(s0), qm = f.q_at(s0 + 0.5 * L), qb = f.q_at(s0 + L);
    for (int c = 0; c < 2; ++c) {
      const double total = L / 6.0 * (qa[c] + 4.0 * qm[c] + qb[c]);
      const double far = L / 6.0 * (2.0 * qm[c] + qb[c]);  // int q (s - s0)/L ds
      std::vector<double>& f_axis = c == 0 ? d.loads.fx : d.loads.fy;
      f_axis[e] += total - far;
      f_axis[e + 1] += far;
    }
  }
  d.loads.fx[E] += chain.tip_load.Fx;
  d.loads.fy[E] += chain.tip_load.Fy;
  d.loads.m[E] += chain.tip_load.M;
  d.loads.follower = chain.tip_load.follower;
  return d;
}

}  // namespace flexure
