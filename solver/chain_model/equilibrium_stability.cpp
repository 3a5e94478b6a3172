#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <variant>

#include "flexure/solver/chain_model/held_stability.h"
#include "flexure/solver/chain_model/second_variation.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

double segment_length(const Segment& segment) {
  return std::visit([](const auto& seg) { return seg.length; }, segment);
}

// int_a^b EI ds over local arc lengths of a flexible segment, exact for its piecewise linear EI.
double EI_integral(const FlexibleSegment& f, double a, double b) {
  if (f.EI_profile.size() < 2) return f.EI_at(0.5 * (a + b)) * (b - a);
  const int intervals = static_cast<int>(f.EI_profile.size()) - 1;
  const double step = f.length / intervals;
  double sum = 0.0;
  double from = a;
  while (from < b) {
    const int i = std::clamp(static_cast<int>(std::floor(from / step)), 0, intervals - 1);
    double to = std::min(b, (i + 1) * step);
    if (!(to > from)) to = b;  // rounding at a station
    sum += 0.5 * (f.EI_at(from) + f.EI_at(to)) * (to - from);
    from = to;
  }
  return sum;
}

// Dead force N on every segment: the tip's total force (given dead load plus the support's
// reaction) and the node loads beyond the segment (node k lies beyond segments 0..k-1).
std::vector<std::pair<double, double>> segment_forces(const SegmentChain& chain,
                                                      const Reaction& support) {
  const std::size_t n = chain.segments.size();
  std::vector<std::pair<double, double>> N(n);
  for (std::size_t j = 0; j < n; ++j) {
    double Nx = chain.tip_load.Fx + support.Fx, Ny = chain.tip_load.Fy + support.Fy;
    for (const NodeLoad& load : chain.node_loads) {
      if (static_cast<std::size_t>(load.node) >= j + 1) {
        Nx += load.Fx;
        Ny += load.Fy;
      }
    }
    N[j] = {Nx, Ny};
  }
  return N;
}

// The resultant of the dead distributed loads on the segments beyond each segment.
std::vector<std::pair<double, double>> distributed_beyond(const SegmentChain& chain) {
  const std::size_t n = chain.segments.size();
  std::vector<std::pair<double, double>> out(n, {0.0, 0.0});
  double qx = 0.0, qy = 0.0;
  for (std::size_t j = n; j-- > 0;) {
    out[j] = {qx, qy};
    if (const auto* f = std::get_if<FlexibleSegment>(&chain.segments[j])) {
      const std::array<double, 2> q = f->q_resultant(f->length);
      qx += q[0];
      qy += q[1];
    }
  }
  return out;
}

// Whether the verdict takes Reissner's terms (docs/extensible.md, "Stability"): a flexible segment
// with a finite EA or GAs, or a dead distributed load (its internal force varies along s).
bool needs_reissner_terms(const SegmentChain& chain) {
  return std::any_of(chain.segments.begin(), chain.segments.end(), [](const Segment& seg) {
    const auto* f = std::get_if<FlexibleSegment>(&seg);
    return f != nullptr && f->beyond_elastica();
  });
}

// The coordinates the verdict holds: `held` (held_stability.h), else the end condition's.
using Held = std::optional<PrescribedMask>;
PrescribedMask held_mask(const SegmentChain& chain, const Held& held) {
  return held.value_or(prescribed_mask(chain.end));
}

void check_support_reaction(const SegmentChain& chain,
                            const Reaction& support,
                            const Held& held = std::nullopt) {
  require_finite(support.Fx, "tip support reaction Fx");
  require_finite(support.Fy, "tip support reaction Fy");
  require_finite(support.M, "tip support reaction M");
  const PrescribedMask mask = held_mask(chain, held);
  auto refuse = [&](const char* component, const char* coordinate, double value) {
    throw InvalidInput(fmt::format(
        "tip support reaction {} = {:.6g} for a {} end, whose tip {} is not prescribed: pass the "
        "support's reaction only (tip_support_reaction() takes it from the total tip load)",
        component,
        value,
        to_string(chain.end),
        coordinate));
  };
  if (!mask.x && support.Fx != 0.0) refuse("Fx", "x", support.Fx);
  if (!mask.y && support.Fy != 0.0) refuse("Fy", "y", support.Fy);
  if (!mask.theta && support.M != 0.0) refuse("M", "angle", support.M);
}

bool has_flexible_segment(const SegmentChain& chain) {
  return std::any_of(chain.segments.begin(), chain.segments.end(), [](const Segment& s) {
    return std::holds_alternative<FlexibleSegment>(s);
  });
}

