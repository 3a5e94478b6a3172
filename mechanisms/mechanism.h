#pragma once
// Dimensional description of half of a symmetric constant-force slider mechanism as Weight (2001)
// models it (thesis §2.1.1, §3.2, Table 8.1): ground pivot 1, crank r2, middle pivot 2,
// coupler r3, slider pivot 3 on the x axis through the ground pivot. Each pivot is a pin (p), a
// small-length flexural pivot (s) or a long fixed-pinned flexible segment (l).
//
// The PRBM link lengths r2, r3 are the primary geometry (the thesis designs in r_tot = r2 + r3);
// the physical segments follow Table 8.1: an s flexure of length f is centred on its PRB pivot
// (f = 0.1 r_i by default, r_ave for the middle pivot); an l segment is r/gamma long, replaces
// link 2 (at the ground, or plp) or link 3 (slp), and its characteristic pivot is (1 - gamma) l
// from its clamp, with Howell's average gamma (howell_average_fixed_pinned(),
// elements/fixed_pinned_segment.h). The modified configurations of paper 004 add fixed-fixed
// segments (SegmentKind below; builtin_designs.h). Units: SI (m, Pa, N) throughout.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "flexure/elements/prbm_element.h"
#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/solver/common/section.h"

// What a slider force is the force of. A constant-force slider mechanism is symmetric (thesis
// §2.1.1; Howell §10.1; the dynamics paper models "only half of the symmetric mechanism", its
// Fig. 2): two mirror-image halves -- crank, coupler and their springs -- push one slider in
// parallel. Every model in mechanisms/ computes one half; `flexure mechanism` reports that
// half, `flexure dynamics` (and the paper's Table 6 F_Nom) the whole mechanism
// (docs/mechanisms.md "Half or whole mechanism").
//
// F_whole = 2 F_half exactly: the two halves carry equal and opposite transverse loads at the
// slider, which cancel, and equal axial ones, which add. In the dynamics the same holds with the
// slider's inertia shared equally by the halves (docs/dynamics.md §1: the equation of motion is
// linear in the number of halves and the slider mass together).
namespace flexure::mechanism {

enum class ForceOf { kOneHalf, kWholeMechanism };

// "half" or "whole" (case-insensitive); throws InvalidInput naming the allowed values.
ForceOf parse_force_of(const std::string& text);
// The value of the output key `force_of`: "one half" or "whole symmetric mechanism".
std::string force_of_label(ForceOf of);
// The factor that turns a force of `from` into a force of `to` (1, 2 or 1/2).
double force_of_factor(ForceOf from, ForceOf to);

}  // namespace flexure::mechanism

namespace flexure::mechanism {

using cfm::PivotType;

// How a flexible pivot is built. kThesis: thesis Table 8.1 (s: centred flexure, default length
// 0.1 r; l: fixed-pinned segment r/gamma long). kFixedFixed: a flexible segment of the modified
// configurations (paper 004, Ugwuoke & Abolarin): a strip of explicit length clamped at both ends
// into rigid bodies and centred on its PRB pivot -- physically a centred flexure, so its joint
// type is PivotType::kSmall whatever the paper's letter (docs/mechanisms.md "Modified
// configurations").
enum class SegmentKind { kThesis, kFixedFixed };

// Spring constant of a fixed-fixed segment (docs/mechanisms.md): kPureBending k = EI/L (a strip
// between two rigid bodies under an end moment, Howell eq. 5.14); kTable2 the paper's Table 2
// (l: n gamma K_theta EI/L with its printed n = 0.3 or 0.6; s: EI/L); kTable5 the constants the
// paper's Table 5 actually uses, twice Table 2 (docs/dynamics.md §2).
enum class SpringRule { kPureBending, kTable2, kTable5 };

// One pivot of the half-mechanism.
struct JointDesign {
  PivotType type = PivotType::kPin;
  double length = 0.0;     // flexible length, m (s: flexure length; l: r/gamma, derived)
  double thickness = 0.0;  // in-plane thickness h, m (> 0 for s and l)
  double width = 0.0;      // out-of-plane width b, m (> 0 for s and l)
  SegmentKind segment = SegmentKind::kThesis;
  char paper_letter = 0;       // kFixedFixed: the paper's letter, 'l' or 's' (Table 2/5 factor)
  double table2_factor = 0.3;  // kFixedFixed 'l': n of Table 2's n gamma K_theta EI/L

