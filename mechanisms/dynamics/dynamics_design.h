#pragma once
// What `flexure dynamics` runs: the slider-crank parameters of one design (PRBM links r2, r3, the
// torsion springs of one half, the masses), from a built-in design of the paper's Table 5
// (builtin_designs.h) or from any dimensional MechanismDesign, e.g. a TOML file (docs/dynamics.md
// "Designs from TOML", docs/mechanisms.md "TOML").
//
// The springs follow a rule (DynamicsSpringRule), reported as `spring_rule`:
//   "table5-printed"   the constants printed in the paper's Table 5 (the built-in default: it
//                      reproduces the paper's Table 6 F_Nom, docs/dynamics.md §2);
//   "pure-bending", "table2", "table5"
//                      computed from each strip's b, h, L and E as `flexure mechanism analyze`
//                      does (builtin_designs.h spring_rule_factor; k = EI/L for pure bending,
//                      Howell eq. 5.14);
//   "given"            the TOML file's [dynamics] spring_constants;
//   none               a thesis design without fixed-fixed segments: its springs have one rule
//                      (s: EI/l, Howell eq. 5.14; l: gamma K_theta EI/l, eq. 5.72), as in analyze.
#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "flexure/mechanisms/materials_fatigue.h"
#include "flexure/mechanisms/mechanism.h"

namespace flexure::dynamics {

// The rule the springs of a DynamicsDesign follow (above).
enum class DynamicsSpringRule { kTable5Printed, kPureBending, kTable2, kTable5, kGiven };
// "table5-printed", "pure-bending", "table2", "table5", "given" (the JSON key and HDF5 attribute
// `spring_rule`; the middle three are mechanism::spring_rule_name's).
const char* to_string(DynamicsSpringRule rule);
// The rule of that name; throws InvalidInput listing the five.
DynamicsSpringRule dynamics_spring_rule_from_string(std::string_view name);
// A mechanism's spring rule (pure-bending, table2, table5) as the dynamics reports it.
DynamicsSpringRule dynamics_spring_rule(mechanism::SpringRule rule);

struct DynamicsDesign {
  std::string name;
  double r2 = 0.0;                                // PRBM crank, m
  double r3 = 0.0;                                // PRBM coupler, m
  double m2 = 0.0;                                // link 2 of one half, kg
  double m3 = 0.0;                                // link 3 of one half, kg
  double m_slider = 0.0;                          // the one slider, kg
  std::array<double, 3> k{};                      // torsion springs of one half at pivots 1-3, N m
  std::optional<DynamicsSpringRule> spring_rule;  // none: a thesis design's one rule (above)
  double F_nom_paper = 0.0;             // Table 6 F_Nom of the whole mechanism, N (0: none)
  std::optional<double> stroke;         // the design's own stroke, m (a TOML file's)
  std::optional<std::string> material;  // the material whose E set the springs (--material)
  double E = 0.0;                       // that modulus, Pa (0: no material given)
};

// The optional [dynamics] table of a mechanism TOML file (io/toml_files.h): what a dimensional
// design lacks for dynamics. `source` and `line` place it for messages.
struct DynamicsData {
  std::optional<double> m2;        // kg, link 2 of one half (a uniform bar, J = m r^2/12)
  std::optional<double> m3;        // kg, link 3 of one half
  std::optional<double> m_slider;  // kg, the slider shared by both halves
  std::optional<std::array<double, 3>> spring_constants;  // N m per half, 0 at a pin
  std::string source;                                     // the file
  int line = 0;                                           // line of [dynamics]; 0: no table
};

// The masses a run needs: the --zero-slider-mass and --zero-inertia options set some to zero.
enum class MassesNeeded { kAll, kLinksOnly, kNone };

// Built-in design `name` of the paper's Table 5 (case-insensitive) with the printed springs, or
// with those of `rule` computed from the printed strip dimensions (builtin_designs.h). Throws
// InvalidInput for an unknown name, listing the nine. `material` (a row of data/materials.csv)
// replaces the strips' E for the springs of `rule`; with the printed springs (no rule), which are
// constants, it is refused (InvalidInput).
DynamicsDesign builtin_dynamics_design(const std::string& name,
                                       std::optional<mechanism::SpringRule> rule,
                                       const MaterialGrade* material = nullptr);

// A dimensional design with the masses and optional springs of `data`. Springs: data's
// spring_constants if given ("given"), else the design's spring rule (`rule` replaces it, as
// `mechanism analyze --spring-rule` does). Throws InvalidInput "SOURCE[:LINE]: ..." naming the
// field: a mass `needed` but missing, spring_constants with a spring at a pin or none at a flexure,
// or `rule` together with spring_constants. `material` replaces the design's E for the springs
// computed from its strips; refused together with spring_constants (which do not depend on E).
DynamicsDesign dynamics_design(mechanism::MechanismDesign design,
                               const DynamicsData& data,
                               MassesNeeded needed,
                               std::optional<mechanism::SpringRule> rule,
                               const MaterialGrade* material = nullptr);

}  // namespace flexure::dynamics