// The shape's samples of every segment: indices of its first (leaving side of the near node) and
// last (arriving side of the far node) samples; for a flexible segment every sample in between.
struct SampledChain {
  const SegmentChain* chain = nullptr;
  PrescribedMask mask;  // the tip coordinates held
  const std::vector<ShapePoint>* shape = nullptr;
  std::vector<std::pair<double, double>> N;
  // The resultant of the dead distributed loads beyond each segment (on segments j+1 .. n-1).
  std::vector<std::pair<double, double>> distributed_beyond;
  // Some flexible segment is extensible, shear-flexible or carries a dead distributed load: the
  // second variation of Reissner's beam on the sampled angles (reissner_terms() below).
  bool reissner = false;
  std::vector<std::size_t> first, last;  // per segment (unused for zero-length kinks)
  double total = 0.0;
  // Grids available for extrapolation: 1 + the largest L <= 2 such that every flexible segment has
  // equal elements in a number divisible by 2^L (the grids of every 2nd and every 4th sample).
  int levels = 3;
};

SampledChain sample_chain(const SegmentChain& chain,
                          const Reaction& support,
                          const std::vector<ShapePoint>& shape,
                          const Held& held = std::nullopt) {
  SampledChain c;
  c.chain = &chain;
  c.mask = held_mask(chain, held);
  c.shape = &shape;
  c.N = segment_forces(chain, support);
  c.total = chain.total_length();
  c.distributed_beyond = distributed_beyond(chain);
  c.reissner = needs_reissner_terms(chain);
  const double tol = 1e-9 * c.total;
  for (std::size_t i = 0; i < shape.size(); ++i) {
    const ShapePoint& p = shape[i];
    if (!std::isfinite(p.s) || !std::isfinite(p.x) || !std::isfinite(p.y)) {
      throw InvalidInput(fmt::format(
          "shape sample {} is not finite (s = {}, x = {}, y = {})", i + 1, p.s, p.x, p.y));
    }
    if (i > 0 && p.s < shape[i - 1].s - tol) {
      throw InvalidInput(
          fmt::format("the shape's arc lengths must not decrease: sample {} has s = {:.9g} after "
                      "s = {:.9g}",
                      i + 1,
                      p.s,
                      shape[i - 1].s));
    }
  }
  const std::size_t n = chain.segments.size();
  c.first.assign(n, 0);
  c.last.assign(n, 0);
  double start = 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    const double length = segment_length(chain.segments[j]);
    const double end = start + length;
    if (length > 0.0) {
      // Last sample at the near node, first at the far node.
      auto at_start = std::upper_bound(
          shape.begin(), shape.end(), start + tol, [](double s, const ShapePoint& p) {
            return s < p.s;
          });
      auto at_end = std::lower_bound(
          shape.begin(), shape.end(), end - tol, [](const ShapePoint& p, double s) {
            return p.s < s;
          });
      if (at_start == shape.begin() || std::fabs(std::prev(at_start)->s - start) > tol ||
          at_end == shape.end() || std::fabs(at_end->s - end) > tol) {
        throw InvalidInput(fmt::format(
            "the shape must include every node between segments: segment {} ({} to {}) has no "
            "sample at s = {:.9g}",
            j + 1,
            start,
            end,
            (at_start == shape.begin() || std::fabs(std::prev(at_start)->s - start) > tol) ? start
                                                                                           : end));
      }
      c.first[j] = static_cast<std::size_t>(std::prev(at_start) - shape.begin());
      c.last[j] = static_cast<std::size_t>(at_end - shape.begin());
      if (std::holds_alternative<FlexibleSegment>(chain.segments[j])) {
        const std::size_t elements = c.last[j] - c.first[j];
        double h_min = HUGE_VAL, h_max = 0.0;
        for (std::size_t i = c.first[j]; i < c.last[j]; ++i) {
          const double h = shape[i + 1].s - shape[i].s;
          if (!(h > 0.0)) {
            throw InvalidInput(fmt::format(
                "the shape has two samples at s = {:.9g} inside segment {} (only nodes between "
                "segments may be repeated)",
                shape[i].s,
                j + 1));
          }
          h_min = std::min(h_min, h);
          h_max = std::max(h_max, h);
        }
        if (h_max - h_min > 1e-8 * h_max) c.levels = 1;
        if (elements % 4 != 0) c.levels = std::min(c.levels, 2);
        if (elements % 2 != 0) c.levels = 1;
      }
    }
    start = end;
  }
  return c;
}

