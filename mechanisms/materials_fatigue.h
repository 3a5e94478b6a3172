#pragma once
// Materials and fatigue in one header: the material library, the stress-life fatigue of a
// flexure, and the fatigue of a mechanism's flexures over its working cycle.
//
// The materials of data/materials.csv (Howell 2001, Appendix C, Tables C.1-C.6, and Howell's
// polysilicon of §3.2.2): elastic constants, strengths, the uncorrected endurance limit S_e' or
// fatigue strength S_f' (Howell eqs. 3.70, 3.72, 3.132) and density, each with its source, for
// `--material NAME` and `material = "NAME"` (docs/materials.md). Units: SI (Pa, kg/m^3).
//
// Fatigue of a flexure by the stress-life method of Howell 2001, §3.3: the uncorrected endurance
// limit S_e' (or fatigue strength S_f' at a stated life) of the material, the Marin factors of the
// part (eqs. 3.74-3.84, Tables 3.3-3.4), the mean and alternating stresses of a load cycle (eqs.
// 3.107-3.108), the modified Goodman safety factor (eqs. 3.110-3.111; compressive mean stress:
// S_e/sigma_a, §3.3.11), the yield check (eq. 3.112) and the life of a stress above the endurance
// limit from the S-N line (eqs. 3.56-3.69). docs/fatigue.md. Units: SI (Pa, m) except where a
// function says otherwise.
//
// Fatigue of a mechanism's flexures over its working cycle: rest (the as-made position, where
// every flexure is unstressed) to the full stroke and back, checked by the modified Goodman
// criterion of Howell 2001, §3.3 (above; docs/fatigue.md).
//
// Each flexible pivot's stress over the stroke is the governing one `mechanism analyze` reports
// (the larger of the PRBM and exact values at each stroke point: the largest |m| h/(2I) + |N|/A
// of the segment), signed by the PRBM bending moment at that point (PrbmState::moment). A fibre
// on one face sees that signed history, the other face its negative; each starts from 0 at rest.
// For a pivot whose moment keeps its sign -- every built-in design -- the tensile face cycles
// between 0 and sigma_max: sigma_m = sigma_a = sigma_max/2 (eqs. 3.107-3.108), as in Howell's
// orthoplanar spring and bistable switch. Each pivot has its own size factor (d_e of its b x h,
// eq. 3.81); the critical pivot is the one with the lowest Goodman safety factor.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/solver/common/section.h"
#include "flexure/solver/common/status.h"

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

