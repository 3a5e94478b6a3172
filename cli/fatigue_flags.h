#pragma once
// The fatigue flags that `mechanism analyze` and `design mechanism` share (docs/fatigue.md):
// the part's surface finish, reliability, fatigue stress-concentration factor and other Marin
// factor (Howell 2001, §3.3.4-3.3.9), and the material's S_ut and S_e' where the material
// library has none or the user knows better.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "flexure/mechanisms/materials_fatigue.h"
#include "flexure/mechanisms/mechanism.h"

namespace flexure::cli {

struct FatigueFlags {
  std::string finish = "machined";
  double reliability = 0.99;
  double K_f = 1.0;
  double other_factor = 1.0;
  std::string ultimate_strength, endurance_limit;

  // Adds the flags to `command` in an option group "fatigue".
  void add_to(CLI::App& command);
  // The Marin options; throws InvalidInput naming the flag.
  FatigueOptions options() const;
  // --ultimate-strength and --endurance-limit onto `design` (each replaces the material's, with
  // a warning when it differs).
  void apply_strengths(mechanism::MechanismDesign& design) const;
  // The material's fatigue side from `material` (a --material name, may be empty) with
  // --ultimate-strength and --endurance-limit replacing its values and `yield_strength` its S_y;
  // throws InvalidInput naming what is missing.
  FatigueMaterial fatigue_material_of(const std::string& material,
                                      std::optional<double> yield_strength) const;
};

// --material NAME onto a design: E, S_y, S_ut, S_e' of the library row, with a warning naming
// what the design had before when it differs.
void apply_material_flag(mechanism::MechanismDesign& design, const std::string& name);

}  // namespace flexure::cli
