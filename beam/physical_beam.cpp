#include "flexure/beam/physical_beam.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <tuple>
#include <variant>

#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

// The moment maximum is searched on at least this many shape points; at the spacing 1/2000 the
// parabola through the largest sample and its neighbours leaves an error of order h^3 |M'''|
// (docs/units.md).
constexpr int kDenseShapePoints = 2001;

// 2-D cross product a x b.
double cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

// How the solved shape maps to SI: positions r = shape * lever (the units of the reactions' lever
// arms), moments in those units times moment_to_si = N m.
struct Scaling {
  double length = 1.0;  // total arc length, m
  double lever = 1.0;
  double moment_to_si = 1.0;
  double force_to_si = 1.0;
  Reaction root;                        // the clamp's reaction on the chain, in the solver's units
  const SegmentChain* chain = nullptr;  // node and distributed loads (the solver's chain)
};

// A dead load at a joint, at arc length s (per unit length) and position r (lever units).
struct PointLoad {
  double s = 0.0, x = 0.0, y = 0.0;
  double Fx = 0.0, Fy = 0.0, M = 0.0;
};

// The shape's position at arc length s (per unit length), linearly interpolated.
std::pair<double, double> position_at(const std::vector<ShapePoint>& shape, double s) {
  const auto it = std::lower_bound(
      shape.begin(), shape.end(), s, [](const ShapePoint& p, double v) { return p.s < v; });
  if (it == shape.begin()) return {it->x, it->y};
  if (it == shape.end()) return {shape.back().x, shape.back().y};
  const ShapePoint& b = *it;
  const ShapePoint& a = *(it - 1);
  const double t = b.s > a.s ? (s - a.s) / (b.s - a.s) : 0.0;
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
}

std::vector<PointLoad> joint_loads(const Scaling& scale, const std::vector<ShapePoint>& shape) {
  std::vector<PointLoad> loads;
  if (scale.chain == nullptr) return loads;
  const SegmentChain& chain = *scale.chain;
  for (const NodeLoad& load : chain.node_loads) {
    double s = 0.0;  // joint k is the far end of segment k
    for (int k = 0; k < load.node; ++k) {
      s += std::visit([](const auto& segment) { return segment.length; }, chain.segments[k]);
    }
    s /= chain.total_length();
    const auto [x, y] = position_at(shape, s);
    loads.push_back({s, x * scale.lever, y * scale.lever, load.Fx, load.Fy, load.M});
  }
  return loads;
}

// The distributed loads' force on the shape interval [a, b] (positions in lever units, arc
// lengths per unit length): a dead load by the midpoint rule, a follower pressure p R90 (r_b - r_a)
// exactly for the chord (docs/distributed-loads.md).
std::pair<double, double> distributed_force(const Scaling& scale,
                                            const ShapePoint& a,
                                            const ShapePoint& b) {
  if (scale.chain == nullptr || !scale.chain->has_distributed_loads()) return {0.0, 0.0};
  const SegmentChain& chain = *scale.chain;
  const double total = chain.total_length();
  const double mid = 0.5 * (a.s + b.s) * total;
  double start = 0.0;
  for (const Segment& segment : chain.segments) {
    const double length = std::visit([](const auto& seg) { return seg.length; }, segment);
    if (mid <= start + length || &segment == &chain.segments.back()) {
      const auto* f = std::get_if<FlexibleSegment>(&segment);
      if (f == nullptr) return {0.0, 0.0};
      const std::array<double, 2> q = f->q_at(mid - start);
      const double du = (b.s - a.s) * total;
      const double dx = (b.x - a.x) * scale.lever, dy = (b.y - a.y) * scale.lever;
      return {q[0] * du - f->q_follower * dy, q[1] * du + f->q_follower * dx};
    }
    start += length;
  }
  return {0.0, 0.0};
}

struct InternalForces {
  std::vector<double> moment;  // N m
  std::vector<double> axial;   // N . t, N
  std::vector<double> shear;   // N . n, N (n = (-sin theta, cos theta))
};

// Bending moment at each shape point from the statics of the part between the clamp and the
// point: M(s) = -R_M + r(s) x R_F - sum over joint loads before s of [M_k + (r_k - r(s)) x F_k]
// - integral over [0, s] of (r(u) - r(s)) x q(u) du, with (R_F, R_M) the clamp's reaction; and
// the internal force N(s) = -R_F - (the loads on [0, s]). It holds for any end condition (the
// reaction carries the tip's) and needs no derivative of the shape. The distributed loads'
// integral runs over the shape's intervals (second order in their length; 1/2000 gives ~3e-7 of
// q L^2). Returned in N m and N.
InternalForces forces_along(const std::vector<ShapePoint>& shape, const Scaling& scale) {
  const std::vector<PointLoad> loads = joint_loads(scale, shape);
  InternalForces out;
  out.moment.reserve(shape.size());
  out.axial.reserve(shape.size());
  double Fx_acc = 0.0, Fy_acc = 0.0, M_acc = 0.0;  // distributed: sum dF, sum r_mid x dF
  for (std::size_t i = 0; i < shape.size(); ++i) {
    const ShapePoint& p = shape[i];
    if (i > 0 && p.s > shape[i - 1].s) {
      const auto [fx, fy] = distributed_force(scale, shape[i - 1], p);
      const double xm = 0.5 * (p.x + shape[i - 1].x) * scale.lever;
      const double ym = 0.5 * (p.y + shape[i - 1].y) * scale.lever;
      Fx_acc += fx;
      Fy_acc += fy;
      M_acc += cross(xm, ym, fx, fy);
    }
    const double x = p.x * scale.lever, y = p.y * scale.lever;
    double m = -scale.root.M + cross(x, y, scale.root.Fx, scale.root.Fy);
    double Nx = -scale.root.Fx - Fx_acc, Ny = -scale.root.Fy - Fy_acc;
    for (const PointLoad& load : loads) {
      if (load.s < p.s) {
        m -= load.M + cross(load.x - x, load.y - y, load.Fx, load.Fy);
        Nx -= load.Fx;
        Ny -= load.Fy;
      }
    }
    m -= M_acc - cross(x, y, Fx_acc, Fy_acc);
    out.moment.push_back(m * scale.moment_to_si);
    out.axial.push_back((Nx * std::cos(p.theta) + Ny * std::sin(p.theta)) * scale.force_to_si);
    out.shear.push_back((-Nx * std::sin(p.theta) + Ny * std::cos(p.theta)) * scale.force_to_si);
  }
  return out;
}

