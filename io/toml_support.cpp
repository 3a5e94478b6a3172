#include "io/toml_support.h"

#include <fmt/format.h>

#include "solver/common/errors.h"

namespace flexure::io {

int line_of(const toml::node& node) { return static_cast<int>(node.source().begin.line); }

void toml_fail(const std::string& source, int line, const std::string& what) {
  throw InvalidInput(fmt::format("{}:{}: {}", source, line, what));
}

void check_toml_keys(const toml::table& table,
                     const std::set<std::string>& allowed,
                     const std::string& where,
                     const std::string& source) {
  for (const auto& [key, value] : table) {
    if (allowed.count(std::string(key.str())) == 0) {
      std::string list;
      for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
      toml_fail(source,
                line_of(value),
                fmt::format("unknown key '{}' in {} (allowed: {})", key.str(), where, list));
    }
  }
}

}  // namespace flexure::io
