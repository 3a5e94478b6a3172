#include <fmt/format.h>
#include <toml++/toml.h>

#include <cmath>
#include <optional>

#include "flexure/io/toml_files.h"
#include "flexure/io/toml_support.h"
#include "flexure/mechanisms/materials_fatigue.h"
#include "flexure/solver/common/section.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism::general {
namespace {

using io::check_toml_keys;
using io::Dimension;
using io::line_of;
using io::toml_fail;

toml::table parse_root(const std::string& text, const std::string& source) {
  io::check_toml_limits(text, source);
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw InvalidInput(fmt::format(
        "{}:{}: TOML syntax error: {}", source, e.source().begin.line, e.description()));
  }
}

// Reads one item's keys; `item` names it in messages ("flexure 'f4'", "[input]").
class Reader {
 public:
  Reader(const toml::table& table, std::string item, const std::string& source)
      : t_(table), item_(std::move(item)), source_(source) {}

  int line() const { return line_of(t_); }
  const std::string& item() const { return item_; }

  [[noreturn]] void fail(const toml::node* node, const std::string& what) const {
    toml_fail(source_, node != nullptr ? line_of(*node) : line(), item_ + ": " + what);
  }

  std::optional<std::string> string(const std::string& key, bool required) const {
    const toml::node* node = t_.get(key);
    if (node == nullptr) {
      if (required) {
        fail(nullptr, "missing the required key '" + key + "'");
      }
      return std::nullopt;
    }
    if (!node->is_string()) {
      fail(node, key + " must be a string");
    }
    return **node->as_string();
  }

  // A number (SI) or, when `dimension` is given, a string with a unit ("4.2 mm").
  double number(const toml::node& node,
                const std::string& key,
                std::optional<Dimension> dimension) const {
    std::optional<double> v = io::toml_number(node);
    if (!v && dimension && node.is_string()) {
      try {
        v = io::parse_quantity(**node.as_string(), *dimension, key).si;
      } catch (const InvalidInput& e) {
        fail(&node, e.what());
      }
    }
    if (!v) {
      fail(&node,
           dimension ? key +
                           " must be a number (SI) or a string with a unit, e.g. "
                           "\"4.2 mm\""
                     : key + " must be a number (SI units)");
    }
    if (!std::isfinite(*v)) {
      fail(&node, key + " must be finite");
    }
    return *v;
  }

  std::optional<double> number(const std::string& key,
                               std::optional<Dimension> dimension,
                               bool required) const {
    const toml::node* node = t_.get(key);
    if (node == nullptr) {
      if (required) {
        fail(nullptr, "missing the required key '" + key + "'");
      }
      return std::nullopt;
    }
    return number(*node, key, dimension);
  }

  PointRef point(const std::string& key) const {
    const std::string text = *string(key, true);
    try {
      return parse_point_ref(text, key);
    } catch (const InvalidInput& e) {
      fail(t_.get(key), e.what());
    }
  }

  const toml::table& table() const { return t_; }

 private:
  const toml::table& t_;
  std::string item_;
  const std::string& source_;
};

// The tables of an array of tables [[key]] (none when absent).
std::vector<const toml::table*> tables(const toml::table& root,
                                       const std::string& key,
                                       const std::string& source) {
  std::vector<const toml::table*> out;
  const toml::node* node = root.get(key);
  if (node == nullptr) {
    return out;
  }
  const toml::array* array = node->as_array();
  if (array == nullptr) {
    toml_fail(source, line_of(*node), key + " must be an array of tables ([[" + key + "]])");
  }
  for (const toml::node& n : *array) {
    if (!n.is_table()) {
      toml_fail(source, line_of(n), key + " must be an array of tables ([[" + key + "]])");
    }
    out.push_back(n.as_table());
  }
  return out;
}

std::string named(const std::string& kind, const Reader& r) {
  const toml::node* node = r.table().get("name");
  return node != nullptr && node->is_string() ? kind + " '" + std::string(**node->as_string()) + "'"
                                              : "[[" + kind + "]]";
}

}  // namespace

bool is_general_mechanism_toml(const std::string& text, const std::string& source) {
  const toml::table root = parse_root(text, source);
  return root.get("body") != nullptr;
}

