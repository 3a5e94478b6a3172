#include <fmt/format.h>
#include <toml++/toml.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <set>
#include <utility>

#include "flexure/io/toml_files.h"
#include "flexure/io/toml_support.h"
#include "flexure/mechanisms/materials_fatigue.h"
#include "flexure/solver/common/names.h"
#include "flexure/solver/common/section.h"
#include "flexure/solver/common/status.h"

namespace flexure::io {
namespace {

// Reads values of one file, each a number or (in physical units) a string with a unit, and
// remembers whether any unit was written (which makes the file physical).
struct Reader {
  std::string source;
  bool any_unit = false;
  std::vector<std::string> warnings;

  // A number or a string with a unit of `dimension` at `key`; nullopt if absent.
  std::optional<double> number(const toml::table& table,
                               const std::string& key,
                               const std::string& where,
                               std::optional<Dimension> dimension = std::nullopt) {
    const std::optional<Quantity> q = quantity(table, key, where, dimension);
    if (!q) return std::nullopt;
    return q->si;
  }

  std::optional<Quantity> quantity(const toml::table& table,
                                   const std::string& key,
                                   const std::string& where,
                                   std::optional<Dimension> dimension) {
    const toml::node* node = table.get(key);
    if (node == nullptr) return std::nullopt;
    if (const std::optional<double> v = toml_number(*node)) {
      if (!std::isfinite(*v)) {
        toml_fail(source, line_of(*node), fmt::format("{}.{} must be a finite number", where, key));
      }
      return Quantity{*v, ""};
    }
    if (dimension && node->is_string()) {
      try {
        Quantity q = parse_quantity(**node->as_string(), *dimension, where + "." + key);
        any_unit = any_unit || q.has_unit();
        return q;
      } catch (const InvalidInput& e) {
        toml_fail(source, line_of(*node), e.what());
      }
    }
    toml_fail(source,
              line_of(*node),
              dimension ? fmt::format("{}.{} must be a number or a string with a unit, e.g. "
                                      "\"50 mm\" ({})",
                                      where,
                                      key,
                                      fmt::join(unit_names(*dimension), ", "))
                        : fmt::format("{}.{} must be a number", where, key));
  }

  double required(const toml::table& table,
                  const std::string& key,
                  const std::string& where,
                  int table_line,
                  std::optional<Dimension> dimension = std::nullopt) {
    const std::optional<double> v = number(table, key, where, dimension);
    if (!v)
      toml_fail(source, table_line, fmt::format("{} is missing the required key '{}'", where, key));
    return *v;
  }

  void warn(const std::string& text) {
    if (!text.empty()) warnings.push_back(fmt::format("{}: {}", source, text));
  }

