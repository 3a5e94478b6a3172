// Drawings of the buildable geometry (io/mechanism_drawing.h) read back: the DXF by its group
// codes (read here), the SVG by an XML parser (Python's xml.etree under /usr/bin/python3), and the
// dimensions in both compared with the design's own numbers to 1e-9 relative. Where Chromium is
// installed, the SVG is rendered headless; otherwise that test is skipped and says so.
#include "flexure/io/mechanism_drawing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/mechanisms/mechanism_exact_geometry.h"
#include "flexure/solver/common/status.h"

namespace flexure::io {
namespace {

namespace fs = std::filesystem;
using mechanism::MechanismDesign;

struct Scratch {
  fs::path dir;
  Scratch() {
    dir = fs::temp_directory_path() / ("flexure-drawing-" + std::to_string(::getpid()));
    fs::create_directories(dir);
  }
  ~Scratch() { fs::remove_all(dir); }
};

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The value of "NAME = VALUE mm ..." in mm, or NaN.
double text_value(const std::string& text, const std::string& name) {
  const std::string head = name + " = ";
  if (text.rfind(head, 0) != 0) return std::nan("");
  return std::stod(text.substr(head.size()));
}
// "; h = VALUE mm" / ", b = VALUE mm" inside a flexure's dimension text.
double labelled(const std::string& text, const std::string& label) {
  const auto at = text.find(label);
  if (at == std::string::npos) return std::nan("");
  return std::stod(text.substr(at + label.size()));
}

void expect_relative(double got, double want, const std::string& what) {
  EXPECT_NEAR(got, want, 1e-9 * std::abs(want)) << what;
}

// The design's own numbers that every drawing must show, in mm.
std::map<std::string, double> expected_dimensions(const MechanismDesign& d) {
  std::map<std::string, double> m{
      {"r2", d.r2 * 1e3}, {"r3", d.r3 * 1e3}, {"stroke", d.stroke * 1e3}};
  for (int p = 1; p <= 3; ++p) {
    if (d.joints[p - 1].type != mechanism::PivotType::kPin) {
      m["flexure " + std::to_string(p) + " length"] = d.joints[p - 1].length * 1e3;
    }
  }
  return m;
}

// ---- DXF ------------------------------------------------------------------------------------

struct DxfEntity {
  std::string type, layer;
  std::vector<std::pair<double, double>> vertices;  // POLYLINE
  bool closed = false;
  std::string text;  // TEXT
};

std::vector<std::pair<int, std::string>> group_codes(const std::string& dxf) {
  std::istringstream in(dxf);
  std::vector<std::pair<int, std::string>> out;
  std::string code, value;
  while (std::getline(in, code) && std::getline(in, value)) out.push_back({std::stoi(code), value});
  return out;
}

// The ENTITIES section, POLYLINE ... VERTEX ... SEQEND joined into one entity.
std::vector<DxfEntity> dxf_entities(const std::vector<std::pair<int, std::string>>& g) {
  std::vector<DxfEntity> out;
  bool in_entities = false;
  DxfEntity* poly = nullptr;
  for (std::size_t i = 0; i < g.size(); ++i) {
    const auto& [code, value] = g[i];
    if (code == 2 && value == "ENTITIES") in_entities = true;
    if (!in_entities || code != 0) continue;
    if (value == "ENDSEC") break;
    // Gather this entity's groups.
    std::map<int, std::string> f;
    for (std::size_t k = i + 1; k < g.size() && g[k].first != 0; ++k) f[g[k].first] = g[k].second;
    if (value == "POLYLINE") {
      out.push_back({"POLYLINE", f[8], {}, (std::stoi(f[70]) & 1) != 0, ""});
      poly = &out.back();
    } else if (value == "VERTEX") {
      EXPECT_NE(poly, nullptr);
      if (poly) poly->vertices.push_back({std::stod(f[10]), std::stod(f[20])});
    } else if (value == "SEQEND") {
      poly = nullptr;
    } else if (value == "TEXT") {
      out.push_back({"TEXT", f[8], {}, false, f[1]});
    } else {
      out.push_back({value, f[8], {}, false, ""});
    }
  }
  return out;
}

class Drawings : public ::testing::TestWithParam<const char*> {};

TEST_P(Drawings, DxfReadBackByGroupCodesMatchesTheDesign) {
  const MechanismDesign d = mechanism::find_builtin_mechanism(GetParam());
  const auto g = mechanism::mechanism_geometry(d);
  Scratch s;
  const fs::path path = s.dir / "design.dxf";
  write_mechanism_drawing(path.string(), g, DrawingOptions{});
  const auto codes = group_codes(read(path));
  ASSERT_FALSE(codes.empty());
  EXPECT_EQ(codes.back().second, "EOF");
  // Layer table: every named layer declared.
  std::vector<std::string> layers;
  for (std::size_t i = 0; i + 1 < codes.size(); ++i) {
    if (codes[i] == std::pair<int, std::string>{0, "LAYER"} && codes[i + 1].first == 2) {
      layers.push_back(codes[i + 1].second);
    }
  }
  for (const char* name : {"LINKS", "FLEXURES", "PINS", "SLIDER", "DIMENSIONS", "DEFORMED"}) {
    EXPECT_NE(std::find(layers.begin(), layers.end(), name), layers.end()) << name;
  }
  const auto entities = dxf_entities(codes);
  // Dimension texts against the design.
  const auto want = expected_dimensions(d);
  std::map<std::string, double> seen;
  for (const auto& e : entities) {
    if (e.type != "TEXT" || e.layer != "DIMENSIONS") continue;
    for (const auto& [name, value] : want) {
      const double v = text_value(e.text, name);
      if (std::isnan(v)) continue;
      expect_relative(v, value, e.text);
      seen[name] = v;
      if (name.rfind("flexure ", 0) == 0) {
        const int p = name[8] - '0';
        expect_relative(labelled(e.text, "; h = "), d.joints[p - 1].thickness * 1e3, e.text);
        expect_relative(labelled(e.text, ", b = "), d.joints[p - 1].width * 1e3, e.text);
      }
    }
  }
  EXPECT_EQ(seen.size(), want.size());
  // Flexure outlines: closed, their real length by their real thickness.
  std::vector<std::pair<double, double>> outlines;  // (length, thickness), mm
  int deformed = 0;
  for (const auto& e : entities) {
    if (e.type == "POLYLINE" && e.layer == "DEFORMED") ++deformed;
    if (e.type != "POLYLINE" || e.layer != "FLEXURES") continue;
    EXPECT_TRUE(e.closed);
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (auto [x, y] : e.vertices) {
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
    outlines.push_back({x1 - x0, y1 - y0});
  }
  ASSERT_EQ(outlines.size(), g.flexures.size());
  for (std::size_t i = 0; i < outlines.size(); ++i) {
    const auto& j = d.joints[g.flexures[i].pivot - 1];
    expect_relative(outlines[i].first, j.length * 1e3, "outline length");
    expect_relative(outlines[i].second, j.thickness * 1e3, "outline thickness");
  }
  EXPECT_GT(deformed, 0);
}

// ---- SVG ------------------------------------------------------------------------------------

// Parses the SVG with xml.etree and prints, as JSON: the root tag, its viewBox, the ids of its
// groups, every dimension text (data-name, data-value-mm, text) and the FLEXURES polygons.
constexpr const char* kSvgReader = R"PY(
import json, sys, xml.etree.ElementTree as ET
ns = '{http://www.w3.org/2000/svg}'
root = ET.parse(sys.argv[1]).getroot()
groups = {g.get('id'): g for g in root.iter(ns + 'g')}
dims = [{'name': t.get('data-name'), 'value': float(t.get('data-value-mm')), 'text': t.text}
        for t in groups['DIMENSIONS'].iter(ns + 'text')]
polys = [[[float(v) for v in p.split(',')] for p in e.get('points').split()]
         for e in groups['FLEXURES'].iter(ns + 'polygon')]
deformed = {c: [[[float(v) for v in p.split(',')] for p in e.get('points').split()]
                for e in groups['DEFORMED'].iter(ns + 'polyline') if e.get('class') == c]
            for c in ('deformed-flexure', 'deformed')} if 'DEFORMED' in groups else {}
print(json.dumps({'root': root.tag, 'viewBox': root.get('viewBox'), 'groups': sorted(groups),
                  'dimensions': dims, 'flexures': polys, 'deformed': deformed}))
)PY";

nlohmann::json parse_svg(const fs::path& svg, const fs::path& dir) {
  const fs::path script = dir / "read_svg.py", out = dir / "svg.json";
  std::ofstream(script) << kSvgReader;
  const std::string cmd =
      "/usr/bin/python3 '" + script.string() + "' '" + svg.string() + "' > '" + out.string() + "'";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  return nlohmann::json::parse(read(out));
}

TEST_P(Drawings, SvgParsedAsXmlMatchesTheDesign) {
  const MechanismDesign d = mechanism::find_builtin_mechanism(GetParam());
  const auto g = mechanism::mechanism_geometry(d);
  Scratch s;
  const fs::path path = s.dir / "design.svg";
  write_mechanism_drawing(path.string(), g, DrawingOptions{});
  const nlohmann::json j = parse_svg(path, s.dir);
  EXPECT_EQ(j["root"], "{http://www.w3.org/2000/svg}svg");
  for (const char* name :
       {"LINKS", "FLEXURES", "PINS", "SLIDER", "DIMENSIONS", "DEFORMED", "NOTES"}) {
    EXPECT_NE(std::find(j["groups"].begin(), j["groups"].end(), name), j["groups"].end()) << name;
  }
  const auto want = expected_dimensions(d);
  std::map<std::string, double> seen;
  for (const auto& dim : j["dimensions"]) {
    const std::string name = dim["name"];
    if (!want.count(name)) continue;
    expect_relative(dim["value"].get<double>(), want.at(name), name);
    expect_relative(text_value(dim["text"].get<std::string>(), name), want.at(name), name);
    seen[name] = 1;
  }
  EXPECT_EQ(seen.size(), want.size());
  ASSERT_EQ(j["flexures"].size(), g.flexures.size());
  for (std::size_t i = 0; i < g.flexures.size(); ++i) {
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (const auto& p : j["flexures"][i]) {
      const double x = p[0], y = p[1];
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
    const auto& jd = d.joints[g.flexures[i].pivot - 1];
    expect_relative(x1 - x0, jd.length * 1e3, "svg outline length");
    expect_relative(y1 - y0, jd.thickness * 1e3, "svg outline thickness");
  }
  // viewBox in mm: four numbers, wide enough for the overall length.
  std::istringstream vb(j["viewBox"].get<std::string>());
  double vx, vy, vw, vh;
  ASSERT_TRUE(vb >> vx >> vy >> vw >> vh);
  EXPECT_GT(vw, g.overall_length() * 1e3);
  EXPECT_GT(vh, 0.0);
}

TEST_P(Drawings, StrokeEndOffLeavesOutTheDeformedLayer) {
  const auto g = mechanism::mechanism_geometry(mechanism::find_builtin_mechanism(GetParam()));
  DrawingOptions off;
  off.stroke_end = false;
  EXPECT_EQ(mechanism_svg(g, off).find("id=\"DEFORMED\""), std::string::npos);
  EXPECT_NE(mechanism_svg(g, DrawingOptions{}).find("id=\"DEFORMED\""), std::string::npos);
}

// The end of the stroke drawn with the exact model's bent flexures (mechanisms/
// mechanism_exact_geometry.h), parsed back from the SVG (y is down there): the drawn centrelines
// end where the exact model's chains end -- their tips as the shooting solver's own integration of
// the solved point gives them (not the re-integration at the drawing's stations), to 1e-9 mm --
// and start at the ground attachment; a serial chain closes on the slider joint (to the solver's
// closure tolerance); every drawn flexure keeps its real length (a polyline of 101 points on a
// smooth curve: shorter by O(h^2), < 1e-4).
TEST_P(Drawings, ExactStrokeEndShapesMatchTheExactModelsTips) {
  const MechanismDesign d = mechanism::find_builtin_mechanism(GetParam());
  mechanism::AnalysisOptions o;
  o.points = 50;
  o.stability = false;
  o.exact_stress = false;
  const mechanism::MechanismAnalysis a = mechanism::analyze_mechanism(d, o);
  ASSERT_TRUE(a.has_exact && a.exact.converged()) << a.exact.message;
  const mechanism::ExactPoint& end = a.exact.points.back();
  auto g = mechanism::mechanism_geometry(d);
  mechanism::add_exact_stroke_end(g, d, end);
  ASSERT_TRUE(g.exact_stroke_end);
  Scratch s;
  const fs::path path = s.dir / "exact.svg";
  write_mechanism_drawing(path.string(), g, DrawingOptions{});
  const nlohmann::json j = parse_svg(path, s.dir);
  const auto& drawn = j["deformed"]["deformed-flexure"];
  ASSERT_EQ(drawn.size(), g.flexures.size());
  // Every end point of a drawn flexure or link, mm, y up.
  std::vector<std::pair<double, double>> ends;
  for (const char* cls : {"deformed-flexure", "deformed"}) {
    for (const auto& line : j["deformed"][cls]) {
      ends.push_back({line.front()[0].get<double>(), -line.front()[1].get<double>()});
      ends.push_back({line.back()[0].get<double>(), -line.back()[1].get<double>()});
    }
  }
  const auto nearest = [&](double x, double y) {
    double best = 1e300;
    for (const auto& [ex, ey] : ends) best = std::min(best, std::hypot(ex - x, ey - y));
    return best;
  };
  const double L = end.length_scale * 1e3;  // mm
  const mechanism::PhysicalChain pc = mechanism::physical_chain(d);
  const double slider_x = (g.ground_attach_x + pc.slider_x0 - d.stroke) * 1e3;
  const ShootingSolver solver(mechanism::ExactMechanismSolver::Options{}.shooting);
  const ShootingResult crank = solver.solve_from(end.chain, end.unknowns);
  ASSERT_TRUE(crank.converged()) << crank.message;
  const double tip_x = g.ground_attach_x * 1e3 + L * crank.tip.x, tip_y = L * crank.tip.y;
  EXPECT_LT(nearest(tip_x, tip_y), 1e-9) << "chain tip (" << tip_x << ", " << tip_y << ") mm";
  EXPECT_LT(nearest(g.ground_attach_x * 1e3, 0.0), 1e-12) << "ground attachment";
  if (!end.coupler_chain.segments.empty()) {
    // The middle-pin coupler chain, rooted at the displaced slider clamp, turned by pi.
    const ShootingResult coupler = solver.solve_from(end.coupler_chain, end.coupler_unknowns);
    ASSERT_TRUE(coupler.converged()) << coupler.message;
    const double cx = slider_x - L * coupler.tip.x, cy = -L * coupler.tip.y;
    EXPECT_LT(nearest(cx, cy), 1e-9) << "coupler chain tip";
    EXPECT_LT(nearest(slider_x, 0.0), 1e-12) << "slider clamp";
    EXPECT_LT(std::hypot(cx - tip_x, cy - tip_y), 1e-6) << "the pin closes";
  }
  if (mechanism::exact_support(d) == mechanism::ExactSupport::kDirectChain) {
    EXPECT_LT(std::hypot(tip_x - slider_x, tip_y), 1e-6) << "the chain closes on the slider";
    const auto& last = drawn.back().back();
    EXPECT_LT(std::hypot(last[0].get<double>() - tip_x, -last[1].get<double>() - tip_y), 1e-9);
  }
  for (std::size_t i = 0; i < g.flexures.size(); ++i) {
    double length = 0.0;
    for (std::size_t k = 1; k < drawn[i].size(); ++k) {
      length += std::hypot(drawn[i][k][0].get<double>() - drawn[i][k - 1][0].get<double>(),
                           drawn[i][k][1].get<double>() - drawn[i][k - 1][1].get<double>());
    }
    const double real = g.flexures[i].length * 1e3;
    EXPECT_LE(length, real * (1 + 1e-12)) << "flexure " << g.flexures[i].pivot;
    EXPECT_GT(length, real * (1 - 1e-4)) << "flexure " << g.flexures[i].pivot;
    // Bent: the exact shape is not the PRBM's three-point polyline.
    EXPECT_GT(drawn[i].size(), 3u);
  }
}

// One design of each kind of pivot layout: s everywhere, an l at the ground, an l in the middle
// on either link, pins at both ends, a Howell design.
INSTANTIATE_TEST_SUITE_P(
    Designs,
    Drawings,
    ::testing::Values("3A-sss", "1A-lpp", "plp", "slp", "psp", "lps", "howell-1A-spp-b"),
    [](const auto& info) {
      std::string n = info.param;
      for (char& c : n) {
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      }
      return n;
    });

TEST(Drawings, UnknownExtensionIsRefusedAndNothingIsWritten) {
  const auto g = mechanism::mechanism_geometry(mechanism::find_builtin_mechanism("3A-sss"));
  Scratch s;
  const fs::path path = s.dir / "design.png";
  EXPECT_THROW(write_mechanism_drawing(path.string(), g, DrawingOptions{}), InvalidInput);
  EXPECT_FALSE(fs::exists(path));
  EXPECT_EQ(drawing_format("A.SVG"), DrawingFormat::kSvg);
  EXPECT_EQ(drawing_format("dir.svg/a.dxf"), DrawingFormat::kDxf);
  EXPECT_THROW(drawing_format("dir.svg/noext"), InvalidInput);
}

// Headless Chromium renders the SVG to a PNG where it is installed.
TEST(Drawings, SvgRendersInHeadlessChromium) {
  std::string browser;
  for (const char* name : {"chromium", "chromium-browser", "google-chrome"}) {
    if (std::system((std::string("command -v ") + name + " >/dev/null 2>&1").c_str()) == 0) {
      browser = name;
      break;
    }
  }
  if (browser.empty()) {
    GTEST_SKIP() << "no chromium, chromium-browser or google-chrome on PATH: the SVG is checked "
                    "by the XML parse of SvgParsedAsXmlMatchesTheDesign only";
  }
  const auto g = mechanism::mechanism_geometry(mechanism::find_builtin_mechanism("3A-sss"));
  Scratch s;
  const fs::path svg = s.dir / "design.svg", png = s.dir / "design.png";
  write_mechanism_drawing(svg.string(), g, DrawingOptions{});
  const std::string cmd = browser + " --headless --disable-gpu --no-sandbox --screenshot='" +
                          png.string() + "' --window-size=1200,600 'file://" + svg.string() +
                          "' >/dev/null 2>&1";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  ASSERT_TRUE(fs::exists(png));
  EXPECT_GT(fs::file_size(png), 1000u);
}

}  // namespace
}  // namespace flexure::io