// Largest value of f sampled at s (ascending), refined by the parabola through the largest sample
// and its neighbours when they lie in one piece (same `piece`, e.g. one segment). Returns {value,
// s}.
std::pair<double, double> refined_max(const std::vector<double>& s,
                                      const std::vector<double>& f,
                                      const std::vector<int>& piece) {
  const auto top = std::max_element(f.begin(), f.end());
  const std::size_t i = static_cast<std::size_t>(top - f.begin());
  double value = f[i], at = s[i];
  if (i == 0 || i + 1 == f.size() || piece[i - 1] != piece[i] || piece[i + 1] != piece[i]) {
    return {value, at};
  }
  // Vertex of the parabola through (s0, f0), (s1, f1), (s2, f2).
  const double s0 = s[i - 1], s1 = s[i], s2 = s[i + 1];
  const double f0 = f[i - 1], f1 = f[i], f2 = f[i + 1];
  const double d01 = (f1 - f0) / (s1 - s0), d12 = (f2 - f1) / (s2 - s1);
  const double curvature = (d12 - d01) / (s2 - s0);  // half the second derivative
  if (!(curvature < 0.0)) return {value, at};
  const double vertex = 0.5 * (s0 + s1) - d01 / (2.0 * curvature);
  if (vertex < s0 || vertex > s2) return {value, at};
  const double refined = f1 + d01 * (vertex - s1) + curvature * (vertex - s0) * (vertex - s1);
  return refined > value ? std::pair{refined, vertex} : std::pair{value, at};
}

// Section modulus I / c of each segment (0 where no stress can be computed).
struct SectionSpan {
  double s0 = 0.0, s1 = 0.0;  // per unit length
  std::optional<double> section_modulus;
  bool flexible = true;
  // Extensible segments: the axial stress N/A joins the bending stress, N/EA is the strain.
  std::optional<double> area;  // m^2
  std::optional<double> EA;    // N
  // The section's area where known (any segment), for the fibre stresses N/A -+ m c/I.
  std::optional<double> fibre_area;
  // A tapered cantilever (one span over the whole beam): the section at each point is the
  // beam's there, b(s) h(s)^2/6 and b(s) h(s), instead of the constants above.
  const PhysicalCantilever* tapered = nullptr;

  // I/c and the area at arc length s (per unit length).
  std::optional<double> modulus_at(double s) const {
    if (tapered == nullptr || !section_modulus) return section_modulus;
    const double at = s * tapered->length;
    return tapered->second_moment_at(at) / (0.5 * tapered->thickness_at(at).value_or(0.0));
  }
  std::optional<double> area_at(double s) const {
    if (tapered == nullptr || !fibre_area) return fibre_area;
    const double at = s * tapered->length;
    return tapered->width_at(at).value_or(0.0) * tapered->thickness_at(at).value_or(0.0);
  }
};

