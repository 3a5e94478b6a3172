#include "cli/modulus_output.h"

#include <fmt/format.h>

#include "flexure/beam/beam_keys.h"

namespace flexure::cli {

// The keys are written by the beam layer's one writer (beam/beam_keys.h), shared with the Python
// module.
Json modulus_choice_json(const ModulusChoice& c) { return beam_keys::modulus_choice<Json>(c); }

void add_modulus_json(Json& out, const std::vector<ModulusChoice>& choices) {
  beam_keys::add_modulus(out, choices);
}

void print_modulus(const std::vector<ModulusChoice>& choices) {
  for (const ModulusChoice& c : choices) {
    if (c.rule == PlateRule::kOff) continue;
    fmt::print("  bending modulus: {:.6g} Pa -- {}\n", c.effective_E, c.reason());
  }
}

}  // namespace flexure::cli
