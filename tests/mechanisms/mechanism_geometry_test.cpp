// The buildable geometry (mechanisms/mechanism.h) against values computed here by other
// routes: the slider-crank's end-of-stroke pose from the law of cosines (not the library's
// asin/loop-closure form, cfm/slider_crank.h), the overall length from the exact model's physical
// chain (mechanism_exact.h, built separately from Table 8.1), the l segments from gamma = 0.85
// (Howell §5.2), and the parts laid end to end without gaps or overlaps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_exact.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {
namespace {

double dist(GeometryPoint a, GeometryPoint b) { return std::hypot(a.x - b.x, a.y - b.y); }

// Every built-in design, thesis, Howell's and the modified configurations (not the inversions,
// which are the same geometry read the other way).
std::vector<MechanismDesign> designs() {
  std::vector<MechanismDesign> out;
  for (const auto& d : builtin_mechanisms()) {
    if (!d.inverted) out.push_back(d);
  }
  return out;
}

// Pivot 2 at the end of the stroke from the triangle (pivot 1, pivot 2, pivot 3) with sides r2,
// r3 and x3 = r2 + r3 - stroke: cos theta2 = (r2^2 + x3^2 - r3^2) / (2 r2 x3), pivot 2 above the
// axis (the mechanism's branch, theta2 >= 0).
GeometryPoint pivot2_by_cosines(double r2, double r3, double stroke) {
  const double x3 = r2 + r3 - stroke;
  const double c = (r2 * r2 + x3 * x3 - r3 * r3) / (2.0 * r2 * x3);
  return {r2 * c, r2 * std::sqrt(std::max(0.0, 1.0 - c * c))};
}

void expect_pose(const MechanismDesign& d, const MechanismGeometry& g) {
  const double scale = d.r2 + d.r3;
  const GeometryPoint p2 = pivot2_by_cosines(d.r2, d.r3, d.stroke);
  EXPECT_NEAR(g.pivots[1].stroke_end.x, p2.x, 1e-9 * scale) << d.name;
  EXPECT_NEAR(g.pivots[1].stroke_end.y, p2.y, 1e-9 * scale) << d.name;
  EXPECT_NEAR(g.pivots[2].stroke_end.x, scale - d.stroke, 1e-12 * scale) << d.name;
  EXPECT_NEAR(g.pivots[2].stroke_end.y, 0.0, 1e-12 * scale) << d.name;
  // Rigid bodies keep their lengths; the flexures' two pseudo-rigid pieces keep theirs.
  for (const auto& l : g.links) {
    EXPECT_NEAR(dist(l.stroke_end_start, l.stroke_end_end), l.length, 1e-12 * scale) << d.name;
  }
  for (const auto& f : g.flexures) {
    const double pieces =
        dist(f.stroke_end[0], f.stroke_end[1]) + dist(f.stroke_end[1], f.stroke_end[2]);
    EXPECT_NEAR(pieces, f.length, 1e-12 * scale) << d.name << " flexure " << f.pivot;
  }
}

TEST(MechanismGeometry, EndOfStrokeMatchesTheLawOfCosinesForEveryBuiltinDesign) {
  for (const MechanismDesign& d : designs()) expect_pose(d, mechanism_geometry(d));
}

// Seeded random strokes over the whole valid range of each design.
TEST(MechanismGeometry, RandomStrokesMatchTheLawOfCosines) {
  std::mt19937 rng(32);
  std::uniform_real_distribution<double> u(0.01, 1.0);
  for (MechanismDesign d : designs()) {
    for (int k = 0; k < 5; ++k) {
      d.stroke = u(rng) * d.toggle_stroke();
      expect_pose(d, mechanism_geometry(d));
    }
  }
}

TEST(MechanismGeometry, PartsLieEndToEndAtRestAndSpanTheExactModelsChain) {
  for (const MechanismDesign& d : designs()) {
    const MechanismGeometry g = mechanism_geometry(d);
    const double scale = d.r2 + d.r3;
    struct Span {
      double a, b;
    };
    std::vector<Span> spans;
    for (const auto& f : g.flexures) {
      EXPECT_NEAR(f.rest_end.x - f.rest_start.x, f.length, 1e-12 * scale) << d.name;
      EXPECT_EQ(f.length, d.joints[f.pivot - 1].length);
      EXPECT_EQ(f.thickness, d.joints[f.pivot - 1].thickness);
      EXPECT_EQ(f.width, d.joints[f.pivot - 1].width);
      spans.push_back({f.rest_start.x, f.rest_end.x});
    }
    for (const auto& l : g.links) spans.push_back({l.rest_start.x, l.rest_end.x});
    std::sort(spans.begin(), spans.end(), [](Span p, Span q) { return p.a < q.a; });
    ASSERT_FALSE(spans.empty());
    EXPECT_NEAR(spans.front().a, g.ground_attach_x, 1e-12 * scale) << d.name;
    EXPECT_NEAR(spans.back().b, g.slider_attach_x_rest, 1e-12 * scale) << d.name;
    for (std::size_t i = 1; i < spans.size(); ++i) {
      EXPECT_NEAR(spans[i].a, spans[i - 1].b, 1e-12 * scale) << d.name << " part " << i;
    }
    // The exact model builds its physical chain from Table 8.1 on its own; its undeflected slider
    // position, measured from its root (the ground clamp or pin), is the overall length.
    if (exact_support(d) != ExactSupport::kPrbmOnly) {
      EXPECT_NEAR(g.overall_length(), physical_chain(d).slider_x0, 1e-12 * scale) << d.name;
    }
  }
}

TEST(MechanismGeometry, LongSegmentsAreRoverGammaWithTheirPivotAtGammaL) {
  int seen = 0;
  for (const MechanismDesign& d : designs()) {
    const MechanismGeometry g = mechanism_geometry(d);
    for (const auto& f : g.flexures) {
      if (f.kind != FlexureKind::kLong) continue;
      ++seen;
      const double r = f.pivot == 1 ? d.r2 : d.configuration().middle_long_on_r2 ? d.r2 : d.r3;
      EXPECT_NEAR(0.85 * f.length, r, 1e-9 * r) << d.name;  // Howell's average gamma
      // The characteristic pivot 0.15 l from the clamp end.
      const GeometryPoint pivot = g.pivots[f.pivot - 1].rest;
      const bool clamp_first = !(f.pivot == 2 && d.configuration().middle_long_on_r2);
      const double from_clamp = clamp_first ? pivot.x - f.rest_start.x : f.rest_end.x - pivot.x;
      EXPECT_NEAR(from_clamp, 0.15 * f.length, 1e-9 * r) << d.name;
    }
  }
  EXPECT_GT(seen, 3);
}

TEST(MechanismGeometry, RefusesAStrokePastTheToggle) {
  MechanismDesign d = find_builtin_mechanism("3A-sss");
  d.stroke = 1.01 * d.toggle_stroke();
  EXPECT_THROW(mechanism_geometry(d), InvalidInput);
}

}  // namespace
}  // namespace flexure::mechanism