PhysicalResults evaluate(const BeamSolution& solution,
                         const Scaling& scale,
                         const std::vector<SectionSpan>& spans,
                         std::optional<double> yield_strength,
                         int requested_points,
                         int dense_step) {
  PhysicalResults out;
  out.length = scale.length;
  out.tip_x = solution.tip.a_over_l * scale.length;
  out.tip_y = solution.tip.b_over_l * scale.length;
  out.theta0 = solution.tip.theta0;
  out.yield_strength = yield_strength;
  out.root_moment = -scale.root.M * scale.moment_to_si;
  // A stress needs the section of every flexible segment; rigid links are taken as stiff and
  // strong.
  const bool stresses = std::all_of(spans.begin(), spans.end(), [](const SectionSpan& span) {
    return !span.flexible || span.section_modulus.has_value();
  });
  const std::vector<ShapePoint>& shape = solution.shape;
  if (shape.empty()) {
    // The PRBM has no shape: its moment is largest at an end (linear in the position, extreme
    // at the ends unless the beam's tangent turns parallel to the force, which the PRBM cannot
    // see).
    out.max_from = "ends";
    const double tip_moment = out.root_moment - cross(solution.tip.a_over_l * scale.lever,
                                                      solution.tip.b_over_l * scale.lever,
                                                      -scale.root.Fx,
                                                      -scale.root.Fy) *
                                                    scale.moment_to_si;
    const bool root_larger = std::fabs(out.root_moment) >= std::fabs(tip_moment);
    out.max_moment = std::max(std::fabs(out.root_moment), std::fabs(tip_moment));
    out.max_moment_at = root_larger ? 0.0 : scale.length;
    if (stresses) {
      out.max_stress = out.max_moment / *spans.front().section_modulus;
      out.max_stress_at = out.max_moment_at;
    }
  } else {
    const InternalForces forces = forces_along(shape, scale);
    const std::vector<double>& moments = forces.moment;
    std::vector<double> s(shape.size()), magnitude(shape.size()), stress(shape.size(), 0.0);
    std::vector<int> piece(shape.size(), 0);
    for (std::size_t i = 0; i < shape.size(); ++i) {
      s[i] = shape[i].s;
      magnitude[i] = std::fabs(moments[i]);
      // A point on a joint belongs to both segments: the larger stress counts.
      for (std::size_t k = 0; k < spans.size(); ++k) {
        const double eps = 1e-12;
        if (shape[i].s < spans[k].s0 - eps || shape[i].s > spans[k].s1 + eps) continue;
        if (spans[k].EA) {
          const double strain = std::fabs(forces.axial[i]) / *spans[k].EA;
          out.max_axial_strain = std::max(out.max_axial_strain.value_or(0.0), strain);
        }
        if (spans[k].section_modulus) {
          double sigma = magnitude[i] / *spans[k].modulus_at(shape[i].s);
          if (spans[k].EA && spans[k].area) sigma += std::fabs(forces.axial[i]) / *spans[k].area;
          if (sigma >= stress[i]) {
            stress[i] = sigma;
            piece[i] = static_cast<int>(k);
          }
        } else if (stress[i] == 0.0) {
          piece[i] = static_cast<int>(k);
        }
      }
    }
    for (double N : forces.axial) out.max_axial_force = std::max(out.max_axial_force, std::fabs(N));
    std::vector<int> one_piece(shape.size(), 0);  // the moment is smooth across joints
    const auto [m, m_at] = refined_max(s, magnitude, one_piece);
    out.max_moment = m;
    out.max_moment_at = m_at * scale.length;
    if (stresses) {
      const auto [sigma, sigma_at] = refined_max(s, stress, piece);
      out.max_stress = sigma;
      out.max_stress_at = sigma_at * scale.length;
    }
    const std::size_t stride = static_cast<std::size_t>(dense_step);
    for (std::size_t i = 0; requested_points >= 2 && i < shape.size(); i += stride) {
      PhysicalShapePoint p;
      p.s = shape[i].s * scale.length;
      p.x = shape[i].x * scale.length;
      p.y = shape[i].y * scale.length;
      p.theta = shape[i].theta;
      p.moment = moments[i];
      p.axial_force = forces.axial[i];
      p.shear_force = forces.shear[i];
      if (stresses) p.stress = stress[i];
      // Fibre stresses where the span holding the point has its area and section modulus.
      for (const SectionSpan& span : spans) {
        if (shape[i].s < span.s0 - 1e-12 || shape[i].s > span.s1 + 1e-12) continue;
        if (!span.flexible || !span.section_modulus || !span.fibre_area) break;
        const double axial = forces.axial[i] / *span.area_at(shape[i].s);
        const double bending = moments[i] / *span.modulus_at(shape[i].s);
        p.stress_pos_fibre = axial - bending;
        p.stress_neg_fibre = axial + bending;
        break;
      }
      out.shape.push_back(p);
    }
  }
  if (out.max_stress && *out.max_stress > 0.0 && yield_strength) {
    out.safety_factor = *yield_strength / *out.max_stress;
  }
  return out;
}

// Shape points to solve for: a superset of the `requested` points (every `step`-th), at least
// kDenseShapePoints of them.
std::pair<int, int> dense_shape(int requested) {
  if (requested < 2) return {kDenseShapePoints, 1};
  const int step = std::max(1, (kDenseShapePoints - 1 + requested - 2) / (requested - 1));
  return {(requested - 1) * step + 1, step};
}

// Keeps the requested points of the dense shape in the nondimensional solution.
void thin_shape(BeamSolution& solution, int requested, int step) {
  if (requested < 2) {
    solution.shape.clear();
    return;
  }
  std::vector<ShapePoint> kept;
  for (std::size_t i = 0; i < solution.shape.size(); i += static_cast<std::size_t>(step)) {
    kept.push_back(solution.shape[i]);
  }
  solution.shape = std::move(kept);
}

void require_positive(double value, const char* what) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw InvalidInput(fmt::format("{} must be a finite number > 0 (got {:g})", what, value));
  }
}

// The checks validate() makes before the section's, shared with set_section() so that a front
// end's messages come in one order.
void validate_length_and_modulus(const PhysicalCantilever& beam) {
  require_positive(beam.length, "--length (beam length, m)");
  require_positive(beam.material.E, "--E (Young's modulus, Pa)");
}

void require_nu_in_range(double nu) {
  if (!(nu > -1.0 && nu < 0.5)) {
    throw InvalidInput(fmt::format("--nu must be in (-1, 0.5) (got {:g})", nu));
  }
}

}  // namespace

