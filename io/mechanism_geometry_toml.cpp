#include "flexure/io/mechanism_geometry_toml.h"

#include <fmt/format.h>

namespace flexure::io {
namespace {

using mechanism::GeometryPoint;

std::string n17(double v) { return fmt::format("{:.17g}", v); }
std::string point(const GeometryPoint& p) { return "[" + n17(p.x) + ", " + n17(p.y) + "]"; }

const char* type_name(mechanism::PivotType t) {
  return t == mechanism::PivotType::kPin ? "pin" : t == mechanism::PivotType::kSmall ? "s" : "l";
}

}  // namespace

std::string geometry_toml(const mechanism::MechanismGeometry& g) {
  std::string s;
  s += "\n# Buildable geometry (m, rad): written for the builder, ignored when the file is read\n"
       "# (it follows from the keys above). Pivot 1 at the origin, slider axis along x; "
       "docs/drawings.md.\n"
       "[geometry]\n";
  s += fmt::format("overall_length = {}\n", n17(g.overall_length()));
  s += fmt::format("ground_attach_x = {}\n", n17(g.ground_attach_x));
  s += fmt::format("slider_attach_x_rest = {}\n", n17(g.slider_attach_x_rest));
  s += fmt::format("slider_attach_x_end = {}\n", n17(g.slider_attach_x_end));
  s += fmt::format("theta2_end = {}\n", n17(g.theta2_end));
  s += fmt::format("theta3_end = {}\n", n17(g.theta3_end));
  s += fmt::format("deformed_model = \"{}\"\n", g.deformed_model);
  for (const auto& f : g.flexures) {
    s += "\n[[geometry.flexures]]\n";
    s += fmt::format("pivot = {}\nkind = \"{}\"\n", f.pivot, to_string(f.kind));
    s += fmt::format(
        "length = {}\nwidth = {}\nthickness = {}\n", n17(f.length), n17(f.width), n17(f.thickness));
    s += fmt::format("rest_start = {}\nrest_end = {}\n", point(f.rest_start), point(f.rest_end));
    s += fmt::format("stroke_end = [{}, {}, {}]\n",
                     point(f.stroke_end[0]),
                     point(f.stroke_end[1]),
                     point(f.stroke_end[2]));
  }
  for (const auto& l : g.links) {
    s += "\n[[geometry.links]]\n";
    s += fmt::format("link = {}\nlength = {}\n", l.link, n17(l.length));
    s += fmt::format("rest = [{}, {}]\nstroke_end = [{}, {}]\n",
                     point(l.rest_start),
                     point(l.rest_end),
                     point(l.stroke_end_start),
                     point(l.stroke_end_end));
  }
  for (const auto& p : g.pivots) {
    s += "\n[[geometry.pivots]]\n";
    s += fmt::format("pivot = {}\ntype = \"{}\"\nrest = {}\nstroke_end = {}\n",
                     p.pivot,
                     type_name(p.type),
                     point(p.rest),
                     point(p.stroke_end));
  }
  return s;
}

}  // namespace flexure::io
