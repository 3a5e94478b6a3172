#include "flexure/io/chain_toml.h"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <set>

#include "flexure/io/toml_support.h"
#include "flexure/solver/common/errors.h"

namespace flexure::io {
namespace {

// A number (integer or float) at `key`; nullopt if absent.
std::optional<double> number(const toml::table& table,
                             const std::string& key,
                             const std::string& where,
                             const std::string& source) {
  const toml::node* node = table.get(key);
  if (node == nullptr) return std::nullopt;
  if (const std::optional<double> v = toml_number(*node)) {
    if (!std::isfinite(*v)) {
      toml_fail(source, line_of(*node), fmt::format("{}.{} must be a finite number", where, key));
    }
    return *v;
  }
  toml_fail(source, line_of(*node), fmt::format("{}.{} must be a number", where, key));
}

double required_number(const toml::table& table,
                       const std::string& key,
                       const std::string& where,
                       const std::string& source,
                       int table_line) {
  const std::optional<double> v = number(table, key, where, source);
  if (!v)
    toml_fail(source, table_line, fmt::format("{} is missing the required key '{}'", where, key));
  return *v;
}

const toml::table& as_table(const toml::node& node,
                            const std::string& where,
                            const std::string& source) {
  const toml::table* t = node.as_table();
  if (t == nullptr) toml_fail(source, line_of(node), fmt::format("{} must be a table", where));
  return *t;
}

Segment read_segment(const toml::table& t, int index, const std::string& source) {
  const std::string where = fmt::format("segment {}", index + 1);
  const toml::node* type_node = t.get("type");
  if (type_node == nullptr || !type_node->is_string()) {
    toml_fail(
        source, line_of(t), fmt::format("{} needs type = \"flexible\" or type = \"rigid\"", where));
  }
  const std::string type = **type_node->as_string();
  if (type == "flexible") {
    check_toml_keys(t, {"type", "length", "EI", "EI_profile", "kappa0"}, where, source);
    FlexibleSegment s;
    s.length = required_number(t, "length", where, source, line_of(t));
    s.EI = number(t, "EI", where, source).value_or(1.0);
    s.kappa0 = number(t, "kappa0", where, source).value_or(0.0);
    if (const toml::node* profile = t.get("EI_profile")) {
      const toml::array* a = profile->as_array();
      if (a == nullptr)
        toml_fail(source, line_of(*profile), where + ".EI_profile must be an array");
      for (const toml::node& v : *a) {
        const std::optional<double> x = toml_number(v);
        if (!x) toml_fail(source, line_of(v), where + ".EI_profile must contain numbers");
        s.EI_profile.push_back(*x);
      }
    }
    return s;
  }
  if (type == "rigid") {
    check_toml_keys(t, {"type", "length", "angle_offset"}, where, source);
    RigidSegment s;
    s.length = required_number(t, "length", where, source, line_of(t));
    s.angle_offset = number(t, "angle_offset", where, source).value_or(0.0);
    return s;
  }
  toml_fail(source,
            line_of(*type_node),
            fmt::format("{}: type '{}' is unknown (allowed: flexible, rigid)", where, type));
}

// node_load.node: an intermediate joint, 1 .. `joints` (= segments - 1), written as an integer or
// an integral float (2.0). Range-checked while still a double or an int64: casting 1e300 to int is
// undefined behaviour (it came out as -2147483648 in the message).
int joint_index(const toml::table& t,
                const std::string& where,
                const std::string& source,
                int joints) {
  const double value = required_number(t, "node", where, source, line_of(t));
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

}  // namespace

SegmentChain parse_chain_toml(const std::string& text, const std::string& source) {
  check_toml_limits(text, source);
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw InvalidInput(fmt::format(
        "{}:{}: TOML syntax error: {}", source, e.source().begin.line, e.description()));
  }
  check_toml_keys(
      root, {"boundary", "segment", "tip_load", "tip", "node_load"}, "the file", source);
  SegmentChain chain;
  if (const toml::node* b = root.get("boundary")) {
    if (!b->is_string()) toml_fail(source, line_of(*b), "boundary must be a string");
    try {
      chain.end = end_condition_from_string(**b->as_string());
    } catch (const InvalidInput& e) {
      toml_fail(source, line_of(*b), e.what());
    }
  }
  const toml::node* segments = root.get("segment");
  if (segments == nullptr) {
    toml_fail(source, 1, "no [[segment]] tables: a chain needs at least one segment");
  }
  const toml::array* list = segments->as_array();
  if (list == nullptr) toml_fail(source, line_of(*segments), "segment must be an array of tables");
  int index = 0;
  for (const toml::node& node : *list) {
    chain.segments.push_back(
        read_segment(as_table(node, fmt::format("segment {}", index + 1), source), index, source));
    ++index;
  }
  if (const toml::node* node = root.get("tip_load")) {
    const toml::table& t = as_table(*node, "tip_load", source);
    check_toml_keys(t, {"Fx", "Fy", "M", "follower"}, "tip_load", source);
    chain.tip_load.Fx = number(t, "Fx", "tip_load", source).value_or(0.0);
    chain.tip_load.Fy = number(t, "Fy", "tip_load", source).value_or(0.0);
    chain.tip_load.M = number(t, "M", "tip_load", source).value_or(0.0);
    chain.tip_load.follower = number(t, "follower", "tip_load", source).value_or(0.0);
  }
  if (const toml::node* node = root.get("tip")) {
    const toml::table& t = as_table(*node, "tip", source);
    check_toml_keys(t, {"x", "y", "theta"}, "tip", source);
    chain.prescribed.x = number(t, "x", "tip", source);
    chain.prescribed.y = number(t, "y", "tip", source);
    chain.prescribed.theta = number(t, "theta", "tip", source);
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
      load.node = joint_index(t, where, source, chain.segment_count() - 1);
      load.Fx = number(t, "Fx", where, source).value_or(0.0);
      load.Fy = number(t, "Fy", where, source).value_or(0.0);
      load.M = number(t, "M", where, source).value_or(0.0);
      chain.node_loads.push_back(load);
    }
  }
  try {
    chain.validate();
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("{}: {}", source, e.what()));
  }
  return chain;
}

SegmentChain read_chain_toml(const std::string& path) {
  return parse_chain_toml(read_toml_file(path, "--chain file"), path);
}

}  // namespace flexure::io
