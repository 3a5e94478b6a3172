#include "cli/physical_flags.h"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <utility>

#include "cli/cli_common.h"
#include "flexure/mechanisms/materials_fatigue.h"
#include "flexure/solver/common/section.h"
#include "flexure/solver/common/status.h"

namespace flexure::cli {
namespace {

std::optional<double> quantity_option(const std::string& text,
                                      io::Dimension dimension,
                                      const char* what) {
  if (text.empty()) return std::nullopt;
  return io::parse_quantity(text, dimension, what).si;
}

// A dimensionless number (Poisson's ratio, a shear coefficient): no unit allowed.
double plain_number(const std::string& text, const char* what) {
  const io::Quantity q = io::parse_quantity(text, io::Dimension::kAngle, what);
  if (q.has_unit()) {
    throw InvalidInput(fmt::format("{} is a plain number without a unit (got '{}')", what, text));
  }
  return q.si;
}

}  // namespace

void PhysicalFlags::add_to(CLI::App& command, bool with_yield_strength) {
  this->with_yield_strength = with_yield_strength;
  CLI::Option_group* group = command.add_option_group(
      "physical beam", "A cantilever in physical units (SI, or with units: 50mm, 200GPa, 5N)");
  const std::pair<const char*, std::string*> flags[] = {
      {"--length", &length},
      {"--E", &E},
      {"--I", &I},
      {"--width", &width},
      {"--thickness", &thickness},
      {"--Fx", &Fx},
      {"--Fy", &Fy},
      {"--M", &M},
      {"--yield-strength", &yield_strength},
      {"--material", &material},
  };
  const char* help[] = {
      "Beam length L (m, or 50mm, 2in)",
      "Young's modulus E (Pa, or 200GPa, 30Msi)",
      "Area moment of inertia I (m^4, or mm^4, in^4); or --width and --thickness",
      "Section width b (m, or mm, in), out of the plane of bending",
      "Section thickness h (m, or mm, in), in the plane of bending: I = b h^3/12, stress M h/2I",
      "Tip force along the undeformed beam, from the clamp (N, or lbf)",
      "Tip force perpendicular to the undeformed beam (N, or lbf)",
      "Tip moment, counter-clockwise (N m, or N mm, lbf in)",
      "Yield strength S_y for the safety factor (Pa, or MPa, ksi)",
      "Material from the library (E and S_y; `flexure materials`), e.g. steel-1095-hr",
  };
  for (std::size_t i = 0; i < std::size(flags); ++i) {
    if (!with_yield_strength && flags[i].second == &yield_strength) continue;
    options.push_back(group->add_option(flags[i].first, *flags[i].second, help[i]));
  }
  // Distributed loads and extension (docs/distributed-loads.md, docs/extensible.md).
  const std::pair<const char*, std::string*> more[] = {
      {"--qx", &qx},
      {"--qy", &qy},
      {"--q-follower", &q_follower},
      {"--density", &density},
      {"--g", &g},
      {"--nu", &nu},
      {"--shear-coefficient", &shear_coefficient},
      {"--curvature", &curvature},
      {"--width-tip", &width_tip},
      {"--thickness-tip", &thickness_tip},
  };
  const char* more_help[] = {
      "Dead load per unit length along the undeformed beam (N/m, or N/mm, lbf/in)",
      "Dead load per unit length perpendicular to the undeformed beam (N/m, or N/mm, lbf/in)",
      "Follower pressure per unit length along the deflected normal, toward the left of the "
      "tangent (N/m)",
      "Density for the self-weight rho A g along -y (kg/m^3, or g/cm^3; needs --width and "
      "--thickness)",
      "Gravity of the self-weight (m/s^2; default 9.80665)",
      "Poisson's ratio (with --extensible: G = E / (2 (1 + nu)))",
      "Timoshenko's shear coefficient k (with --extensible; default 5/6, the rectangle)",
      "Stress-free curvature kappa0 (1/m, or 1/mm, 1/in; positive bends toward +y): m = EI "
      "(theta' - kappa0)",
      "Taper: section width at the tip (m, or mm, in), linear from --width at the clamp",
      "Taper: section thickness at the tip (m, or mm, in), linear from --thickness at the clamp",
  };
  for (std::size_t i = 0; i < std::size(more); ++i) {
    options.push_back(group->add_option(more[i].first, *more[i].second, more_help[i]));
  }
  options.push_back(group->add_option(
      "--plate",
      plate,
      "Bending modulus of a wide strip: off (E, default), on (plate modulus E/(1 - nu^2)), auto "
      "(plate where the Searle parameter b^2/(R h) >= about 6.3; docs/plate-modulus.md); on and "
      "auto need --nu or a --material with nu"));
  options.push_back(group->add_flag(
      "--extensible",
      extensible,
      "Extensible and shear-flexible beam (Reissner): EA = E b h, GAs = k G b h (needs --nu)"));
}

bool PhysicalFlags::given() const {
  return std::any_of(options.begin(), options.end(), [](const CLI::Option* o) { return bool(*o); });
}

PhysicalCantilever PhysicalFlags::parse() const {
  using io::Dimension;
  PhysicalCantilever beam;
  if (length.empty() || (E.empty() && material.empty())) {
    throw InvalidInput(
        "a physical beam needs --length and --E (or --material), a section (--I, or --width and "
        "--thickness) and its tip loads (--Fx, --Fy, --M; default 0)");
  }
  const MaterialGrade* grade = material.empty() ? nullptr : &find_material(material);
  beam.length = io::parse_quantity(length, Dimension::kLength, "--length").si;
  const io::Quantity modulus =
      E.empty() ? io::Quantity{grade->E, ""} : io::parse_quantity(E, Dimension::kStress, "--E");
  beam.material.E = modulus.si;
  if (grade != nullptr && !E.empty()) {
    warn(fmt::format("--E {:.6g} Pa replaces the {:.6g} Pa of material '{}'",
                     beam.material.E,
                     grade->E,
                     grade->id));
  }
  // The section's values as given; which of them are given is checked with the length and
  // modulus by set_section() below, in validate()'s order.
  const std::optional<double> I_given = quantity_option(I, Dimension::kSecondMoment, "--I");
  const std::optional<double> width_given = quantity_option(width, Dimension::kLength, "--width");
  const std::optional<double> thickness_given =
      quantity_option(thickness, Dimension::kLength, "--thickness");
  beam.Fx = quantity_option(Fx, Dimension::kForce, "--Fx").value_or(0.0);
  beam.Fy = quantity_option(Fy, Dimension::kForce, "--Fy").value_or(0.0);
  beam.M = quantity_option(M, Dimension::kMoment, "--M").value_or(0.0);
  beam.material.yield_strength =
      quantity_option(yield_strength, Dimension::kStress, "--yield-strength");
  beam.qx = quantity_option(qx, Dimension::kForcePerLength, "--qx").value_or(0.0);
  beam.qy = quantity_option(qy, Dimension::kForcePerLength, "--qy").value_or(0.0);
  beam.q_follower =
      quantity_option(q_follower, Dimension::kForcePerLength, "--q-follower").value_or(0.0);
  beam.material.density = quantity_option(density, Dimension::kDensity, "--density");
  if (!g.empty()) {
    if (!beam.material.density)
      throw InvalidInput("--g is the gravity of the self-weight; give --density");
    beam.g = io::parse_quantity(g, Dimension::kAcceleration, "--g").si;
  }
  beam.extensible = extensible;
  beam.curvature = quantity_option(curvature, Dimension::kCurvature, "--curvature").value_or(0.0);
  beam.width_tip = quantity_option(width_tip, Dimension::kLength, "--width-tip");
  beam.thickness_tip = quantity_option(thickness_tip, Dimension::kLength, "--thickness-tip");
  if (!nu.empty()) beam.set_nu(plain_number(nu, "--nu"));
  if (!plate.empty()) {
    beam.plate = plate_rule_from_string(plate, "--plate");
    beam.plate_given = true;
  }
  // The material's Poisson's ratio where the plate modulus needs one and --nu is not given.
  if (beam.plate != PlateRule::kOff && !beam.nu_given && grade != nullptr) beam.set_nu(grade->nu);
  if (!shear_coefficient.empty()) {
    if (!extensible) throw InvalidInput("--shear-coefficient is used with --extensible only");
    beam.shear_coefficient = plain_number(shear_coefficient, "--shear-coefficient");
  }
  if (grade != nullptr) {
    const std::optional<double> strength = grade->static_strength();
    std::optional<double>& given_strength = beam.material.yield_strength;
    if (given_strength && strength && *given_strength != *strength) {
      warn(fmt::format("--yield-strength {:.6g} Pa replaces the {:.6g} Pa of material '{}'",
                       *given_strength,
                       *strength,
                       grade->id));
    }
    // The material's strength where the command reports a safety factor and the section gives a
    // stress (a thickness).
    if (!given_strength && with_yield_strength && !thickness.empty()) given_strength = strength;
  }
  beam.set_section(I_given, width_given, thickness_given);
  beam.validate();
  warn(io::modulus_warning(modulus, "--E"));
  if (thickness_given) warn(io::thickness_warning(*thickness_given, beam.length, "--thickness"));
  return beam;
}

}  // namespace flexure::cli
