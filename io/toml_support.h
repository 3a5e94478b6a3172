#pragma once
// Error reporting shared by flexure's TOML readers (segment chains, mechanisms): every problem is
// an InvalidInput that names the file, the line and the key.
#include <toml++/toml.h>

#include <set>
#include <string>

namespace flexure::io {

int line_of(const toml::node& node);

// Throws InvalidInput "source:line: what".
[[noreturn]] void toml_fail(const std::string& source, int line, const std::string& what);

// Rejects keys of `table` outside `allowed`, naming the key, its line and the allowed keys.
void check_toml_keys(const toml::table& table,
                     const std::set<std::string>& allowed,
                     const std::string& where,
                     const std::string& source);

}  // namespace flexure::io