void PhysicalCantilever::set_section(std::optional<double> I,
                                     std::optional<double> width,
                                     std::optional<double> thickness) {
  validate_length_and_modulus(*this);
  if (I.has_value() == (width.has_value() || thickness.has_value())) {
    throw InvalidInput(
        "the section is either --I (area moment of inertia, m^4) or --width and --thickness "
        "(rectangle, I = b h^3/12): give exactly one of them");
  }
  section = Section{};
  if (I) {
    section.shape = Section::Shape::kGeneral;
    section.I = *I;
    return;
  }
  if (!width || !thickness) {
    throw InvalidInput("a rectangular section needs both --width and --thickness");
  }
  // Unchecked here: validate() names a bad width or thickness by its flag.
  section.shape = Section::Shape::kRectangle;
  section.width = *width;
  section.thickness = *thickness;
}

void PhysicalCantilever::validate() const {
  validate_length_and_modulus(*this);
  if (rectangle()) {
    require_positive(section.width, "--width (section width, m)");
    require_positive(section.thickness,
                     "--thickness (section thickness in the plane of bending, m)");
  } else {
    require_positive(section.I, "--I (area moment of inertia, m^4)");
    // A general section's thickness is 0 where unknown; given, it is checked as a rectangle's.
    if (section.thickness != 0.0) {
      require_positive(section.thickness,
                       "--thickness (section thickness in the plane of bending, m)");
    }
  }
  // What no flag gives: an I on a rectangle (Section::I), a width on a general section.
  section.validate();
  require_finite(Fx, "--Fx (tip force along the undeformed beam, N)");
  require_finite(Fy, "--Fy (tip force perpendicular to the undeformed beam, N)");
  require_finite(M, "--M (tip moment, N m)");
  if (material.yield_strength) {
    require_positive(*material.yield_strength, "--yield-strength (Pa)");
    if (!section.section_modulus()) {
      throw InvalidInput(
          "--yield-strength needs the stress, and the stress M c/I needs the thickness: give the "
          "section as --width and --thickness instead of --I");
    }
  }
  require_finite(qx, "--qx (distributed load along the beam, N/m)");
  require_finite(qy, "--qy (distributed load across the beam, N/m)");
  require_finite(q_follower, "--pressure (follower pressure, N/m)");
  if ((material.density || extensible) && !area()) {
    throw InvalidInput(
        "--density and --extensible need the section's area: give the section as --width and "
        "--thickness");
  }
  if (material.density) require_positive(*material.density, "--density (kg/m^3)");
  if (!(std::isfinite(g) && g >= 0.0)) {
    throw InvalidInput(fmt::format("--g must be a finite number >= 0 (got {:g})", g));
  }
  if (extensible) {
    if (!nu_given) throw InvalidInput("--extensible needs Poisson's ratio --nu");
    require_nu_in_range(material.nu);
    if (!(shear_coefficient > 0.0 && shear_coefficient <= 1.0)) {
      throw InvalidInput(
          fmt::format("--shear-coefficient must be in (0, 1] (got {:g})", shear_coefficient));
    }
  } else if (nu_given && !plate_given) {
    throw InvalidInput("--nu is used with --extensible or --plate on/auto only");
  }
  if (plate != PlateRule::kOff) {
    if (!nu_given) {
      throw InvalidInput(fmt::format(
          "--plate {} needs Poisson's ratio --nu (or a --material whose row gives nu): the "
          "plate modulus is E/(1 - nu^2)",
          to_string(plate)));
    }
    require_nu_in_range(material.nu);
    if (plate == PlateRule::kAuto && !rectangle()) {
      throw InvalidInput(
          "--plate auto needs the strip's width and thickness (the Searle parameter b^2/(R h)): "
          "give the section as --width and --thickness, or choose --plate on or off");
    }
  }
  // Given with --plate off, nu is unused but still a Poisson's ratio.
  if (nu_given) require_nu_in_range(material.nu);
  if (!nu_given && material.nu != Material{}.nu) {
    throw InvalidInput(fmt::format(
        "Material::nu = {:g} is set but not given (nu_given is false, so it would be ignored): "
        "give Poisson's ratio by PhysicalCantilever::set_nu",
        material.nu));
  }
  require_finite(curvature, "--curvature (stress-free curvature, 1/m)");
  if (tapered()) {
    if (!rectangle()) {
      throw InvalidInput(
          "a taper (--width-tip, --thickness-tip) varies the rectangle: give the section as "
          "--width and --thickness");
    }
    if (width_tip) require_positive(*width_tip, "--width-tip (section width at the tip, m)");
    if (thickness_tip) {
      require_positive(*thickness_tip, "--thickness-tip (section thickness at the tip, m)");
    }
    if (extensible) {
      throw InvalidInput(
          "--extensible with a taper: the extensible segment has one axial and shear rigidity "
          "(EA, GAs), a taper varies them; give a chain file of several segments instead");
    }
    if (plate == PlateRule::kAuto) {
      throw InvalidInput(
          "--plate auto with a taper: the Searle parameter b^2/(R h) varies along the strip; "
          "choose --plate on or off");
    }
  }
  for (const auto& [value, what] : {std::pair{prescribed.x, "--tip-x (m)"},
                                    std::pair{prescribed.y, "--tip-y (m)"},
                                    std::pair{prescribed.theta, "--tip-angle (rad)"}}) {
    if (value) require_finite(*value, what);
  }
  // The rest of the Material (its E, S_y, density and a given nu are checked above).
  material.validate();
  const double EI = flexural_rigidity();
  if (!(std::isfinite(EI) && EI > 0.0)) {
    throw InvalidInput(
        fmt::format("the flexural rigidity E I = {:g} N m^2 is not a positive "
                    "finite number; check --E and the section",
                    EI));
  }
}

