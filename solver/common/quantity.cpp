#include <fmt/format.h>

#include <array>
#include <charconv>
#include <cmath>
#include <numbers>

#include "flexure/solver/common/names.h"
#include "flexure/solver/common/section.h"
#include "flexure/solver/common/status.h"

namespace flexure::io {
namespace {

// Exact conversion factors: the inch is 0.0254 m and the pound-force 4.4482216152605 N by
// definition (NIST SP 811, appendix B); psi = lbf/in^2.
constexpr double kInch = 0.0254;
constexpr double kPoundForce = 4.4482216152605;
constexpr double kPsi = kPoundForce / (kInch * kInch);
constexpr double kPoundInch = kPoundForce * kInch;
constexpr double kPoundInch2 = kPoundForce * kInch * kInch;

struct Unit {
  Dimension dimension;
  std::string_view name;
  double to_si;
};

constexpr std::array kUnits{
    Unit{Dimension::kLength, "m", 1.0},
    Unit{Dimension::kLength, "mm", 1e-3},
    Unit{Dimension::kLength, "cm", 1e-2},
    Unit{Dimension::kLength, "um", 1e-6},
    Unit{Dimension::kLength, "µm", 1e-6},
    Unit{Dimension::kLength, "in", kInch},
    Unit{Dimension::kLength, "ft", 12.0 * kInch},
    Unit{Dimension::kForce, "N", 1.0},
    Unit{Dimension::kForce, "mN", 1e-3},
    Unit{Dimension::kForce, "kN", 1e3},
    Unit{Dimension::kForce, "lbf", kPoundForce},
    Unit{Dimension::kMoment, "N m", 1.0},
    Unit{Dimension::kMoment, "Nm", 1.0},
    Unit{Dimension::kMoment, "N*m", 1.0},
    Unit{Dimension::kMoment, "N.m", 1.0},
    Unit{Dimension::kMoment, "N·m", 1.0},
    Unit{Dimension::kMoment, "N mm", 1e-3},
    Unit{Dimension::kMoment, "Nmm", 1e-3},
    Unit{Dimension::kMoment, "N*mm", 1e-3},
    Unit{Dimension::kMoment, "lbf in", kPoundInch},
    Unit{Dimension::kMoment, "lbf*in", kPoundInch},
    Unit{Dimension::kMoment, "lbf-in", kPoundInch},
    Unit{Dimension::kMoment, "in lbf", kPoundInch},
    Unit{Dimension::kMoment, "in*lbf", kPoundInch},
    Unit{Dimension::kMoment, "in-lbf", kPoundInch},
    Unit{Dimension::kStress, "Pa", 1.0},
    Unit{Dimension::kStress, "kPa", 1e3},
    Unit{Dimension::kStress, "MPa", 1e6},
    Unit{Dimension::kStress, "GPa", 1e9},
    Unit{Dimension::kStress, "psi", kPsi},
    Unit{Dimension::kStress, "ksi", 1e3 * kPsi},
    Unit{Dimension::kStress, "Msi", 1e6 * kPsi},
    Unit{Dimension::kSecondMoment, "m^4", 1.0},
    Unit{Dimension::kSecondMoment, "cm^4", 1e-8},
    Unit{Dimension::kSecondMoment, "mm^4", 1e-12},
    Unit{Dimension::kSecondMoment, "um^4", 1e-24},
    Unit{Dimension::kSecondMoment, "in^4", kInch* kInch* kInch* kInch},
    Unit{Dimension::kRigidity, "N m^2", 1.0},
    Unit{Dimension::kRigidity, "N*m^2", 1.0},
    Unit{Dimension::kRigidity, "N mm^2", 1e-6},
    Unit{Dimension::kRigidity, "N*mm^2", 1e-6},
    Unit{Dimension::kRigidity, "lbf in^2", kPoundInch2},
    Unit{Dimension::kRigidity, "lbf*in^2", kPoundInch2},
    Unit{Dimension::kAngle, "rad", 1.0},
    Unit{Dimension::kAngle, "deg", std::numbers::pi / 180.0},
    Unit{Dimension::kAngle, "°", std::numbers::pi / 180.0},
    Unit{Dimension::kForcePerLength, "N/m", 1.0},
    Unit{Dimension::kForcePerLength, "N/mm", 1e3},
    Unit{Dimension::kForcePerLength, "kN/m", 1e3},
    Unit{Dimension::kForcePerLength, "lbf/in", kPoundForce / kInch},
    Unit{Dimension::kDensity, "kg/m^3", 1.0},
    Unit{Dimension::kDensity, "g/cm^3", 1e3},
    Unit{Dimension::kAcceleration, "m/s^2", 1.0},
    Unit{Dimension::kArea, "m^2", 1.0},
    Unit{Dimension::kArea, "mm^2", 1e-6},
    Unit{Dimension::kArea, "cm^2", 1e-4},
    Unit{Dimension::kArea, "in^2", kInch* kInch},
    Unit{Dimension::kCurvature, "1/m", 1.0},
    Unit{Dimension::kCurvature, "1/mm", 1e3},
    Unit{Dimension::kCurvature, "1/in", 1.0 / kInch},
};

// What each dimension is called in messages, and its SI unit.
struct DimensionInfo {
  std::string_view name;
  std::string_view si;
};

DimensionInfo info(Dimension dimension) {
  constexpr std::array<DimensionInfo, 12> kInfo{{
      {"a length", "m"},
      {"a force", "N"},
      {"a moment", "N m"},
      {"a stress or modulus", "Pa"},
      {"an area moment of inertia", "m^4"},
      {"a flexural rigidity", "N m^2"},
      {"an angle", "rad"},
      {"a force per unit length", "N/m"},
      {"a density", "kg/m^3"},
      {"an acceleration", "m/s^2"},
      {"an area", "m^2"},
      {"a curvature", "1/m"},
  }};
  return kInfo[static_cast<std::size_t>(dimension)];
}

std::string_view dimension_name(Dimension dimension) { return info(dimension).name; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// "N  m" and "N m" are one unit: inner runs of blanks count as one space.
std::string squeeze_blanks(std::string_view s) {
  std::string out;
  for (char c : s) {
    const bool blank = c == ' ' || c == '\t';
    if (blank && (out.empty() || out.back() == ' ')) continue;
    out.push_back(blank ? ' ' : c);
  }
  return out;
}

}  // namespace

std::string_view si_unit(Dimension dimension) { return info(dimension).si; }

std::vector<std::string> unit_names(Dimension dimension) {
  std::vector<std::string> names;
  for (const Unit& u : kUnits) {
    if (u.dimension == dimension) names.emplace_back(u.name);
  }
  return names;
}

Quantity parse_quantity(std::string_view text, Dimension dimension, std::string_view what) {
  const std::string_view s = trim(text);
  if (s.empty()) throw InvalidInput(fmt::format("{}: a value is required", what));
  // A leading '+' is allowed; from_chars does not accept it.
  const std::string_view number = s.front() == '+' ? s.substr(1) : s;
  double value = 0.0;
  const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
  if (error != std::errc() || end == number.data()) {
    throw InvalidInput(fmt::format(
        "{}: '{}' is not a number with an optional unit (e.g. 50mm, 200GPa)", what, text));
  }
  if (!std::isfinite(value)) {
    throw InvalidInput(fmt::format("{}: '{}' is not a finite number", what, text));
  }
  Quantity q;
  q.unit = squeeze_blanks(trim(std::string_view(end, number.data() + number.size() - end)));
  if (q.unit.empty()) {
    q.si = value;
    return q;
  }
  const std::string accepted = fmt::format("{}", fmt::join(unit_names(dimension), ", "));
  const Unit* near_miss = nullptr;
  for (const Unit& u : kUnits) {
    if (u.name == q.unit) {
      if (u.dimension != dimension) {
        throw InvalidInput(fmt::format("{}: '{}' is {}, but {} is {} ({})",
                                       what,
                                       text,
                                       dimension_name(u.dimension),
                                       what,
                                       dimension_name(dimension),
                                       accepted));
      }
      q.si = value * u.to_si;
      if (!std::isfinite(q.si)) {
        throw InvalidInput(fmt::format("{}: '{}' overflows in SI units", what, text));
      }
      return q;
    }
    if (u.dimension == dimension && same_name(u.name, q.unit)) near_miss = &u;
  }
  if (near_miss != nullptr) {
    throw InvalidInput(fmt::format(
        "{}: unknown unit '{}' in '{}'; did you mean '{}'? (units are case-sensitive: {})",
        what,
        q.unit,
        text,
        near_miss->name,
        accepted));
  }
  throw InvalidInput(fmt::format(
      "{}: unknown unit '{}' in '{}' ({} takes {})", what, q.unit, text, what, accepted));
}

std::string angle_warning(const Quantity& angle, std::string_view what) {
  if (angle.has_unit() || !(std::fabs(angle.si) > 2.0 * std::numbers::pi)) return "";
  return fmt::format(
      "{} = {:g} rad is more than a full turn: plain angles are radians; for degrees write "
      "{:g}deg",
      what,
      angle.si,
      angle.si);
}

std::string thickness_warning(double thickness, double length, std::string_view where) {
  if (!(thickness > 0.1 * length)) return "";
  return fmt::format(
      "{}: the thickness {:g} m is more than a tenth of the length {:g} m; Euler-Bernoulli beam "
      "theory (no shear deformation) is questionable for so thick a beam (or a unit is wrong)",
      where,
      thickness,
      length);
}

std::string modulus_warning(const Quantity& modulus, std::string_view what) {
  if (!(modulus.si > 0.0 && modulus.si < 1e6)) return "";
  return fmt::format(
      "{} = {:g} Pa is softer than any structural solid (lengths are in metres); did you mean "
      "{:g}MPa or {:g}GPa?",
      what,
      modulus.si,
      modulus.si,
      modulus.si);
}

QuantityRange parse_quantity_range(std::string_view text,
                                   Dimension dimension,
                                   std::string_view what) {
  const std::size_t colon = text.find(':');
  if (colon == std::string_view::npos) {
    const Quantity q = parse_quantity(text, dimension, what);
    return {q, q};
  }
  if (text.find(':', colon + 1) != std::string_view::npos) {
    throw InvalidInput(fmt::format("{} '{}': give one range A:B (or one value A)", what, text));
  }
  QuantityRange r{parse_quantity(text.substr(0, colon), dimension, what),
                  parse_quantity(text.substr(colon + 1), dimension, what)};
  if (r.lower.si > r.upper.si) {
    throw InvalidInput(fmt::format("{} '{}' is inverted: {} {} > {} {}; give the lower end first",
                                   what,
                                   text,
                                   r.lower.si,
                                   si_unit(dimension),
                                   r.upper.si,
                                   si_unit(dimension)));
  }
  return r;
}

}  // namespace flexure::io
