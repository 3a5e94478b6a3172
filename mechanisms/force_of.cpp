#include <fmt/format.h>

#include "flexure/mechanisms/mechanism.h"
#include "flexure/solver/common/names.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {

ForceOf parse_force_of(const std::string& text) {
  const std::string t = to_lower(text);
  if (t == "half") return ForceOf::kOneHalf;
  if (t == "whole") return ForceOf::kWholeMechanism;
  throw InvalidInput(fmt::format(
      "--force-of '{}' is unknown (allowed: whole = the whole symmetric mechanism, half = one "
      "half)",
      text));
}

std::string force_of_label(ForceOf of) {
  return of == ForceOf::kOneHalf ? "one half" : "whole symmetric mechanism";
}

double force_of_factor(ForceOf from, ForceOf to) {
  if (from == to) return 1.0;
  return to == ForceOf::kWholeMechanism ? 2.0 : 0.5;
}

}  // namespace flexure::mechanism