std::optional<double> PhysicalCantilever::width_at(double s) const {
  if (!rectangle()) return std::nullopt;
  const double t = std::clamp(s / length, 0.0, 1.0);
  return width_tip ? section.width + t * (*width_tip - section.width) : section.width;
}

std::optional<double> PhysicalCantilever::thickness_at(double s) const {
  if (section.thickness == 0.0) return std::nullopt;  // a general section without h
  const double t = std::clamp(s / length, 0.0, 1.0);
  return thickness_tip ? section.thickness + t * (*thickness_tip - section.thickness)
                       : section.thickness;
}

double PhysicalCantilever::second_moment_at(double s) const {
  if (!rectangle() || !tapered()) return second_moment();
  return Section{Section::Shape::kRectangle, *width_at(s), *thickness_at(s)}.second_moment();
}

double PhysicalCantilever::bending_modulus() const {
  const bool applied = plate == PlateRule::kOn || (plate == PlateRule::kAuto && plate_applied);
  return applied && nu_given ? material.E / (1.0 - material.nu * material.nu) : material.E;
}

double PhysicalCantilever::second_moment() const { return section.second_moment(); }

BeamProblem PhysicalCantilever::to_problem(BeamProblem problem) const {
  validate();
  const double EI = flexural_rigidity();
  const double force_scale = length * length / EI;  // F l^2/EI (Howell eq. 2.83)
  const double alpha2 = Fy * force_scale;
  const double mu = M * length / EI;
  problem.given = BeamProblem::Given::kAlpha2;
  problem.value = alpha2;
  problem.mu = mu;
  problem.chain.reset();
  problem.boundary = EndCondition::kFree;
  if (beyond_elastica() || shaped() || end != EndCondition::kFree) {
    // Distributed loads, extension, a curvature, a taper or a prescribed tip: the one-segment
    // chain (l = 1, EI = 1 at the clamp) carries them.
    problem.chain = to_chain();
    problem.boundary = end;
    return problem;
  }
  for (const auto& [value, name] : {std::pair{alpha2, "alpha2 = Fy L^2/EI"},
                                    std::pair{Fx * force_scale, "Fx L^2/EI"},
                                    std::pair{mu, "mu = M L/EI"}}) {
    if (!std::isfinite(value)) {
      throw InvalidInput(
          fmt::format("the nondimensional load {} overflows; check the units", name));
    }
  }
  problem.load_ratio_n = 0.0;
  if (Fy != 0.0 || Fx == 0.0) {
    problem.load_ratio_n = Fy != 0.0 ? -Fx / Fy + 0.0 : 0.0;  // n > 0 compressive (eq. 2.67)
  } else {
    // Axial load only: no Howell's n; the same beam as a chain (l = 1, EI = 1).
    problem.chain = uniform_cantilever(EndLoad{Fx * force_scale, 0.0, mu});
  }
  return problem;
}

SegmentChain PhysicalCantilever::to_chain(EndCondition end,
                                          const TipPrescription& prescribed_m) const {
  validate();
  const double EI = flexural_rigidity();
  const double force_scale = length * length / EI;  // F l^2/EI (Howell eq. 2.83)
  SegmentChain chain =
      uniform_cantilever(EndLoad{Fx * force_scale, Fy * force_scale, M * length / EI});
  // Distributed loads q L^3/EI, rigidities EA L^2/EI (docs/distributed-loads.md, extensible.md).
  auto& segment = std::get<FlexibleSegment>(chain.segments[0]);
  segment.qx = qx * force_scale * length;
  segment.qy = total_qy() * force_scale * length;
  segment.q_follower = q_follower * force_scale * length;
  segment.kappa0 = curvature * length;  // kappa0 L
  if (tapered()) {
    // EI(s)/EI(0) at equally spaced stations, interpolated linearly by the solvers; the
    // self-weight rho b(s) h(s) g with it.
    const int n = kTaperStations;
    const double root_I = second_moment_at(0.0);
    for (int k = 0; k < n; ++k) {
      const double at = length * k / (n - 1);
      segment.EI_profile.push_back(second_moment_at(at) / root_I);
      if (material.density) {
        const double weight = *material.density * *width_at(at) * *thickness_at(at) * g;
        segment.q_profile.push_back(
            {qx * force_scale * length, (qy - weight) * force_scale * length});
      }
    }
  }
  if (extensible) {
    const double A = area().value_or(0.0);
    // (Not material.shear_modulus() times k: k E/(2 (1 + nu)) keeps the product's order.)
    segment.EA = material.E * A * force_scale;
    segment.GAs = shear_coefficient * material.E / (2.0 * (1.0 + material.nu)) * A * force_scale;
  }
  for (const auto& [value, name] : {std::pair{chain.tip_load.Fx, "Fx L^2/EI"},
                                    std::pair{chain.tip_load.Fy, "Fy L^2/EI"},
                                    std::pair{chain.tip_load.M, "M L/EI"}}) {
    if (!std::isfinite(value)) {
      throw InvalidInput(
          fmt::format("the nondimensional load {} overflows; check the units", name));
    }
  }
  chain.end = end;
  const PrescribedMask mask = prescribed_mask(end);
  for (const auto& [prescribed, load, flag, coordinate] :
       {std::tuple{mask.x, Fx, "--Fx", "x"},
        std::tuple{mask.y, Fy, "--Fy", "y"},
        std::tuple{mask.theta, M, "--M", "angle"}}) {
    if (prescribed && load != 0.0) {
      throw InvalidInput(fmt::format(
          "a {} end prescribes the tip {}, so {} must be 0 (got {:g}): the support supplies it "
          "as a reaction",
          to_string(end),
          coordinate,
          flag,
          load));
    }
  }
  for (const auto& [value, what] : {std::pair{prescribed_m.x, "--tip-x (m)"},
                                    std::pair{prescribed_m.y, "--tip-y (m)"},
                                    std::pair{prescribed_m.theta, "--tip-angle (rad)"}}) {
    if (value) require_finite(*value, what);
  }
  if (prescribed_m.x) chain.prescribed.x = *prescribed_m.x / length;
  if (prescribed_m.y) chain.prescribed.y = *prescribed_m.y / length;
  chain.prescribed.theta = prescribed_m.theta;
  chain.validate();
  return chain;
}

