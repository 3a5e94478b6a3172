#include "mechanisms/mechanism_toml.h"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <fstream>
#include <set>
#include <sstream>

#include "io/toml_support.h"
#include "solver/common/errors.h"

namespace flexure::mechanism {
namespace {

using io::check_toml_keys;
using io::line_of;
using io::toml_fail;

// A positive finite number at `key` (required unless `fallback` is given).
double positive(const toml::table& t,
                const std::string& key,
                const std::string& where,
                const std::string& source,
                int table_line,
                std::optional<double> fallback = {}) {
  const toml::node* node = t.get(key);
  if (node == nullptr) {
    if (fallback) return *fallback;
    toml_fail(source, table_line, fmt::format("{} is missing the required key '{}'", where, key));
  }
  const std::optional<double> v = node->value<double>();
  if (!v) toml_fail(source, line_of(*node), fmt::format("{}.{} must be a number", where, key));
  if (!std::isfinite(*v) || *v <= 0.0) {
    toml_fail(source,
              line_of(*node),
              fmt::format("{}.{} must be finite and > 0 (got {})", where, key, *v));
  }
  return *v;
}

const char* kJointTables[3] = {"ground", "middle", "slider"};

}  // namespace

MechanismDesign parse_mechanism_toml(const std::string& text, const std::string& source) {
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw InvalidInput(fmt::format(
        "{}:{}: TOML syntax error: {}", source, e.source().begin.line, e.description()));
  }
  check_toml_keys(
      root,
      {"name", "config", "note", "r2", "r3", "stroke", "material", "ground", "middle", "slider"},
      "the file",
      source);
  MechanismDesign d;
  d.name = root["name"].value_or(std::string(source));
  d.note = root["note"].value_or(std::string());
  const toml::node* config = root.get("config");
  if (config == nullptr || !config->is_string()) {
    toml_fail(source,
              1,
              "the file needs config = \"lpp\" (one of spp, lpp, psp, plp, ssp, slp, sps, "
              "lps, sss)");
  }
  d.config = **config->as_string();
  const cfm::CfmConfiguration* cfg = nullptr;
  try {
    cfg = &cfm::find_cfm_configuration(d.config);
  } catch (const InvalidInput& e) {
    toml_fail(source, line_of(*config), fmt::format("config: {}", e.what()));
  }
  d.r2 = positive(root, "r2", "the file", source, 1);
  d.r3 = positive(root, "r3", "the file", source, 1);
  d.stroke = positive(root, "stroke", "the file", source, 1);
  const toml::node* mat = root.get("material");
  if (mat == nullptr || !mat->is_table()) {
    toml_fail(source,
              mat ? line_of(*mat) : 1,
              "the file needs a [material] table with E and "
              "yield_strength");
  }
  const toml::table& m = *mat->as_table();
  check_toml_keys(m, {"E", "yield_strength", "name"}, "[material]", source);
  d.E = positive(m, "E", "material", source, line_of(m));
  d.yield_strength = positive(m, "yield_strength", "material", source, line_of(m));
  for (int p = 1; p <= 3; ++p) {
    const std::string name = kJointTables[p - 1];
    const toml::node* node = root.get(name);
    JointDesign& j = d.joints[p - 1];
    j.type = cfg->pivots[p - 1];
    if (j.type == PivotType::kPin) {
      if (node != nullptr) {
        toml_fail(source,
                  line_of(*node),
                  fmt::format("[{}]: pivot {} of configuration '{}' is a pin and takes no table",
                              name,
                              p,
                              d.config));
      }
      continue;
    }
    if (node == nullptr || !node->is_table()) {
      toml_fail(source,
                node ? line_of(*node) : 1,
                fmt::format("configuration '{}' needs a [{}] table (thickness, width{})",
                            d.config,
                            name,
                            j.type == PivotType::kSmall ? ", optional length" : ""));
    }
    const toml::table& t = *node->as_table();
    if (j.type == PivotType::kSmall) {
      check_toml_keys(t, {"thickness", "width", "length"}, "[" + name + "]", source);
      j.length = positive(t, "length", name, source, line_of(t), 0.0);
    } else {
      // An l segment is r/gamma long by definition (thesis Table 8.1): its length is derived.
      check_toml_keys(
          t, {"thickness", "width"}, "[" + name + "] (l segment, length = r/0.85)", source);
    }
    j.thickness = positive(t, "thickness", name, source, line_of(t));
    j.width = positive(t, "width", name, source, line_of(t));
  }
  try {
    d.finalise();
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("{}: {}", source, e.what()));
  }
  return d;
}

MechanismDesign load_mechanism_toml(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InvalidInput(fmt::format("cannot read mechanism file '{}'", path));
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parse_mechanism_toml(buffer.str(), path);
}

}  // namespace flexure::mechanism
