#pragma once
// Physical quantities as a designer writes them: "50mm", "0.5 mm", "2in", "200GPa", "30Msi",
// "167ksi", "25lbf", "30deg". A plain number is SI (metres, newtons, pascals, radians); a unit
// suffix converts to SI. Units are spelled with their case (MPa, not mpa: a milli and a mega
// differ by 10^9); a near miss is an error that names the intended spelling, never a guess.
// The units accepted per dimension are listed in docs/units.md.
#include <string>
#include <string_view>
#include <vector>

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