namespace {

// One solve of the cantilever with its bending modulus as it stands (plate_applied decided).
PhysicalBeamSolution solve_cantilever(BeamMethod method,
                                      const PhysicalCantilever& beam,
                                      BeamProblem problem) {
  problem = beam.to_problem(problem);
  const int shape_points = problem.shape_points;
  if (problem.chain && beam.beyond_elastica() &&
      (method == BeamMethod::kElliptic || method == BeamMethod::kPrbm)) {
    throw InvalidInput(fmt::format(
        "a distributed load, self-weight or an extensible beam is solved by the shooting method "
        "(auto chooses it; the chain method takes dead loads), not by the {} method",
        to_string(method)));
  }
  if (problem.chain && (beam.shaped() || beam.end != EndCondition::kFree) &&
      (method == BeamMethod::kElliptic || method == BeamMethod::kPrbm)) {
    throw InvalidInput(fmt::format(
        "a curved or tapered beam, or one with a prescribed tip (--boundary {}), is solved by the "
        "shooting or chain method (auto chooses shooting), not by the {} method",
        to_string(beam.end),
        to_string(method)));
  }
  if (problem.chain && (method == BeamMethod::kElliptic || method == BeamMethod::kPrbm)) {
    throw InvalidInput(fmt::format(
        "a tip load along the beam only (Fy = 0, Fx = {:g} N) has no Howell's load ratio n; the "
        "{} method needs Fy != 0 (the shooting and chain methods solve it; auto chooses shooting)",
        beam.Fx,
        to_string(method)));
  }
  const auto [dense, step] = dense_shape(shape_points);
  // The PRBM has no shape; the others are sampled densely for the moment maximum.
  problem.shape_points = method == BeamMethod::kPrbm ? shape_points : dense;
  PhysicalBeamSolution out;
  out.solution = solve_beam(method, problem);
  if (!out.solution.converged()) return out;
  if (out.solution.method == BeamMethod::kPrbm) {
    out.solution.shape.clear();
  }
  Scaling scale;
  scale.length = beam.length;
  scale.moment_to_si = beam.flexural_rigidity() / beam.length;                 // M = mu EI / L
  scale.force_to_si = beam.flexural_rigidity() / (beam.length * beam.length);  // F L^2/EI
  // A chain problem's reactions are the chain's (its distributed loads enter the statics).
  scale.root = problem.chain ? out.solution.chain_reactions : out.solution.reactions;
  if (problem.chain) scale.chain = &*problem.chain;
  SectionSpan span;
  span.s0 = 0.0;
  span.s1 = 1.0;
  span.section_modulus = beam.section.section_modulus();  // I/c, c = h/2
  span.fibre_area = beam.area();
  if (beam.tapered()) span.tapered = &beam;
  if (beam.extensible) {
    span.area = beam.area();
    span.EA = beam.material.E * beam.area().value_or(0.0);
  }
  out.physical =
      evaluate(out.solution, scale, {span}, beam.material.yield_strength, shape_points, step);
  if (out.solution.method != BeamMethod::kPrbm) thin_shape(out.solution, shape_points, step);
  return out;
}

}  // namespace

ShapeInternalForces shape_internal_forces(const SegmentChain& chain,
                                          const std::vector<ShapePoint>& shape,
                                          const Reaction& root) {
  // forces_along takes arc lengths per unit length and positions in lever units.
  const double total = chain.total_length();
  std::vector<ShapePoint> unit = shape;
  for (ShapePoint& p : unit) p.s /= total;
  Scaling scale;
  scale.length = total;
  scale.root = root;
  scale.chain = &chain;
  InternalForces f = forces_along(unit, scale);
  return {std::move(f.moment), std::move(f.axial), std::move(f.shear)};
}

void PhysicalCantilever::fibre_sections(int points,
                                        std::vector<double>& modulus,
                                        std::vector<double>& area) const {
  modulus.clear();
  area.clear();
  if (!rectangle() || points < 2) return;
  for (int k = 0; k < points; ++k) {
    const double at = length * k / (points - 1);
    modulus.push_back(second_moment_at(at) / (0.5 * *thickness_at(at)));
    area.push_back(*width_at(at) * *thickness_at(at));
  }
}

