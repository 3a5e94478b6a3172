#include "flexure/solver/chain_model/segment_chain.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "flexure/solver/common/status.h"

namespace flexure {

namespace {

// sin(u)/u, accurate near u = 0 where the stress-free arc degenerates to a straight segment.
double sinc(double u) {
  if (std::abs(u) < 1e-4) return 1.0 - u * u / 6.0;
  return std::sin(u) / u;
}

void require_finite_field(double value, const std::string& where, const char* field) {
  if (!std::isfinite(value)) {
    throw InvalidInput(fmt::format("{}: {} must be a finite number (got {})", where, field, value));
  }
}

}  // namespace

double FlexibleSegment::EI_at(double s_local) const {
  if (EI_profile.empty()) return EI;
  const int stations = static_cast<int>(EI_profile.size());
  if (stations == 1) return EI_profile.front();
  const double t = std::clamp(s_local / length, 0.0, 1.0) * (stations - 1);
  const int i = std::min(static_cast<int>(t), stations - 2);
  const double w = t - i;
  return (1.0 - w) * EI_profile[i] + w * EI_profile[i + 1];
}

std::array<double, 2> FlexibleSegment::q_at(double s_local) const {
  if (q_profile.empty()) return {qx, qy};
  const int stations = static_cast<int>(q_profile.size());
  if (stations == 1) return q_profile.front();
  const double t = std::clamp(s_local / length, 0.0, 1.0) * (stations - 1);
  const int i = std::min(static_cast<int>(t), stations - 2);
  const double w = t - i;
  return {(1.0 - w) * q_profile[i][0] + w * q_profile[i + 1][0],
          (1.0 - w) * q_profile[i][1] + w * q_profile[i + 1][1]};
}

std::array<double, 2> FlexibleSegment::q_resultant(double s_local) const {
  const double s = std::clamp(s_local, 0.0, length);
  if (q_profile.empty()) return {qx * s, qy * s};
  if (q_profile.size() == 1) return {q_profile[0][0] * s, q_profile[0][1] * s};
  // Trapezoids over the whole station intervals before s, then the partial one (exact for the
  // piecewise-linear profile).
  const int intervals = static_cast<int>(q_profile.size()) - 1;
  const double h = length / intervals;
  std::array<double, 2> sum{0.0, 0.0};
  int i = 0;
  for (; i < intervals && (i + 1) * h <= s; ++i) {
    for (int c = 0; c < 2; ++c) sum[c] += 0.5 * h * (q_profile[i][c] + q_profile[i + 1][c]);
  }
  const double rest = s - i * h;
  if (i < intervals && rest > 0.0) {
    const std::array<double, 2> q_end = q_at(s);
    for (int c = 0; c < 2; ++c) sum[c] += 0.5 * rest * (q_profile[i][c] + q_end[c]);
  }
  return sum;
}

bool SegmentChain::has_distributed_loads() const {
  return std::any_of(segments.begin(), segments.end(), [](const Segment& seg) {
    const auto* f = std::get_if<FlexibleSegment>(&seg);
    return f != nullptr && f->has_distributed_load();
  });
}

bool SegmentChain::has_follower_pressure() const {
  return std::any_of(segments.begin(), segments.end(), [](const Segment& seg) {
    const auto* f = std::get_if<FlexibleSegment>(&seg);
    return f != nullptr && f->q_follower != 0.0;
  });
}

bool SegmentChain::has_extensible_segments() const {
  return std::any_of(segments.begin(), segments.end(), [](const Segment& seg) {
    const auto* f = std::get_if<FlexibleSegment>(&seg);
    return f != nullptr && (f->extensible() || f->shear_flexible());
  });
}

void SegmentChain::require_elastica_only(const char* who) const {
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const auto* f = std::get_if<FlexibleSegment>(&segments[i]);
    if (f == nullptr || !f->beyond_elastica()) continue;
    const char* what = f->has_distributed_load()
                           ? "carries a distributed load"
                           : "is extensible or shear-flexible (finite EA or GAs)";
    throw InvalidInput(fmt::format(
        "segment {} {}, which {} does not model; use the shooting method (--method shooting)",
        i + 1,
        what,
        who));
  }
}

const char* to_string(EndCondition end) {
  switch (end) {
    case EndCondition::kFree:
      return "free";
    case EndCondition::kGuided:
      return "guided";
    case EndCondition::kPinned:
      return "pinned";
    case EndCondition::kSlider:
      return "slider";
    case EndCondition::kFixed:
      return "fixed";
  }
  return "unknown";
}

EndCondition end_condition_from_string(const std::string& name) {
  for (EndCondition e : {EndCondition::kFree,
                         EndCondition::kGuided,
                         EndCondition::kPinned,
                         EndCondition::kSlider,
                         EndCondition::kFixed}) {
    if (name == to_string(e)) return e;
  }
  throw InvalidInput(fmt::format(
      "end condition '{}' is unknown; allowed: free, guided, pinned, slider, fixed", name));
}