// One grid: the discrete second variation before its constraints are reduced.
struct Grid {
  DiscreteSecondVariation q;
  std::vector<double> weight;                 // lumped weight of int eta^2 at each dof
  std::vector<std::vector<double>> raw_rows;  // sin(theta) row if x prescribed, cos if y
  // The compliance of the raw rows (Reissner's terms; zero otherwise): D00, D01, D11.
  std::array<double, 3> raw_compliance{0.0, 0.0, 0.0};
  std::vector<double> flexibility;  // G_i: sum of 1 / B_e from the clamp to dof i
};

Grid assemble(const SampledChain& c, int stride) {
  const SegmentChain& chain = *c.chain;
  const std::vector<ShapePoint>& shape = *c.shape;
  const PrescribedMask mask = c.mask;
  Grid g;
  const std::size_t rows = (mask.x ? 1 : 0) + (mask.y ? 1 : 0);
  g.raw_rows.resize(rows);
  int dof = -1;
  auto add_dof = [&] {
    g.q.bending_diag.push_back(0.0);
    if (dof >= 0) g.q.bending_off.push_back(0.0);
    g.q.axial.push_back(0.0);
    g.weight.push_back(0.0);
    for (std::vector<double>& row : g.raw_rows) row.push_back(0.0);
    g.flexibility.push_back(dof >= 0 ? g.flexibility[static_cast<std::size_t>(dof)] : 0.0);
    ++dof;
  };
  // Axial term, weight and constraint rows of a piece of length `h` whose tangent is the chord
  // (dx, dy), lumped onto dof d.
  auto lump = [&](int d, double h, double tx, double ty, std::size_t segment) {
    if (d < 0) return;
    const double Nx = c.N[segment].first + c.distributed_beyond[segment].first;
    const double Ny = c.N[segment].second + c.distributed_beyond[segment].second;
    const std::size_t i = static_cast<std::size_t>(d);
    g.q.axial[i] += h * (Nx * tx + Ny * ty);
    g.weight[i] += h;
    std::size_t r = 0;
    if (mask.x) g.raw_rows[r++][i] += h * ty;  // int sin(theta) eta ds
    if (mask.y) g.raw_rows[r++][i] += h * tx;  // int cos(theta) eta ds
  };
  // Reissner's beam (docs/extensible.md, "Stability"): the second variation in (u, eta), u the
  // displacement, minimised over u' pointwise, leaves
  //     Q[eta] = int EI eta'^2 + (N_a + (N_a^2 - V^2) delta) eta^2 ds + c^T D^{-1} c,
  //     delta = 1/EA - 1/GAs,  N_a = N . t,  V = N . n  (t = (cos theta, sin theta)),
  // c = int (a t + b n) eta ds the tip's displacement, a = V delta, b = 1 + N_a delta, and
  // D = int (t t^T / EA + n n^T / GAs) ds the compliance of the held tip coordinates; delta = 0
  // (EA = GAs = infinity) is the elastica's Q with its rigid constraints int n eta ds = 0. Each
  // node of a flexible segment's element gets half the element's length of these (trapezoid, on
  // the sampled angle theta and the internal force N(s) there).
  auto lump_reissner = [&](int d,
                           double h,
                           std::size_t sample,
                           const FlexibleSegment& f,
                           std::size_t segment,
                           double segment_start) {
    const ShapePoint& p = shape[sample];
    const double s_local = p.s - segment_start;
    const std::array<double, 2> q_before = f.q_resultant(s_local);
    const std::array<double, 2> q_all = f.q_resultant(f.length);
    const double Nx =
        c.N[segment].first + c.distributed_beyond[segment].first + q_all[0] - q_before[0];
    const double Ny =
        c.N[segment].second + c.distributed_beyond[segment].second + q_all[1] - q_before[1];
    const double tx = std::cos(p.theta), ty = std::sin(p.theta);
    const double Na = Nx * tx + Ny * ty, V = -Nx * ty + Ny * tx;
    const double inv_EA = 1.0 / f.EA, inv_GAs = 1.0 / f.GAs;
    const double delta = inv_EA - inv_GAs;
    // The displacement per unit eta, a t + b n; the rows keep the elastica's sign (sin, cos).
    const double a = V * delta, b = 1.0 + Na * delta;
    const double gx = a * tx - b * ty, gy = a * ty + b * tx;
    std::size_t r = 0;
    const double dxx = h * (tx * tx * inv_EA + ty * ty * inv_GAs);
    const double dxy = h * tx * ty * (inv_EA - inv_GAs);
    const double dyy = h * (ty * ty * inv_EA + tx * tx * inv_GAs);
    if (mask.x && mask.y) {
      g.raw_compliance[0] += dxx;
      g.raw_compliance[1] += -dxy;  // the x row is -c_x
      g.raw_compliance[2] += dyy;
    } else if (mask.x) {
      g.raw_compliance[0] += dxx;
    } else if (mask.y) {
      g.raw_compliance[0] += dyy;
    }
    if (d < 0) return;
    const std::size_t i = static_cast<std::size_t>(d);
    g.q.axial[i] += h * (Na + (Na * Na - V * V) * delta);
    g.weight[i] += h;
    if (mask.x) g.raw_rows[r++][i] -= h * gx;
    if (mask.y) g.raw_rows[r++][i] += h * gy;
  };
  auto chord = [&](std::size_t a, std::size_t b, double h, std::size_t segment) {
    const double dx = shape[b].x - shape[a].x, dy = shape[b].y - shape[a].y;
    const double length = std::hypot(dx, dy);
    // A sanity check, not a precision one: a chain algorithm element without foreshortening ends
    // a little beyond its arc length.
    if (length > h * 1.05 + 1e-12 * c.total || !(length > 1e-6 * h)) {
      throw InvalidInput(fmt::format(
          "the shape is not one of this chain: the samples at s = {:.9g} and {:.9g} (segment {}) "
          "are {:.9g} apart, for an arc length of {:.9g}",
          shape[a].s,
          shape[b].s,
          segment + 1,
          length,
          h));
    }
    return std::pair<double, double>{dx / length, dy / length};
  };
  double start = 0.0;
  for (std::size_t j = 0; j < chain.segments.size(); ++j) {
    const double length = segment_length(chain.segments[j]);
    if (length > 0.0) {
      if (const auto* f = std::get_if<FlexibleSegment>(&chain.segments[j])) {
        const std::size_t step = static_cast<std::size_t>(stride);
        for (std::size_t a = c.first[j]; a < c.last[j]; a += step) {
          const std::size_t b = std::min(a + step, c.last[j]);
          const double h = shape[b].s - shape[a].s;
          const double EI = EI_integral(*f, shape[a].s - start, shape[b].s - start);
          const double k = EI / (h * h);  // int EI eta'^2 with eta' = (eta_b - eta_a) / h
          const int near = dof;
          add_dof();
          const std::size_t far = static_cast<std::size_t>(dof);
          g.q.bending_diag[far] += k;
          g.flexibility[far] += 1.0 / k;
          if (near >= 0) {
            g.q.bending_diag[static_cast<std::size_t>(near)] += k;
            g.q.bending_off[static_cast<std::size_t>(near)] -= k;
          }
          if (c.reissner) {
            lump_reissner(near, 0.5 * h, a, *f, j, start);
            lump_reissner(dof, 0.5 * h, b, *f, j, start);
          } else {
            const auto [tx, ty] = chord(a, b, h, j);
            lump(near, 0.5 * h, tx, ty, j);
            lump(dof, 0.5 * h, tx, ty, j);
          }
        }
      } else {
        // A rigid link: eta constant along it, the axial term and constraints exact.
        const auto [tx, ty] = chord(c.first[j], c.last[j], length, j);
        lump(dof, length, tx, ty, j);
      }
    }
    start += length;
  }
  if (mask.theta && dof >= 0) {
    // eta(L) = 0: the last dof (the tip, or the node where the trailing rigid links start).
    g.q.bending_diag.pop_back();
    if (!g.q.bending_off.empty()) g.q.bending_off.pop_back();
    g.q.axial.pop_back();
    g.weight.pop_back();
    g.flexibility.pop_back();
    for (std::vector<double>& row : g.raw_rows) row.pop_back();
  }
  for (std::size_t i = 0; i < g.q.axial.size(); ++i) {
    g.q.compression_bound += std::max(0.0, -g.q.axial[i]) * g.flexibility[i];
  }
  return g;
}

}  // namespace