PhysicalBeamSolution solve_physical_beam(BeamMethod method,
                                         const PhysicalCantilever& given,
                                         BeamProblem problem) {
  given.validate();
  PhysicalCantilever beam = given;
  beam.plate_applied = false;
  if (beam.plate != PlateRule::kAuto) {
    PhysicalBeamSolution out = solve_cantilever(method, beam, problem);
    out.physical.modulus = {choose_modulus(beam.plate,
                                           beam.material.E,
                                           beam.given_nu(),
                                           beam.width_at(0.0),
                                           beam.thickness_at(0.0),
                                           {},
                                           "the beam")};
    return out;
  }
  // auto: the Searle parameter at the largest curvature |M|/EI of the beam solved with E decides
  // (docs/plate-modulus.md); a plate is then solved again with E/(1 - nu^2).
  PhysicalBeamSolution first = solve_cantilever(method, beam, problem);
  if (!first.solution.converged()) return first;
  const double curvature = first.physical.max_moment / beam.flexural_rigidity();
  const ModulusChoice choice = choose_modulus(PlateRule::kAuto,
                                              beam.material.E,
                                              beam.given_nu(),
                                              beam.width_at(0.0),
                                              beam.thickness_at(0.0),
                                              curvature,
                                              "the beam");
  if (!choice.plate) {
    first.physical.modulus = {choice};
    return first;
  }
  beam.plate_applied = true;
  PhysicalBeamSolution out = solve_cantilever(method, beam, problem);
  out.physical.modulus = {choice};
  return out;
}

std::optional<double> SegmentProperties::cross_section_area() const {
  if (area) return area;
  return section.area();
}

double SegmentProperties::chain_modulus() const {
  return plate == PlateRule::kOn ? material.E / (1.0 - material.nu * material.nu) : material.E;
}

void PhysicalChain::validate() const {
  if (segments.size() != chain.segments.size()) {
    throw InvalidInput(fmt::format(
        "PhysicalChain::segments has {} entries for a chain of {} segments; give one per segment "
        "(nullopt where a segment has no section)",
        segments.size(),
        chain.segments.size()));
  }
  std::optional<double> yield;
  for (std::size_t k = 0; k < segments.size(); ++k) {
    if (!segments[k]) continue;
    const SegmentProperties& p = *segments[k];
    const auto* flexible = std::get_if<FlexibleSegment>(&chain.segments[k]);
    if (flexible == nullptr) {
      throw InvalidInput(fmt::format(
          "PhysicalChain segment {} is a rigid link; only a flexible segment takes a section and "
          "a material",
          k + 1));
    }
    try {
      p.section.validate();
      p.material.validate();
    } catch (const InvalidInput& e) {
      throw InvalidInput(fmt::format("PhysicalChain segment {}: {}", k + 1, e.what()));
    }
    if (p.area && !(std::isfinite(*p.area) && *p.area > 0.0)) {
      throw InvalidInput(fmt::format(
          "PhysicalChain segment {}: SegmentProperties::area = {} must be finite and > 0",
          k + 1,
          *p.area));
    }
    if (!flexible->EI_profile.empty()) {
      throw InvalidInput(fmt::format(
          "PhysicalChain segment {} gives an EI_profile and a section; give one", k + 1));
    }
    // EI of the segment is E I of its section, or E I/(1 - nu^2) with plate on (the reader
    // computes it so; a chain built from objects must agree, or its stresses would belong to
    // another beam). With plate auto it is E I: the plate modulus is decided when solving.
    const double EI = p.chain_modulus() * p.section.second_moment();
    if (!(std::fabs(flexible->EI - EI) <= 1e-12 * EI)) {
      throw InvalidInput(fmt::format(
          "PhysicalChain segment {}: EI = {:g} N m^2 is not {} = {:g} N m^2 of its section and "
          "material",
          k + 1,
          flexible->EI,
          p.plate == PlateRule::kOn ? "E I/(1 - nu^2) (plate on)" : "E I",
          EI));
    }
    if (p.plate == PlateRule::kAuto && p.section.shape != Section::Shape::kRectangle) {
      throw InvalidInput(fmt::format(
          "PhysicalChain segment {}: plate auto needs a rectangle section (the Searle parameter "
          "b^2/(R h) needs the width and thickness); choose plate on or off",
          k + 1));
    }
    if (p.material.yield_strength) {
      if (yield && *yield != *p.material.yield_strength) {
        throw InvalidInput(fmt::format(
            "PhysicalChain segment {}: yield strength {:g} Pa differs from another segment's {:g} "
            "Pa; one yield strength per chain (the safety factor is S_y over the largest stress)",
            k + 1,
            *p.material.yield_strength,
            *yield));
      }
      yield = p.material.yield_strength;
    }
  }
  if (yield && yield_strength && *yield != *yield_strength) {
    throw InvalidInput(
        fmt::format("PhysicalChain::yield_strength = {:g} Pa differs from the segments' {:g} Pa",
                    *yield_strength,
                    *yield));
  }
  if (yield_strength && !(std::isfinite(*yield_strength) && *yield_strength > 0.0)) {
    throw InvalidInput(fmt::format("PhysicalChain::yield_strength = {:g} Pa must be finite and > 0",
                                   *yield_strength));
  }
}

