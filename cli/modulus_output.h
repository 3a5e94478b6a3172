#pragma once
// The bending modulus a command used (plate off/on/auto, docs/plate-modulus.md): the `--plate`
// flag's value and its JSON keys (`modulus_rule`, `effective_E`, `plate`) and words.
#include <string>
#include <vector>

#include "cli/cli_common.h"
#include "flexure/solver/common/section.h"

namespace flexure::cli {

// The JSON object of one choice: rule, modulus_rule, E, nu, effective_E, plate, and for auto the
// Searle parameter, its threshold, the share of the plate stiffening and the curvature.
Json modulus_choice_json(const ModulusChoice& choice);

// Adds `modulus_rule`, `effective_E` (the first choice's, or null when the segments differ or none
// has a section) and `modulus` (the list) to `out`.
void add_modulus_json(Json& out, const std::vector<ModulusChoice>& choices);

// "  bending modulus: plate modulus E/(1 - nu^2) = 219.8 GPa (plate = on)"; nothing for a plain
// "off" choice (today's output stays as it was).
void print_modulus(const std::vector<ModulusChoice>& choices);

}  // namespace flexure::cli