void StabilityOptions::validate() const {
  if (!(critical_tolerance >= 0.0) || !std::isfinite(critical_tolerance)) {
    throw InvalidInput(fmt::format(
        "stability critical_tolerance must be a finite number >= 0 (got {})", critical_tolerance));
  }
  if (!(eigenvalue_tolerance >= 1e-16 && eigenvalue_tolerance <= 1e-3)) {
    throw InvalidInput(fmt::format(
        "stability eigenvalue_tolerance must be in [1e-16, 1e-3] (got {})", eigenvalue_tolerance));
  }
  if (min_elements < 1) {
    throw InvalidInput(
        fmt::format("stability min_elements must be at least 1 (got {})", min_elements));
  }
  if (!(element_resolution > 0.0) || !std::isfinite(element_resolution)) {
    throw InvalidInput(fmt::format(
        "stability element_resolution must be a finite number > 0 (got {})", element_resolution));
  }
  if (!(margin_accuracy > 0.0) || !std::isfinite(margin_accuracy)) {
    throw InvalidInput(fmt::format("stability margin_accuracy must be a finite number > 0 (got {})",
                                   margin_accuracy));
  }
  if (max_elements < min_elements) {
    throw InvalidInput(
        fmt::format("stability max_elements must be at least min_elements = {} (got {})",
                    min_elements,
                    max_elements));
  }
}

