#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>

#include "flexure/elements/prbm_element.h"
#include "flexure/mechanisms/cfm/slider_crank.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/solver/common/enum_names.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {
namespace {

// The rigid bodies of the half mechanism; each moves rigidly between rest and stroke end.
enum class Body { kGround, kCrank, kCoupler, kSlider };

// (1 - gamma): the clamp of an l segment lies this fraction of its length behind its
// characteristic pivot (Howell §5.2, eq. 5.49 geometry; the exact model's physical chain).
double long_segment_pivot() { return howell_average_fixed_pinned().geometry().pivot_x; }

struct Placement {
  double theta2 = 0.0, theta3 = 0.0, dx = 0.0;
  double X2 = 0.0, X3 = 0.0;  // rest x of pivots 2 and 3
  GeometryPoint p2;           // pivot 2 at the end of the stroke

  // Image at the end of the stroke of the rest point (x, 0) of `body`.
  GeometryPoint map(Body body, double x) const {
    switch (body) {
      case Body::kGround:
        return {x, 0.0};
      case Body::kCrank:
        return {x * std::cos(theta2), x * std::sin(theta2)};
      case Body::kCoupler:
        return {p2.x + (x - X2) * std::cos(theta3), p2.y + (x - X2) * std::sin(theta3)};
      case Body::kSlider:
        return {x - dx, 0.0};
    }
    return {};
  }
};

}  // namespace

namespace {
constexpr std::array<const char*, 3> kFlexureKindNames = {"small", "long", "fixed-fixed"};
}  // namespace

const char* to_string(FlexureKind kind) { return enum_name(kFlexureKindNames, kind); }

FlexureKind flexure_kind_from_string(std::string_view name) {
  return enum_from_name<FlexureKind>(kFlexureKindNames, name, "flexure kind");
}

std::optional<FlexureKind> flexure_kind(const MechanismDesign& design, int pivot) {
  const JointDesign& j = design.joints[pivot - 1];
  if (j.type == PivotType::kPin) return std::nullopt;
  if (j.segment == SegmentKind::kFixedFixed) return FlexureKind::kFixedFixed;
  return j.type == PivotType::kLong ? FlexureKind::kLong : FlexureKind::kSmall;
}

