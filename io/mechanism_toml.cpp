#include <fmt/format.h>
#include <toml++/toml.h>

#include <array>
#include <cmath>
#include <optional>
#include <set>
#include <sstream>

#include "flexure/elements/prbm_element.h"
#include "flexure/io/toml_files.h"
#include "flexure/io/toml_support.h"
#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/materials_fatigue.h"
#include "flexure/solver/common/section.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {
namespace {

using io::check_toml_keys;
using io::line_of;
using io::toml_fail;

// A positive finite number at `key` (required unless `fallback` is given); a quantity of
// `dimension` may also be written with a unit, "50 mm" (solver/common/section.h). Plain numbers
// are SI.
double positive(const toml::table& t,
                const std::string& key,
                const std::string& where,
                const std::string& source,
                int table_line,
                std::optional<io::Dimension> dimension,
                std::optional<double> fallback = {}) {
  const toml::node* node = t.get(key);
  if (node == nullptr) {
    if (fallback) return *fallback;
    toml_fail(source, table_line, fmt::format("{} is missing the required key '{}'", where, key));
  }
  // Top-level keys are named bare ("r2"), table keys dotted ("ground.thickness").
  const std::string name = where == "the file" ? key : where + "." + key;
  std::optional<double> v = io::toml_number(*node);
  if (!v && dimension && node->is_string()) {
    try {
      v = io::parse_quantity(**node->as_string(), *dimension, name).si;
    } catch (const InvalidInput& e) {
      toml_fail(source, line_of(*node), e.what());
    }
  }
  if (!v) {
    toml_fail(source,
              line_of(*node),
              dimension ? fmt::format("{} must be a number (SI) or a string with a unit, e.g. "
                                      "\"50 mm\"",
                                      name)
                        : fmt::format("{} must be a number", name));
  }
  if (!std::isfinite(*v) || *v <= 0.0) {
    toml_fail(source, line_of(*node), fmt::format("{} must be finite and > 0 (got {})", name, *v));
  }
  return *v;
}

const char* kJointTables[3] = {"ground", "middle", "slider"};

// A finite number >= 0 (masses and spring constants may be zero).
double nonnegative(const toml::node& node, const std::string& name, const std::string& source) {
  const std::optional<double> v = io::toml_number(node);
  if (!v) toml_fail(source, line_of(node), fmt::format("{} must be a number", name));
  if (!std::isfinite(*v) || *v < 0.0) {
    toml_fail(source, line_of(node), fmt::format("{} must be finite and >= 0 (got {})", name, *v));
  }
  return *v;
}

// [dynamics]: m2, m3, m_slider (kg) and spring_constants = [k1, k2, k3] (N m per half), all
// optional here; flexure dynamics says which it needs (dynamics.h).
dynamics::DynamicsData parse_dynamics_table(const toml::table& root, const std::string& source) {
  dynamics::DynamicsData data;
  data.source = source;
  const toml::node* node = root.get("dynamics");
  if (node == nullptr) return data;
  if (!node->is_table()) {
    toml_fail(source, line_of(*node), "dynamics must be a table ([dynamics])");
  }
  const toml::table& t = *node->as_table();
  data.line = line_of(t);
  check_toml_keys(t, {"m2", "m3", "m_slider", "spring_constants"}, "[dynamics]", source);
  if (const toml::node* n = t.get("m2")) data.m2 = nonnegative(*n, "dynamics.m2", source);
  if (const toml::node* n = t.get("m3")) data.m3 = nonnegative(*n, "dynamics.m3", source);
  if (const toml::node* n = t.get("m_slider")) {
    data.m_slider = nonnegative(*n, "dynamics.m_slider", source);
  }
  if (const toml::node* n = t.get("spring_constants")) {
    const toml::array* a = n->as_array();
    if (a == nullptr || a->size() != 3) {
      toml_fail(source,
                line_of(*n),
                "dynamics.spring_constants must be an array of three numbers [k1, k2, k3] (N m "
                "per half, 0 at a pin)");
    }
    std::array<double, 3> k{};
    for (std::size_t i = 0; i < 3; ++i) {
      k[i] = nonnegative((*a)[i], fmt::format("dynamics.spring_constants[{}]", i), source);
    }
    data.spring_constants = k;
  }
  return data;
}

}  // namespace