  // An angle: warn when a plain number (radians) exceeds a full turn (probably degrees).
  std::optional<double> angle(const toml::table& table,
                              const std::string& key,
                              const std::string& where) {
    const std::optional<Quantity> q = quantity(table, key, where, Dimension::kAngle);
    if (!q) return std::nullopt;
    warn(angle_warning(*q, where + "." + key));
    return q->si;
  }
};

const toml::table& as_table(const toml::node& node,
                            const std::string& where,
                            const std::string& source) {
  const toml::table* t = node.as_table();
  if (t == nullptr) toml_fail(source, line_of(node), fmt::format("{} must be a table", where));
  return *t;
}

// A flexible segment's section: E with I, or E with width and thickness (b h^3 / 12). Only in
// physical units; checked against the units once the whole file is read.
struct SectionKeys {
  std::optional<Quantity> E;
  // The segment's material (its own `material`, or the file's for a segment with a section):
  // E where the segment gives none, nu where plate or extensible needs one (docs/chain-toml.md).
  const MaterialGrade* material = nullptr;
  bool own_material = false;
  std::optional<double> I, width, thickness, area;
  std::optional<double> density, g, nu, shear_coefficient;
  std::optional<std::string> plate;
  bool extensible = false;
  int line = 0;
};

// material = "NAME": a row of data/materials.csv (`flexure materials`).
const MaterialGrade& material_of(const toml::node& node,
                                 const std::string& where,
                                 const std::string& source) {
  if (!node.is_string()) {
    toml_fail(source,
              line_of(node),
              where + " must be a material name, e.g. \"steel-1095-hr\" (see `flexure materials`)");
  }
  try {
    return find_material(**node.as_string());
  } catch (const InvalidInput& e) {
    toml_fail(source, line_of(node), fmt::format("{}: {}", where, e.what()));
  }
}

// A pair of numbers or strings with a unit of `dimension`: a distributed load [qx, qy] (force
// per length) or a point [x, y] (length). `form` names the pair and `example` shows one value
// with its unit in the messages.
std::array<double, 2> read_pair(const toml::node& node,
                                const std::string& what,
                                Reader& r,
                                Dimension dimension,
                                const std::string& form,
                                const std::string& example) {
  const toml::array* a = node.as_array();
  if (a == nullptr || a->size() != 2) {
    toml_fail(r.source, line_of(node), what + " must be an array of two values " + form);
  }
  std::array<double, 2> out{};
  for (std::size_t c = 0; c < 2; ++c) {
    const toml::node& v = *a->get(c);
    if (const std::optional<double> x = toml_number(v)) {
      if (!std::isfinite(*x)) toml_fail(r.source, line_of(v), what + " must be finite numbers");
      out[c] = *x;
    } else if (v.is_string()) {
      try {
        const Quantity q = parse_quantity(**v.as_string(), dimension, what);
        r.any_unit = r.any_unit || q.has_unit();
        out[c] = q.si;
      } catch (const InvalidInput& e) {
        toml_fail(r.source, line_of(v), e.what());
      }
    } else {
      toml_fail(r.source,
                line_of(v),
                what + " must contain numbers or strings with a unit (e.g. " + example + ")");
    }
  }
  return out;
}

Segment read_segment(const toml::table& t,
                     int index,
                     Reader& r,
                     SectionKeys& section,
                     const MaterialGrade* file_material) {
  const std::string where = fmt::format("segment {}", index + 1);
  const toml::node* type_node = t.get("type");
  if (type_node == nullptr || !type_node->is_string()) {
    toml_fail(r.source,
              line_of(t),
              fmt::format("{} needs type = \"flexible\" or type = \"rigid\"", where));
  }
  const std::string type = **type_node->as_string();
  if (type == "flexible") {
    check_toml_keys(t,
                    {"type",  "length",    "EI",         "EI_profile", "kappa0",
                     "E",     "I",         "width",      "thickness",  "A",
                     "q",     "q_profile", "q_follower", "density",    "g",
                     "EA",    "GAs",       "extensible", "nu",         "shear_coefficient",
                     "plate", "material"},
                    where,
                    r.source);
    FlexibleSegment s;
    s.length = r.required(t, "length", where, line_of(t), Dimension::kLength);
    s.kappa0 = r.number(t, "kappa0", where).value_or(0.0);
    section.E = r.quantity(t, "E", where, Dimension::kStress);
    section.I = r.number(t, "I", where, Dimension::kSecondMoment);
    section.width = r.number(t, "width", where, Dimension::kLength);
    section.thickness = r.number(t, "thickness", where, Dimension::kLength);
    section.area = r.number(t, "A", where, Dimension::kArea);
    section.density = r.number(t, "density", where, Dimension::kDensity);
    section.g = r.number(t, "g", where, Dimension::kAcceleration);
    section.nu = r.number(t, "nu", where);
    section.shear_coefficient = r.number(t, "shear_coefficient", where);
    if (const toml::node* p = t.get("plate")) {
      if (!p->is_string()) {
        toml_fail(r.source, line_of(*p), where + ".plate must be \"off\", \"on\" or \"auto\"");
      }
      section.plate = **p->as_string();
    }
    if (const toml::node* e = t.get("extensible")) {
      if (!e->is_boolean())
        toml_fail(r.source, line_of(*e), where + ".extensible must be true or false");
      section.extensible = **e->as_boolean();
    }
    section.line = line_of(t);
    // Distributed loads (docs/distributed-loads.md) and axial/shear rigidity (docs/extensible.md).
    if (const toml::node* q = t.get("q")) {
      const std::array<double, 2> v =
          read_pair(*q, where + ".q", r, Dimension::kForcePerLength, "[qx, qy]", "\"-2 N/m\"");
      s.qx = v[0];
      s.qy = v[1];
    }
    if (const toml::node* profile = t.get("q_profile")) {
      const toml::array* a = profile->as_array();
      if (a == nullptr) {
        toml_fail(r.source, line_of(*profile), where + ".q_profile must be an array of [qx, qy]");
      }
      if (t.get("q") != nullptr) {
        toml_fail(r.source, line_of(*profile), where + " gives both q and q_profile; give one");
      }
      for (const toml::node& v : *a) {
        s.q_profile.push_back(read_pair(
            v, where + ".q_profile[]", r, Dimension::kForcePerLength, "[qx, qy]", "\"-2 N/m\""));
      }
    }
    s.q_follower = r.number(t, "q_follower", where, Dimension::kForcePerLength).value_or(0.0);
    if (const std::optional<double> EA = r.number(t, "EA", where, Dimension::kForce)) {
      if (!(*EA > 0.0)) toml_fail(r.source, line_of(t), where + ".EA must be > 0");
      s.EA = *EA;
    }
    if (const std::optional<double> GAs = r.number(t, "GAs", where, Dimension::kForce)) {
      if (!(*GAs > 0.0)) toml_fail(r.source, line_of(t), where + ".GAs must be > 0");
      s.GAs = *GAs;
    }
    if (section.extensible && (t.get("EA") != nullptr || t.get("GAs") != nullptr)) {
      toml_fail(r.source,
                line_of(t),
                where +
                    " gives extensible = true and EA or GAs; give one (extensible = true takes "
                    "EA and GAs from the section, E and nu)");
    }
    const std::optional<double> EI = r.number(t, "EI", where, Dimension::kRigidity);
    if (const toml::node* m = t.get("material")) {
      section.material = &material_of(*m, where + ".material", r.source);
      section.own_material = true;
    }
    const bool has_section = section.E || section.I || section.width || section.thickness ||
                             section.area || section.own_material;
    if (has_section) {
      if (EI || t.get("EI_profile") != nullptr) {
        toml_fail(r.source,
                  line_of(t),
                  where + " gives both EI and a section (E or material, I, width, thickness); " +
                      "give one");
      }
      // The file's material applies to the segments that give a section (not to those of EI).
      if (!section.material) section.material = file_material;
      if (!section.E) {
        if (!section.material) {
          toml_fail(r.source,
                    line_of(t),
                    where + ": a section needs the modulus E (or material = \"NAME\")");
        }
        section.E = Quantity{section.material->E, ""};
      } else if (section.material && section.E->si != section.material->E) {
        // An explicit value replaces the library's, with a note (as --E with --material does).
        r.warn(fmt::format("{}.E = {:.6g} Pa replaces the {:.6g} Pa of material '{}' ({})",
                           where,
                           section.E->si,
                           section.material->E,
                           section.material->id,
                           section.material->source));
      }
      if (section.area && (section.width || section.thickness)) {
        toml_fail(r.source,
                  line_of(t),
                  where + " gives A with width and thickness; A = width thickness already");
      }
      if (section.I.has_value() == (section.width.has_value() || section.thickness.has_value()) ||
          section.width.has_value() != section.thickness.has_value()) {
        toml_fail(r.source,
                  line_of(t),
                  where +
                      ": give E with either I or both width and thickness (rectangular "
                      "section, I = width thickness^3 / 12)");
      }
      for (const auto& [name, value] : {std::pair{"E", section.E->si},
                                        std::pair{"I", section.I.value_or(1.0)},
                                        std::pair{"width", section.width.value_or(1.0)},
                                        std::pair{"thickness", section.thickness.value_or(1.0)},
                                        std::pair{"A", section.area.value_or(1.0)}}) {
        if (!(value > 0.0)) {
          toml_fail(r.source, line_of(t), fmt::format("{}.{} must be > 0", where, name));
        }
      }
      const double I = section.I
                           ? *section.I
                           : Section::rectangle(*section.width, *section.thickness).second_moment();
      s.EI = section.E->si * I;
    } else {
      s.EI = EI.value_or(1.0);
    }
    if (const toml::node* profile = t.get("EI_profile")) {
      const toml::array* a = profile->as_array();
      if (a == nullptr)
        toml_fail(r.source, line_of(*profile), where + ".EI_profile must be an array");
      for (const toml::node& v : *a) {
        const std::optional<double> x = toml_number(v);
        if (!x) toml_fail(r.source, line_of(v), where + ".EI_profile must contain numbers");
        s.EI_profile.push_back(*x);
      }
    }
    return s;
  }
  if (type == "rigid") {
    check_toml_keys(t, {"type", "length", "angle_offset"}, where, r.source);
    RigidSegment s;
    s.length = r.required(t, "length", where, line_of(t), Dimension::kLength);
    s.angle_offset = r.angle(t, "angle_offset", where).value_or(0.0);
    return s;
  }
  toml_fail(r.source,
            line_of(*type_node),
            fmt::format("{}: type '{}' is unknown (allowed: flexible, rigid)", where, type));
}

// node_load.node: an intermediate joint, 1 .. `joints` (= segments - 1), written as an integer or
// an integral float (2.0). Range-checked while still a double or an int64: casting 1e300 to int is
// undefined behaviour (it came out as -2147483648 in the message).
int joint_index(const toml::table& t, const std::string& where, Reader& r, int joints) {
  const double value = r.required(t, "node", where, line_of(t));
  const std::string& source = r.source;
  const toml::node& node = *t.get("node");
  // The value as written: an int64 exactly, a float in its shortest round-trip form.
  const std::string given =
      node.is_integer() ? fmt::format("{}", *node.value<std::int64_t>()) : fmt::format("{}", value);
  if (value != std::floor(value)) {
    toml_fail(source,
              line_of(node),
              fmt::format("{}.node must be an integer joint index (got {})", where, given));
  }
  if (!(value >= 1.0 && value <= joints)) {
    toml_fail(source,
              line_of(node),
              joints < 1 ? fmt::format("{}.node: a chain of one segment has no intermediate joint "
                                       "(got {}); put tip loads in [tip_load]",
                                       where,
                                       given)
                         : fmt::format("{}.node must be an intermediate joint in [1, {}] (joint k "
                                       "is the far end of segment k; got {}); put tip loads in "
                                       "[tip_load]",
                                       where,
                                       joints,
                                       given));
  }
  return static_cast<int>(value);
}

// [[contact]]: one rigid surface (docs/contact.md).
void read_contacts(const toml::node& node, Reader& r, ChainFile& file) {
  const std::string& source = r.source;
  const toml::array* list = node.as_array();
  if (list == nullptr) toml_fail(source, line_of(node), "contact must be an array of tables");
  int i = 0;
  for (const toml::node& n : *list) {
    const std::string where = fmt::format("contact {}", ++i);
    const toml::table& t = as_table(n, where, source);
    ChainFile::Contact contact;
    contact.line = line_of(n);
    const toml::node* type = t.get("type");
    if (type == nullptr || !type->is_string()) {
      toml_fail(source, contact.line, where + " needs type = \"circle\" or \"line\"");
    }
    const std::string name = **type->as_string();
    if (same_name(name, "circle")) {
      check_toml_keys(t, {"type", "center", "radius", "start_tip_load", "steps"}, where, source);
      contact.surface.type = ContactSurfaceType::kCircle;
      const toml::node* c = t.get("center");
      if (c == nullptr)
        toml_fail(source, contact.line, where + " is missing the required key 'center'");
      contact.surface.center =
          read_pair(*c, where + ".center", r, Dimension::kLength, "[x, y]", "\"10 mm\"");
      contact.surface.radius = r.required(t, "radius", where, contact.line, Dimension::kLength);
    } else if (same_name(name, "line")) {
      check_toml_keys(t, {"type", "point", "normal", "start_tip_load", "steps"}, where, source);
      contact.surface.type = ContactSurfaceType::kLine;
      const toml::node* p = t.get("point");
      if (p == nullptr)
        toml_fail(source, contact.line, where + " is missing the required key 'point'");
      contact.surface.point =
          read_pair(*p, where + ".point", r, Dimension::kLength, "[x, y]", "\"10 mm\"");
      const toml::node* nn = t.get("normal");
      if (nn == nullptr)
        toml_fail(source, contact.line, where + " is missing the required key 'normal'");
      const toml::array* a = nn->as_array();
      std::array<double, 2> normal{};
      for (std::size_t k = 0; a != nullptr && a->size() == 2 && k < 2; ++k) {
        const std::optional<double> v = toml_number(*a->get(k));
        if (!v || !std::isfinite(*v))
          a = nullptr;
        else
          normal[k] = *v;
      }
      if (a == nullptr || a->size() != 2 || std::hypot(normal[0], normal[1]) == 0.0) {
        toml_fail(source,
                  line_of(*nn),
                  where +
                      ".normal must be two numbers [nx, ny], not both zero, pointing from the "
                      "stop toward the beam");
      }
      contact.surface.normal = normal;
    } else {
      toml_fail(source,
                line_of(*type),
                fmt::format("{}: type '{}' is unknown (allowed: circle, line)", where, name));
    }
    if (const toml::node* s = t.get("start_tip_load")) {
      const std::string w = where + ".start_tip_load";
      const toml::table& st = as_table(*s, w, source);
      check_toml_keys(st, {"Fx", "Fy", "M"}, w, source);
      contact.start_tip_load.Fx = r.number(st, "Fx", w, Dimension::kForce).value_or(0.0);
      contact.start_tip_load.Fy = r.number(st, "Fy", w, Dimension::kForce).value_or(0.0);
      contact.start_tip_load.M = r.number(st, "M", w, Dimension::kMoment).value_or(0.0);
      contact.start_given = true;
    }
    if (const toml::node* s = t.get("steps")) {
      const std::optional<int64_t> v = s->value<int64_t>();
      if (!s->is_integer() || !v || *v < 1 || *v > 100000) {
        toml_fail(source, line_of(*s), where + ".steps must be an integer in [1, 100000]");
      }
      contact.steps = static_cast<int>(*v);
    }
    file.contacts.push_back(contact);
  }
  // Several surfaces share one continuation: its start load and steps once (or equal).
  const ChainFile::Contact* first_start = nullptr;
  const ChainFile::Contact* first_steps = nullptr;
  for (const ChainFile::Contact& c : file.contacts) {
    if (c.start_given) {
      if (first_start != nullptr && (c.start_tip_load.Fx != first_start->start_tip_load.Fx ||
                                     c.start_tip_load.Fy != first_start->start_tip_load.Fy ||
                                     c.start_tip_load.M != first_start->start_tip_load.M)) {
        toml_fail(source,
                  c.line,
                  "start_tip_load differs between [[contact]] tables: the surfaces share one load "
                  "continuation, so give its start load once");
      }
      if (first_start == nullptr) first_start = &c;
    }
    if (c.steps) {
      if (first_steps != nullptr && *c.steps != *first_steps->steps) {
        toml_fail(source,
                  c.line,
                  "steps differs between [[contact]] tables: the surfaces share one load "
                  "continuation, so give its steps once");
      }
      if (first_steps == nullptr) first_steps = &c;
    }
  }
}

}  // namespace

ChainFile parse_chain_file(const std::string& text, const std::string& source) {
  check_toml_limits(text, source);
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw InvalidInput(fmt::format(
        "{}:{}: TOML syntax error: {}", source, e.source().begin.line, e.description()));
  }
  check_toml_keys(root,
                  {"boundary",
                   "units",
                   "yield_strength",
                   "material",
                   "segment",
                   "tip_load",
                   "tip",
                   "node_load",
                   "contact"},
                  "the file",
                  source);
  Reader r;
  r.source = source;
  ChainFile file;
  SegmentChain& chain = file.chain;
  bool units_si = false;
  if (const toml::node* u = root.get("units")) {
    if (!u->is_string() || !same_name(**u->as_string(), "SI")) {
      toml_fail(source,
                line_of(*u),
                "units must be \"SI\" (metres, newtons, pascals, radians; values may also be "
                "written with a unit, e.g. \"50 mm\")");
    }
    units_si = true;
  }
  if (const toml::node* b = root.get("boundary")) {
    if (!b->is_string()) toml_fail(source, line_of(*b), "boundary must be a string");
    try {
      chain.end = end_condition_from_string(**b->as_string());
    } catch (const InvalidInput& e) {
      toml_fail(source, line_of(*b), e.what());
    }
  }
  // material = "NAME": E (and nu, S_y) of every segment that gives a section without its own E or
  // material (docs/chain-toml.md).
  const MaterialGrade* file_material = nullptr;
  if (const toml::node* m = root.get("material"))
    file_material = &material_of(*m, "material", source);
  const toml::node* segments = root.get("segment");
  if (segments == nullptr) {
    toml_fail(source, 1, "no [[segment]] tables: a chain needs at least one segment");
  }
  const toml::array* list = segments->as_array();
  if (list == nullptr) toml_fail(source, line_of(*segments), "segment must be an array of tables");
  std::vector<SectionKeys> sections;
  int index = 0;
  for (const toml::node& node : *list) {
    sections.emplace_back();
    chain.segments.push_back(
        read_segment(as_table(node, fmt::format("segment {}", index + 1), source),
                     index,
                     r,
                     sections.back(),
                     file_material));
    ++index;
  }
  if (const toml::node* node = root.get("tip_load")) {
    const toml::table& t = as_table(*node, "tip_load", source);
    check_toml_keys(t, {"Fx", "Fy", "M", "follower"}, "tip_load", source);
    chain.tip_load.Fx = r.number(t, "Fx", "tip_load", Dimension::kForce).value_or(0.0);
    chain.tip_load.Fy = r.number(t, "Fy", "tip_load", Dimension::kForce).value_or(0.0);
    chain.tip_load.M = r.number(t, "M", "tip_load", Dimension::kMoment).value_or(0.0);
    chain.tip_load.follower = r.number(t, "follower", "tip_load", Dimension::kForce).value_or(0.0);
  }
  if (const toml::node* node = root.get("tip")) {
    const toml::table& t = as_table(*node, "tip", source);
    check_toml_keys(t, {"x", "y", "theta"}, "tip", source);
    chain.prescribed.x = r.number(t, "x", "tip", Dimension::kLength);
    chain.prescribed.y = r.number(t, "y", "tip", Dimension::kLength);
    chain.prescribed.theta = r.angle(t, "theta", "tip");
  }
  if (const toml::node* node = root.get("node_load")) {
    const toml::array* loads = node->as_array();
    if (loads == nullptr) toml_fail(source, line_of(*node), "node_load must be an array of tables");
    int i = 0;
    for (const toml::node& n : *loads) {
      const std::string where = fmt::format("node_load {}", ++i);
      const toml::table& t = as_table(n, where, source);
      check_toml_keys(t, {"node", "Fx", "Fy", "M"}, where, source);
      NodeLoad load;
      load.node = joint_index(t, where, r, chain.segment_count() - 1);
      load.Fx = r.number(t, "Fx", where, Dimension::kForce).value_or(0.0);
      load.Fy = r.number(t, "Fy", where, Dimension::kForce).value_or(0.0);
      load.M = r.number(t, "M", where, Dimension::kMoment).value_or(0.0);
      chain.node_loads.push_back(load);
    }
  }
  if (const toml::node* node = root.get("contact")) read_contacts(*node, r, file);
  const std::optional<Quantity> yield =
      r.quantity(root, "yield_strength", "the file", Dimension::kStress);
  file.physical = units_si || r.any_unit;
  // Sections and strengths are physical: in a file of "any consistent units" a stress would have
  // no unit to be reported in.
  for (std::size_t k = 0; k < sections.size(); ++k) {
    const SectionKeys& keys = sections[k];
    if (!keys.E) {
      const std::string where = fmt::format("segment {}", k + 1);
      if (keys.density || keys.extensible || keys.nu || keys.shear_coefficient || keys.g ||
          keys.plate) {
        toml_fail(source,
                  keys.line,
                  where +
                      ": density, g, extensible, nu, shear_coefficient and plate need the "
                      "section (E with width and thickness, or with I and A) in physical units");
      }
      file.segments.emplace_back();
      continue;
    }
    const std::string where = fmt::format("segment {}", k + 1);
    if (!file.physical) {
      toml_fail(source,
                keys.line,
                where +
                    " gives a section (E or material, I, width, thickness), which needs physical "
                    "units: add units = \"SI\" at the top of the file (or write values with "
                    "units, e.g. E = \"200 GPa\")");
    }
    // Poisson's ratio: the segment's nu, else its material's where extensible or plate needs one.
    std::optional<double> nu = keys.nu;
    if (keys.material && keys.material->nu && (keys.extensible || keys.plate)) {
      if (!nu) {
        nu = keys.material->nu;
      } else if (*nu != *keys.material->nu) {
        r.warn(fmt::format("{}.nu = {:g} replaces the {:g} of material '{}' ({})",
                           where,
                           *nu,
                           *keys.material->nu,
                           keys.material->id,
                           keys.material->source));
      }
    }
    // E, I = b h^3/12 or the given I, and the area b h or the given A (the same numbers as the
    // Section and Material of `file.segments` below).
    const double E = keys.E->si;
    const double I =
        keys.I ? *keys.I : Section::rectangle(*keys.width, *keys.thickness).second_moment();
    std::optional<double> area = keys.area;
    if (keys.width) area = *keys.width * *keys.thickness;
    auto& segment = std::get<FlexibleSegment>(chain.segments[k]);
    if ((keys.density || keys.extensible) && !area) {
      toml_fail(source,
                keys.line,
                where +
                    ": density and extensible = true need the section's area: give width and "
                    "thickness, or A with I");
    }
    if (!keys.density && keys.g) {
      toml_fail(source, keys.line, where + ": g is the gravity of the self-weight; give density");
    }
    if (keys.density) {
      // Self-weight per unit length rho A g along -y of the root frame (standard gravity unless
      // g is given).
      if (!(*keys.density > 0.0)) toml_fail(source, keys.line, where + ".density must be > 0");
      const double g = keys.g.value_or(9.80665);
      if (!(g >= 0.0)) toml_fail(source, keys.line, where + ".g must be >= 0");
      const double weight = *keys.density * *area * g;
      segment.qy -= segment.q_profile.empty() ? weight : 0.0;
      for (auto& q : segment.q_profile) q[1] -= weight;
    }
    if (keys.extensible) {
      if (!nu) {
        toml_fail(source,
                  keys.line,
                  where + ": extensible = true needs Poisson's ratio nu (or a material with nu)");
      }
      if (!(*nu > -1.0 && *nu < 0.5)) {
        toml_fail(source, keys.line, where + ".nu must be in (-1, 0.5)");
      }
      // Timoshenko's shear coefficient: 5/6 for a rectangle (Cowper 1966 gives 10(1+nu)/(12+11nu);
      // 5/6 is the common engineering value); another section must give its own.
      if (!keys.shear_coefficient && !keys.width) {
        toml_fail(source,
                  keys.line,
                  where +
                      ": extensible = true with a section given by I and A needs "
                      "shear_coefficient (5/6 is taken only for a rectangle)");
      }
      const double kappa = keys.shear_coefficient.value_or(5.0 / 6.0);
      if (!(kappa > 0.0 && kappa <= 1.0)) {
        toml_fail(source, keys.line, where + ".shear_coefficient must be in (0, 1]");
      }
      segment.EA = E * *area;
      segment.GAs = kappa * E / (2.0 * (1.0 + *nu)) * *area;
    } else if (keys.shear_coefficient) {
      toml_fail(
          source, keys.line, where + ": shear_coefficient is used with extensible = true only");
    }
    // The bending modulus (docs/plate-modulus.md): E, or E/(1 - nu^2) for a wide strip. With
    // plate = "on" the segment's EI is E I/(1 - nu^2) (PhysicalChain::validate() expects it so,
    // and the chain alone then bends as a plate); "auto" keeps E I until solve_physical_chain
    // decides.
    PlateRule plate = PlateRule::kOff;
    if (keys.plate) {
      try {
        plate = plate_rule_from_string(*keys.plate, where + ".plate");
        const ModulusChoice choice = choose_modulus(
            plate == PlateRule::kAuto ? PlateRule::kOff : plate, E, nu, {}, {}, {}, where);
        if (plate == PlateRule::kAuto) {
          // Checked now (nu, width and thickness), decided after the solve.
          choose_modulus(PlateRule::kAuto, E, nu, keys.width, keys.thickness, 0.0, where);
        }
        segment.EI = choice.effective_E * I;
      } catch (const InvalidInput& e) {
        toml_fail(source, keys.line, e.what());
      }
    }
    if (nu && !(*nu > -1.0 && *nu < 0.5)) {
      toml_fail(source, keys.line, where + ".nu must be in (-1, 0.5)");
    }
    if (keys.nu && !keys.extensible && !keys.plate) {
      toml_fail(source,
                keys.line,
                where + ": nu is used with extensible = true or plate = \"on\"/\"auto\" only");
    }
    // The same as the library's types: the rectangle or the general I (with its thickness), and
    // the material (nu where extensible gives it, else the default; the yield strength below).
    SegmentProperties properties{keys.width ? Section::rectangle(*keys.width, *keys.thickness)
                                            : Section::general(*keys.I, keys.thickness),
                                 Material{},
                                 keys.width ? std::optional<double>() : keys.area};
    properties.material.E = keys.E->si;
    if (nu) properties.material.nu = *nu;
    properties.material.density = keys.density;
    properties.plate = plate;
    file.segments.push_back(properties);
    r.warn(modulus_warning(*keys.E, where + ".E"));
    if (keys.thickness) {
      r.warn(thickness_warning(
          *keys.thickness, std::get<FlexibleSegment>(chain.segments[k]).length, where));
    }
  }
  if (file_material && !file.physical) {
    toml_fail(source,
              line_of(*root.get("material")),
              "material needs physical units (its values are SI): add units = \"SI\" at the top "
              "of the file (or write values with units, e.g. width = \"10 mm\")");
  }
  // The strength of the safety factor: yield_strength, else the materials' (S_y, or S_ut of a
  // brittle one: MaterialGrade::static_strength), one for the whole chain (PhysicalChain::validate:
  // the safety factor is that strength over the chain's largest stress).
  std::optional<double> strength;
  if (yield) {
    if (!file.physical) {
      toml_fail(source,
                line_of(*root.get("yield_strength")),
                "yield_strength needs physical units: add units = \"SI\" at the top of the file "
                "(or write it with a unit, e.g. \"1.5 GPa\")");
    }
    if (!(yield->si > 0.0)) {
      toml_fail(source, line_of(*root.get("yield_strength")), "yield_strength must be > 0");
    }
    strength = yield->si;
  }
  std::string strength_from;  // the material and where it is named, for messages
  std::set<std::string> noted;
  const auto material_strength = [&](const MaterialGrade* m, const std::string& where, int line) {
    if (m == nullptr) return;
    const std::optional<double> s = m->static_strength();
    if (!s) return;
    const std::string what = fmt::format("material '{}' of {}", m->id, where);
    if (yield) {
      if (*s != yield->si && noted.insert(m->id).second) {
        r.warn(
            fmt::format("yield_strength = {:.6g} Pa replaces the {:.6g} Pa of material '{}' ({})",
                        yield->si,
                        *s,
                        m->id,
                        m->source));
      }
    } else if (strength && *strength != *s) {
      toml_fail(source,
                line,
                fmt::format("{} has strength {:.6g} Pa, {} {:.6g} Pa: one yield strength per chain "
                            "(the safety factor is it over the largest stress); give "
                            "yield_strength at the top of the file",
                            what,
                            *s,
                            strength_from,
                            *strength));
    } else {
      strength = s;
      strength_from = what;
    }
  };
  if (file_material) material_strength(file_material, "the file", line_of(*root.get("material")));
  for (std::size_t k = 0; k < sections.size(); ++k) {
    if (sections[k].own_material) {
      material_strength(sections[k].material, fmt::format("segment {}", k + 1), sections[k].line);
    }
  }
  if (strength) {
    file.yield_strength = *strength;
    for (std::optional<SegmentProperties>& properties : file.segments) {
      if (properties) properties->material.yield_strength = *strength;
    }
  }
  try {
    chain.validate();
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("{}: {}", source, e.what()));
  }
  file.warnings = std::move(r.warnings);
  return file;
}

ChainFile read_chain_file(const std::string& path) {
  return parse_chain_file(read_toml_file(path, "--chain file"), path);
}

SegmentChain parse_chain_toml(const std::string& text, const std::string& source) {
  ChainFile file = parse_chain_file(text, source);
  if (!file.contacts.empty()) {
    toml_fail(source,
              file.contacts.front().line,
              "a [[contact]] is solved by `flexure beam --chain FILE` only (docs/contact.md)");
  }
  return std::move(file.chain);
}

SegmentChain read_chain_toml(const std::string& path) {
  return parse_chain_toml(read_toml_file(path, "--chain file"), path);
}

}  // namespace flexure::io
