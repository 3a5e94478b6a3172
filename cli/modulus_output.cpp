#include "cli/modulus_output.h"

#include <fmt/format.h>

namespace flexure::cli {

Json modulus_choice_json(const ModulusChoice& c) {
  auto optional = [](const std::optional<double>& v) { return v ? Json(*v) : Json(nullptr); };
  return Json{{"rule", to_string(c.rule)},
              {"modulus_rule", c.modulus_rule()},
              {"plate", c.plate},
              {"E", c.E},
              {"nu", optional(c.nu)},
              {"effective_E", c.effective_E},
              {"searle_beta", optional(c.beta)},
              {"searle_threshold", optional(c.threshold)},
              {"plate_fraction", optional(c.fraction)},
              {"curvature", optional(c.curvature)},
              {"reason", c.reason()}};
}

void add_modulus_json(Json& out, const std::vector<ModulusChoice>& choices) {
  Json list = Json::array();
  bool same = !choices.empty();
  for (const ModulusChoice& c : choices) {
    list.push_back(modulus_choice_json(c));
    same = same && c.plate == choices.front().plate && c.effective_E == choices.front().effective_E;
  }
  out["modulus_rule"] = same ? Json(choices.front().modulus_rule()) : Json(nullptr);
  out["effective_E"] = same ? Json(choices.front().effective_E) : Json(nullptr);
  out["modulus"] = std::move(list);
}

void print_modulus(const std::vector<ModulusChoice>& choices) {
  for (const ModulusChoice& c : choices) {
    if (c.rule == PlateRule::kOff) continue;
    fmt::print("  bending modulus: {:.6g} Pa -- {}\n", c.effective_E, c.reason());
  }
}

}  // namespace flexure::cli