MechanismDesign parse_mechanism_toml(const std::string& text, const std::string& source) {
  return parse_mechanism_file(text, source).design;
}

MechanismFile parse_mechanism_file(const std::string& text, const std::string& source) {
  io::check_toml_limits(text, source);
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw InvalidInput(fmt::format(
        "{}:{}: TOML syntax error: {}", source, e.source().begin.line, e.description()));
  }
  check_toml_keys(root,
                  {"name",
                   "config",
                   "note",
                   "r2",
                   "r3",
                   "stroke",
                   "spring_rule",
                   "material",
                   "ground",
                   "middle",
                   "slider",
                   "dynamics",
                   "force_of",
                   "plate",
                   // Written by design mechanism for the builder (mechanism_geometry_toml.h);
                   // ignored here: it follows from the keys above.
                   "geometry"},
                  "the file",
                  source);
  MechanismDesign d;
  // Optional strings; another type was silently replaced by the default.
  auto optional_string =
      [&](const toml::table& t, const std::string& key, const std::string& name) {
        const toml::node* node = t.get(key);
        if (node == nullptr) return std::optional<std::string>();
        if (!node->is_string()) toml_fail(source, line_of(*node), name + " must be a string");
        return std::optional<std::string>(**node->as_string());
      };
  d.name = optional_string(root, "name", "name").value_or(source);
  d.note = optional_string(root, "note", "note").value_or("");
  const toml::node* config = root.get("config");
  if (config == nullptr || !config->is_string()) {
    toml_fail(source,
              1,
              "the file needs config = \"lpp\" (one of spp, lpp, psp, plp, ssp, slp, sps, "
              "lps, sss, or a modified configuration of paper 004 such as lplm)");
  }
  // The pivot letters as written: a thesis configuration ("lps") or a modified one ("lplm":
  // every flexible segment fixed-fixed by default). The thesis pattern the solvers use is known
  // once each joint's segment kind is read (a fixed-fixed segment is a centred flexure, "s").
  const std::string written = **config->as_string();
  const ModifiedConfiguration* modified = nullptr;
  std::string letters = written;
  if (written.size() == 4 && written.back() == 'm') {
    try {
      modified = &find_modified_configuration(written);
    } catch (const InvalidInput& e) {
      toml_fail(source, line_of(*config), fmt::format("config: {}", e.what()));
    }
    letters = written.substr(0, 3);
  } else if (written.size() != 3 || written.find_first_not_of("psl") != std::string::npos) {
    try {
      cfm::find_cfm_configuration(written);  // throws, listing the nine
    } catch (const InvalidInput& e) {
      toml_fail(source,
                line_of(*config),
                fmt::format("config: {} (or a modified configuration of paper 004 such as lplm)",
                            e.what()));
    }
  }
  d.r2 = positive(root, "r2", "the file", source, 1, io::Dimension::kLength);
  d.r3 = positive(root, "r3", "the file", source, 1, io::Dimension::kLength);
  d.stroke = positive(root, "stroke", "the file", source, 1, io::Dimension::kLength);
  // The material: material = "NAME" (a data/materials.csv id), or a [material] table with E and
  // yield_strength, optional fatigue values, and a name that, when the library knows it, supplies
  // every value the table leaves out (docs/materials.md).
  std::vector<std::string> material_notes;
  const toml::node* mat = root.get("material");
  if (mat != nullptr && mat->is_string()) {
    try {
      apply_material(d, find_material(**mat->as_string()));
    } catch (const InvalidInput& e) {
      toml_fail(source, line_of(*mat), fmt::format("material: {}", e.what()));
    }
  } else if (mat == nullptr || !mat->is_table()) {
    toml_fail(source,
              mat ? line_of(*mat) : 1,
              "the file needs material = \"NAME\" (see `flexure materials`) or a [material] "
              "table with E and yield_strength");
  } else {
    const toml::table& m = *mat->as_table();
    check_toml_keys(m,
                    {"E",
                     "yield_strength",
                     "name",
                     "ultimate_strength",
                     "endurance_limit",
                     "endurance_cycles",
                     "nu"},
                    "[material]",
                    source);
    const std::optional<std::string> name = optional_string(m, "name", "material.name");
    const MaterialGrade* grade = nullptr;
    if (name) {
      try {
        grade = &find_material(*name);
      } catch (const InvalidInput& e) {
        // Without E or S_y the name must supply them; with both it only documents the file.
        if (m.get("E") == nullptr || m.get("yield_strength") == nullptr) {
          toml_fail(source, line_of(*m.get("name")), fmt::format("material.name: {}", e.what()));
        }
      }
    }
    if (grade != nullptr) {
      try {
        apply_material(d, *grade);
      } catch (const InvalidInput& e) {
        if (m.get("yield_strength") == nullptr) {
          toml_fail(source, line_of(*m.get("name")), fmt::format("material.name: {}", e.what()));
        }
        d.material_id = grade->id;  // S_y comes from the table below
        d.material.E = grade->E;
        d.ultimate_strength = grade->ultimate_strength;
        d.endurance_limit = grade->fatigue_strength;
        d.endurance_cycles = grade->fatigue_cycles;
        d.ductile = grade->ductile;
      }
    }
    // A value in the table replaces the library's, with a note when it differs.
    const auto value = [&](const char* key, std::optional<io::Dimension> dim, double library) {
      const double v = positive(m,
                                key,
                                "material",
                                source,
                                line_of(m),
                                dim,
                                library > 0.0 ? std::optional<double>(library) : std::nullopt);
      if (grade != nullptr && library > 0.0 && m.get(key) != nullptr && v != library) {
        material_notes.push_back(
            fmt::format("material.{} = {:.6g} replaces the {:.6g} of '{}' ({})",
                        key,
                        v,
                        library,
                        grade->id,
                        grade->source));
      }
      return v;
    };
    d.material.E = value("E", io::Dimension::kStress, grade ? d.material.E : 0.0);
    d.material.yield_strength = value("yield_strength",
                                      io::Dimension::kStress,
                                      grade ? d.material.yield_strength.value_or(0.0) : 0.0);
    if (m.get("ultimate_strength") != nullptr || d.ultimate_strength) {
      d.ultimate_strength =
          value("ultimate_strength", io::Dimension::kStress, d.ultimate_strength.value_or(0.0));
    }
    if (m.get("endurance_limit") != nullptr || d.endurance_limit) {
      d.endurance_limit =
          value("endurance_limit", io::Dimension::kStress, d.endurance_limit.value_or(0.0));
      if (m.get("endurance_limit") != nullptr) d.endurance_cycles.reset();
    }
    if (const toml::node* nu = m.get("nu")) {
      const std::optional<double> v = nu->value<double>();
      if (!v || !(*v > -1.0 && *v < 0.5)) {
        toml_fail(source, line_of(*nu), "material.nu must be a number in (-1, 0.5)");
      }
      d.set_nu(*v);
    }
    if (m.get("endurance_cycles") != nullptr) {
      d.endurance_cycles =
          positive(m, "endurance_cycles", "material", source, line_of(m), std::nullopt);
    }
  }
  // The bending modulus of the strips (docs/plate-modulus.md).
  if (const toml::node* plate = root.get("plate")) {
    if (!plate->is_string()) {
      toml_fail(source, line_of(*plate), "plate must be \"off\", \"on\" or \"auto\"");
    }
    try {
      d.plate = plate_rule_from_string(**plate->as_string(), "plate");
    } catch (const InvalidInput& e) {
      toml_fail(source, line_of(*plate), e.what());
    }
    if (d.plate != PlateRule::kOff && !d.nu_given) {
      toml_fail(source,
                line_of(*plate),
                fmt::format("plate = \"{}\" needs Poisson's ratio: give [material].nu (or a "
                            "library material with nu)",
                            to_string(d.plate)));
    }
  }
  std::string pattern;
  for (int p = 1; p <= 3; ++p) {
    const std::string name = kJointTables[p - 1];
    const toml::node* node = root.get(name);
    JointDesign& j = d.joints[p - 1];
    const char letter = letters[p - 1];
    if (letter == 'p') {
      j.type = PivotType::kPin;
      pattern += 'p';
      if (node != nullptr) {
        toml_fail(source,
                  line_of(*node),
                  fmt::format("[{}]: pivot {} of configuration '{}' is a pin and takes no table",
                              name,
                              p,
                              written));
      }
      continue;
    }
    if (node == nullptr || !node->is_table()) {
      toml_fail(source,
                node ? line_of(*node) : 1,
                fmt::format("configuration '{}' needs a [{}] table (thickness, width{})",
                            written,
                            name,
                            modified != nullptr ? ", length"
                            : letter == 's'     ? ", optional length"
                                                : ""));
    }
    const toml::table& t = *node->as_table();
    // Segment kind: the thesis's element for the letter unless "fixed-fixed" (the default of a
    // modified configuration).
    bool fixed_fixed = modified != nullptr;
    if (const toml::node* seg = t.get("segment")) {
      const std::optional<std::string> v = seg->value<std::string>();
      const std::string allowed =
          letter == 'l' ? "fixed-fixed, fixed-pinned" : "fixed-fixed, small-length";
      if (!v || (*v != "fixed-fixed" && *v != (letter == 'l' ? "fixed-pinned" : "small-length"))) {
        toml_fail(source,
                  line_of(*seg),
                  fmt::format("{}.segment must be one of {} for an {} pivot (got {})",
                              name,
                              allowed,
                              letter,
                              v ? "'" + *v + "'" : std::string("a non-string")));
      }
      if (modified != nullptr && *v != "fixed-fixed") {
        toml_fail(source,
                  line_of(*seg),
                  fmt::format("{}.segment: every flexible segment of the modified configuration "
                              "'{}' is fixed-fixed",
                              name,
                              written));
      }
      fixed_fixed = *v == "fixed-fixed";
    }
    if (fixed_fixed) {
      j.type = PivotType::kSmall;
      j.segment = SegmentKind::kFixedFixed;
      j.paper_letter = letter;
      j.table2_factor = modified != nullptr ? modified->table2_factor[p - 1] : 0.3;
      check_toml_keys(
          t,
          letter == 'l'
              ? std::set<std::string>{"thickness", "width", "length", "segment", "table2_factor"}
              : std::set<std::string>{"thickness", "width", "length", "segment"},
          "[" + name + "] (fixed-fixed segment)",
          source);
      j.length = positive(
          t, "length", name + " (fixed-fixed segment)", source, line_of(t), io::Dimension::kLength);
      if (letter == 'l') {
        j.table2_factor =
            positive(t, "table2_factor", name, source, line_of(t), std::nullopt, j.table2_factor);
      }
    } else if (letter == 's') {
      j.type = PivotType::kSmall;
      check_toml_keys(t, {"thickness", "width", "length", "segment"}, "[" + name + "]", source);
      j.length = positive(t, "length", name, source, line_of(t), io::Dimension::kLength, 0.0);
    } else {
      // An l segment is r/gamma long by definition (thesis Table 8.1): its length is derived.
      j.type = PivotType::kLong;
      check_toml_keys(t,
                      {"thickness", "width", "segment"},
                      fmt::format("[{}] (l segment, length = r/{:g})",
                                  name,
                                  howell_average_fixed_pinned().constants().gamma),
                      source);
    }
    pattern += j.type == PivotType::kSmall ? 's' : 'l';
    j.thickness = positive(t, "thickness", name, source, line_of(t), io::Dimension::kLength);
    j.width = positive(t, "width", name, source, line_of(t), io::Dimension::kLength);
  }
  d.config = pattern;
  try {
    cfm::find_cfm_configuration(d.config);
  } catch (const InvalidInput&) {
    toml_fail(
        source,
        line_of(*config),
        fmt::format("config '{}' with these segments is the pattern '{}', not one of the nine "
                    "(spp, lpp, psp, plp, ssp, slp, sps, lps, sss): give its l segments "
                    "segment = \"fixed-fixed\" (or write the modified name '{}m')",
                    written,
                    pattern,
                    written));
  }
  if (modified != nullptr || pattern != written) d.paper_config = letters + "m";
  if (const toml::node* rule = root.get("spring_rule")) {
    const std::optional<std::string> v = rule->value<std::string>();
    try {
      if (!v) throw InvalidInput("spring_rule must be a string (pure-bending, table2, table5)");
      d.spring_rule = parse_spring_rule(*v);
      if (!has_fixed_fixed(d)) {
        throw InvalidInput(
            "spring_rule applies to fixed-fixed segments only; this design has none");
      }
    } catch (const InvalidInput& e) {
      toml_fail(source, line_of(*rule), e.what());
    }
  } else {
    d.spring_rule = kDefaultSpringRule;
  }
  try {
    d.finalise();
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("{}: {}", source, e.what()));
  }
  // What the design's forces are reported as unless --force-of says otherwise (written by
  // `flexure design mechanism` for the force it was specified by).
  if (const toml::node* of = root.get("force_of")) {
    const std::optional<std::string> v = of->value<std::string>();
    try {
      if (!v) throw InvalidInput("not a string");
      d.force_of = parse_force_of(*v);
    } catch (const InvalidInput&) {
      toml_fail(source,
                line_of(*of),
                fmt::format("force_of = {} is unknown; allowed: \"half\" (one half of the "
                            "symmetric mechanism) or \"whole\" (both halves on one slider)",
                            v ? "'" + *v + "'" : std::string("a non-string")));
    }
  }
  MechanismFile file{d, parse_dynamics_table(root, source), {}};
  const auto warn = [&](const std::string& text) {
    if (!text.empty()) file.warnings.push_back(fmt::format("{}: {}", source, text));
  };
  for (const std::string& n : material_notes) warn(n);
  warn(io::modulus_warning({d.material.E, ""}, "material.E"));
  for (std::size_t k = 0; k < d.joints.size(); ++k) {
    const JointDesign& j = d.joints[k];
    if (j.thickness > 0.0 && j.length > 0.0) {
      warn(io::thickness_warning(j.thickness, j.length, kJointTables[k]));
    }
  }
  return file;
}

