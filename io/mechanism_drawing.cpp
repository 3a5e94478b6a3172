#include "flexure/io/mechanism_drawing.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

#include "flexure/io/platform/output_path.h"
#include "flexure/solver/common/status.h"

namespace flexure::io {
namespace {

using mechanism::FlexureGeometry;
using mechanism::FlexureKind;
using mechanism::GeometryPoint;
using mechanism::MechanismGeometry;
using mechanism::PivotType;

constexpr double kMm = 1e3;  // drawings are in millimetres

// A polyline of the drawing (m), on one layer, open or closed, with an SVG style class.
struct Polyline {
  std::string layer;
  std::vector<GeometryPoint> points;
  bool closed = false;
  std::string style;       // SVG class: "outline", "centre", "deformed", "dimension", "guide"
  double svg_width = 0.0;  // SVG stroke width, m (0: the class's default)
};
struct Circle {
  std::string layer;
  GeometryPoint centre;
  double radius = 0.0;
};
struct Text {
  std::string layer;
  GeometryPoint at;
  double height = 0.0;  // m
  std::string text;
  std::string name;  // dimension name (SVG data-name), empty for notes
  double value = std::numeric_limits<double>::quiet_NaN();  // dimension value, m
};

struct Drawing {
  std::vector<Polyline> lines;
  std::vector<Circle> circles;
  std::vector<Text> texts;
};

// Dimension texts with 10 significant digits (1e-10 relative: read back, they match the design to
// better than 1e-9, tests/io/mechanism_drawing_test); coordinates with 15, so that a 0.1 mm
// thickness taken as the difference of two coordinates near 100 mm keeps 1e-11.
std::string num(double v) { return fmt::format("{:.10g}", v); }
std::string mm(double metres) { return num(metres * kMm); }
std::string coord(double metres) { return fmt::format("{:.15g}", metres * kMm); }

// Scale of the drawing's decorations (text, blocks, offsets): the PRBM length r2 + r3.
double scale(const MechanismGeometry& g) { return g.r2 + g.r3; }

std::string kind_letter(FlexureKind kind) {
  return kind == FlexureKind::kLong ? "l" : kind == FlexureKind::kSmall ? "s" : to_string(kind);
}

// The rest outline of a flexure: its real length by its real thickness.
std::vector<GeometryPoint> flexure_outline(const FlexureGeometry& f) {
  const double h = 0.5 * f.thickness;
  return {{f.rest_start.x, -h}, {f.rest_end.x, -h}, {f.rest_end.x, h}, {f.rest_start.x, h}};
}

Drawing build_drawing(const MechanismGeometry& g, const DrawingOptions& options) {
  Drawing d;
  const double L = scale(g);
  const double block_length = 0.08 * L, block_height = 0.06 * L, pin_radius = 0.008 * L;
  const double text_height = 0.015 * L;
  for (const auto& link : g.links) {
    d.lines.push_back({"LINKS", {link.rest_start, link.rest_end}, false, "centre", 0.0});
  }
  for (const auto& f : g.flexures) {
    d.lines.push_back({"FLEXURES", flexure_outline(f), true, "outline", 0.0});
  }
  for (const auto& p : g.pivots) {
    if (p.type == PivotType::kPin) d.circles.push_back({"PINS", p.rest, pin_radius});
  }
  // The ground body's face at the ground attachment and the slider block beyond the slider
  // attachment, with the guide along the slider axis over the whole travel.
  const double xg = g.ground_attach_x, xs = g.slider_attach_x_rest, xe = g.slider_attach_x_end;
  const double hb = 0.5 * block_height;
  d.lines.push_back({"GROUND",
                     {{xg, -hb}, {xg, hb}, {xg - block_length, hb}, {xg - block_length, -hb}},
                     true,
                     "outline",
                     0.0});
  auto slider_block = [&](double x) {
    return std::vector<GeometryPoint>{
        {x, -hb}, {x + block_length, -hb}, {x + block_length, hb}, {x, hb}};
  };
  d.lines.push_back({"SLIDER", slider_block(xs), true, "outline", 0.0});
  const double guide_from = xe - 0.02 * L, guide_to = xs + block_length + 0.02 * L;
  for (double y : {-hb - 0.005 * L, hb + 0.005 * L}) {
    d.lines.push_back({"SLIDER", {{guide_from, y}, {guide_to, y}}, false, "guide", 0.0});
  }
  if (options.stroke_end) {
    // The exact model's bent shapes where they were added (mechanism_exact_geometry.h), else the
    // PRBM's pseudo-rigid polylines.
    const bool exact = g.exact_stroke_end;
    for (const auto& link : g.links) {
      d.lines.push_back({"DEFORMED",
                         {exact ? link.exact_end_start : link.stroke_end_start,
                          exact ? link.exact_end_end : link.stroke_end_end},
                         false,
                         "deformed",
                         0.0});
    }
    for (const auto& f : g.flexures) {
      d.lines.push_back({"DEFORMED",
                         exact
                             ? f.stroke_end_exact
                             : std::vector<GeometryPoint>(f.stroke_end.begin(), f.stroke_end.end()),
                         false,
                         "deformed-flexure",
                         f.thickness});
    }
    for (const auto& p : g.pivots) {
      if (p.type == PivotType::kPin) {
        d.circles.push_back({"DEFORMED", exact ? p.exact_end : p.stroke_end, pin_radius});
      }
    }
    d.lines.push_back({"DEFORMED", slider_block(xe), true, "deformed", 0.0});
  }
  // Dimensions: extension lines from the points to the dimension line, the line, the text.
  for (const DrawingDimension& dim : principal_dimensions(g)) {
    const double y = dim.offset;
    const GeometryPoint a{dim.from.x, y}, b{dim.to.x, y};
    d.lines.push_back({"DIMENSIONS", {dim.from, a}, false, "extension", 0.0});
    d.lines.push_back({"DIMENSIONS", {dim.to, b}, false, "extension", 0.0});
    d.lines.push_back({"DIMENSIONS", {a, b}, false, "dimension", 0.0});
    std::string text = fmt::format("{} = {} mm", dim.name, mm(dim.value));
    for (const auto& f : g.flexures) {
      if (dim.name == fmt::format("flexure {} length", f.pivot)) {
        text += fmt::format(
            " ({}; h = {} mm, b = {} mm)", kind_letter(f.kind), mm(f.thickness), mm(f.width));
      }
    }
    d.texts.push_back({"DIMENSIONS",
                       {std::min(a.x, b.x), y + 0.3 * text_height},
                       text_height,
                       text,
                       dim.name,
                       dim.value});
  }
  return d;
}

struct Box {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  void add(GeometryPoint p) {
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  }
};

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::vector<std::string> notes(const MechanismGeometry& g, const DrawingOptions& options) {
  std::vector<std::string> n{
      fmt::format("{} ({}): half of a symmetric constant-force slider mechanism, to scale, "
                  "millimetres",
                  g.name,
                  g.config),
      fmt::format("PRBM r2 = {} mm, r3 = {} mm, stroke = {} mm; pivot 1 at the origin, slider axis "
                  "along x",
                  mm(g.r2),
                  mm(g.r3),
                  mm(g.stroke)),
      "flexures: outline = real length x real thickness h (b = out-of-plane width); rigid links "
      "drawn as centrelines (their section is the designer's choice, stiff against the flexures)"};
  if (options.stroke_end) {
    n.push_back(g.exact_stroke_end ? fmt::format("end of stroke (dashed): {}", g.exact_model)
                                   : fmt::format("end of stroke (dashed): theta2 = {} deg; {}",
                                                 num(g.theta2_end * 180.0 / M_PI),
                                                 g.deformed_model));
  }
  if (g.inverted) {
    n.push_back(
        "inversion: drawn in the original orientation; in use the slider block is fixed "
        "and the ground block slides");
  }
  return n;
}

}  // namespace

DrawingFormat drawing_format(const std::string& path) {
  const auto dot = path.find_last_of('.');
  const auto slash = path.find_last_of('/');
  std::string ext;
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) {
    ext = path.substr(dot + 1);
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  if (ext == "svg") return DrawingFormat::kSvg;
  if (ext == "dxf") return DrawingFormat::kDxf;
  throw InvalidInput(fmt::format(
      "drawing '{}': unknown format '{}' (the extension must be .svg or .dxf)", path, ext));
}

std::vector<DrawingDimension> principal_dimensions(const MechanismGeometry& g) {
  const double L = scale(g);
  std::vector<DrawingDimension> dims;
  for (const auto& f : g.flexures) {
    dims.push_back(
        {fmt::format("flexure {} length", f.pivot), f.length, f.rest_start, f.rest_end, -0.06 * L});
  }
  dims.push_back({"r2", g.r2, g.pivots[0].rest, g.pivots[1].rest, -0.12 * L});
  dims.push_back({"r3", g.r3, g.pivots[1].rest, g.pivots[2].rest, -0.12 * L});
  for (const auto& link : g.links) {
    dims.push_back({fmt::format("link {} rigid length", link.link),
                    link.length,
                    link.rest_start,
                    link.rest_end,
                    -0.18 * L});
  }
  dims.push_back({"overall length",
                  g.overall_length(),
                  {g.ground_attach_x, 0.0},
                  {g.slider_attach_x_rest, 0.0},
                  -0.24 * L});
  dims.push_back(
      {"stroke", g.stroke, {g.slider_attach_x_end, 0.0}, {g.slider_attach_x_rest, 0.0}, -0.30 * L});
  return dims;
}

std::string mechanism_svg(const MechanismGeometry& g, const DrawingOptions& options) {
  const Drawing d = build_drawing(g, options);
  const double L = scale(g);
  const double text_height = 0.015 * L;
  const std::vector<std::string> note_lines = notes(g, options);
  Box box;
  for (const auto& l : d.lines) {
    for (const auto& p : l.points) box.add(p);
  }
  for (const auto& c : d.circles) {
    box.add({c.centre.x - c.radius, c.centre.y - c.radius});
    box.add({c.centre.x + c.radius, c.centre.y + c.radius});
  }
  for (const auto& t : d.texts) {
    box.add(t.at);
    // Text runs right of its anchor: about 0.55 em per character.
    box.add({t.at.x + 0.55 * t.height * t.text.size(), t.at.y + t.height});
  }
  const double note_top = box.y1 + 1.5 * text_height * (note_lines.size() + 1);
  box.add({box.x0, note_top});
  const double margin = 0.05 * L;
  // SVG's y axis points down: every y is written negated.
  const double vx = (box.x0 - margin) * kMm, vy = -(box.y1 + margin) * kMm;
  const double vw = (box.x1 - box.x0 + 2 * margin) * kMm, vh = (box.y1 - box.y0 + 2 * margin) * kMm;
  std::string s;
  s += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  s += fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}mm\" height=\"{}mm\" "
      "viewBox=\"{} {} {} {}\" data-units=\"mm\">\n",
      num(vw),
      num(vh),
      num(vx),
      num(vy),
      num(vw),
      num(vh));
  s += fmt::format("<title>{}</title>\n", xml_escape(g.name + " (" + g.config + "), mm"));
  const double thin = 0.0015 * L * kMm;
  s += "<style>\n";
  s += fmt::format(
      "  .outline {{ fill: none; stroke: black; stroke-width: {}; }}\n"
      "  .centre {{ fill: none; stroke: #333; stroke-width: {}; }}\n"
      "  .guide {{ fill: none; stroke: #777; stroke-width: {}; }}\n"
      "  .deformed {{ fill: none; stroke: #c03; stroke-width: {}; stroke-dasharray: {} {}; }}\n"
      "  .deformed-flexure {{ fill: none; stroke: #c03; stroke-opacity: 0.8; }}\n"
      "  .extension, .dimension {{ fill: none; stroke: #06c; stroke-width: {}; }}\n"
      "  .pin {{ fill: white; stroke: black; stroke-width: {}; }}\n"
      "  text {{ font-family: sans-serif; font-size: {}px; fill: #06c; }}\n"
      "  #NOTES text {{ fill: black; }}\n",
      num(thin),
      num(4 * thin),
      num(thin),
      num(2 * thin),
      num(6 * thin),
      num(3 * thin),
      num(0.6 * thin),
      num(thin),
      num(text_height * kMm));
  s += "</style>\n";
  auto points = [](const std::vector<GeometryPoint>& pts) {
    std::string out;
    for (const auto& p : pts) {
      if (!out.empty()) out += ' ';
      out += coord(p.x) + "," + coord(-p.y);
    }
    return out;
  };
  for (const char* layer :
       {"GROUND", "LINKS", "FLEXURES", "PINS", "SLIDER", "DEFORMED", "DIMENSIONS"}) {
    if (std::string(layer) == "DEFORMED" && !options.stroke_end) continue;
    s += fmt::format("<g id=\"{}\">\n", layer);
    for (const auto& l : d.lines) {
      if (l.layer != layer) continue;
      const std::string width =
          l.svg_width > 0.0 ? fmt::format(" stroke-width=\"{}\"", mm(l.svg_width)) : "";
      s += fmt::format("  <{} class=\"{}\"{} points=\"{}\"/>\n",
                       l.closed ? "polygon" : "polyline",
                       l.style,
                       width,
                       points(l.points));
    }
    for (const auto& c : d.circles) {
      if (c.layer != layer) continue;
      s += fmt::format("  <circle class=\"{}\" cx=\"{}\" cy=\"{}\" r=\"{}\"/>\n",
                       std::string(layer) == "DEFORMED" ? "deformed" : "pin",
                       mm(c.centre.x),
                       mm(-c.centre.y),
                       mm(c.radius));
    }
    for (const auto& t : d.texts) {
      if (t.layer != layer) continue;
      s +=
          fmt::format("  <text x=\"{}\" y=\"{}\" data-name=\"{}\" data-value-mm=\"{}\">{}</text>\n",
                      mm(t.at.x),
                      mm(-t.at.y),
                      xml_escape(t.name),
                      mm(t.value),
                      xml_escape(t.text));
    }
    s += "</g>\n";
  }
  s += "<g id=\"NOTES\">\n";
  for (std::size_t i = 0; i < note_lines.size(); ++i) {
    s += fmt::format("  <text x=\"{}\" y=\"{}\">{}</text>\n",
                     mm(box.x0),
                     mm(-(note_top - 1.5 * text_height * (i + 1))),
                     xml_escape(note_lines[i]));
  }
  s += "</g>\n</svg>\n";
  return s;
}