Reaction tip_support_reaction(const SegmentChain& chain, const Reaction& total_tip_load) {
  const PrescribedMask mask = prescribed_mask(chain.end);
  return Reaction{mask.x ? total_tip_load.Fx : 0.0,
                  mask.y ? total_tip_load.Fy : 0.0,
                  mask.theta ? total_tip_load.M : 0.0};
}

Reaction tip_support_reaction_from_root(const SegmentChain& chain, const Reaction& root_reaction) {
  // N(0) = -R_clamp; across node k the internal force drops by the node's load.
  double Nx = -root_reaction.Fx, Ny = -root_reaction.Fy;
  for (const NodeLoad& load : chain.node_loads) {
    Nx -= load.Fx;
    Ny -= load.Fy;
  }
  const PrescribedMask mask = prescribed_mask(chain.end);
  return Reaction{mask.x ? Nx : 0.0, mask.y ? Ny : 0.0, 0.0};
}

namespace {

std::vector<double> stations_held(const SegmentChain& chain,
                                  const Reaction& support_reaction,
                                  const StabilityOptions& options,
                                  const Held& held) {
  options.validate();
  chain.validate();
  check_support_reaction(chain, support_reaction, held);
  const std::size_t n = chain.segments.size();
  auto N = segment_forces(chain, support_reaction);
  // Distributed loads: |N| on a segment is at most the node loads' and tip's plus every
  // distributed load beyond its near end.
  const auto beyond = distributed_beyond(chain);
  for (std::size_t j = 0; j < n; ++j) {
    double qx = beyond[j].first, qy = beyond[j].second, extra = 0.0;
    if (const auto* f = std::get_if<FlexibleSegment>(&chain.segments[j])) {
      const std::array<double, 2> q = f->q_resultant(f->length);
      extra = std::hypot(q[0], q[1]);
      if (!f->q_profile.empty()) {
        extra = 0.0;  // a varying profile: the sum of |q| over its stations' intervals
        for (std::size_t i = 0; i < f->q_profile.size(); ++i) {
          extra += std::hypot(f->q_profile[i][0], f->q_profile[i][1]) * f->length /
                   std::max<std::size_t>(1, f->q_profile.size() - 1);
        }
      }
    }
    N[j].first = std::hypot(N[j].first, N[j].second) + std::hypot(qx, qy) + extra;
    N[j].second = 0.0;
  }
  // A bound on |m| over every segment, from the tip towards the root: across a segment |m| grows
  // by at most |N| times its length (|m'| = |t x N| <= |N|); on a uniform straight segment
  // also m^2 / (2 EI) + N . t is constant, so m^2 <= m_far^2 + 4 EI |N| (often far smaller).
  std::vector<double> m_bound(n);
  double m_far = std::fabs(chain.tip_load.M) + std::fabs(support_reaction.M);
  for (std::size_t j = n; j-- > 0;) {
    const double force = std::hypot(N[j].first, N[j].second);
    const double length = segment_length(chain.segments[j]);
    double m_near = m_far + force * length;
    if (const auto* f = std::get_if<FlexibleSegment>(&chain.segments[j])) {
      if (f->EI_profile.empty() && f->kappa0 == 0.0 && !f->beyond_elastica()) {
        m_near = std::min(m_near, std::sqrt(m_far * m_far + 4.0 * f->EI * force));
      }
    }
    m_bound[j] = std::max(m_far, m_near);
    m_far = m_near;
    for (const NodeLoad& load : chain.node_loads) {
      if (static_cast<std::size_t>(load.node) == j) m_far += std::fabs(load.M);
    }
  }
  std::vector<double> s{0.0};
  double start = 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    const double length = segment_length(chain.segments[j]);
    if (const auto* f = std::get_if<FlexibleSegment>(&chain.segments[j])) {
      double EI_min = f->EI;
      int profile_intervals = 1;
      if (f->EI_profile.size() >= 2) {
        EI_min = *std::min_element(f->EI_profile.begin(), f->EI_profile.end());
        profile_intervals = static_cast<int>(f->EI_profile.size()) - 1;
      }
      const double force = std::hypot(N[j].first, N[j].second);
      const double q = std::sqrt(force / EI_min) + m_bound[j] / EI_min + std::fabs(f->kappa0);
      // A multiple of 4 (three grids) and of the profile's intervals (its kinks on nodes).
      const int unit = 4 * profile_intervals;
      const double wanted = std::clamp(std::ceil(length * q / options.element_resolution),
                                       static_cast<double>(options.min_elements),
                                       static_cast<double>(options.max_elements));
      int elements = static_cast<int>(std::ceil(wanted / unit)) * unit;
      if (elements > options.max_elements) elements = std::max(4, options.max_elements / 4 * 4);
      for (int i = 1; i < elements; ++i) s.push_back(start + length * i / elements);
    }
    start += length;
    if (length > 0.0) s.push_back(start);
  }
  return s;
}

}  // namespace