GeneralMechanism parse_general_mechanism_toml(const std::string& text, const std::string& source) {
  const toml::table root = parse_root(text, source);
  check_toml_keys(
      root,
      {"name", "note", "material", "body", "joint", "flexure", "spring", "load", "input"},
      "the file",
      source);
  // material = "NAME" (data/materials.csv, `flexure materials`): at the top of the file, the
  // modulus of every flexure that gives neither its own E nor its own material.
  const auto material_of = [&](const toml::node& node, const std::string& where) {
    if (!node.is_string()) {
      toml_fail(
          source,
          line_of(node),
          where + " must be a material name, e.g. \"polypropylene\" (see `flexure materials`)");
    }
    try {
      return &find_material(**node.as_string());
    } catch (const InvalidInput& e) {
      toml_fail(source, line_of(node), where + ": " + e.what());
    }
  };
  const MaterialGrade* file_material = nullptr;
  if (const toml::node* n = root.get("material")) file_material = material_of(*n, "material");
  GeneralMechanism m;
  m.source = source;
  m.name = source;
  if (const toml::node* n = root.get("name")) {
    if (!n->is_string()) {
      toml_fail(source, line_of(*n), "name must be a string");
    }
    m.name = **n->as_string();
  }
  if (const toml::node* n = root.get("note"); n != nullptr && !n->is_string()) {
    toml_fail(source, line_of(*n), "note must be a string");
  }

  for (const toml::table* t : tables(root, "body", source)) {
    Reader r(*t, "[[body]]", source);
    check_toml_keys(*t, {"name", "points"}, "[[body]]", source);
    Body b;
    b.name = *r.string("name", true);
    b.line = r.line();
    Reader named_r(*t, "body '" + b.name + "'", source);
    const toml::node* points = t->get("points");
    if (points == nullptr || !points->is_table()) {
      named_r.fail(points, "needs points = { NAME = [x, y], ... } (m, or strings with units)");
    }
    for (const auto& [key, value] : *points->as_table()) {
      const toml::array* xy = value.as_array();
      if (xy == nullptr || xy->size() != 2) {
        named_r.fail(
            &value,
            "point '" + std::string(key.str()) + "' must be an array of two coordinates [x, y]");
      }
      const std::string what = "point '" + std::string(key.str()) + "'";
      b.points.push_back({std::string(key.str()),
                          {named_r.number((*xy)[0], what + " x", Dimension::kLength),
                           named_r.number((*xy)[1], what + " y", Dimension::kLength)}});
    }
    m.bodies.push_back(std::move(b));
  }
  if (m.find_body("ground") == nullptr) {
    // The ground may have no points of its own (nothing is joined to it by name then).
    m.bodies.insert(m.bodies.begin(), Body{"ground", {}, 0});
  }

  for (const toml::table* t : tables(root, "joint", source)) {
    const Reader r(*t, named("joint", Reader(*t, "", source)), source);
    check_toml_keys(*t, {"name", "type", "a", "b", "axis"}, r.item(), source);
    Joint j;
    j.name = *r.string("name", true);
    j.line = r.line();
    const std::string type = *r.string("type", true);
    if (type == "pin") {
      j.kind = JointKind::kPin;
    } else if (type == "slider") {
      j.kind = JointKind::kSlider;
      j.axis_angle = *r.number("axis", Dimension::kAngle, true);
    } else if (type == "weld") {
      j.kind = JointKind::kWeld;
    } else {
      r.fail(t->get("type"), "type '" + type + "' is not one of pin, slider, weld");
    }
    if (j.kind != JointKind::kSlider && t->get("axis") != nullptr) {
      r.fail(t->get("axis"), "axis belongs to a slider only");
    }
    j.a = r.point("a");
    j.b = r.point("b");
    m.joints.push_back(j);
  }

  for (const toml::table* t : tables(root, "flexure", source)) {
    const Reader r(*t, named("flexure", Reader(*t, "", source)), source);
    check_toml_keys(*t,
                    {"name",
                     "a",
                     "b",
                     "width",
                     "thickness",
                     "E",
                     "material",
                     "length",
                     "prbm",
                     "model",
                     "tolerance",
                     "elements",
                     "extensible",
                     "curvature",
                     "width_tip",
                     "thickness_tip"},
                    r.item(),
                    source);
    Flexure f;
    f.name = *r.string("name", true);
    f.line = r.line();
    f.a = r.point("a");
    f.b = r.point("b");
    // A missing section is left at 0 for validate(), which names it as such.
    f.width = r.number("width", Dimension::kLength, false).value_or(0.0);
    f.thickness = r.number("thickness", Dimension::kLength, false).value_or(0.0);
    f.material.E = r.number("E", Dimension::kStress, false).value_or(0.0);
    // E from the flexure's material, else the file's; a flexure's own E replaces the file's
    // material (a flexure of another stock), but not its own material (give one of the two).
    const MaterialGrade* material = file_material;
    if (const toml::node* n = t->get("material")) {
      if (t->get("E") != nullptr) {
        r.fail(n, "gives both E and material; give one (material = \"NAME\" sets E)");
      }
      material = material_of(*n, r.item() + ".material");
    }
    if (material != nullptr && t->get("E") == nullptr) {
      f.material = material->material();  // E, nu, S_y, density of the library's row
      f.material_id = material->id;
    }
    f.length = r.number("length", Dimension::kLength, false).value_or(0.0);
    const std::string prbm = r.string("prbm", false).value_or("small-length");
    if (prbm == "small-length") {
      f.prbm = PrbmKind::kSmallLengthPivot;
    } else if (prbm == "fixed-pinned") {
      f.prbm = PrbmKind::kFixedPinned;
    } else if (prbm == "fixed-guided") {
      f.prbm = PrbmKind::kFixedGuided;
    } else {
      r.fail(t->get("prbm"),
             "prbm '" + prbm + "' is not one of small-length, fixed-pinned, fixed-guided");
    }
    const std::string model = r.string("model", false).value_or("prbm");
    try {
      f.model = parse_flexure_model(model);
    } catch (const InvalidInput& e) {
      r.fail(t->get("model"), e.what());
    }
    // auto's tolerance (per length of the flexure) and the CBCM's or the chain algorithm's
    // elements (--model mixed; absent: the model's default, 6 or 100, Flexure::model_elements).
    if (t->get("tolerance") != nullptr) {
      if (f.model != FlexureModel::kAuto) {
        r.fail(t->get("tolerance"), "tolerance belongs to model = \"auto\"");
      }
      f.tolerance = *r.number("tolerance", std::nullopt, true);
    } else if (f.model == FlexureModel::kAuto) {
      r.fail(t->get("model"),
             "model = \"auto\" needs a tolerance (the largest mapped tip "
             "error per length of the flexure, e.g. tolerance = 1e-3)");
    }
    if (t->get("elements") != nullptr) {
      if (f.model != FlexureModel::kCbcm && f.model != FlexureModel::kChain) {
        r.fail(t->get("elements"), "elements belongs to model = \"cbcm\" or \"chain\"");
      }
      const double n = *r.number("elements", std::nullopt, true);
      if (n != std::floor(n) || n < 1 || n > 2000) {
        r.fail(t->get("elements"),
               fmt::format("elements must be a whole number in [1, 2000] (got {:g})", n));
      }
      f.elements = static_cast<int>(n);
    }
    if (const toml::node* n = t->get("extensible")) {
      const std::optional<bool> v = n->value<bool>();
      if (!v) {
        r.fail(n, "extensible must be true or false");
      }
      f.extensible = *v;
    }
    // The rest shape (general_mechanism.h): a stress-free curvature (1/m, or "20 1/m") and a
    // taper to the tip's section, as `flexure beam --curvature --width-tip --thickness-tip`.
    f.curvature = r.number("curvature", Dimension::kCurvature, false).value_or(0.0);
    f.width_tip = r.number("width_tip", Dimension::kLength, false).value_or(0.0);
    f.thickness_tip = r.number("thickness_tip", Dimension::kLength, false).value_or(0.0);
    for (const char* key : {"width_tip", "thickness_tip"}) {
      if (t->get(key) != nullptr && !(*r.number(key, Dimension::kLength, true) > 0.0)) {
        r.fail(t->get(key), std::string(key) + " must be > 0");
      }
    }
    m.flexures.push_back(f);
  }

  for (const toml::table* t : tables(root, "spring", source)) {
    const Reader r(*t, named("spring", Reader(*t, "", source)), source);
    const std::string type = *r.string("type", true);
    if (type == "linear") {
      check_toml_keys(*t, {"name", "type", "a", "b", "stiffness", "rest_length"}, r.item(), source);
      LinearSpring s;
      s.name = *r.string("name", true);
      s.line = r.line();
      s.a = r.point("a");
      s.b = r.point("b");
      s.stiffness = *r.number("stiffness", std::nullopt, true);
      s.rest_length = r.number("rest_length", Dimension::kLength, false).value_or(-1.0);
      if (t->get("rest_length") != nullptr && s.rest_length < 0.0) {
        r.fail(t->get("rest_length"), "rest_length must be >= 0");
      }
      m.linear_springs.push_back(s);
    } else if (type == "torsion") {
      check_toml_keys(*t, {"name", "type", "a", "b", "stiffness", "rest_angle"}, r.item(), source);
      TorsionSpring s;
      s.name = *r.string("name", true);
      s.line = r.line();
      s.body_a = *r.string("a", true);
      s.body_b = *r.string("b", true);
      s.stiffness = *r.number("stiffness", std::nullopt, true);
      s.rest_angle = r.number("rest_angle", Dimension::kAngle, false).value_or(0.0);
      m.torsion_springs.push_back(s);
    } else {
      r.fail(t->get("type"), "type '" + type + "' is not one of linear, torsion");
    }
  }

  for (const toml::table* t : tables(root, "load", source)) {
    const Reader r(*t, named("load", Reader(*t, "", source)), source);
    check_toml_keys(*t, {"name", "at", "fx", "fy", "moment"}, r.item(), source);
    DeadLoad l;
    l.name = *r.string("name", true);
    l.line = r.line();
    l.at = r.point("at");
    l.fx = r.number("fx", Dimension::kForce, false).value_or(0.0);
    l.fy = r.number("fy", Dimension::kForce, false).value_or(0.0);
    l.moment = r.number("moment", Dimension::kMoment, false).value_or(0.0);
    m.loads.push_back(l);
  }

  if (const toml::node* node = root.get("input")) {
    if (!node->is_table()) {
      toml_fail(source, line_of(*node), "input must be a table ([input])");
    }
    const toml::table& t = *node->as_table();
    const Reader r(t, "[input]", source);
    check_toml_keys(
        t,
        {"coordinate", "point", "to", "control", "start", "stop", "count", "start_rotation"},
        "[input]",
        source);
    Input& in = m.input;
    in.line = r.line();
    const std::string coordinate = *r.string("coordinate", true);
    if (coordinate == "x") {
      in.coordinate = InputCoordinate::kX;
    } else if (coordinate == "y") {
      in.coordinate = InputCoordinate::kY;
    } else if (coordinate == "angle") {
      in.coordinate = InputCoordinate::kAngle;
    } else {
      r.fail(t.get("coordinate"), "coordinate '" + coordinate + "' is not one of x, y, angle");
    }
    const PointRef p = r.point("point");
    in.body = p.body;
    in.point = p.point;
    if (in.coordinate == InputCoordinate::kAngle) {
      const PointRef q = r.point("to");
      if (q.body != p.body) {
        r.fail(t.get("to"),
               "the angle's line must join two points of one body (" + p.text() + ", " + q.text() +
                   ")");
      }
      in.point_to = q.point;
    } else if (t.get("to") != nullptr) {
      r.fail(t.get("to"), "to belongs to an angle input only");
    }
    const std::string control = r.string("control", false).value_or("displacement");
    if (control == "displacement") {
      in.control = InputControl::kDisplacement;
    } else if (control == "force") {
      in.control = InputControl::kForce;
    } else {
      r.fail(t.get("control"), "control '" + control + "' is not one of displacement, force");
    }
    const bool angle = in.coordinate == InputCoordinate::kAngle;
    const Dimension dimension = in.control == InputControl::kDisplacement
                                    ? (angle ? Dimension::kAngle : Dimension::kLength)
                                    : (angle ? Dimension::kMoment : Dimension::kForce);
    in.start = *r.number("start", dimension, true);
    in.stop = *r.number("stop", dimension, true);
    const double count = r.number("count", std::nullopt, false).value_or(51.0);
    if (count != std::floor(count) || count < 2 || count > 100000) {
      r.fail(t.get("count"), "count must be a whole number between 2 and 100000");
    }
    in.count = static_cast<int>(count);
    if (const toml::node* n = t.get("start_rotation")) {
      if (!n->is_table()) {
        r.fail(n, "start_rotation must be a table { BODY = ANGLE, ... }");
      }
      for (const auto& [key, value] : *n->as_table()) {
        in.start_rotation.push_back(
            {std::string(key.str()),
             r.number(value, "start_rotation." + std::string(key.str()), Dimension::kAngle)});
      }
    }
    m.has_input = true;
  }

  m.validate();
  return m;
}

GeneralMechanism load_general_mechanism_toml(const std::string& path) {
  return parse_general_mechanism_toml(io::read_toml_file(path, "mechanism file"), path);
}

}  // namespace flexure::mechanism::general