PrescribedMask prescribed_mask(EndCondition end) {
  switch (end) {
    case EndCondition::kFree:
      return {false, false, false};
    case EndCondition::kGuided:
      return {false, false, true};
    case EndCondition::kPinned:
      return {true, true, false};
    case EndCondition::kSlider:
      return {false, true, false};
    case EndCondition::kFixed:
      return {true, true, true};
  }
  return {};
}

double SegmentChain::total_length() const {
  double total = 0.0;
  for (const Segment& seg : segments) {
    total += std::visit([](const auto& s) { return s.length; }, seg);
  }
  return total;
}

void SegmentChain::validate() const {
  if (segments.empty()) throw InvalidInput("segment chain: at least one segment is required");
  // Messages count segments and node loads from 1, root to tip, as the TOML files list them
  // (docs/chain-toml.md); node indices are joints (node k is the far end of the k-th segment).
  bool has_flexible = false;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const std::string where = fmt::format("segment {}", i + 1);
    if (const auto* f = std::get_if<FlexibleSegment>(&segments[i])) {
      require_finite_field(f->length, where, "length");
      require_finite_field(f->EI, where, "EI");
      require_finite_field(f->kappa0, where, "kappa0");
      has_flexible = true;
      if (f->length <= 0.0) {
        throw InvalidInput(
            fmt::format("{} (flexible): length must be > 0 (got {})", where, f->length));
      }
      if (f->EI_profile.empty() && f->EI <= 0.0) {
        throw InvalidInput(fmt::format("{} (flexible): EI must be > 0 (got {})", where, f->EI));
      }
      if (f->EI_profile.size() == 1) {
        throw InvalidInput(
            fmt::format("{} (flexible): EI_profile needs at least 2 stations (got 1)", where));
      }
      require_finite_field(f->qx, where, "qx");
      require_finite_field(f->qy, where, "qy");
      require_finite_field(f->q_follower, where, "q_follower");
      if (!(f->EA > 0.0) || std::isnan(f->EA)) {
        throw InvalidInput(fmt::format(
            "{} (flexible): EA must be > 0 (got {}; infinity = inextensible)", where, f->EA));
      }
      if (!(f->GAs > 0.0) || std::isnan(f->GAs)) {
        throw InvalidInput(fmt::format(
            "{} (flexible): GAs must be > 0 (got {}; infinity = shear-rigid)", where, f->GAs));
      }
      if (f->q_profile.size() == 1) {
        throw InvalidInput(
            fmt::format("{} (flexible): q_profile needs at least 2 stations (got 1)", where));
      }
      for (std::size_t j = 0; j < f->q_profile.size(); ++j) {
        for (int c = 0; c < 2; ++c) {
          if (!std::isfinite(f->q_profile[j][c])) {
            throw InvalidInput(
                fmt::format("{} (flexible): q_profile[{}] must be finite numbers (got {})",
                            where,
                            j,
                            f->q_profile[j][c]));
          }
        }
      }
      if (!f->q_profile.empty() && (f->qx != 0.0 || f->qy != 0.0)) {
        throw InvalidInput(fmt::format("{} (flexible): give q or q_profile, not both", where));
      }
      for (std::size_t j = 0; j < f->EI_profile.size(); ++j) {
        const double v = f->EI_profile[j];
        if (!std::isfinite(v) || v <= 0.0) {
          throw InvalidInput(fmt::format(
              "{} (flexible): EI_profile[{}] must be a finite number > 0 (got {})", where, j, v));
        }
      }
    } else {
      const auto& r = std::get<RigidSegment>(segments[i]);
      require_finite_field(r.length, where, "length");
      require_finite_field(r.angle_offset, where, "angle_offset");
      if (r.length < 0.0) {
        throw InvalidInput(fmt::format(
            "{} (rigid): length must be >= 0 (got {}; 0 is a pure kink)", where, r.length));
      }
    }
  }
  // A rigid link of length 0 is a pure kink (an angle change at a point) and is kept: the pose
  // of every node is still well defined. But results are per unit total length (a/l, b/l) and the
  // solvers scale by it, so a chain of kinks only (total length 0) has no meaningful answer: it
  // gave a/l = 0/0 = NaN (shooting) or an error of its own (chain algorithm).
  if (!(total_length() > 0.0)) {
    throw InvalidInput(fmt::format(
        "segment chain: total length is {} (every segment is a rigid link of length 0, a pure "
        "kink); a chain needs a segment of length > 0",
        total_length()));
  }
  // Without a flexible segment the chain is one rigid body clamped at the root: its tip cannot
  // move, so a prescribed tip coordinate is either unreachable or holds a reaction that statics
  // cannot determine (the clamp and the tip share it in any proportion).
  if (!has_flexible && end != EndCondition::kFree) {
    throw InvalidInput(fmt::format(
        "segment chain: a {} end needs a flexible segment; a chain of rigid links only cannot "
        "move its tip and leaves the tip reaction undetermined (use a free end)",
        to_string(end)));
  }
  const int n = segment_count();
  for (std::size_t i = 0; i < node_loads.size(); ++i) {
    const NodeLoad& load = node_loads[i];
    const std::string where = fmt::format("node load {} (node {})", i + 1, load.node);
    if (load.node < 1 || load.node > n - 1) {
      throw InvalidInput(fmt::format(
          "node load {}: node must be an intermediate joint in [1, {}] (got {}); put tip loads in "
          "tip_load",
          i + 1,
          n - 1,
          load.node));
    }
    require_finite_field(load.Fx, where, "Fx");
    require_finite_field(load.Fy, where, "Fy");
    require_finite_field(load.M, where, "M");
  }
  require_finite_field(tip_load.Fx, "tip load", "Fx");
  require_finite_field(tip_load.Fy, "tip load", "Fy");
  require_finite_field(tip_load.M, "tip load", "M");
  require_finite_field(tip_load.follower, "tip load", "follower");
  const PrescribedMask mask = prescribed_mask(end);
  const char* end_name = to_string(end);
  if (mask.x && tip_load.Fx != 0.0) {
    throw InvalidInput(fmt::format(
        "tip load Fx must be 0 for a {} end (x is prescribed; Fx is the reaction)", end_name));
  }
  if (mask.y && tip_load.Fy != 0.0) {
    throw InvalidInput(fmt::format(
        "tip load Fy must be 0 for a {} end (y is prescribed; Fy is the reaction)", end_name));
  }
  if (mask.theta && tip_load.M != 0.0) {
    throw InvalidInput(fmt::format(
        "tip load M must be 0 for a {} end (theta is prescribed; M is the reaction)", end_name));
  }
  if (prescribed.x) require_finite_field(*prescribed.x, "prescribed tip", "x");
  if (prescribed.y) require_finite_field(*prescribed.y, "prescribed tip", "y");
  if (prescribed.theta) require_finite_field(*prescribed.theta, "prescribed tip", "theta");
}

