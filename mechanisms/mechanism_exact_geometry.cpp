#include "flexure/mechanisms/mechanism_exact_geometry.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <variant>

#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/solver/common/status.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure::mechanism {
namespace {

// One chain of the solved point placed in the drawing frame: drawing point = origin + L R(q),
// where q is the chain's nondimensional point and R turns by pi when `reversed` (the middle-pin
// coupler chain, rooted at the slider clamp with +x towards the ground).
struct PlacedChain {
  const SegmentChain& chain;
  const std::vector<double>& unknowns;
  const std::vector<int>& pivots;  // pivots[j]: the pivot of segment j (0: rigid)
  GeometryPoint origin;            // the chain's root in the drawing frame, m
  double rest_origin_x = 0.0;      // ... and at rest (on the x axis), m
  bool reversed = false;
};

// One computed segment: its pivot (0: rigid), its rest x at its root and tip ends (drawing frame,
// m) and its deformed points from root to tip.
struct PlacedSegment {
  int pivot = 0;
  double rest_root = 0.0, rest_tip = 0.0;
  std::vector<GeometryPoint> points;
};

double segment_length(const Segment& seg) {
  return std::holds_alternative<FlexibleSegment>(seg) ? std::get<FlexibleSegment>(seg).length
                                                      : std::get<RigidSegment>(seg).length;
}

std::vector<PlacedSegment> place(const PlacedChain& c, double L, int samples) {
  // The arc lengths: each flexible segment's ends and `samples` points between (ends included),
  // each rigid piece's two ends; shared ends once.
  const double total = c.chain.total_length();
  std::vector<double> s;
  std::vector<std::pair<std::size_t, std::size_t>> range;  // per segment: first index, count
  double s0 = 0.0;
  const auto add = [&](double v) {
    v = std::min(v, total);
    if (s.empty() || v > s.back()) s.push_back(v);
    return s.size() - 1;
  };
  for (const Segment& seg : c.chain.segments) {
    const double len = segment_length(seg);
    const bool flexible = std::holds_alternative<FlexibleSegment>(seg);
    const int n = flexible ? samples : 2;
    const std::size_t first = add(s0);
    for (int k = 1; k < n; ++k) add(k == n - 1 ? s0 + len : s0 + len * k / (n - 1));
    range.emplace_back(first, s.size() - first);
    s0 += len;
  }
  ShootingSolver::Options o = ExactMechanismSolver::Options{}.shooting;
  const ShootingResult r = ShootingSolver(o).solve_from(c.chain, c.unknowns);
  if (!r.converged()) {
    throw NoConvergence("re-solving an exact stroke point for its shapes failed: " + r.message);
  }
  const std::vector<ShapePoint> shape = shooting_shape_at(c.chain, r, s, o);
  const double sign = c.reversed ? -1.0 : 1.0;
  std::vector<PlacedSegment> out;
  s0 = 0.0;
  for (std::size_t j = 0; j < c.chain.segments.size(); ++j) {
    const double len = segment_length(c.chain.segments[j]);
    PlacedSegment p;
    p.pivot = j < c.pivots.size() ? c.pivots[j] : 0;
    p.rest_root = c.rest_origin_x + sign * s0 * L;
    p.rest_tip = c.rest_origin_x + sign * (s0 + len) * L;
    for (std::size_t i = range[j].first; i < range[j].first + range[j].second; ++i) {
      p.points.push_back({c.origin.x + sign * shape[i].x * L, c.origin.y + sign * shape[i].y * L});
    }
    if (len > 0.0) out.push_back(std::move(p));
    s0 += len;
  }
  return out;
}

// Fills the exact fields of `g` from the converged exact point `end`, at any Delta x (the
// slider placed at its rest position minus end.displacement).
void fill_exact(MechanismGeometry& g,
                const MechanismDesign& design,
                const ExactPoint& end,
                int samples) {
  if (samples < 2) throw InvalidInput(fmt::format("samples must be >= 2 (got {})", samples));
  if (!end.converged()) {
    throw InvalidInput("the exact shapes of a stroke point need a converged exact point");
  }
  const PhysicalChain pc = physical_chain(design);
  const ExactSupport support = exact_support(design);
  const double L = end.length_scale;
  // The slider joint at the end of the stroke (the slider clamp of an s pivot 3, or pin 3).
  const double slider_rest = g.ground_attach_x + pc.slider_x0;
  const GeometryPoint slider{slider_rest - end.displacement, 0.0};
  std::vector<PlacedSegment> segments = place({end.chain,
                                               end.unknowns,
                                               pc.flexible_pivot,
                                               {g.ground_attach_x, 0.0},
                                               g.ground_attach_x,
                                               false},
                                              L,
                                              samples);
  if (support == ExactSupport::kPinnedMiddle) {
    // From the slider clamp back to pivot 2, drawn from the ground side: reversed.
    for (PlacedSegment& p : place({end.coupler_chain,
                                   end.coupler_unknowns,
                                   pc.coupler_flexible_pivot,
                                   slider,
                                   slider_rest,
                                   true},
                                  L,
                                  samples)) {
      std::swap(p.rest_root, p.rest_tip);
      std::reverse(p.points.begin(), p.points.end());
      segments.push_back(std::move(p));
    }
  }
  if (support == ExactSupport::kTwoForceCoupler) {
    // The rigid coupler between two pins: from the crank's tip (pivot 2) to the slider pin.
    const PlacedSegment& crank_tip = segments.back();
    segments.push_back({0, crank_tip.rest_tip, slider_rest, {crank_tip.points.back(), slider}});
  }
  const double tol = 1e-9 * (design.r2 + design.r3);
  for (FlexureGeometry& f : g.flexures) {
    f.stroke_end_exact.clear();
    for (const PlacedSegment& p : segments) {
      if (p.pivot != f.pivot) continue;
      const auto from = f.stroke_end_exact.empty() ? p.points.begin() : p.points.begin() + 1;
      f.stroke_end_exact.insert(f.stroke_end_exact.end(), from, p.points.end());
    }
    if (f.stroke_end_exact.empty()) {
      throw std::logic_error(fmt::format("exact shapes: no segment of flexure {}", f.pivot));
    }
  }
  for (RigidLinkGeometry& link : g.links) {
    bool found = false;
    for (const PlacedSegment& p : segments) {
      if (p.pivot != 0 || std::abs(p.rest_root - link.rest_start.x) > tol ||
          std::abs(p.rest_tip - link.rest_end.x) > tol) {
        continue;
      }
      link.exact_end_start = p.points.front();
      link.exact_end_end = p.points.back();
      found = true;
    }
    if (!found)
      throw std::logic_error(fmt::format("exact shapes: no segment of link {}", link.link));
  }
  // Pins: the segment end at the pin's rest position.
  for (PivotGeometry& pivot : g.pivots) {
    pivot.exact_end = pivot.stroke_end;
    if (pivot.type != PivotType::kPin) continue;
    for (const PlacedSegment& p : segments) {
      if (std::abs(p.rest_root - pivot.rest.x) <= tol) pivot.exact_end = p.points.front();
      if (std::abs(p.rest_tip - pivot.rest.x) <= tol) pivot.exact_end = p.points.back();
    }
  }
  g.exact_stroke_end = true;
}

}  // namespace