std::string mechanism_dxf(const MechanismGeometry& g, const DrawingOptions& options) {
  const Drawing d = build_drawing(g, options);
  std::string s;
  auto pair = [&s](int code, const std::string& value) {
    s += fmt::format("{:>3}\n{}\n", code, value);
  };
  // ASCII DXF R12 (AC1009): the oldest version every CAD program reads; no handles needed.
  pair(0, "SECTION");
  pair(2, "HEADER");
  pair(9, "$ACADVER");
  pair(1, "AC1009");
  pair(9, "$MEASUREMENT");  // 1: metric drawing (the coordinates are millimetres)
  pair(70, "1");
  pair(0, "ENDSEC");
  pair(0, "SECTION");
  pair(2, "TABLES");
  pair(0, "TABLE");
  pair(2, "LTYPE");
  pair(70, "1");
  pair(0, "LTYPE");
  pair(2, "CONTINUOUS");
  pair(70, "0");
  pair(3, "Solid line");
  pair(72, "65");
  pair(73, "0");
  pair(40, "0.0");
  pair(0, "ENDTAB");
  const std::vector<std::pair<const char*, int>> layers{{"LINKS", 7},
                                                        {"FLEXURES", 5},
                                                        {"PINS", 3},
                                                        {"SLIDER", 8},
                                                        {"GROUND", 8},
                                                        {"DIMENSIONS", 4},
                                                        {"DEFORMED", 1}};
  pair(0, "TABLE");
  pair(2, "LAYER");
  pair(70, std::to_string(layers.size()));
  for (const auto& [name, colour] : layers) {
    pair(0, "LAYER");
    pair(2, name);
    pair(70, "0");
    pair(62, std::to_string(colour));
    pair(6, "CONTINUOUS");
  }
  pair(0, "ENDTAB");
  pair(0, "ENDSEC");
  pair(0, "SECTION");
  pair(2, "ENTITIES");
  for (const auto& l : d.lines) {
    pair(0, "POLYLINE");
    pair(8, l.layer);
    pair(66, "1");
    pair(10, "0.0");
    pair(20, "0.0");
    pair(30, "0.0");
    pair(70, l.closed ? "1" : "0");
    for (const auto& p : l.points) {
      pair(0, "VERTEX");
      pair(8, l.layer);
      pair(10, coord(p.x));
      pair(20, coord(p.y));
      pair(30, "0.0");
    }
    pair(0, "SEQEND");
    pair(8, l.layer);
  }
  for (const auto& c : d.circles) {
    pair(0, "CIRCLE");
    pair(8, c.layer);
    pair(10, mm(c.centre.x));
    pair(20, mm(c.centre.y));
    pair(30, "0.0");
    pair(40, mm(c.radius));
  }
  for (const auto& t : d.texts) {
    pair(0, "TEXT");
    pair(8, t.layer);
    pair(10, mm(t.at.x));
    pair(20, mm(t.at.y));
    pair(30, "0.0");
    pair(40, mm(t.height));
    pair(1, t.text);
  }
  pair(0, "ENDSEC");
  pair(0, "EOF");
  return s;
}

void write_mechanism_drawing(const std::string& path,
                             const MechanismGeometry& g,
                             const DrawingOptions& options,
                             const std::string& option) {
  DrawingFormat format;
  try {
    format = drawing_format(path);
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("{}: {}", option, e.what()));
  }
  write_text_file(
      path,
      format == DrawingFormat::kSvg ? mechanism_svg(g, options) : mechanism_dxf(g, options),
      option);
}

}  // namespace flexure::io
