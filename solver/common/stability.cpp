#include <fmt/format.h>

#include <array>
#include <cstddef>

#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

// In the order of the enum.
constexpr std::array<std::string_view, 5> kNames = {
    "stable", "unstable", "critical", "not_conservative", "not_checked"};

}  // namespace

std::string_view stability_name(StabilityKind kind) {
  return kNames.at(static_cast<std::size_t>(kind));
}

StabilityKind stability_kind_from_name(std::string_view name) {
  for (std::size_t i = 0; i < kNames.size(); ++i) {
    if (kNames[i] == name) return static_cast<StabilityKind>(i);
  }
  throw InvalidInput(
      fmt::format("unknown stability '{}' (one of: stable, unstable, critical, not_conservative, "
                  "not_checked)",
                  name));
}

Stability classify_stability(int index,
                             double margin,
                             double critical_tolerance,
                             std::string_view subject) {
  Stability s;
  s.index = index;
  s.margin = margin;
  if (index > 0) {
    s.kind = StabilityKind::kUnstable;
    s.message = fmt::format(
        "unstable: {} independent direction{} in which the potential energy decreases (stability "
        "margin {:.6g}); a small disturbance makes {} buckle or snap away from this equilibrium, "
        "which therefore cannot be held under these loads and supports",
        index,
        index == 1 ? "" : "s",
        margin,
        subject);
  } else if (margin <= critical_tolerance) {
    s.kind = StabilityKind::kCritical;
    s.message = fmt::format(
        "critical: the second variation of the potential energy is singular within the tolerance "
        "(stability margin {:.3g}, |margin| <= {:.3g}); this is a buckling (bifurcation) or limit "
        "point, where {} can buckle or snap under the slightest further load",
        margin,
        critical_tolerance,
        subject);
  } else {
    s.kind = StabilityKind::kStable;
    s.message = fmt::format(
        "stable: the potential energy has a strict minimum here (stability margin {:.6g}: the "
        "lowest stiffness against buckling is that fraction of the unloaded bending stiffness)",
        margin);
  }
  return s;
}

Stability not_conservative_stability(std::string_view why) {
  Stability s;
  s.kind = StabilityKind::kNotConservative;
  s.message = fmt::format(
      "not judged: {}; a follower load has no potential energy, so the energy criterion cannot "
      "tell stable from unstable (that needs a dynamic criterion)",
      why);
  return s;
}

Stability not_checked_stability(std::string_view why) {
  Stability s;
  s.kind = StabilityKind::kNotChecked;
  s.message = fmt::format("stability not checked: {}", why);
  return s;
}

}  // namespace flexure