std::vector<double> stability_stations(const SegmentChain& chain,
                                       const Reaction& support_reaction,
                                       const StabilityOptions& options) {
  return stations_held(chain, support_reaction, options, std::nullopt);
}

namespace {

// The grids of a shape (fine first, then every 2nd and every 4th sample) and their extrapolated
// eigenvalues.
struct Grids {
  std::vector<Grid> levels;
  double tolerance = 1e-12;

  // The k-th eigenvalue, extrapolated over the grids (second_variation.h,
  // extrapolated_eigenvalue).
  double eigenvalue(int k, double* error = nullptr, double* fine_value = nullptr) const {
    std::vector<const DiscreteSecondVariation*> q;
    q.reserve(levels.size());
    for (const auto& level : levels) q.push_back(&level.q);
    return extrapolated_eigenvalue(q, k, tolerance, error, fine_value);
  }
};

Grids make_grids(const SegmentChain& chain,
                 const Reaction& support_reaction,
                 const std::vector<ShapePoint>& shape,
                 double eigenvalue_tolerance,
                 const Held& held = std::nullopt) {
  const SampledChain sampled = sample_chain(chain, support_reaction, shape, held);
  Grids grids;
  grids.tolerance = eigenvalue_tolerance;
  for (int level = 0; level < sampled.levels; ++level) {
    grids.levels.push_back(assemble(sampled, 1 << level));
  }
  const Grid& fine = grids.levels.front();
  const std::array<double, 3>& D = fine.raw_compliance;
  if (D[0] == 0.0 && D[1] == 0.0 && D[2] == 0.0) {
    const auto combinations =
        independent_row_combinations(fine.raw_rows, fine.weight, sampled.total);
    for (Grid& grid : grids.levels) grid.q.constraints = combine_rows(grid.raw_rows, combinations);
    return grids;
  }
  // Compliant constraints (an extensible or shear-flexible chain): the rows along D's principal
  // directions. A direction with compliance keeps its row even where the row vanishes (S + D /
  // sigma is positive there, second_variation.h); one without (D's null direction: a beam rigid
  // along it) is a rigid constraint, dropped where its row vanishes like the elastica's.
  std::vector<std::array<double, 2>> combinations;
  std::vector<double> compliance;
  if (fine.raw_rows.size() == 1) {
    combinations.push_back({1.0, 0.0});
  } else {
    const double mean = 0.5 * (D[0] + D[2]);
    const double radius = std::hypot(0.5 * (D[0] - D[2]), D[1]);
    const double largest = mean + radius;
    for (const double d : {mean + radius, mean - radius}) {
      double vx = D[1], vy = d - D[0];
      if (std::hypot(d - D[2], D[1]) > std::hypot(vx, vy)) {
        vx = d - D[2];
        vy = D[1];
      }
      const double norm = std::hypot(vx, vy);
      if (!(norm > 0.0)) {  // D diagonal with this eigenvalue on the axis not yet taken
        vx = combinations.empty() ? (D[0] >= D[2] ? 1.0 : 0.0) : -combinations[0][1];
        vy = combinations.empty() ? (D[0] >= D[2] ? 0.0 : 1.0) : combinations[0][0];
      } else {
        vx /= norm;
        vy /= norm;
      }
      if (d <= 1e-12 * largest) {
        // Rigid along this direction: kept where its row constrains (rms above 1e-10).
        const auto rigid = independent_row_combinations(
            combine_rows(fine.raw_rows, {{vx, vy}}), fine.weight, sampled.total);
        if (rigid.empty()) continue;
      }
      combinations.push_back({vx, vy});
    }
  }
  for (Grid& grid : grids.levels) {
    grid.q.constraints = combine_rows(grid.raw_rows, combinations);
    // D' = K D K^T over the kept combinations K.
    const std::array<double, 3>& Dg = grid.raw_compliance;
    auto quad = [&](const std::array<double, 2>& u, const std::array<double, 2>& v) {
      return u[0] * (Dg[0] * v[0] + Dg[1] * v[1]) + u[1] * (Dg[1] * v[0] + Dg[2] * v[1]);
    };
    grid.q.compliance = {0.0, 0.0, 0.0};
    if (!combinations.empty()) grid.q.compliance[0] = quad(combinations[0], combinations[0]);
    if (combinations.size() > 1) {
      grid.q.compliance[1] = quad(combinations[0], combinations[1]);
      grid.q.compliance[2] = quad(combinations[1], combinations[1]);
    }
  }
  return grids;
}

// Refuses what the energy cannot judge (for the functions that return numbers only).
void require_conservative_and_flexible(const SegmentChain& chain) {
  if (chain.tip_load.follower != 0.0) {
    throw InvalidInput(
        "a follower tip force is not conservative: the second variation of a "
        "potential energy does not describe it");
  }
  if (chain.has_follower_pressure()) {
    throw InvalidInput(
        "a follower pressure is not conservative: the second variation of a potential energy "
        "does not describe it");
  }
  if (!has_flexible_segment(chain)) {
    throw InvalidInput("the chain has no flexible segment, so it has no second variation");
  }
}

}  // namespace

