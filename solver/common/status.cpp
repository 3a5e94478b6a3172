#include "flexure/solver/common/status.h"

#include <fmt/format.h>

#include <array>

namespace flexure {

std::string_view termination_name(Termination termination) {
  // In the order of the enum.
  static constexpr std::array<std::string_view, 5> kNames = {
      "converged", "no_convergence", "limit_point", "invalid_input", "infeasible"};
  return kNames.at(static_cast<std::size_t>(termination));
}

std::string_view warning_kind_name(WarningKind kind) {
  // In the order of the enum.
  static constexpr std::array<std::string_view, 8> kNames = {"units",
                                                             "outside_validity",
                                                             "stroke_clamped",
                                                             "force_vanishes",
                                                             "yield",
                                                             "safety_factor",
                                                             "design",
                                                             "other"};
  return kNames.at(static_cast<std::size_t>(kind));
}

std::string limit_points_note(int limit_points, double first_limit_load_factor) {
  if (limit_points <= 0) return {};
  return fmt::format(
      "; the path passed {} limit point{}: under load control the beam would snap at the first, "
      "at load factor {:.6g}",
      limit_points,
      limit_points == 1 ? "" : "s",
      first_limit_load_factor);
}

}  // namespace flexure
