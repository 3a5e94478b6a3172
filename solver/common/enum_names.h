#pragma once
// The names of an enum's values, as one table in the enum's order: its to_string and its parser
// of text read from files and flags (docs/architecture.md, "One result vocabulary"). Internal.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

#include "flexure/solver/common/status.h"

namespace flexure {

// The name of `value`: names[value].
template <typename Enum, std::size_t N>
const char* enum_name(const std::array<const char*, N>& names, Enum value) {
  return names[static_cast<std::size_t>(value)];
}

// The value named exactly `name`, or empty (for a parser whose refusal says more).
template <typename Enum, std::size_t N>
std::optional<Enum> enum_find(const std::array<const char*, N>& names, std::string_view name) {
  for (std::size_t i = 0; i < N; ++i) {
    if (name == names[i]) return static_cast<Enum>(i);
  }
  return std::nullopt;
}

// The value named exactly `name`; throws InvalidInput "WHAT 'NAME' is unknown (allowed: a, b,
// ...)".
template <typename Enum, std::size_t N>
Enum enum_from_name(const std::array<const char*, N>& names,
                    std::string_view name,
                    std::string_view what) {
  if (const std::optional<Enum> value = enum_find<Enum>(names, name)) return *value;
  throw InvalidInput(
      fmt::format("{} '{}' is unknown (allowed: {})", what, name, fmt::join(names, ", ")));
}

}  // namespace flexure