  // The strip's cross-section as the library's one Section (solver/common/section.h): the
  // rectangle b x h, second moment b h^3/12, section modulus b h^2/6, area b h. Not validated
  // here (a pin has no strip): finalise() checks every flexible pivot's width and thickness.
  Section section() const {
    Section s;
    s.shape = Section::Shape::kRectangle;
    s.width = width;
    s.thickness = thickness;
    return s;
  }
  // E I = E b h^3/12 of the strip in `material` (the EI of Howell eqs. 5.14 and 5.72). Not
  // validated either: check_loads (mechanism.cpp) reports a product outside double precision.
  double flexural_rigidity(const Material& material) const {
    return material.E * section().second_moment();
  }
};

struct MechanismDesign {
  std::string name;                   // "1A-lpp", or the TOML file name
  std::string config;                 // spp, lpp, psp, plp, ssp, slp, sps, lps, sss
  std::string note;                   // where the numbers come from
  double r2 = 0.0;                    // PRBM crank length, m (pivot 1 to pivot 2)
  double r3 = 0.0;                    // PRBM coupler length, m (pivot 2 to pivot 3)
  std::array<JointDesign, 3> joints;  // pivot 1 (ground), 2 (middle), 3 (slider)
  // The strips' material as the library's one Material (solver/common/section.h): E (Pa; the
  // effective modulus once the plate rule is applied), nu (Poisson's ratio: Material's default
  // unless nu_given) and S_y (Pa; required by finalise()), read by the stiffness and stress code.
  Material material;
  // The bending modulus of the strips (docs/plate-modulus.md): off E, on E/(1 - nu^2), auto by
  // the Searle parameter. nu from the material (library row, [material].nu, --nu): nu_given says
  // whether material.nu was given (the plate rules need it, a design file writes it). Applied by
  // analyze_mechanism_with_modulus (mechanism_plate.h), which replaces material.E by the effective
  // modulus and records the choice (and the E as given) in `modulus`.
  PlateRule plate = PlateRule::kOff;
  bool nu_given = false;
  std::vector<ModulusChoice> modulus;
  // The material beyond E and S_y, for the fatigue check (materials_fatigue.h, docs/fatigue.md):
  // the data/materials.csv id it was taken from (empty: given by value), S_ut, the uncorrected
  // endurance limit S_e' (or fatigue strength S_f' at endurance_cycles), brittleness.
  std::string material_id;
  std::optional<double> ultimate_strength;  // Pa
  std::optional<double> endurance_limit;    // Pa
  std::optional<double> endurance_cycles;   // life of a fatigue strength; empty: endurance limit
  bool ductile = true;
  double stroke = 0.0;  // slider travel Delta x at the end of the stroke, m
  // An inversion (thesis §3.2.4, Fig. 3.2): the slider block is fixed and the ground block
  // slides. The fields above still describe the ORIGINAL orientation (the frame every model
  // computes in; the relative motion is the same); mechanisms/inversion.h gives the mirrored
  // description (pivot string reversed, r2 <-> r3, pivots renumbered 1 <-> 3) used for output.
  bool inverted = false;
  // Modified configurations (paper 004): the paper's pivot string with its trailing m ("lplm");
  // `config` is then the thesis pattern of the same topology with every segment an s ("sps").
  std::string paper_config;
  SpringRule spring_rule = SpringRule::kPureBending;  // fixed-fixed segments only
  // What the design's slider forces are reported as unless a command is told otherwise
  // (--force-of): a design file's `force_of` key, which `flexure design mechanism` writes for the
  // force it was specified by. Empty: one half (every model computes one half, ForceOf above).
  std::optional<ForceOf> force_of;

  // Poisson's ratio where given (nu_given), else empty: what the plate rules and a design file
  // read. set_nu gives it (or, empty, returns material.nu to Material's default).
  std::optional<double> given_nu() const {
    return nu_given ? std::optional<double>(material.nu) : std::nullopt;
  }
  void set_nu(std::optional<double> nu) {
    nu_given = nu.has_value();
    material.nu = nu.value_or(Material{}.nu);
  }