namespace {

struct Verdict {
  Stability stability;
  double margin_error = 0.0;  // estimated error of the margin
};

Verdict judge(const SegmentChain& chain,
              const Reaction& support_reaction,
              const std::vector<ShapePoint>& shape,
              const StabilityOptions& options,
              const Held& held = std::nullopt) {
  Verdict v;
  if (chain.tip_load.follower != 0.0) {
    v.stability = not_conservative_stability(
        fmt::format("a follower force of {:.6g} acts at the tip", chain.tip_load.follower));
    return v;
  }
  if (chain.has_follower_pressure()) {
    v.stability = not_conservative_stability(
        "a follower pressure acts on the beam (it has no potential energy)");
    return v;
  }
  if (!has_flexible_segment(chain)) {
    v.stability = not_checked_stability("the chain has no flexible segment, so it cannot deflect");
    return v;
  }
  const Grids grids =
      make_grids(chain, support_reaction, shape, options.eigenvalue_tolerance, held);
  const DiscreteSecondVariation& fine = grids.levels.front().q;
  const double threshold = -options.critical_tolerance;
  const int below = constrained_count(fine, threshold);
  double fine_lowest = 1.0;
  const double lowest = grids.eigenvalue(1, &v.margin_error, &fine_lowest);
  int index = below;
  if (grids.levels.size() > 1) {
    // The extrapolated count differs from the fine grid's only by eigenvalues that the
    // extrapolation moves across the threshold: those within the fine grid's error of it. With
    // none within `band` of it (far more than that error, about (h q)^2 / 12 <= 1e-3 on the
    // stations, or 10 times the lowest eigenvalue's correction) the fine count stands.
    const double band = std::max(0.05, 10.0 * std::fabs(fine_lowest - lowest));
    const bool near = below == 0 || constrained_count(fine, threshold - band) != below ||
                      constrained_count(fine, std::min(threshold + band, 0.5)) != below;
    if (near) {
      if (below >= 1 && (below == 1 ? lowest : grids.eigenvalue(below)) >= threshold) --index;
      if ((below == 0 ? lowest : grids.eigenvalue(below + 1)) < threshold) ++index;
    }
  }
  v.stability = classify_stability(index,
                                   lowest,
                                   options.critical_tolerance,
                                   chain.segments.size() == 1 ? "the beam" : "the chain");
  return v;
}

}  // namespace

Stability equilibrium_stability(const SegmentChain& chain,
                                const Reaction& support_reaction,
                                const std::vector<ShapePoint>& shape,
                                const StabilityOptions& options) {
  options.validate();
  chain.validate();
  check_support_reaction(chain, support_reaction);
  return judge(chain, support_reaction, shape, options).stability;
}

