#pragma once
// Error reporting shared by flexure's TOML readers (segment chains, mechanisms): every problem is
// an InvalidInput that names the file, the line and the key.
#include <toml++/toml.h>

#include <cstddef>
#include <optional>
#include <set>
#include <string>
#include <string_view>

namespace flexure::io {

// Limits checked before a TOML text reaches toml++. toml++ parses and destroys tables recursively,
// so a header such as [a.a.a...] with tens of thousands of levels overflows the stack (SIGSEGV).
// flexure's formats nest at most three levels ([[segment]] -> EI_profile) and are a few kB long;
// the limits leave ample room for comments and long tables while keeping recursion shallow.
inline constexpr int kMaxTomlNesting = 64;
inline constexpr std::size_t kMaxTomlBytes = std::size_t{1} << 20;  // 1 MiB

int line_of(const toml::node& node);

// The value of an integer or float node as a double; nullopt for any other type. Unlike
// node.value<double>(), an integer a double cannot hold exactly (2^63 - 1) is converted (rounded)
// instead of being refused as "not a number".
std::optional<double> toml_number(const toml::node& node);

// Throws InvalidInput "source:line: what".
[[noreturn]] void toml_fail(const std::string& source, int line, const std::string& what);

// Rejects keys of `table` outside `allowed`, naming the key, its line and the allowed keys.
void check_toml_keys(const toml::table& table,
                     const std::set<std::string>& allowed,
                     const std::string& where,
                     const std::string& source);

// Cheap pre-scan of TOML text, to be called before toml::parse: throws InvalidInput
// "source:line: ..." naming the limit if the text is longer than kMaxTomlBytes or nests tables,
// dotted keys, arrays or inline tables deeper than kMaxTomlNesting levels. Strings and comments are
// skipped; anything else malformed is left for toml++ to report.
void check_toml_limits(std::string_view text, const std::string& source);

// Reads the file at `path` whole, but no more than kMaxTomlBytes + 1 bytes (a huge file or a
// device such as /dev/zero is refused by check_toml_limits rather than read into memory). Throws
// InvalidInput "`what` 'path': reason" if it is a directory or cannot be read.
std::string read_toml_file(const std::string& path, const std::string& what);

}  // namespace flexure::io
