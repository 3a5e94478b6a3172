#pragma once
// Sections, materials and the quantities they are given in, in one header: Section and Material,
// the bending modulus of a strip (beam or plate), quantities with units.
//
// One cross-section and one material for every part of the library that needs them (physical
// beams and chains, PRBM elements, mechanism designs, design synthesis; issue 28, docs/units.md).
// Any consistent units: SI throughout the tool (m, m^4, Pa, kg/m^3).
//
// A Section is a rectangle (width b out of the plane of bending, thickness h in it: I = b h^3/12,
// Howell §2.1) or a general section given by its second moment I, with its thickness h when known
// (the extreme fibre c = h/2 gives the bending stress M c/I). A Material has Young's modulus E,
// Poisson's ratio nu, and optionally the yield strength S_y and the density.
//
// The factories and validate() throw InvalidInput naming the field (Section::width, Material::E,
// ...); code that receives a Section or Material it did not build validates it.
//
// The bending modulus of a strip: a beam's E, or the plate (cylindrical-bending) modulus
// E/(1 - nu^2) of a strip many times wider than thick (issue 29 item 7; docs/plate-modulus.md).
//
// A bent strip's fibres contract sideways by nu times their axial strain. A narrow strip is free
// to do so: its cross-section takes the anticlastic curvature -nu/R and the bending stiffness is
// E I. A wide strip cannot: away from a boundary layer along each edge, about sqrt(R h) wide, the
// curved strip's own membrane stiffness keeps the section straight (plane strain across the
// width), and the stiffness is E I/(1 - nu^2). Which case holds is set by the anticlastic
// (Searle) parameter beta = b^2/(R h) -- the square of the width over the boundary layer's width.
//
// The transition is the exact linear solution of a strip bent to curvature 1/R (plate bending
// across the width on the elastic foundation E h/R^2 of the curved membrane; derivation in
// docs/plate-modulus.md): the bending stiffness is
//   E I/(1 - nu^2) * Phi,   Phi = 1 + nu^2 f'(t)/t + (2 nu^2/t) int_{-t}^{t} f^2,
// with t = lambda b/2, lambda^4 = 3 (1 - nu^2)/(R h)^2 (so t^2 = sqrt(3 (1 - nu^2)) beta/4) and f
// the even solution of f'''' + 4 f = 0 with f''(t) = -1, f'''(t) = 0 (free edges). Phi runs from
// 1 - nu^2 (beam, beta -> 0) to 1 (plate, beta -> inf). plate_fraction() is the share of the plate
// effect present, (Phi - (1 - nu^2))/nu^2, in [0, 1]; "auto" takes the plate modulus where it is at
// least 1/2 (the modulus nearer the exact one): beta >= 6.30 for nu = 0.3 (6.0 as nu -> 0, 6.9 as
// nu -> 0.5).
//
// Physical quantities as a designer writes them: "50mm", "0.5 mm", "2in", "200GPa", "30Msi",
// "167ksi", "25lbf", "30deg". A plain number is SI (metres, newtons, pascals, radians); a unit
// suffix converts to SI. Units are spelled with their case (MPa, not mpa: a milli and a mega
// differ by 10^9); a near miss is an error that names the intended spelling, never a guess.
// The units accepted per dimension are listed in docs/units.md.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace flexure {

struct Section {
  enum class Shape { kRectangle, kGeneral };
  Shape shape = Shape::kRectangle;
  double width = 0.0;      // b, out of the plane of bending (rectangle only; 0 for a general one)
  double thickness = 0.0;  // h, in the plane of bending (general: 0 when unknown)
  double I = 0.0;          // second moment of a general section (0 for a rectangle: computed)

  // Validated constructions.
  static Section rectangle(double width, double thickness);
  static Section general(double I, std::optional<double> thickness = {});

  // b h^3/12 for a rectangle, I for a general section.
  double second_moment() const;
  // b h for a rectangle; unknown for a general section.
  std::optional<double> area() const;
  // I/c with c = h/2 (b h^2/6 for a rectangle): the bending stress is |M|/S; unknown without h.
  std::optional<double> section_modulus() const;

  // Throws InvalidInput naming the field: a rectangle needs a finite width and thickness > 0 and
  // no I; a general section a finite I > 0, a thickness that is 0 (unknown) or finite and > 0, and
  // no width.
  void validate() const;
};

struct Material {
  double E = 0.0;   // Young's modulus
  double nu = 0.3;  // Poisson's ratio, -1 < nu < 0.5 (isotropic: positive shear and bulk moduli)
  std::optional<double> yield_strength;  // S_y, for stresses and safety factors
  std::optional<double> density;         // for masses (dynamics)

  // G = E/(2 (1 + nu)).
  double shear_modulus() const;

  // Throws InvalidInput naming the field: E finite and > 0, nu finite in (-1, 0.5), a yield
  // strength or density finite and > 0 when given.
  void validate() const;
};

// E I, after validating both.
double flexural_rigidity(const Section& section, const Material& material);

}  // namespace flexure