void add_exact_stroke_end(MechanismGeometry& g,
                          const MechanismDesign& design,
                          const ExactPoint& end,
                          int samples) {
  if (std::abs(end.displacement - design.stroke) > 1e-12 * (design.r2 + design.r3)) {
    throw InvalidInput(fmt::format("the exact point is at Delta x = {} m, not at the stroke {} m",
                                   end.displacement,
                                   design.stroke));
  }
  fill_exact(g, design, end, samples);
  g.exact_model = fmt::format(
      "exact model (elastica, shooting): every flexure's bent centreline ({} points) and the "
      "links at Delta x = stroke, as mechanism analyze solves it (input force {:.6g} N, one half)",
      samples,
      end.force);
}

MechanismGeometry exact_geometry_at(const MechanismDesign& design,
                                    const ExactPoint& point,
                                    int samples) {
  MechanismGeometry g = mechanism_geometry(design);
  fill_exact(g, design, point, samples);
  g.exact_model = fmt::format(
      "exact model (elastica, shooting) at Delta x = {:.6g} m (input force {:.6g} N, one half)",
      point.displacement,
      point.force);
  return g;
}

std::string add_exact_stroke_end(MechanismGeometry& g,
                                 const MechanismDesign& design,
                                 int points,
                                 int samples) {
  if (exact_support(design) == ExactSupport::kPrbmOnly) return exact_support_reason(design);
  AnalysisOptions o;
  o.points = points;
  o.exact = true;
  o.exact_stress = false;
  o.stability = false;
  const MechanismAnalysis a = analyze_mechanism(design, o);
  if (!a.has_exact) return a.exact_note;
  if (!a.exact.converged() || a.exact.points.empty()) return a.exact.message;
  add_exact_stroke_end(g, design, a.exact.points.back(), samples);
  return "";
}

}  // namespace flexure::mechanism