MechanismGeometry mechanism_geometry(const MechanismDesign& d) {
  if (!(d.r2 > 0.0) || !(d.r3 > 0.0) || !std::isfinite(d.r2 + d.r3)) {
    throw InvalidInput(
        fmt::format("mechanism geometry: r2 and r3 must be > 0 (got {}, {})", d.r2, d.r3));
  }
  if (!(d.stroke > 0.0) || d.stroke > d.toggle_stroke()) {
    throw InvalidInput(fmt::format(
        "mechanism geometry: the stroke {} m must be > 0 and within the toggle stroke {} m",
        d.stroke,
        d.toggle_stroke()));
  }
  const auto& cfg = d.configuration();
  const auto& j = d.joints;
  MechanismGeometry g;
  g.name = d.name;
  g.config = d.config;
  g.r2 = d.r2;
  g.r3 = d.r3;
  g.stroke = d.stroke;
  g.inverted = d.inverted;
  g.deformed_model =
      "PRBM pseudo-rigid approximation: each flexure drawn as its two pseudo-rigid pieces meeting "
      "at its characteristic pivot (not the exact elastica shape); pivots placed by the PRBM "
      "slider-crank kinematics (Weight 2001 eqs. 2.1-2.3)";

  const double r_tot = d.r2 + d.r3;
  const auto pose = cfm::slider_crank_pose(d.R(), d.stroke / r_tot);
  Placement pl;
  pl.theta2 = pose.theta2;
  pl.theta3 = pose.theta3;
  pl.dx = d.stroke;
  pl.X2 = d.r2;
  pl.X3 = r_tot;
  pl.p2 = {d.r2 * std::cos(pose.theta2), d.r2 * std::sin(pose.theta2)};
  g.theta2_end = pose.theta2;
  g.theta3_end = pose.theta3;

  const std::array<double, 3> X{0.0, d.r2, r_tot};
  const std::array<GeometryPoint, 3> P_end{GeometryPoint{0.0, 0.0}, pl.p2, {r_tot - d.stroke, 0.0}};
  for (int p = 0; p < 3; ++p) g.pivots[p] = {p + 1, j[p].type, {X[p], 0.0}, P_end[p], {}};

  // Each flexure as (start x, start body, end x, end body) along the rest line.
  const double back = long_segment_pivot();
  auto add_flexure = [&](int pivot, double x0, Body b0, double x1, Body b1) {
    const JointDesign& jd = j[pivot - 1];
    FlexureGeometry f;
    f.pivot = pivot;
    f.kind = flexure_kind(d, pivot).value();  // called for flexures only, never a pin
    f.length = jd.length;
    f.width = jd.width;
    f.thickness = jd.thickness;
    f.rest_start = {x0, 0.0};
    f.rest_end = {x1, 0.0};
    f.stroke_end = {pl.map(b0, x0), P_end[pivot - 1], pl.map(b1, x1)};
    g.flexures.push_back(f);
  };
  // Rigid pieces of the crank (x from a to b) and the coupler.
  double crank_a = 0.0, crank_b = d.r2, coupler_a = d.r2, coupler_b = r_tot;
  bool crank_rigid = true, coupler_rigid = true;

  // Pivot 1 (ground).
  g.ground_attach_x = 0.0;
  if (j[0].type == PivotType::kSmall) {
    const double f = j[0].length;
    add_flexure(1, -0.5 * f, Body::kGround, 0.5 * f, Body::kCrank);
    crank_a = 0.5 * f;
    g.ground_attach_x = -0.5 * f;
  } else if (j[0].type == PivotType::kLong) {
    // Clamped into the ground (1 - gamma) l behind pivot 1, pinned at pivot 2: the whole crank.
    const double l = j[0].length;
    add_flexure(1, -back * l, Body::kGround, d.r2, Body::kCrank);
    crank_rigid = false;
    g.ground_attach_x = -back * l;
  }
  // Pivot 2 (middle).
  if (j[1].type == PivotType::kSmall) {
    const double f = j[1].length;
    add_flexure(2, d.r2 - 0.5 * f, Body::kCrank, d.r2 + 0.5 * f, Body::kCoupler);
    crank_b = d.r2 - 0.5 * f;
    coupler_a = d.r2 + 0.5 * f;
  } else if (j[1].type == PivotType::kLong) {
    const double l = j[1].length;
    if (cfg.middle_long_on_r2) {
      // plp: pinned at pivot 1, clamped into link 3 (1 - gamma) l beyond pivot 2: the whole crank.
      add_flexure(2, 0.0, Body::kCrank, d.r2 + back * l, Body::kCoupler);
      crank_rigid = false;
      coupler_a = d.r2 + back * l;
    } else {
      // slp: clamped to link 2 (1 - gamma) l before pivot 2, pinned at the slider: the coupler.
      add_flexure(2, d.r2 - back * l, Body::kCrank, r_tot, Body::kCoupler);
      crank_b = d.r2 - back * l;
      coupler_rigid = false;
    }
  }
  // Pivot 3 (slider).
  g.slider_attach_x_rest = r_tot;
  if (j[2].type == PivotType::kSmall) {
    const double f = j[2].length;
    add_flexure(3, r_tot - 0.5 * f, Body::kCoupler, r_tot + 0.5 * f, Body::kSlider);
    coupler_b = r_tot - 0.5 * f;
    g.slider_attach_x_rest = r_tot + 0.5 * f;
  } else if (j[2].type == PivotType::kLong) {
    throw InvalidInput(fmt::format(
        "mechanism geometry: configuration '{}' has a long segment at the slider, which no "
        "built-in configuration has",
        d.config));
  }
  g.slider_attach_x_end = g.slider_attach_x_rest - d.stroke;
  if (crank_rigid && crank_b > crank_a) {
    g.links.push_back({2,
                       crank_b - crank_a,
                       {crank_a, 0.0},
                       {crank_b, 0.0},
                       pl.map(Body::kCrank, crank_a),
                       pl.map(Body::kCrank, crank_b),
                       {},
                       {}});
  }
  if (coupler_rigid && coupler_b > coupler_a) {
    g.links.push_back({3,
                       coupler_b - coupler_a,
                       {coupler_a, 0.0},
                       {coupler_b, 0.0},
                       pl.map(Body::kCoupler, coupler_a),
                       pl.map(Body::kCoupler, coupler_b),
                       {},
                       {}});
  }
  return g;
}

}  // namespace flexure::mechanism