namespace {

Stability stability_from_shape_function(const SegmentChain& chain,
                                        const Reaction& support_reaction,
                                        const ShapeAtStations& shape_at,
                                        const StabilityOptions& options,
                                        const Held& held) {
  options.validate();
  chain.validate();
  check_support_reaction(chain, support_reaction, held);
  StabilityOptions o = options;
  for (;;) {
    const std::vector<double> s = stations_held(chain, support_reaction, o, held);
    const std::vector<ShapePoint> shape = shape_at(s);
    if (shape.size() != s.size()) {
      throw InvalidInput(fmt::format(
          "the shape function returned {} points for {} stations", shape.size(), s.size()));
    }
    const Verdict v = judge(chain, support_reaction, shape, o, held);
    const bool refinable = 2 * (s.size() - 1) <= static_cast<std::size_t>(o.max_elements);
    if (!v.stability.judged() || !refinable ||
        v.margin_error <= o.margin_accuracy * std::max(1.0, std::fabs(v.stability.margin))) {
      return v.stability;
    }
    // Twice the elements everywhere (the critical mode of a weakly compressed chain oscillates
    // faster than the loads' wavenumber says: sqrt(|N| / (EI (1 - margin)))).
    o.element_resolution *= 0.5;
    o.min_elements = std::min(2 * o.min_elements, o.max_elements);
  }
}

}  // namespace

Stability equilibrium_stability(const SegmentChain& chain,
                                const Reaction& support_reaction,
                                const ShapeAtStations& shape_at,
                                const StabilityOptions& options) {
  return stability_from_shape_function(chain, support_reaction, shape_at, options, std::nullopt);
}

Stability equilibrium_stability_held(const SegmentChain& chain,
                                     const Reaction& support_reaction,
                                     const ShapeAtStations& shape_at,
                                     const PrescribedMask& held,
                                     const StabilityOptions& options) {
  return stability_from_shape_function(chain, support_reaction, shape_at, options, held);
}

std::vector<double> second_variation_eigenvalues(const SegmentChain& chain,
                                                 const Reaction& support_reaction,
                                                 const std::vector<ShapePoint>& shape,
                                                 int count,
                                                 const StabilityOptions& options) {
  options.validate();
  chain.validate();
  check_support_reaction(chain, support_reaction);
  require_conservative_and_flexible(chain);
  if (count < 0) throw InvalidInput(fmt::format("eigenvalue count must be >= 0 (got {})", count));
  const Grids grids = make_grids(chain, support_reaction, shape, options.eigenvalue_tolerance);
  std::vector<double> values;
  for (int k = 1; k <= count; ++k) values.push_back(grids.eigenvalue(k));
  return values;
}

DiscreteSecondVariation discrete_second_variation(const SegmentChain& chain,
                                                  const Reaction& support_reaction,
                                                  const std::vector<ShapePoint>& shape,
                                                  int stride) {
  chain.validate();
  check_support_reaction(chain, support_reaction);
  require_conservative_and_flexible(chain);
  if (stride != 1 && stride != 2 && stride != 4) {
    throw InvalidInput(fmt::format("stride must be 1, 2 or 4 (got {})", stride));
  }
  const SampledChain sampled = sample_chain(chain, support_reaction, shape);
  if (stride > 1 && (1 << (sampled.levels - 1)) < stride) {
    throw InvalidInput(fmt::format(
        "stride {} needs equal elements in a number divisible by {} in every flexible segment",
        stride,
        stride));
  }
  Grid fine = assemble(sampled, 1);
  const auto combinations = independent_row_combinations(fine.raw_rows, fine.weight, sampled.total);
  Grid grid = stride == 1 ? std::move(fine) : assemble(sampled, stride);
  grid.q.constraints = combine_rows(grid.raw_rows, combinations);
  return grid.q;
}

StabilityVerdict equilibrium_stability(const SegmentChain& chain,
                                       const std::vector<ShapePoint>& shape) {
  StabilityVerdict verdict;
  if (chain.end != EndCondition::kFree || chain.tip_load.follower != 0.0) {
    verdict.message = "stability is checked for a free end with dead loads only";
    return verdict;
  }
  Stability s;
  try {
    s = equilibrium_stability(chain, Reaction{}, shape);
  } catch (const InvalidInput& e) {
    verdict.message = e.what();
    return verdict;
  }
  if (!s.judged()) {
    verdict.message = s.message;
    return verdict;
  }
  verdict.unstable_directions = s.index;
  verdict.kind = s.index == 0 ? StabilityVerdict::Kind::kStable : StabilityVerdict::Kind::kUnstable;
  verdict.message =
      s.index == 0 ? "stable: the second variation of the potential energy is positive definite"
                   : fmt::format(
                         "unstable: the second variation of the potential energy has {} negative "
                         "direction{} (a buckled state that the load path from zero does not reach "
                         "without passing a limit point)",
                         s.index,
                         s.index == 1 ? "" : "s");
  return verdict;
}

}  // namespace flexure
