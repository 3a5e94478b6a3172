#pragma once
// The materials of data/materials.csv (Howell 2001, Appendix C, Tables C.1-C.6, and Howell's
// polysilicon of §3.2.2): elastic constants, strengths, the uncorrected endurance limit S_e' or
// fatigue strength S_f' (Howell eqs. 3.70, 3.72, 3.132) and density, each with its source, for
// `--material NAME` and `material = "NAME"` (docs/materials.md). Units: SI (Pa, kg/m^3).
#include <optional>
#include <string>
#include <vector>

#include "flexure/solver/common/section.h"

namespace flexure {

// Whether the material's fatigue strength is an endurance limit (infinite life below it) or a
// fatigue strength at a stated life (Howell §3.3.2).
enum class FatigueStrengthKind { kEnduranceLimit, kFatigueStrength };

struct MaterialGrade {
  std::string id;           // "steel-1095-hr"
  std::string designation;  // "1095 HR", as the source prints it
  std::string family;       // "carbon-steel", "polymer", ... (the table's class column)
  std::string source;       // "Howell Table C.5 (E nu density: Table C.1)"
  double E = 0.0;           // Pa
  std::optional<double> nu;
  std::optional<double> yield_strength;     // S_y, Pa
  std::optional<double> ultimate_strength;  // S_ut, Pa
  // S_e' or S_f' of a polished specimen, Pa; fatigue_cycles is the life of S_f' (empty for an
  // endurance limit).
  std::optional<double> fatigue_strength;
  std::optional<FatigueStrengthKind> fatigue_kind;
  std::optional<double> fatigue_cycles;
  std::optional<double> density;  // kg/m^3
  bool ductile = true;
  std::string fatigue_source;  // how fatigue_strength was obtained
  std::string notes;           // creep and stress relaxation of polymers; what the row lacks

  // The strength a static safety factor divides: S_y of a ductile material; S_ut of a brittle
  // one (Coulomb-Mohr with sigma_3 >= 0, Howell eq. 3.44). Empty when the row has neither.
  std::optional<double> static_strength() const;
  // E, nu (0.3 when the source gives none: a shear modulus is then an estimate), S_y, density.
  Material material() const;
};

// Every row of data/materials.csv, in the file's order (parsed once).
const std::vector<MaterialGrade>& material_library();

// The row whose id or designation matches `name`, ignoring case, blanks and punctuation
// ("1095 HR", "steel-1095-hr", "Steel 1095 HR"). Throws InvalidInput for an unknown name, listing
// the closest ids (sharing a word with the name, or within a small edit distance) and pointing to
// `flexure materials`.
const MaterialGrade& find_material(const std::string& name);

// Up to `count` ids closest to `name` (for messages).
std::vector<std::string> closest_material_ids(const std::string& name, std::size_t count = 6);

}  // namespace flexure