std::optional<double> PhysicalChain::effective_yield_strength() const {
  for (const std::optional<SegmentProperties>& p : segments) {
    if (p && p->material.yield_strength) return p->material.yield_strength;
  }
  return yield_strength;
}

namespace {

PhysicalBeamSolution solve_chain_once(BeamMethod method,
                                      BeamProblem problem,
                                      const PhysicalChain& physical_chain) {
  const SegmentChain& chain = physical_chain.chain;
  problem.chain = chain;
  problem.boundary = chain.end;
  const int requested = problem.shape_points;
  const auto [dense, step] = dense_shape(requested);
  problem.shape_points = dense;
  PhysicalBeamSolution out;
  out.solution = solve_beam(method, problem);
  if (!out.solution.converged()) return out;
  Scaling scale;
  scale.length = chain.total_length();
  scale.lever = scale.length;  // the chain's loads are in N and N m, its lengths in m
  scale.moment_to_si = 1.0;
  scale.root = out.solution.chain_reactions;
  scale.chain = &chain;
  std::vector<SectionSpan> spans;
  double s = 0.0;
  for (std::size_t k = 0; k < chain.segments.size(); ++k) {
    SectionSpan span;
    const double length =
        std::visit([](const auto& segment) { return segment.length; }, chain.segments[k]);
    span.s0 = s / scale.length;
    s += length;
    span.s1 = s / scale.length;
    span.flexible = std::holds_alternative<FlexibleSegment>(chain.segments[k]);
    const std::optional<SegmentProperties>& properties = physical_chain.segments[k];
    if (properties && properties->section.thickness > 0.0) {
      // I / c with c = h/2 (the section's own second moment: b h^3/12 or the given I).
      span.section_modulus =
          properties->section.second_moment() / (0.5 * properties->section.thickness);
    }
    if (properties) span.fibre_area = properties->cross_section_area();
    if (const auto* f = std::get_if<FlexibleSegment>(&chain.segments[k]); f && f->extensible()) {
      span.EA = f->EA;
      if (properties) span.area = properties->cross_section_area();
    }
    spans.push_back(span);
  }
  out.physical = evaluate(
      out.solution, scale, spans, physical_chain.effective_yield_strength(), requested, step);
  // The largest |m| of each segment, for plate = "auto" (on the dense shape, before thinning).
  if (std::any_of(physical_chain.segments.begin(),
                  physical_chain.segments.end(),
                  [](const auto& properties) {
                    return properties && properties->plate == PlateRule::kAuto;
                  })) {
    const InternalForces forces = forces_along(out.solution.shape, scale);
    out.segment_max_moment.assign(spans.size(), 0.0);
    for (std::size_t i = 0; i < out.solution.shape.size(); ++i) {
      for (std::size_t k = 0; k < spans.size(); ++k) {
        const double s_i = out.solution.shape[i].s;
        if (s_i < spans[k].s0 - 1e-12 || s_i > spans[k].s1 + 1e-12) continue;
        out.segment_max_moment[k] =
            std::max(out.segment_max_moment[k], std::fabs(forces.moment[i]));
      }
    }
  }
  thin_shape(out.solution, requested, step);
  return out;
}

}  // namespace

PhysicalBeamSolution solve_physical_chain(BeamMethod method,
                                          BeamProblem problem,
                                          const PhysicalChain& physical_chain) {
  physical_chain.validate();
  PhysicalBeamSolution out = solve_chain_once(method, problem, physical_chain);
  if (!out.solution.converged()) return out;
  // The modulus of each flexible segment with a section: on and off as given (the chain's EI
  // already holds on's E I/(1 - nu^2)); auto by the Searle parameter at the segment's largest
  // curvature |m|/EI of this solve (docs/plate-modulus.md), and the chain solved again where a
  // segment turns out a plate.
  std::vector<ModulusChoice> choices;
  PhysicalChain plated = physical_chain;
  bool again = false;
  for (std::size_t k = 0; k < physical_chain.segments.size(); ++k) {
    const std::optional<SegmentProperties>& properties = physical_chain.segments[k];
    if (!properties) continue;
    const std::string where = fmt::format("segment {}", k + 1);
    const Material& material = properties->material;
    if (properties->plate != PlateRule::kAuto) {
      // Material::nu always holds a value (0.3 by default): reported where the rule uses it.
      const std::optional<double> nu =
          properties->plate == PlateRule::kOff ? std::nullopt : std::optional<double>(material.nu);
      choices.push_back(choose_modulus(properties->plate, material.E, nu, {}, {}, {}, where));
      continue;
    }
    auto& segment = std::get<FlexibleSegment>(plated.chain.segments[k]);
    const double curvature = out.segment_max_moment[k] / segment.EI;
    const ModulusChoice choice = choose_modulus(PlateRule::kAuto,
                                                material.E,
                                                material.nu,
                                                properties->section.width,
                                                properties->section.thickness,
                                                curvature,
                                                where);
    if (choice.plate) {
      segment.EI = choice.effective_E * properties->section.second_moment();
      again = true;
    }
    choices.push_back(choice);
  }
  // The re-solve skips validate(): an auto segment's EI is now E I/(1 - nu^2) by decision.
  if (again) out = solve_chain_once(method, problem, plated);
  out.physical.modulus = std::move(choices);
  return out;
}

}  // namespace flexure