  const cfm::CfmConfiguration& configuration() const;
  double R() const { return r3 / r2; }
  // Largest allowed stroke (the toggle position of the PRBM slider-crank), m.
  double toggle_stroke() const;
  // Torsional spring constant of the PRB pivot i (1..3), N m/rad; 0 for a pin. The elements'
  // stiffness coefficients times EI/l:
  //   s: K = EI/l (SmallLengthFlexuralPivot, Howell eq. 5.14);  l: K = gamma K_theta EI/l
  //   (howell_average_fixed_pinned(), eq. 5.72; Weight 2001 §2.2); a fixed-fixed segment by
  //   `spring_rule` (spring_rule_factor in builtin_designs.h).
  double spring_constant(int pivot) const;
  // Fills the derived flexible lengths (s: 0.1 r_i if unset; l: r_i/gamma) and checks every value.
  // Throws InvalidInput naming the quantity and the allowed range: unknown configuration, r2, r3,
  // E, yield strength, stroke <= 0 or non-finite, a flexible pivot without positive thickness and
  // width, an s flexure longer than its link, a stroke past the toggle position (the message names
  // the limit in m and in % of r2 + r3). A fixed-fixed segment needs an explicit length, and the
  // rigid rest of each link (r minus half of each fixed-fixed segment on it) must stay > 0.
  // Geometry outside the slender-beam model (SlenderBeamLimits below) is refused, naming the
  // segment and the ratio.
  void finalise();
};

// Limits of the slender-beam (Euler-Bernoulli, inextensible elastica) model that the PRBM and the
// exact model both rest on, checked by MechanismDesign::finalise for every flexible segment
// (docs/mechanisms.md "Geometry limits"; the built-in designs reach at most h/L = 0.349
// (howell-3A-sss-a), b/h = 4, |P| L^2/EI = 44 (3A-lslm), |P|/(EA) = 8.4e-4):
struct SlenderBeamLimits {
  // h/L: beyond it the segment is a block, not a beam -- shear adds about (E/(4 kappa G))(h/L)^2
  // = 0.8 (h/L)^2 to the bending deflection under a transverse load (Timoshenko, nu = 0.3:
  // 20 % at 0.5) and the clamp end zones (about h each, Saint-Venant) take the whole length.
  // Not 0.1: Howell's small-length pivots (book §10.1.4, thesis designs) run at 0.15-0.35, where
  // they carry mostly moment and shear does not enter.
  static constexpr double kMaxThicknessOverLength = 0.5;
  // b/h: the model bends each strip in the mechanism's plane; with b < h the out-of-plane
  // stiffness E h b^3/12 is the smaller one and the strip would bend or buckle out of the plane.
  static constexpr double kMinWidthOverThickness = 1.0;
  // |P| L^2/(EI) with P the largest PRBM pin force over the stroke (every flexible segment of the
  // half mechanism carries it): 23 times the most loaded built-in design. Beyond it the axial
  // load, not bending, sets the segment's stiffness (the geometric stiffness of a strip under P
  // is ~ sqrt(|P| EI) ~ sqrt(alpha^2) EI/L, over 30 EI/L here), so the PRBM springs EI/l and
  // gamma K_theta EI/l are off by more than an order of magnitude; a compressed strip is hundreds
  // of times past its buckling load, a tensioned one a string with bending boundary layers of
  // sqrt(EI/|P|) < 3 % of its length. The exact solvers would still run (EllipticSolver accepts
  // |F| l^2/EI <= 1e4) but their cost grows as sqrt(alpha^2) per integration: a 50-point stroke
  // of the sss example with a 3 um ground strip (alpha^2 = 9300) took 29 s, the 1e-9 m strip of
  // issue 11 (alpha^2 = 2.5e14) never ended.
  static constexpr double kMaxLoadParameter = 1e3;
  // |P|/(EA): the elastica is inextensible; at this axial strain every segment's length is 5 %
  // off, and no engineering material stays elastic (polypropylene yields near 2.5 %).
  static constexpr double kMaxAxialStrain = 0.05;
};

// The link a flexible pivot's default length is based on (Table 8.1): r2 at the ground, r3 at the
// slider, r_ave in the middle (s) or r2/r3 for a middle long segment (plp/slp).
double associated_link_length(const MechanismDesign& design, int pivot);

// The flexible length finalise() gives a thesis segment of pivot `pivot` (1..3) of `design`
// (config, r2 and r3 set): Table 8.1's l = r/gamma for an l segment, 0.1 r for an s pivot without
// a length of its own (its own length where it has one, and for a fixed-fixed segment); 0 for a
// pin. Lets the design layer bound sections by h/L before a design is finalised.
double table_8_1_segment_length(const MechanismDesign& design, int pivot);

// Gives every flexure of `design` (its config, r2, r3 and E set) width `width` and sizes the
// thicknesses so that the spring ratios are k2/k_ref = K1 and k3/k_ref = K2 (thesis eqs.
// 2.11-2.12; class 1B: k2 is the reference, eq. 2.19), the reference flexure being
// `reference_thickness` thick. At equal width k scales with h^3 (k = EI/l, Howell eq. 5.14;
// gamma K_theta EI/l, eq. 5.72). Lengths follow the PRBM rules (finalise()). Throws InvalidInput
// for a ratio that is not finite and > 0 where the configuration has that spring.
void size_flexures_for_spring_ratios(
    MechanismDesign& design, double width, double reference_thickness, double K1, double K2);

// Built-in designs, one per configuration, named by class and configuration ("1A-lpp", ...; the
// documented choices are in docs/mechanisms.md). "1A-lpp" is the thesis design example 1
// (thesis §8.5.1, Table 8.4).
const std::vector<MechanismDesign>& builtin_mechanisms();
// Accepts "1A-lpp" or "lpp" (case-insensitive), any thesis sub-class ("lpp-b"), Howell's designs
// (builtin_designs.h: "howell-1A-spp-b", "howell-ex1", ...) and the inversion of any of them with a
// type-asymmetric configuration ("1A-lpp'", "1A-lpp-inv", "ppl"; inversion.h); throws
// InvalidInput listing the names.
MechanismDesign find_builtin_mechanism(const std::string& name);

// The buildable geometry of a half constant-force slider mechanism (MechanismDesign): where every
// physical part sits, at rest and at the end of the stroke -- what a drawing, a CAD sketch or a
// laser cutter needs, as opposed to the PRBM link lengths r2, r3 the models compute with.
//
// Frame: PRB pivot 1 at the origin, the slider axis along +x, y up (docs/mechanisms.md). At rest
// the half mechanism is straight along the x axis; the parts follow thesis Table 8.1 as the exact
// model's physical chain does (mechanism_exact.h, physical_chain): an s flexure (or a fixed-fixed
// strip) of length f centred on its PRB pivot; an l segment l = r/gamma long, clamped (1 - gamma) l
// behind its characteristic pivot and pinned at its far end; rigid links fill the rest of r2, r3.
//
// At the end of the stroke (Delta x = stroke) the pivots are placed by the PRBM slider-crank
// kinematics (thesis eqs. 2.1-2.3, cfm/slider_crank.h): pivot 2 at r2 (cos theta2, sin theta2),
// pivot 3 at (r2 + r3 - Delta x, 0). Each rigid body moves rigidly (ground fixed, crank turned
// by theta2 about pivot 1, coupler along theta3 from pivot 2, slider translated by -Delta x). The
// deformed flexures are drawn in the PRBM's pseudo-rigid approximation: each flexure as the two
// pseudo-rigid pieces that meet at its characteristic pivot (a polyline of three points); the
// exact elastica shapes are added on request by mechanism_exact_geometry.h (drawings). An inverted
// design (inversion.h) is drawn in its original orientation. Units: SI (m) throughout; writers
// convert.

struct GeometryPoint {
  double x = 0.0;  // m
  double y = 0.0;  // m
};

// What a flexible segment is: a small-length flexure (s, centred on its pivot), a long one (l,
// fixed-pinned) or a fixed-fixed strip.
enum class FlexureKind { kSmall, kLong, kFixedFixed };
// "small", "long", "fixed-fixed" (the JSON and TOML key `kind` of a flexure's geometry).
const char* to_string(FlexureKind kind);
// The kind of that name; throws InvalidInput listing the three.
FlexureKind flexure_kind_from_string(std::string_view name);

// One flexible segment.
struct FlexureGeometry {
  int pivot = 0;  // PRB pivot it realises, 1..3
  FlexureKind kind = FlexureKind::kSmall;
  double length = 0.0;     // physical flexible length, m
  double width = 0.0;      // out-of-plane width b, m
  double thickness = 0.0;  // in-plane thickness h, m
  // Centreline at rest: from the end nearer the ground to the end nearer the slider.
  GeometryPoint rest_start, rest_end;
  // Pseudo-rigid polyline at the end of the stroke: rest_start's image, the characteristic
  // pivot, rest_end's image. The two pieces keep their lengths (|pivot - start| + |end - pivot|
  // = length).
  std::array<GeometryPoint, 3> stroke_end{};
  // The exact model's bent centreline at the end of the stroke (mechanism_exact_geometry.h), from
  // rest_start's image to rest_end's image; empty where it was not computed.
  std::vector<GeometryPoint> stroke_end_exact;
};

// One rigid link piece (what remains of r2 or r3 after the flexures; absent when an l segment is
// the whole link).
struct RigidLinkGeometry {
  int link = 0;         // 2 (crank, pivot 1 to 2) or 3 (coupler, pivot 2 to 3)
  double length = 0.0;  // m
  GeometryPoint rest_start, rest_end;
  GeometryPoint stroke_end_start, stroke_end_end;
  // The exact model's position of the same ends (valid when MechanismGeometry::exact_stroke_end).
  GeometryPoint exact_end_start, exact_end_end;
};

// One PRB pivot (characteristic pivot of a flexure, or a real pin joint).
struct PivotGeometry {
  int pivot = 0;  // 1..3
  PivotType type = PivotType::kPin;
  GeometryPoint rest;
  GeometryPoint stroke_end;
  GeometryPoint exact_end;  // the exact model's (valid when MechanismGeometry::exact_stroke_end)
};

struct MechanismGeometry {
  std::string name;
  std::string config;
  double r2 = 0.0, r3 = 0.0;  // PRBM link lengths, m
  double stroke = 0.0;        // m
  double theta2_end = 0.0;    // crank angle at the end of the stroke, rad
  double theta3_end = 0.0;    // principal coupler angle at the end of the stroke, rad (<= 0)
  bool inverted = false;      // drawn in the original orientation (slider block fixed in use)
  std::array<PivotGeometry, 3> pivots{};
  std::vector<FlexureGeometry> flexures;  // in pivot order
  std::vector<RigidLinkGeometry> links;   // crank piece first
  // Where the mechanism attaches to the ground body (the ground clamp of an s or l pivot 1, or
  // pin 1) and to the slider (the slider clamp of an s pivot 3, or pin 3), on the x axis, m.
  double ground_attach_x = 0.0;
  double slider_attach_x_rest = 0.0;
  double slider_attach_x_end = 0.0;
  // Overall length at rest, ground attachment to slider attachment, m.
  double overall_length() const { return slider_attach_x_rest - ground_attach_x; }
  // The model that placed the deformed flexures (for a drawing's notes).
  std::string deformed_model;
  // Whether the exact model's shapes at the end of the stroke were added (the fields *_exact,
  // exact_end_*; mechanism_exact_geometry.h); the drawing then draws those.
  bool exact_stroke_end = false;
  std::string exact_model;  // what placed them (for a drawing's notes)
};

// The geometry of a finalised design (MechanismDesign::finalise()). Throws InvalidInput for a
// design whose stroke is past the toggle position or whose lengths are not positive.
MechanismGeometry mechanism_geometry(const MechanismDesign& design);

// The kind of the flexure at pivot `pivot` (1..3) of a design; none for a pin.
std::optional<FlexureKind> flexure_kind(const MechanismDesign& design, int pivot);

// `flexure mechanism analyze --method auto --tol T`: model no more than the design needs. The PRBM
// stroke costs microseconds, the exact stroke tens of milliseconds; auto uses the PRBM alone when
// its measured force error for this configuration, with a safety margin, is within the tolerance.

// Worst PRBM force error (relative to the exact model) measured over the full stroke of the
// built-in design of `config` (`flexure mechanism validate --points 50`, docs/validation.md).
// tests/mechanisms/mechanism_method_test.cpp recomputes these so that the table cannot go stale.
double measured_prbm_force_error(const std::string& config);
// The same for a design: its configuration's value, or for a modified configuration of paper 004
// (paper_config set) the value of the built-in design of that configuration under the design's
// spring rule. Throws InvalidInput if none was measured.
double measured_prbm_force_error(const MechanismDesign& design);

// The force error the exact model is known to stay within: tightening every tolerance of its
// solves (integrator rtol 1e-12 -> 1e-13, atol 1e-14 -> 1e-15, pin closure 1e-10 -> 1e-12,
// shooting residual 1e-10 -> 1e-13) moved the slider force of 13 built-in designs (20 stroke points
// each) by at most 4.6e-10 relative (1A-spp 4.2e-10, 1B-plp 4.0e-10; docs/mechanisms.md).
inline constexpr double kExactForceErrorBound = 1e-9;

// Margin applied to the measured error: other dimensions of the same configuration move the error.
inline constexpr double kPrbmErrorMargin = 1.5;

// The models `mechanism analyze --method` chooses from.
enum class MechanismMethod { kAuto, kPrbm, kExact };
// "auto", "prbm", "exact" (the --method names and the JSON key "method").
std::string_view to_string(MechanismMethod method);
// The method of that name; throws InvalidInput listing the names.
MechanismMethod mechanism_method_from_string(std::string_view name);

struct MechanismMethodChoice {
  bool exact = true;                                 // run the exact model (the PRBM always runs)
  MechanismMethod method = MechanismMethod::kExact;  // kPrbm or kExact
  std::string reason;                                // why, with the numbers
};

// `tolerance` is the relative force error allowed. With kAuto, a tolerance below
// kExactForceErrorBound (when the PRBM does not meet it either) throws bench::ToleranceBelowReach
// (beam_problem.h): no model meets it.
MechanismMethodChoice choose_mechanism_method(const MechanismDesign& design,
                                              MechanismMethod method,
                                              double tolerance);

}  // namespace flexure::mechanism