namespace flexure {

// Surface finish of the part: Table 3.3's fits of the Marin surface factor (eq. 3.76); polished is
// the fatigue specimen itself (c_surf = 1).
enum class SurfaceFinish { kPolished, kGround, kMachined, kHotRolled, kAsForged };
// Table 3.3 has one fit with S_ut in MPa and one with S_ut in kpsi; they differ by up to a few per
// cent (Howell's examples use kpsi).
enum class SurfaceFitUnits { kMPa, kKpsi };
// The loading of the flexure: bending (every flexure of a mechanism), axial, torsion.
enum class FatigueLoading { kBending, kAxial, kTorsion };

// Names as the tool takes them: polished, ground, machined (= cold-rolled), hot-rolled,
// as-forged; bending, axial, torsion. The parsers throw InvalidInput listing the names.
const char* surface_finish_name(SurfaceFinish finish);
SurfaceFinish parse_surface_finish(const std::string& name);
const char* fatigue_loading_name(FatigueLoading loading);
FatigueLoading parse_fatigue_loading(const std::string& name);

// Eq. 3.76: c_surf = a S_ut^b (Table 3.3), at most 1; S_ut in Pa.
double marin_surface_factor(SurfaceFinish finish,
                            double S_ut,
                            SurfaceFitUnits units = SurfaceFitUnits::kMPa);
// Eq. 3.81: the equivalent diameter d_e = 0.808 sqrt(b h) of a rectangular section in
// non-rotating bending, m.
double equivalent_diameter_rectangle(double width, double thickness);
// Eqs. 3.77-3.78: 1 below d = 0.11 in (2.79 mm), (d/7.62 mm)^-0.1133 up to 2 in (51 mm), 0.6
// beyond; 1 for axial loading. d in m (d_e for a non-circular section).
double marin_size_factor(double d, FatigueLoading loading);
// Eqs. 3.82-3.83: 1.0 bending, 0.70 axial, 0.577 torsion.
double marin_load_factor(FatigueLoading loading);
// Table 3.4: c_reliab = 1 - 0.08 z_R, the standard normal deviate of the reliability R (the
// endurance limit of steel normally distributed with a standard deviation of 8 % of its mean,
// §3.3.8). 0.5 <= R < 1.
double marin_reliability_factor(double reliability);
// Eq. 3.57: c_f = 0.9 in bending (and torsion), 0.75 axial: S_L = c_f S_ut at 1e3 cycles.
double low_cycle_strength_fraction(FatigueLoading loading);

// What a part's fatigue strength is made of.
struct FatigueOptions {
  SurfaceFinish finish = SurfaceFinish::kMachined;
  SurfaceFitUnits surface_fit = SurfaceFitUnits::kMPa;
  FatigueLoading loading = FatigueLoading::kBending;
  double reliability = 0.5;  // 50 %: c_reliab = 1
  double K_f = 1.0;          // fatigue stress-concentration factor (eq. 3.24), >= 1
  // Other miscellaneous effects multiplied into c_misc (corrosion, plating, §3.3.9), in (0, 1].
  double other_factor = 1.0;
  // Throws InvalidInput naming the field.
  void validate() const;
};

// The material's side: S_ut, S_e' or S_f' (with its life), S_y, ductility.
struct FatigueMaterial {
  double ultimate_strength = 0.0;        // S_ut, Pa
  double uncorrected_strength = 0.0;     // S_e' or S_f', Pa
  std::optional<double> fatigue_cycles;  // life of S_f'; empty: an endurance limit
  std::optional<double> yield_strength;  // S_y, Pa (eq. 3.112)
  bool ductile = true;                   // brittle: K_f on the stress (eq. 3.85)
  std::string source;                    // where S_e' came from, for reports
  // Throws InvalidInput naming the field (S_ut and S_e' finite and > 0, S_e' < S_ut, ...).
  void validate() const;
};
// From a library row, each value replaced by the one given; throws InvalidInput naming what the
// row lacks (S_ut, S_e') when nothing replaces it.
FatigueMaterial fatigue_material(const MaterialGrade* grade,
                                 std::optional<double> ultimate_strength = {},
                                 std::optional<double> uncorrected_strength = {},
                                 std::optional<double> yield_strength = {});

struct MarinFactors {
  double surface = 1.0, size = 1.0, load = 1.0, reliability = 1.0, misc = 1.0;
  double product() const { return surface * size * load * reliability * misc; }
};

// The corrected endurance limit S_e (or fatigue strength S_f) of a part, eqs. 3.74-3.75.
struct PartFatigueStrength {
  MarinFactors factors;
  double uncorrected = 0.0;              // S_e' or S_f', Pa
  double corrected = 0.0;                // S_e or S_f, Pa
  std::optional<double> fatigue_cycles;  // life of S_f; empty: an endurance limit
  // K_f on the stress (brittle material, eq. 3.85) or 1 (ductile: 1/K_f is in c_misc, eq. 3.84).
  double stress_factor = 1.0;
};
// d_e: the equivalent diameter of the section (eq. 3.81 for a rectangle), m.
PartFatigueStrength part_fatigue_strength(const FatigueMaterial& material,
                                          const FatigueOptions& options,
                                          double equivalent_diameter);

// The S-N line of the part (eqs. 3.56-3.69): (1, S_ut), (1e3, c_f S_ut), (1e6, S_e) then flat for
// an endurance limit, or through (N2, S_f) and beyond for a fatigue strength. Cycles to failure
// of a completely reversed stress amplitude S (Pa): infinity at or below an endurance limit.
struct SnCurve {
  double S_ut = 0.0, S_L = 0.0, S_2 = 0.0, N_2 = 1e6;
  bool endurance_limit = true;
  double a_f = 0.0, b_f = 0.0;  // eq. 3.58: S_f = a_f N^b_f between 1e3 and N_2 (eqs. 3.63-3.66)
  double cycles_to_failure(double S) const;
};
SnCurve sn_curve(const FatigueMaterial& material,
                 const PartFatigueStrength& strength,
                 FatigueLoading loading);

// One load cycle of a fibre between two stresses (Pa, tension > 0), checked against a part's
// strength: eqs. 3.107-3.112.
struct FatigueCheck {
  double sigma_max = 0.0, sigma_min = 0.0;  // after K_f for a brittle material (eq. 3.85)
  double mean_stress = 0.0;                 // sigma_m, eq. 3.107
  double alternating_stress = 0.0;          // sigma_a, eq. 3.108
  double endurance_limit = 0.0;             // corrected S_e (or S_f), Pa
  // Modified Goodman, eq. 3.110/3.111: 1/SF = sigma_a/S_e + sigma_m/S_ut; for sigma_m <= 0,
  // SF = S_e/sigma_a (a compressive mean closes cracks, §3.3.11). Infinity for no alternation.
  double safety_factor = 0.0;
  // Against yield on the first load (eq. 3.112): S_y/max|sigma| (S_ut for a brittle material,
  // eq. 3.44); empty without S_y.
  std::optional<double> yield_safety_factor;
  // safety_factor >= 1 with an endurance limit (for a fatigue strength: a life of at least
  // fatigue_cycles).
  bool infinite_life = false;
  // Below safety factor 1: the cycles to failure of the completely reversed stress with the same
  // Goodman safety factor, sigma_a/(1 - sigma_m/S_ut) (the Goodman line through the point,
  // §3.3.11), on the S-N line (eq. 3.69); infinity when safety_factor >= 1 with an endurance
  // limit.
  double cycles_to_failure = 0.0;
};
FatigueCheck check_fatigue(double sigma_max,
                           double sigma_min,
                           const FatigueMaterial& material,
                           const PartFatigueStrength& strength,
                           FatigueLoading loading = FatigueLoading::kBending);

// The smallest corrected endurance limit S_e that gives a cycle of mean sigma_m and alternation
// sigma_a (Pa) the safety factor `safety_factor` on the modified Goodman line: eq. 3.110 solved
// for S_e, sigma_a / (1/SF - sigma_m/S_ut) (eq. 3.137 at SF = 1; eq. 3.106 for sigma_m <= 0).
// Throws InvalidInput when the mean stress alone uses up the safety factor (sigma_m >= S_ut/SF).
double required_endurance_limit(double alternating_stress,
                                double mean_stress,
                                double ultimate_strength,
                                double safety_factor = 1.0);

}  // namespace flexure

