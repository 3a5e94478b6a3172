#include "cli/mechanism_geometry_output.h"

#include <fmt/format.h>

#include "flexure/io/platform/output_path.h"
#include "flexure/solver/common/section.h"
#include "flexure/solver/common/status.h"

namespace flexure::cli {
namespace {

using mechanism::GeometryPoint;

Json point_json(const GeometryPoint& p) { return Json::array({p.x, p.y}); }

const char* pivot_type_name(mechanism::PivotType t) {
  return t == mechanism::PivotType::kPin ? "pin" : t == mechanism::PivotType::kSmall ? "s" : "l";
}

}  // namespace

Json geometry_json(const mechanism::MechanismGeometry& g) {
  Json flexures = Json::array(), links = Json::array(), pivots = Json::array();
  for (const auto& f : g.flexures) {
    flexures.push_back(
        Json{{"pivot", f.pivot},
             {"kind", to_string(f.kind)},
             {"length", f.length},
             {"width", f.width},
             {"thickness", f.thickness},
             {"rest", Json::array({point_json(f.rest_start), point_json(f.rest_end)})},
             {"stroke_end",
              Json::array({point_json(f.stroke_end[0]),
                           point_json(f.stroke_end[1]),
                           point_json(f.stroke_end[2])})}});
  }
  for (const auto& l : g.links) {
    links.push_back(
        Json{{"link", l.link},
             {"length", l.length},
             {"rest", Json::array({point_json(l.rest_start), point_json(l.rest_end)})},
             {"stroke_end",
              Json::array({point_json(l.stroke_end_start), point_json(l.stroke_end_end)})}});
  }
  for (const auto& p : g.pivots) {
    pivots.push_back(Json{{"pivot", p.pivot},
                          {"type", pivot_type_name(p.type)},
                          {"rest", point_json(p.rest)},
                          {"stroke_end", point_json(p.stroke_end)}});
  }
  return Json{{"units", "SI: m, rad"},
              {"flexures", flexures},
              {"links", links},
              {"pivots", pivots},
              {"overall_length", g.overall_length()},
              {"ground_attach_x", g.ground_attach_x},
              {"slider_attach_x_rest", g.slider_attach_x_rest},
              {"slider_attach_x_end", g.slider_attach_x_end},
              {"theta2_end", g.theta2_end},
              {"theta3_end", g.theta3_end},
              {"deformed_model", g.deformed_model}};
}

Json dimensions_json(const std::vector<io::DrawingDimension>& dims) {
  Json a = Json::array();
  for (const auto& d : dims) a.push_back(Json{{"name", d.name}, {"value", d.value}});
  return a;
}

Json design_geometry_json(const mechanism::MechanismDesign& design) {
  try {
    return geometry_json(mechanism::mechanism_geometry(design));
  } catch (const InvalidInput&) {
    return Json(nullptr);
  }
}

std::string design_geometry_text(const mechanism::MechanismDesign& design,
                                 const std::string& unit) {
  mechanism::MechanismGeometry g;
  try {
    g = mechanism::mechanism_geometry(design);
  } catch (const InvalidInput&) {
    return "";
  }
  return fmt::format("{} ({}):\n", design.name, design.config) + geometry_text(g, unit);
}

void check_drawing_path(const std::string& path, const std::string& option) {
  try {
    io::drawing_format(path);
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("{}: {}", option, e.what()));
  }
  io::check_output_path(path, option);
}

std::string length_unit_of(const std::string& quantity_text) {
  try {
    const io::Quantity q = io::parse_quantity(quantity_text, io::Dimension::kLength, "length");
    if (q.has_unit()) return q.unit;
  } catch (const InvalidInput&) {
  }
  return "mm";
}

std::string geometry_text(const mechanism::MechanismGeometry& g,
                          const std::string& unit,
                          const std::string& indent) {
  const double factor = io::parse_quantity("1" + unit, io::Dimension::kLength, "--unit").si;
  auto v = [&](double metres) { return fmt::format("{:.5g}", metres / factor); };
  auto pt = [&](const GeometryPoint& p) { return fmt::format("({}, {})", v(p.x), v(p.y)); };
  std::string s = fmt::format(
      "{}buildable geometry ({}; pivot 1 at the origin, slider axis along x; overall length {}):\n",
      indent,
      unit,
      v(g.overall_length()));
  for (const auto& f : g.flexures) {
    s += fmt::format("{}  flexure {} ({}): length {}, width {}, thickness {}; from x = {} to {}\n",
                     indent,
                     f.pivot,
                     to_string(f.kind),
                     v(f.length),
                     v(f.width),
                     v(f.thickness),
                     v(f.rest_start.x),
                     v(f.rest_end.x));
  }
  for (const auto& l : g.links) {
    s += fmt::format("{}  rigid link {} ({}): length {}; from x = {} to {}\n",
                     indent,
                     l.link,
                     l.link == 2 ? "crank" : "coupler",
                     v(l.length),
                     v(l.rest_start.x),
                     v(l.rest_end.x));
  }
  for (const auto& p : g.pivots) {
    s += fmt::format("{}  pivot {} ({}): at rest {}, end of stroke {}\n",
                     indent,
                     p.pivot,
                     pivot_type_name(p.type),
                     pt(p.rest),
                     pt(p.stroke_end));
  }
  s += fmt::format("{}  slider attachment: x = {} at rest, {} at the end of the stroke\n",
                   indent,
                   v(g.slider_attach_x_rest),
                   v(g.slider_attach_x_end));
  return s;
}

}  // namespace flexure::cli
