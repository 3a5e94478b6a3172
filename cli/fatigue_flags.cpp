#include "cli/fatigue_flags.h"

#include <fmt/format.h>

#include "cli/cli_common.h"
#include "flexure/mechanisms/materials_fatigue.h"
#include "flexure/solver/common/section.h"
#include "flexure/solver/common/status.h"

namespace flexure::cli {

void FatigueFlags::add_to(CLI::App& command) {
  CLI::Option_group* g = command.add_option_group(
      "fatigue", "Fatigue check (Howell §3.3, modified Goodman; docs/fatigue.md)");
  g->add_option("--surface-finish",
                finish,
                "Surface of the flexures for the Marin surface factor (Howell Table 3.3): "
                "polished, ground, machined (= cold-rolled), hot-rolled, as-forged")
      ->default_str("machined");
  g->add_option("--reliability",
                reliability,
                "Reliability of the endurance limit, 0.5..0.999999 (Howell Table 3.4)")
      ->default_str("0.99");
  g->add_option("--Kf",
                K_f,
                "Fatigue stress-concentration factor at the flexures' roots (>= 1; Howell eq. "
                "3.24; its examples use 1.2-1.4)")
      ->default_str("1");
  g->add_option("--fatigue-factor",
                other_factor,
                "Other Marin factor in (0, 1]: corrosion, plating (Howell §3.3.9)")
      ->default_str("1");
  g->add_option("--ultimate-strength",
                ultimate_strength,
                "Ultimate tensile strength S_ut (Pa, or MPa, ksi); replaces the material's");
  g->add_option("--endurance-limit",
                endurance_limit,
                "Uncorrected endurance limit S_e' of a polished specimen (Pa, or MPa, ksi); "
                "replaces the material's");
}

FatigueOptions FatigueFlags::options() const {
  FatigueOptions o;
  try {
    o.finish = parse_surface_finish(finish);
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("--surface-finish: {}", e.what()));
  }
  o.reliability = reliability;
  o.K_f = K_f;
  o.other_factor = other_factor;
  try {
    o.validate();
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("--reliability, --Kf or --fatigue-factor: {}", e.what()));
  }
  return o;
}

void FatigueFlags::apply_strengths(mechanism::MechanismDesign& design) const {
  const auto apply = [&](const std::string& text,
                         const char* flag,
                         std::optional<double>& field,
                         bool is_endurance) {
    if (text.empty()) return;
    const double v = io::parse_quantity(text, io::Dimension::kStress, flag).si;
    if (!(v > 0.0)) throw InvalidInput(fmt::format("{} must be > 0 (got {})", flag, text));
    if (field && *field != v) {
      warn(fmt::format(
          "{} {:.6g} Pa replaces the {:.6g} Pa of {}",
          flag,
          v,
          *field,
          design.material_id.empty() ? "the design" : "material '" + design.material_id + "'"));
    }
    field = v;
    if (is_endurance) design.endurance_cycles.reset();
  };
  apply(ultimate_strength, "--ultimate-strength", design.ultimate_strength, false);
  apply(endurance_limit, "--endurance-limit", design.endurance_limit, true);
}

FatigueMaterial FatigueFlags::fatigue_material_of(const std::string& material,
                                                  std::optional<double> yield_strength) const {
  const MaterialGrade* grade = material.empty() ? nullptr : &find_material(material);
  const auto stress = [](const std::string& text, const char* flag) -> std::optional<double> {
    if (text.empty()) return std::nullopt;
    return io::parse_quantity(text, io::Dimension::kStress, flag).si;
  };
  try {
    return fatigue_material(grade,
                            stress(ultimate_strength, "--ultimate-strength"),
                            stress(endurance_limit, "--endurance-limit"),
                            yield_strength);
  } catch (const InvalidInput& e) {
    throw InvalidInput(
        fmt::format("{}: give --material NAME (`flexure materials`) or --ultimate-strength and "
                    "--endurance-limit",
                    e.what()));
  }
}

void apply_material_flag(mechanism::MechanismDesign& design, const std::string& name) {
  const MaterialGrade& g = find_material(name);
  const double E = design.material.E, S_y = design.material.yield_strength.value_or(0.0);
  mechanism::apply_material(design, g);
  if (E > 0.0 && (E != design.material.E || S_y != design.material.yield_strength.value_or(0.0))) {
    warn(
        fmt::format("--material {}: E {:.6g} Pa and S_y {:.6g} Pa replace the design's {:.6g} "
                    "Pa and {:.6g} Pa",
                    g.id,
                    design.material.E,
                    design.material.yield_strength.value_or(0.0),
                    E,
                    S_y));
  }
}

}  // namespace flexure::cli