MechanismDesign load_mechanism_toml(const std::string& path) {
  return load_mechanism_file(path).design;
}

MechanismFile load_mechanism_file(const std::string& path) {
  return parse_mechanism_file(io::read_toml_file(path, "mechanism file"), path);
}

}  // namespace flexure::mechanism

namespace flexure::mechanism {
namespace {

// A TOML float that reads back to the same double (17 significant digits, always a float).
std::string toml_number(double v) {
  std::string s = fmt::format("{:.17g}", v);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

// A TOML basic string with toml++'s escaping.
std::string toml_string(const std::string& s) {
  std::ostringstream out;
  out << toml::value<std::string>(s);
  return out.str();
}

}  // namespace

std::string mechanism_toml(const MechanismDesign& d, const std::string& comment) {
  std::string out;
  std::istringstream lines(comment);
  for (std::string line; std::getline(lines, line);) out += "# " + line + "\n";
  if (d.inverted) {
    out +=
        "# The inversion of this design (slider block fixed, mechanisms/inversion.h) is the same\n"
        "# mechanism read the other way; written here in its original orientation.\n";
  }
  // The pivot letters as parse_mechanism_toml reads them: the paper's string of a modified
  // configuration without its trailing m, with each fixed-fixed segment named below.
  const std::string letters = d.paper_config.empty() ? d.config : d.paper_config.substr(0, 3);
  // A modified configuration of paper 004 by its name, so that the reader takes its Table 2
  // factors; else the letters with each fixed-fixed segment named.
  std::string config = letters;
  if (!d.paper_config.empty()) {
    try {
      find_modified_configuration(d.paper_config);
      config = d.paper_config;
    } catch (const InvalidInput&) {
    }
  }
  out += fmt::format("name = {}\n", toml_string(d.name));
  out += fmt::format("config = {}\n", toml_string(config));
  if (!d.note.empty()) out += fmt::format("note = {}\n", toml_string(d.note));
  out +=
      fmt::format("r2 = {}            # m, PRBM crank (pivot 1 to pivot 2)\n", toml_number(d.r2));
  out += fmt::format("r3 = {}            # m, PRBM coupler\n", toml_number(d.r3));
  out += fmt::format("stroke = {}        # m, slider travel\n", toml_number(d.stroke));
  if (d.force_of) {
    out += fmt::format("force_of = {}       # the forces `flexure mechanism analyze` reports: {}\n",
                       toml_string(*d.force_of == ForceOf::kOneHalf ? "half" : "whole"),
                       force_of_label(*d.force_of));
  }
  if (d.plate != PlateRule::kOff) {
    out +=
        fmt::format("plate = {}          # bending modulus E/(1 - nu^2) (docs/plate-modulus.md)\n",
                    toml_string(to_string(d.plate)));
  }
  bool fixed_fixed = false;
  for (const JointDesign& j : d.joints) fixed_fixed |= j.segment == SegmentKind::kFixedFixed;
  if (fixed_fixed) {
    out += fmt::format("spring_rule = {}\n", toml_string(spring_rule_name(d.spring_rule)));
  }
  out += "\n[material]\n";
  if (!d.material_id.empty()) {
    out += fmt::format("name = {}  # data/materials.csv (`flexure materials`)\n",
                       toml_string(d.material_id));
  }
  if (d.plate != PlateRule::kOff && d.nu_given) {
    out += fmt::format("nu = {}\n", toml_number(d.material.nu));
  }
  out += fmt::format("E = {}               # Pa\nyield_strength = {}  # Pa\n",
                     toml_number(d.material.E),
                     toml_number(d.material.yield_strength.value_or(0.0)));
  if (d.ultimate_strength) {
    out += fmt::format("ultimate_strength = {}  # Pa\n", toml_number(*d.ultimate_strength));
  }
  if (d.endurance_limit) {
    out += fmt::format("endurance_limit = {}  # Pa, uncorrected S_e' (Howell eq. 3.74)\n",
                       toml_number(*d.endurance_limit));
  }
  if (d.endurance_cycles) {
    out += fmt::format("endurance_cycles = {}  # life of that fatigue strength\n",
                       toml_number(*d.endurance_cycles));
  }
  for (int p = 1; p <= 3; ++p) {
    const JointDesign& j = d.joints[p - 1];
    if (j.type == PivotType::kPin) continue;
    out += fmt::format("\n[{}]                 # pivot {}\n", kJointTables[p - 1], p);
    out += fmt::format("thickness = {}  # m\nwidth = {}      # m\n",
                       toml_number(j.thickness),
                       toml_number(j.width));
    if (j.segment == SegmentKind::kFixedFixed) {
      out += "segment = \"fixed-fixed\"\n";
      out += fmt::format("length = {}     # m\n", toml_number(j.length));
      if (letters[p - 1] == 'l')
        out += fmt::format("table2_factor = {}\n", toml_number(j.table2_factor));
    } else if (j.type == PivotType::kSmall) {
      out += fmt::format("length = {}     # m\n", toml_number(j.length));
    }
  }
  return out;
}

}  // namespace flexure::mechanism