namespace flexure::mechanism {

struct PivotFatigue {
  bool present = false;              // a flexible pivot
  double equivalent_diameter = 0.0;  // d_e, m (eq. 3.81)
  PartFatigueStrength strength;
  FatigueCheck check;                // of the face with the lower safety factor
  bool moment_changes_sign = false;  // the PRBM moment takes both signs over the stroke
};

struct MechanismFatigue {
  FatigueMaterial material;
  FatigueOptions options;
  std::array<PivotFatigue, 3> pivots;  // stored (original) pivot order, 1..3 -> [0..2]
  int critical_pivot = 0;              // 1..3, lowest safety factor
  const PivotFatigue& critical() const { return pivots[critical_pivot - 1]; }
};

// The fatigue material of a design: its S_ut and S_e' (from a data/materials.csv row or given),
// S_y and brittleness. Throws InvalidInput naming what is missing ("--ultimate-strength",
// the TOML key) in library words: "the design's material has no ultimate strength S_ut".
FatigueMaterial design_fatigue_material(const MechanismDesign& design);

// The check of an analysed stroke (analysis.prbm over the stroke; the exact stresses where
// analysis.has_exact_stress).
MechanismFatigue mechanism_fatigue(const MechanismAnalysis& analysis,
                                   const FatigueMaterial& material,
                                   const FatigueOptions& options);

// The fatigue check `mechanism analyze` reports beside the static safety factor: the check of the
// stroke with the design's own fatigue material (design_fatigue_material), or why there is none.
struct MechanismFatigueReport {
  std::optional<MechanismFatigue> fatigue;
  std::string not_checked;  // why there is no check (the library's reason); empty when checked
  // A finite life (the critical pivot's stress above the corrected endurance limit):
  // "NAME: fatigue_summary(...)" (kSafetyFactor); empty otherwise.
  std::vector<Warning> warnings;
};
MechanismFatigueReport mechanism_fatigue_report(const MechanismAnalysis& analysis,
                                                const FatigueOptions& options);

// The check in one line, pivots numbered as the design is described (inversion.h): "fatigue (rest
// to full stroke, pivot P): sigma_a ... Pa, sigma_m ... Pa, S_e ... Pa (S_e' ... Pa x Marin ...:
// FINISH, R ..., K_f ...); fatigue safety factor ... (modified Goodman), LIFE" with LIFE "infinite
// life", "life >= N cycles (no endurance limit)" or "FINITE LIFE, about N cycles".
std::string fatigue_summary(const MechanismDesign& design, const MechanismFatigue& fatigue);

// Sets E, nu-free S_y, S_ut, S_e' (and its life), ductility and the id of `grade` on `design`;
// a brittle grade's static strength is its S_ut (Howell eq. 3.44). Throws InvalidInput when the
// row has no yield (or ultimate) strength for the static safety factor.
void apply_material(MechanismDesign& design, const MaterialGrade& grade);

}  // namespace flexure::mechanism
