#include "flexure/mechanisms/general/general_mechanism.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

#include "flexure/solver/common/status.h"

namespace flexure::mechanism::general {
namespace {

// A pin or weld whose points are farther apart than this fraction of the mechanism's size, or a
// slider point this far off its line, is a loop that cannot close in the described configuration.
// 1e-6 accepts coordinates written with seven significant digits; the assembled model then closes
// the loops exactly (general_prbm.cpp projects the described state onto the constraints).
constexpr double kClosureTolerance = 1e-6;

std::string fmt(double v) {
  std::ostringstream out;
  out.precision(6);
  out << v;
  return out.str();
}

std::string at(Vec2 p) { return "(" + fmt(p.x) + ", " + fmt(p.y) + ") m"; }

}  // namespace

std::string_view prbm_kind_name(PrbmKind kind) {
  switch (kind) {
    case PrbmKind::kSmallLengthPivot:
      return "small-length";
    case PrbmKind::kFixedPinned:
      return "fixed-pinned";
    case PrbmKind::kFixedGuided:
      return "fixed-guided";
  }
  return "?";
}

std::string_view flexure_model_name(FlexureModel model) {
  switch (model) {
    case FlexureModel::kPrbm:
      return "prbm";
    case FlexureModel::kExact:
      return "exact";
    case FlexureModel::kLinear:
      return "linear";
    case FlexureModel::kBcm:
      return "bcm";
    case FlexureModel::kPrbm3r:
      return "prbm3r";
    case FlexureModel::kCbcm:
      return "cbcm";
    case FlexureModel::kChain:
      return "chain";
    case FlexureModel::kAuto:
      return "auto";
  }
  return "?";
}

FlexureModel parse_flexure_model(std::string_view name) {
  for (FlexureModel m : {FlexureModel::kPrbm,
                         FlexureModel::kExact,
                         FlexureModel::kLinear,
                         FlexureModel::kBcm,
                         FlexureModel::kPrbm3r,
                         FlexureModel::kCbcm,
                         FlexureModel::kChain,
                         FlexureModel::kAuto}) {
    if (flexure_model_name(m) == name) {
      return m;
    }
  }
  throw InvalidInput("model '" + std::string(name) +
                     "' is not one of prbm, exact, linear, bcm, prbm3r, cbcm, chain, auto");
}

void set_flexure_model(GeneralMechanism& mechanism,
                       const std::string& flexure,
                       FlexureModel model,
                       double tolerance,
                       int elements) {
  bool found = false;
  std::string names;
  for (Flexure& f : mechanism.flexures) {
    names += (names.empty() ? "" : ", ") + f.name;
    if (!flexure.empty() && f.name != flexure) continue;
    found = true;
    if (tolerance != 0.0) f.tolerance = tolerance;
    // A count given for another model (a CBCM's 24 elements) is not this one's: a new model
    // without elements takes its own default (Flexure::model_elements).
    if (elements != 0) {
      f.elements = elements;
    } else if (f.model != model) {
      f.elements = 0;
    }
    f.model = model;
  }
  if (!found) {
    throw InvalidInput("no flexure named '" + flexure + "' in " + mechanism.name +
                       " (its flexures: " + (names.empty() ? std::string("none") : names) + ")");
  }
}

std::string_view joint_kind_name(JointKind kind) {
  switch (kind) {
    case JointKind::kPin:
      return "pin";
    case JointKind::kSlider:
      return "slider";
    case JointKind::kWeld:
      return "weld";
  }
  return "?";
}

std::string_view input_coordinate_name(InputCoordinate c) {
  switch (c) {
    case InputCoordinate::kX:
      return "x";
    case InputCoordinate::kY:
      return "y";
    case InputCoordinate::kAngle:
      return "angle";
  }
  return "?";
}

std::string_view input_control_name(InputControl c) {
  return c == InputControl::kDisplacement ? "displacement" : "force";
}

PointRef parse_point_ref(const std::string& text, const std::string& what) {
  const auto dot = text.find('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == text.size()) {
    throw InvalidInput(what + ": '" + text + "' is not a point reference \"body.point\"");
  }
  return {text.substr(0, dot), text.substr(dot + 1)};
}

GeneralMechanism& GeneralMechanism::body(const std::string& body_name,
                                         std::vector<NamedPoint> points) {
  bodies.push_back({body_name, std::move(points), 0});
  return *this;
}

GeneralMechanism& GeneralMechanism::pin(const std::string& joint_name,
                                        const std::string& a,
                                        const std::string& b) {
  const std::string what = "pin '" + joint_name + "'";
  joints.push_back(
      {joint_name, JointKind::kPin, parse_point_ref(a, what), parse_point_ref(b, what), 0.0, 0});
  return *this;
}

GeneralMechanism& GeneralMechanism::slider(const std::string& joint_name,
                                           const std::string& a,
                                           const std::string& b,
                                           double axis_angle) {
  const std::string what = "slider '" + joint_name + "'";
  joints.push_back({joint_name,
                    JointKind::kSlider,
                    parse_point_ref(a, what),
                    parse_point_ref(b, what),
                    axis_angle,
                    0});
  return *this;
}

GeneralMechanism& GeneralMechanism::weld(const std::string& joint_name,
                                         const std::string& a,
                                         const std::string& b) {
  const std::string what = "weld '" + joint_name + "'";
  joints.push_back(
      {joint_name, JointKind::kWeld, parse_point_ref(a, what), parse_point_ref(b, what), 0.0, 0});
  return *this;
}

GeneralMechanism& GeneralMechanism::flexure(const std::string& flexure_name,
                                            const std::string& a,
                                            const std::string& b,
                                            double width,
                                            double thickness,
                                            double E,
                                            PrbmKind prbm) {
  const std::string what = "flexure '" + flexure_name + "'";
  Flexure f;
  f.name = flexure_name;
  f.a = parse_point_ref(a, what);
  f.b = parse_point_ref(b, what);
  f.width = width;
  f.thickness = thickness;
  f.material.E = E;
  f.prbm = prbm;
  flexures.push_back(f);
  return *this;
}

GeneralMechanism& GeneralMechanism::linear_spring(const std::string& spring_name,
                                                  const std::string& a,
                                                  const std::string& b,
                                                  double stiffness) {
  const std::string what = "linear spring '" + spring_name + "'";
  linear_springs.push_back(
      {spring_name, parse_point_ref(a, what), parse_point_ref(b, what), stiffness, -1.0, 0});
  return *this;
}

GeneralMechanism& GeneralMechanism::torsion_spring(const std::string& spring_name,
                                                   const std::string& body_a,
                                                   const std::string& body_b,
                                                   double stiffness) {
  torsion_springs.push_back({spring_name, body_a, body_b, stiffness, 0.0, 0});
  return *this;
}

GeneralMechanism& GeneralMechanism::load(const std::string& load_name,
                                         const std::string& at_point,
                                         double fx,
                                         double fy,
                                         double moment) {
  loads.push_back(
      {load_name, parse_point_ref(at_point, "load '" + load_name + "'"), fx, fy, moment, 0});
  return *this;
}

GeneralMechanism& GeneralMechanism::input_coordinate(InputCoordinate coordinate,
                                                     const std::string& point_text,
                                                     const std::string& point_to,
                                                     InputControl control,
                                                     double start,
                                                     double stop,
                                                     int count) {
  const PointRef p = parse_point_ref(point_text, "input");
  input.body = p.body;
  input.point = p.point;
  input.point_to.clear();
  if (coordinate == InputCoordinate::kAngle) {
    const PointRef q = parse_point_ref(point_to, "input");
    if (q.body != p.body) {
      throw InvalidInput("input: the angle's line runs from " + p.text() + " to " + q.text() +
                         ", which are on different bodies; name two points of one body");
    }
    input.point_to = q.point;
  }
  input.coordinate = coordinate;
  input.control = control;
  input.start = start;
  input.stop = stop;
  input.count = count;
  has_input = true;
  return *this;
}

std::string GeneralMechanism::where(int line) const {
  if (source.empty()) {
    return "";
  }
  return line > 0 ? source + ":" + std::to_string(line) + ": " : source + ": ";
}

const Body* GeneralMechanism::find_body(const std::string& body_name) const {
  for (const Body& b : bodies) {
    if (b.name == body_name) {
      return &b;
    }
  }
  return nullptr;
}

Vec2 GeneralMechanism::point(const PointRef& ref) const {
  const Body* b = find_body(ref.body);
  if (b == nullptr) {
    throw InvalidInput("unknown body '" + ref.body + "' in " + ref.text());
  }
  for (const NamedPoint& p : b->points) {
    if (p.name == ref.point) {
      return p.position;
    }
  }
  throw InvalidInput("body '" + ref.body + "' has no point '" + ref.point + "'");
}

double GeneralMechanism::size() const {
  std::vector<Vec2> all;
  for (const Body& b : bodies) {
    for (const NamedPoint& p : b.points) {
      all.push_back(p.position);
    }
  }
  double d = 0.0;
  for (std::size_t i = 0; i < all.size(); ++i) {
    for (std::size_t j = i + 1; j < all.size(); ++j) {
      d = std::max(d, std::hypot(all[i].x - all[j].x, all[i].y - all[j].y));
    }
  }
  return d;
}

void GeneralMechanism::validate() const {
  // Bodies and their points.
  std::set<std::string> body_names;
  for (const Body& b : bodies) {
    const std::string item = where(b.line) + "body '" + b.name + "'";
    if (b.name.empty() || b.name.find('.') != std::string::npos) {
      throw InvalidInput(where(b.line) + "body name '" + b.name +
                         "' must be non-empty and contain no '.'");
    }
    if (!body_names.insert(b.name).second) {
      throw InvalidInput(item + ": a body of this name is already defined");
    }
    std::set<std::string> point_names;
    for (const NamedPoint& p : b.points) {
      if (p.name.empty() || !point_names.insert(p.name).second) {
        throw InvalidInput(item + ": point name '" + p.name + "' is empty or defined twice");
      }
      if (!std::isfinite(p.position.x) || !std::isfinite(p.position.y)) {
        throw InvalidInput(item + ": point '" + p.name + "' has a non-finite coordinate");
      }
    }
  }
  if (body_names.count("ground") == 0) {
    throw InvalidInput(where(0) +
                       "no body 'ground': the ground's points (pivots, clamps) "
                       "must be given as body 'ground'");
  }
  if (bodies.size() < 2) {
    throw InvalidInput(where(0) + "the mechanism has no moving body");
  }
  const double size = this->size();
  if (!(size > 0.0)) {
    throw InvalidInput(where(0) + "all points coincide: the mechanism has no size");
  }
  const double tolerance = kClosureTolerance * size;

  auto resolve = [&](const PointRef& ref, const std::string& item) {
    const Body* b = find_body(ref.body);
    if (b == nullptr) {
      throw InvalidInput(item + ": unknown body '" + ref.body + "' in " + ref.text());
    }
    for (const NamedPoint& p : b->points) {
      if (p.name == ref.point) {
        return p.position;
      }
    }
    throw InvalidInput(item + ": body '" + ref.body + "' has no point '" + ref.point + "'");
  };
  auto require_body = [&](const std::string& name, const std::string& item) {
    if (find_body(name) == nullptr) {
      throw InvalidInput(item + ": unknown body '" + name + "'");
    }
  };

  std::set<std::string> item_names;
  auto unique_item = [&](const std::string& name, const std::string& item) {
    if (name.empty()) {
      throw InvalidInput(item + ": the item has no name");
    }
    if (!item_names.insert(name).second) {
      throw InvalidInput(item + ": an item of this name is already defined");
    }
  };

  // Connectivity through joints and flexures (springs and loads do not hold a body in place).
  std::map<std::string, std::set<std::string>> links;
  for (const Joint& j : joints) {
    const std::string item =
        where(j.line) + std::string(joint_kind_name(j.kind)) + " '" + j.name + "'";
    unique_item(j.name, item);
    const Vec2 pa = resolve(j.a, item);
    const Vec2 pb = resolve(j.b, item);
    if (j.a.body == j.b.body) {
      throw InvalidInput(item + ": joins " + j.a.text() + " and " + j.b.text() +
                         ", two points of the same body; a joint joins two bodies");
    }
    if (j.kind == JointKind::kSlider) {
      if (!std::isfinite(j.axis_angle)) {
        throw InvalidInput(item + ": the slider's axis angle is not finite");
      }
      const double off =
          -std::sin(j.axis_angle) * (pb.x - pa.x) + std::cos(j.axis_angle) * (pb.y - pa.y);
      if (std::fabs(off) > tolerance) {
        throw InvalidInput(item + ": " + j.b.text() + " at " + at(pb) + " lies " + fmt(off) +
                           " m off the slider's line through " + j.a.text() + " at " + at(pa) +
                           "; the loop cannot close in the described configuration (tolerance " +
                           fmt(tolerance) + " m)");
      }
    } else {
      const double gap = std::hypot(pb.x - pa.x, pb.y - pa.y);
      if (gap > tolerance) {
        throw InvalidInput(item + ": " + j.a.text() + " at " + at(pa) + " and " + j.b.text() +
                           " at " + at(pb) + " are " + fmt(gap) +
                           " m apart in the described configuration; the loop cannot close "
                           "there (tolerance " +
                           fmt(tolerance) + " m)");
      }
    }
    links[j.a.body].insert(j.b.body);
    links[j.b.body].insert(j.a.body);
  }
  for (const Flexure& f : flexures) {
    const std::string item = where(f.line) + "flexure '" + f.name + "'";
    unique_item(f.name, item);
    const Vec2 pa = resolve(f.a, item);
    const Vec2 pb = resolve(f.b, item);
    if (f.a.body == f.b.body) {
      throw InvalidInput(item + ": runs between " + f.a.text() + " and " + f.b.text() +
                         ", two points of the same body; a flexure joins two bodies");
    }
    if (!(f.width > 0.0) || !(f.thickness > 0.0) || !std::isfinite(f.width) ||
        !std::isfinite(f.thickness)) {
      throw InvalidInput(item +
                         ": missing or invalid section: width and thickness must be "
                         "finite and > 0 (width " +
                         fmt(f.width) + " m, thickness " + fmt(f.thickness) + " m)");
    }
    if (!(f.material.E > 0.0) || !std::isfinite(f.material.E)) {
      throw InvalidInput(item + ": missing or invalid Young's modulus E (" + fmt(f.material.E) +
                         " Pa)");
    }
    const double distance = std::hypot(pb.x - pa.x, pb.y - pa.y);
    if (!(distance > tolerance)) {
      throw InvalidInput(item + ": its ends " + f.a.text() + " and " + f.b.text() +
                         " coincide; a flexure has a length");
    }
    if (!std::isfinite(f.curvature) || !std::isfinite(f.width_tip) ||
        !std::isfinite(f.thickness_tip) || f.width_tip < 0.0 || f.thickness_tip < 0.0) {
      throw InvalidInput(item + ": curvature, width_tip and thickness_tip must be finite and the " +
                         "tip's section >= 0 (0: the root's)");
    }
    if (f.tapered() && f.extensible) {
      throw InvalidInput(item + ": a tapered flexure cannot be extensible (one EA per flexure)");
    }
    if (f.curved()) {
      const double l = f.arc_length(distance);
      if (!std::isfinite(l)) {
        throw InvalidInput(item + ": no circular arc of curvature " + fmt(f.curvature) +
                           " 1/m joins its ends " + f.a.text() + " and " + f.b.text() + ", " +
                           fmt(distance) + " m apart (|kappa0| chord/2 > 1)");
      }
      const double chord = std::fabs(2.0 * std::sin(0.5 * f.curvature * l) / f.curvature);
      if (f.length != 0.0 &&
          (!(f.length > 0.0) || std::fabs(f.curvature * f.length) >= 2 * std::numbers::pi)) {
        throw InvalidInput(item + ": length " + fmt(f.length) + " m with curvature " +
                           fmt(f.curvature) + " 1/m is not an arc of less than a full circle");
      }
      if (f.length != 0.0 && std::fabs(chord - distance) > 1e-6 * distance) {
        throw InvalidInput(item + ": length " + fmt(f.length) + " m and curvature " +
                           fmt(f.curvature) + " 1/m make an arc whose chord is " + fmt(chord) +
                           " m, but its ends " + f.a.text() + " and " + f.b.text() + " are " +
                           fmt(distance) + " m apart in the described configuration");
      }
    } else if (f.length != 0.0 &&
               (!std::isfinite(f.length) || std::fabs(f.length - distance) > 1e-6 * distance)) {
      throw InvalidInput(item + ": length " + fmt(f.length) + " m, but its ends " + f.a.text() +
                         " and " + f.b.text() + " are " + fmt(distance) +
                         " m apart in the described configuration (a straight flexure)");
    }
    // Thicker than long is a block, not a flexure. Between 0.5 and 1 (Howell's bistable switch
    // has 2.3 mm over 4.2 mm, 0.55) the PRBM spring EI/l is still the book's; the solver warns
    // that slender-beam theory no longer holds (docs/mechanisms.md, geometry limits).
    if (f.thickness > distance) {
      throw InvalidInput(item + ": thickness/length = " + fmt(f.thickness / distance) +
                         " > 1: a block, not a flexure (docs/mechanisms.md, geometry limits)");
    }
    if (f.model == FlexureModel::kAuto &&
        (!(f.tolerance > 0.0) || !(f.tolerance < 1.0) || !std::isfinite(f.tolerance))) {
      throw InvalidInput(item + ": model 'auto' needs a tolerance in (0, 1), the largest mapped " +
                         "tip error per length of the flexure (got " + fmt(f.tolerance) + ")");
    }
    if ((f.model == FlexureModel::kCbcm || f.model == FlexureModel::kChain) &&
        (f.elements < 0 || f.elements > 2000)) {
      throw InvalidInput(item + ": model '" + std::string(flexure_model_name(f.model)) +
                         "' needs elements in [1, 2000] (0: its default, " +
                         std::to_string(f.model == FlexureModel::kChain
                                            ? Flexure::kDefaultChainElements
                                            : Flexure::kDefaultCbcmElements) +
                         "; got " + std::to_string(f.elements) + ")");
    }
    links[f.a.body].insert(f.b.body);
    links[f.b.body].insert(f.a.body);
  }
  for (const LinearSpring& s : linear_springs) {
    const std::string item = where(s.line) + "linear spring '" + s.name + "'";
    unique_item(s.name, item);
    const Vec2 pa = resolve(s.a, item);
    const Vec2 pb = resolve(s.b, item);
    if (s.a.body == s.b.body) {
      throw InvalidInput(item + ": joins two points of the same body '" + s.a.body + "'");
    }
    if (!(s.stiffness >= 0.0) || !std::isfinite(s.stiffness)) {
      throw InvalidInput(item + ": stiffness must be finite and >= 0 N/m");
    }
    if (!std::isfinite(s.rest_length)) {
      throw InvalidInput(item + ": rest length is not finite");
    }
    if (s.rest_length < 0.0 && !(std::hypot(pb.x - pa.x, pb.y - pa.y) > 0.0)) {
      throw InvalidInput(item + ": its ends coincide and no rest length is given");
    }
  }
  for (const TorsionSpring& s : torsion_springs) {
    const std::string item = where(s.line) + "torsion spring '" + s.name + "'";
    unique_item(s.name, item);
    require_body(s.body_a, item);
    require_body(s.body_b, item);
    if (s.body_a == s.body_b) {
      throw InvalidInput(item + ": acts between body '" + s.body_a + "' and itself");
    }
    if (!(s.stiffness >= 0.0) || !std::isfinite(s.stiffness) || !std::isfinite(s.rest_angle)) {
      throw InvalidInput(item +
                         ": stiffness must be finite and >= 0 N m/rad, the rest angle "
                         "finite");
    }
  }
  for (const DeadLoad& l : loads) {
    const std::string item = where(l.line) + "load '" + l.name + "'";
    unique_item(l.name, item);
    resolve(l.at, item);
    if (!std::isfinite(l.fx) || !std::isfinite(l.fy) || !std::isfinite(l.moment)) {
      throw InvalidInput(item + ": fx, fy and moment must be finite");
    }
  }

  // Every moving body must hang on the ground through joints and flexures.
  std::set<std::string> reached{"ground"};
  std::vector<std::string> pending{"ground"};
  while (!pending.empty()) {
    const std::string b = pending.back();
    pending.pop_back();
    for (const std::string& n : links[b]) {
      if (reached.insert(n).second) {
        pending.push_back(n);
      }
    }
  }
  for (const Body& b : bodies) {
    if (reached.count(b.name) == 0) {
      throw InvalidInput(where(b.line) + "body '" + b.name +
                         "' is unconstrained: no chain of joints and flexures joins it to the "
                         "ground");
    }
  }

  // The input.
  const std::string item = where(input.line) + "input";
  if (!has_input) {
    throw InvalidInput(where(0) + "the mechanism has no input (a prescribed coordinate or load)");
  }
  if (input.body == "ground") {
    throw InvalidInput(item + ": the input is a coordinate of the ground, which does not move");
  }
  const PointRef p{input.body, input.point};
  const Vec2 p0 = resolve(p, item);
  if (input.coordinate == InputCoordinate::kAngle) {
    const Vec2 p1 = resolve({input.body, input.point_to}, item);
    if (!(std::hypot(p1.x - p0.x, p1.y - p0.y) > tolerance)) {
      throw InvalidInput(item + ": the angle's line from " + input.point + " to " + input.point_to +
                         " has no length");
    }
  }
  if (!std::isfinite(input.start) || !std::isfinite(input.stop) || input.start == input.stop) {
    throw InvalidInput(item + ": the range must be two different finite values (from " +
                       fmt(input.start) + " to " + fmt(input.stop) + ")");
  }
  for (const auto& [body, angle] : input.start_rotation) {
    if (find_body(body) == nullptr || body == "ground") {
      throw InvalidInput(item + ": start_rotation names '" + body +
                         "', which is not a moving body");
    }
    if (!std::isfinite(angle)) {
      throw InvalidInput(item + ": start_rotation of '" + body + "' is not finite");
    }
  }
  if (input.count < 2 || input.count > 100000) {
    throw InvalidInput(item + ": count must be between 2 and 100000 (" +
                       std::to_string(input.count) + ")");
  }
}

double Flexure::arc_length(double chord) const {
  if (!curved()) return chord;
  if (length > 0.0) return length;
  // chord = 2 sin(kappa0 l/2)/kappa0 on the minor arc (kappa0 l < pi).
  const double x = 0.5 * std::fabs(curvature) * chord;
  if (!(x <= 1.0)) return std::numeric_limits<double>::quiet_NaN();
  return 2.0 * std::asin(x) / std::fabs(curvature);
}

double Flexure::end_angle_from_chord(double chord, int end) const {
  // An arc turning by kappa0 l has its chord at half that turn from either end's tangent.
  const double half_turn = 0.5 * curvature * arc_length(chord);
  return end == 0 ? -half_turn : half_turn;
}

}  // namespace flexure::mechanism::general
