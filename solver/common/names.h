#pragma once
// Names a user types (mechanisms, configurations, segments, methods) match case-insensitively
// everywhere: `2b-lplm`, `2B-lplm` and `2B-LPLM` name one design.
#include <algorithm>
#include <cctype>
#include <string>
#include <string_view>

namespace flexure {

// ASCII lower case (names are ASCII).
inline std::string to_lower(std::string_view text) {
  std::string s(text);
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) {
    return static_cast<char>(std::tolower(c));
  });
  return s;
}

// Whether two names are the same ignoring ASCII case.
inline bool same_name(std::string_view a, std::string_view b) { return to_lower(a) == to_lower(b); }

}  // namespace flexure