namespace flexure {

enum class PlateRule { kOff, kOn, kAuto };

// "off", "on", "auto" (case-insensitive); throws InvalidInput naming `what` and the choices.
PlateRule plate_rule_from_string(const std::string& text, const std::string& what);
const char* to_string(PlateRule rule);

// beta = b^2/(R h) = b^2 |kappa|/h; throws InvalidInput unless b, h > 0 and kappa finite.
double searle_parameter(double width, double thickness, double curvature);

// The share of the plate stiffening present at beta, (Phi - (1 - nu^2))/nu^2 (see above), in
// [0, 1]; nu in (-1, 0.5), nu != 0 (at nu = 0 the two moduli agree; 0 is returned for beta = 0,
// the limit otherwise). Large beta: 1 - (3/4)/t + O(exp(-2t)); small beta: O(beta^2).
double plate_fraction(double beta, double nu);

// The smallest beta where plate_fraction(beta, nu) >= 1/2 (auto's threshold), by bisection.
double searle_threshold(double nu);

// The modulus a strip bends with, and why (reported in JSON as `modulus_rule`, `effective_E`).
struct ModulusChoice {
  PlateRule rule = PlateRule::kOff;
  double E = 0.0;            // Young's modulus as given, Pa
  std::optional<double> nu;  // Poisson's ratio (needed by on and auto)
  bool plate = false;        // whether E/(1 - nu^2) is used
  double effective_E = 0.0;  // E or E/(1 - nu^2)
  // auto: the Searle parameter at the decisive curvature, the threshold and the exact share of
  // the plate effect there (plate_fraction).
  std::optional<double> beta, threshold, fraction;
  std::optional<double> curvature;  // 1/R the decision was taken at, 1/m
  // Set where a caller overrides the parameter's verdict (a mechanism has one modulus for all its
  // strips): appended to reason().
  std::string note;
  // "beam modulus E (plate off)", "plate modulus E/(1 - nu^2) (plate on)", "auto: ...".
  std::string reason() const;
  // The rule's name for JSON: "beam" or "plate" plus how ("off", "on", "auto").
  std::string modulus_rule() const;
};

// The choice of `rule` for a material (E, nu) and strip (width, thickness) bent to `curvature`
// (|1/R| at the decisive point, for auto). Throws InvalidInput naming `where`: on or auto without
// nu; auto without the width and thickness of a rectangle; auto without a curvature. E must be
// > 0. With off, nu may be absent. At curvature 0 auto picks the beam (beta = 0).
ModulusChoice choose_modulus(PlateRule rule,
                             double E,
                             std::optional<double> nu,
                             std::optional<double> width,
                             std::optional<double> thickness,
                             std::optional<double> curvature,
                             const std::string& where);

}  // namespace flexure

namespace flexure::io {

// (info() in quantity.cpp lists names and SI units in this order.)
enum class Dimension {
  kLength,          // m
  kForce,           // N
  kMoment,          // N m
  kStress,          // Pa (moduli and strengths)
  kSecondMoment,    // m^4 (area moment of inertia)
  kRigidity,        // N m^2 (flexural rigidity EI)
  kAngle,           // rad
  kForcePerLength,  // N/m (distributed loads, pressures per unit length)
  kDensity,         // kg/m^3
  kAcceleration,    // m/s^2 (gravity)
  kArea,            // m^2 (cross-section area)
  kCurvature,       // 1/m (a stress-free curvature)
};

// The SI unit of a dimension, e.g. "N m".
std::string_view si_unit(Dimension dimension);

struct Quantity {
  double si = 0.0;   // the value in SI units (radians for angles)
  std::string unit;  // the unit as written, empty for a plain number
  bool has_unit() const { return !unit.empty(); }
};

// Parses `text` as a number with an optional unit of `dimension`. Throws InvalidInput naming
// `what` (e.g. "--length") for an empty or non-numeric value, a non-finite number, a unit of
// another dimension or an unknown unit (listing the accepted ones, and the right spelling of a
// near miss).
Quantity parse_quantity(std::string_view text, Dimension dimension, std::string_view what);

// A range "A:B" of two quantities (each with its own optional unit, e.g. "12in:15in"), or one
// quantity "A" for A:A. Throws InvalidInput naming `what` for a malformed side, more than one
// colon, or A > B.
struct QuantityRange {
  Quantity lower;
  Quantity upper;
};
QuantityRange parse_quantity_range(std::string_view text,
                                   Dimension dimension,
                                   std::string_view what);

// The unit names accepted for a dimension, in the order docs/units.md lists them.
std::vector<std::string> unit_names(Dimension dimension);

// Warnings for values that are valid but probably a unit mistake (issued on stderr by the tool).
// Each returns an empty string when the value is plausible.
//   An angle given as a plain number (radians) above 2 pi: probably degrees.
std::string angle_warning(const Quantity& angle, std::string_view what);
//   A thickness above a tenth of the length: Euler-Bernoulli beam theory (plane sections,
//   negligible shear) is questionable for so thick a beam.
std::string thickness_warning(double thickness, double length, std::string_view where);
//   A modulus below 1e6 Pa where lengths are in metres: probably given in MPa or GPa without a
//   unit (no structural solid is that soft).
std::string modulus_warning(const Quantity& modulus, std::string_view what);

}  // namespace flexure::io

namespace flexure {
// The parser lives in core so that the beam layer and the Python module can read "50mm" without
// linking the I/O layer; its names stay in flexure::io for existing callers.
using io::Dimension;
using io::parse_quantity;
using io::parse_quantity_range;
using io::Quantity;
using io::QuantityRange;
}  // namespace flexure