std::vector<ChainPose> SegmentChain::unloaded_nodes() const {
  std::vector<ChainPose> nodes;
  nodes.reserve(segments.size() + 1);
  ChainPose p;
  nodes.push_back(p);
  for (const Segment& seg : segments) {
    if (const auto* f = std::get_if<FlexibleSegment>(&seg)) {
      // Stress-free shape is a circular arc: chord L*sinc(kL/2) along the mean tangent.
      const double turn = f->kappa0 * f->length;
      const double chord = f->length * sinc(0.5 * turn);
      const double mean = p.theta + 0.5 * turn;
      p.x += chord * std::cos(mean);
      p.y += chord * std::sin(mean);
      p.theta += turn;
    } else {
      const auto& r = std::get<RigidSegment>(seg);
      p.theta += r.angle_offset;
      p.x += r.length * std::cos(p.theta);
      p.y += r.length * std::sin(p.theta);
    }
    nodes.push_back(p);
  }
  return nodes;
}

ChainPose SegmentChain::unloaded_tip() const { return unloaded_nodes().back(); }

ChainPose SegmentChain::prescribed_tip() const {
  const ChainPose free_tip = unloaded_tip();
  return ChainPose{prescribed.x.value_or(free_tip.x),
                   prescribed.y.value_or(free_tip.y),
                   prescribed.theta.value_or(free_tip.theta)};
}

SegmentChain SegmentChain::at_load_factor(double lambda) const {
  SegmentChain out = *this;
  for (NodeLoad& load : out.node_loads) {
    load.Fx *= lambda;
    load.Fy *= lambda;
    load.M *= lambda;
  }
  out.tip_load.Fx *= lambda;
  out.tip_load.Fy *= lambda;
  out.tip_load.M *= lambda;
  out.tip_load.follower *= lambda;
  for (Segment& seg : out.segments) {
    if (auto* f = std::get_if<FlexibleSegment>(&seg)) {
      f->qx *= lambda;
      f->qy *= lambda;
      f->q_follower *= lambda;
      for (auto& q : f->q_profile) {
        q[0] *= lambda;
        q[1] *= lambda;
      }
    }
  }
  const ChainPose start = unloaded_tip();
  const ChainPose target = prescribed_tip();
  out.prescribed.x = start.x + lambda * (target.x - start.x);
  out.prescribed.y = start.y + lambda * (target.y - start.y);
  out.prescribed.theta = start.theta + lambda * (target.theta - start.theta);
  return out;
}

SegmentChain uniform_cantilever(const EndLoad& load) {
  SegmentChain chain;
  chain.segments.push_back(FlexibleSegment{1.0, 1.0, {}, 0.0});
  chain.tip_load = TipLoad{load.Fx, load.Fy, load.mu, 0.0};
  chain.end = EndCondition::kFree;
  return chain;
}

}  // namespace flexure
