#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "flexure/mechanisms/materials_fatigue.h"
#include "flexure/solver/common/status.h"

namespace flexure {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kPsi = 6894.757293168361;  // Pa
constexpr double kInch = 0.0254;            // m

bool finite_positive(double v) { return std::isfinite(v) && v > 0.0; }

// Table 3.3 (Shigley and Mischke 1996): a (MPa fit, kpsi fit) and b.
struct SurfaceFit {
  double a_MPa, a_kpsi, b;
};
SurfaceFit surface_fit(SurfaceFinish finish) {
  switch (finish) {
    case SurfaceFinish::kGround:
      return {1.58, 1.34, -0.086};
    case SurfaceFinish::kMachined:
      return {4.45, 2.67, -0.265};
    case SurfaceFinish::kHotRolled:
      return {58.1, 14.5, -0.719};
    case SurfaceFinish::kAsForged:
      return {271.0, 39.8, -0.995};
    case SurfaceFinish::kPolished:
      break;
  }
  return {1.0, 1.0, 0.0};
}

}  // namespace

const char* surface_finish_name(SurfaceFinish finish) {
  switch (finish) {
    case SurfaceFinish::kPolished:
      return "polished";
    case SurfaceFinish::kGround:
      return "ground";
    case SurfaceFinish::kMachined:
      return "machined";
    case SurfaceFinish::kHotRolled:
      return "hot-rolled";
    case SurfaceFinish::kAsForged:
      return "as-forged";
  }
  return "?";
}

SurfaceFinish parse_surface_finish(const std::string& name) {
  for (SurfaceFinish f : {SurfaceFinish::kPolished,
                          SurfaceFinish::kGround,
                          SurfaceFinish::kMachined,
                          SurfaceFinish::kHotRolled,
                          SurfaceFinish::kAsForged}) {
    if (name == surface_finish_name(f)) return f;
  }
  if (name == "cold-rolled") return SurfaceFinish::kMachined;  // one row of Table 3.3
  throw InvalidInput(fmt::format(
      "unknown surface finish '{}'; allowed: polished, ground, machined (or cold-rolled), "
      "hot-rolled, as-forged (Howell Table 3.3)",
      name));
}

const char* fatigue_loading_name(FatigueLoading loading) {
  switch (loading) {
    case FatigueLoading::kBending:
      return "bending";
    case FatigueLoading::kAxial:
      return "axial";
    case FatigueLoading::kTorsion:
      return "torsion";
  }
  return "?";
}

FatigueLoading parse_fatigue_loading(const std::string& name) {
  for (FatigueLoading l :
       {FatigueLoading::kBending, FatigueLoading::kAxial, FatigueLoading::kTorsion}) {
    if (name == fatigue_loading_name(l)) return l;
  }
  throw InvalidInput(
      fmt::format("unknown fatigue loading '{}'; allowed: bending, axial, torsion", name));
}

double marin_surface_factor(SurfaceFinish finish, double S_ut, SurfaceFitUnits units) {
  if (!finite_positive(S_ut)) {
    throw InvalidInput(
        fmt::format("the ultimate strength S_ut must be finite and > 0 (got {})", S_ut));
  }
  const SurfaceFit fit = surface_fit(finish);
  // Eq. 3.76 takes S_ut in MPa or kpsi, each with its own a.
  const double c = units == SurfaceFitUnits::kMPa
                       ? fit.a_MPa * std::pow(S_ut / 1e6, fit.b)
                       : fit.a_kpsi * std::pow(S_ut / (1e3 * kPsi), fit.b);
  return std::min(c, 1.0);
}

double equivalent_diameter_rectangle(double width, double thickness) {
  if (!finite_positive(width) || !finite_positive(thickness)) {
    throw InvalidInput(fmt::format(
        "the section's width and thickness must be finite and > 0 (got {}, {})", width, thickness));
  }
  return 0.808 * std::sqrt(width * thickness);  // eq. 3.81
}

double marin_size_factor(double d, FatigueLoading loading) {
  if (!finite_positive(d)) {
    throw InvalidInput(fmt::format("the equivalent diameter must be finite and > 0 (got {})", d));
  }
  if (loading == FatigueLoading::kAxial) return 1.0;  // eq. 3.78
  // Eq. 3.77 in inches (the millimetre form is the same line: 0.3 in = 7.62 mm).
  const double d_in = d / kInch;
  if (d_in < 0.11) return 1.0;
  if (d_in > 2.0) return 0.6;
  return std::pow(d_in / 0.3, -0.1133);
}

double marin_load_factor(FatigueLoading loading) {
  switch (loading) {
    case FatigueLoading::kBending:
      return 1.0;  // eq. 3.83
    case FatigueLoading::kAxial:
      return 0.70;  // eq. 3.82
    case FatigueLoading::kTorsion:
      return 0.577;  // eq. 3.83
  }
  return 1.0;
}

double marin_reliability_factor(double reliability) {
  if (!(reliability >= 0.5 && reliability < 1.0)) {
    throw InvalidInput(fmt::format(
        "the reliability must be in [0.5, 1) (50 % to just below 100 %; got {})", reliability));
  }
  // z with Phi(z) = R by bisection on the normal distribution 0.5 erfc(-z/sqrt 2).
  double lo = 0.0, hi = 40.0;
  for (int i = 0; i < 200 && hi - lo > 1e-14; ++i) {
    const double mid = 0.5 * (lo + hi);
    const double tail = 0.5 * std::erfc(mid / std::sqrt(2.0));  // 1 - Phi(mid)
    (tail > 1.0 - reliability ? lo : hi) = mid;
  }
  return 1.0 - 0.08 * 0.5 * (lo + hi);
}

double low_cycle_strength_fraction(FatigueLoading loading) {
  return loading == FatigueLoading::kAxial ? 0.75 : 0.9;  // eq. 3.57
}

void FatigueOptions::validate() const {
  marin_reliability_factor(reliability);
  if (!(std::isfinite(K_f) && K_f >= 1.0)) {
    throw InvalidInput(fmt::format(
        "the fatigue stress-concentration factor K_f must be finite and >= 1 (got {})", K_f));
  }
  if (!(std::isfinite(other_factor) && other_factor > 0.0 && other_factor <= 1.0)) {
    throw InvalidInput(fmt::format(
        "the other miscellaneous fatigue factor must be in (0, 1] (got {})", other_factor));
  }
}

void FatigueMaterial::validate() const {
  if (!finite_positive(ultimate_strength)) {
    throw InvalidInput(fmt::format("the ultimate strength S_ut must be finite and > 0 (got {})",
                                   ultimate_strength));
  }
  if (!finite_positive(uncorrected_strength) || uncorrected_strength >= ultimate_strength) {
    throw InvalidInput(fmt::format(
        "the endurance limit S_e' must be finite, > 0 and below S_ut = {:.6g} Pa (got {})",
        ultimate_strength,
        uncorrected_strength));
  }
  if (fatigue_cycles && !(std::isfinite(*fatigue_cycles) && *fatigue_cycles > 1e3)) {
    throw InvalidInput(
        fmt::format("the life of a fatigue strength must be finite and > 1e3 cycles (got {})",
                    *fatigue_cycles));
  }
  if (yield_strength && !finite_positive(*yield_strength)) {
    throw InvalidInput(
        fmt::format("the yield strength S_y must be finite and > 0 (got {})", *yield_strength));
  }
}

FatigueMaterial fatigue_material(const MaterialGrade* grade,
                                 std::optional<double> ultimate_strength,
                                 std::optional<double> uncorrected_strength,
                                 std::optional<double> yield_strength) {
  FatigueMaterial m;
  const std::string name = grade ? fmt::format("material '{}'", grade->id) : "the material";
  if (!ultimate_strength && grade) ultimate_strength = grade->ultimate_strength;
  if (!ultimate_strength) {
    throw InvalidInput(fmt::format(
        "a fatigue check needs the ultimate strength S_ut, which {} does not give", name));
  }
  m.ultimate_strength = *ultimate_strength;
  if (uncorrected_strength) {
    m.uncorrected_strength = *uncorrected_strength;
    m.source = "given";
  } else if (grade && grade->fatigue_strength) {
    m.uncorrected_strength = *grade->fatigue_strength;
    m.fatigue_cycles = grade->fatigue_cycles;
    m.source = grade->fatigue_source;
  } else {
    throw InvalidInput(fmt::format(
        "a fatigue check needs the endurance limit S_e' (of a polished specimen), which {} does "
        "not give{}",
        name,
        grade && !grade->notes.empty() ? " (" + grade->notes + ")" : ""));
  }
  m.yield_strength = yield_strength ? yield_strength : grade ? grade->yield_strength : std::nullopt;
  m.ductile = grade ? grade->ductile : true;
  m.validate();
  return m;
}

PartFatigueStrength part_fatigue_strength(const FatigueMaterial& material,
                                          const FatigueOptions& options,
                                          double equivalent_diameter) {
  material.validate();
  options.validate();
  PartFatigueStrength s;
  s.factors.surface =
      marin_surface_factor(options.finish, material.ultimate_strength, options.surface_fit);
  s.factors.size = marin_size_factor(equivalent_diameter, options.loading);
  s.factors.load = marin_load_factor(options.loading);
  s.factors.reliability = marin_reliability_factor(options.reliability);
  // Table 3.2: 1/K_f on the strength of a ductile material (eq. 3.84), K_f on the stress of a
  // brittle one (eq. 3.85).
  s.factors.misc = options.other_factor * (material.ductile ? 1.0 / options.K_f : 1.0);
  s.stress_factor = material.ductile ? 1.0 : options.K_f;
  s.uncorrected = material.uncorrected_strength;
  s.corrected = s.factors.product() * s.uncorrected;  // eq. 3.74 / 3.75
  s.fatigue_cycles = material.fatigue_cycles;
  return s;
}

SnCurve sn_curve(const FatigueMaterial& material,
                 const PartFatigueStrength& strength,
                 FatigueLoading loading) {
  SnCurve c;
  c.S_ut = material.ultimate_strength;
  c.S_L = low_cycle_strength_fraction(loading) * c.S_ut;  // eq. 3.56
  c.S_2 = strength.corrected;
  c.endurance_limit = !strength.fatigue_cycles.has_value();
  c.N_2 = strength.fatigue_cycles.value_or(1e6);
  // Eqs. 3.67-3.68 through (1e3, S_L) and (N_2, S_2); with N_2 = 1e6 they are eqs. 3.63-3.64.
  c.b_f = std::log10(c.S_2 / c.S_L) / std::log10(c.N_2 / 1e3);
  c.a_f = std::pow(10.0, std::log10(c.S_L) - 3.0 * c.b_f);
  return c;
}

double SnCurve::cycles_to_failure(double S) const {
  if (!(S > 0.0)) return kInfinity;
  if (endurance_limit && S <= S_2) return kInfinity;
  if (S >= S_ut) return 1.0;
  if (S > S_L) {
    // Low-cycle line from (1, S_ut) to (1e3, S_L) on log-log axes (§3.3.2).
    return std::pow(10.0, 3.0 * std::log10(S_ut / S) / std::log10(S_ut / S_L));
  }
  return std::pow(S / a_f, 1.0 / b_f);  // eq. 3.69
}

FatigueCheck check_fatigue(double sigma_max,
                           double sigma_min,
                           const FatigueMaterial& material,
                           const PartFatigueStrength& strength,
                           FatigueLoading loading) {
  if (!std::isfinite(sigma_max) || !std::isfinite(sigma_min) || sigma_min > sigma_max) {
    throw InvalidInput(
        fmt::format("a load cycle needs finite stresses with sigma_min <= sigma_max (got {}, {})",
                    sigma_min,
                    sigma_max));
  }
  FatigueCheck f;
  f.sigma_max = strength.stress_factor * sigma_max;
  f.sigma_min = strength.stress_factor * sigma_min;
  f.mean_stress = 0.5 * (f.sigma_max + f.sigma_min);         // eq. 3.107
  f.alternating_stress = 0.5 * (f.sigma_max - f.sigma_min);  // eq. 3.108
  f.endurance_limit = strength.corrected;
  const double S_ut = material.ultimate_strength;
  const double inverse = f.mean_stress > 0.0
                             ? f.alternating_stress / f.endurance_limit + f.mean_stress / S_ut
                             : f.alternating_stress / f.endurance_limit;  // eq. 3.110, §3.3.11
  f.safety_factor = inverse > 0.0 ? 1.0 / inverse : kInfinity;
  const std::optional<double> static_strength =
      material.ductile ? material.yield_strength : std::optional<double>(S_ut);
  const double peak = std::max(std::abs(f.sigma_max), std::abs(f.sigma_min));
  if (static_strength && peak > 0.0) f.yield_safety_factor = *static_strength / peak;  // 3.112
  f.infinite_life = f.safety_factor >= 1.0;
  // The completely reversed stress on the same Goodman line.
  double reversed = f.alternating_stress;
  if (f.mean_stress > 0.0) {
    reversed =
        f.mean_stress >= S_ut ? kInfinity : f.alternating_stress / (1.0 - f.mean_stress / S_ut);
  }
  const SnCurve curve = sn_curve(material, strength, loading);
  f.cycles_to_failure = f.infinite_life && curve.endurance_limit
                            ? kInfinity
                            : (std::isinf(reversed) ? 0.0 : curve.cycles_to_failure(reversed));
  return f;
}

double required_endurance_limit(double alternating_stress,
                                double mean_stress,
                                double ultimate_strength,
                                double safety_factor) {
  if (!std::isfinite(alternating_stress) || alternating_stress < 0.0 ||
      !std::isfinite(mean_stress) || !finite_positive(ultimate_strength) ||
      !finite_positive(safety_factor)) {
    throw InvalidInput(fmt::format(
        "required endurance limit: sigma_a >= 0, sigma_m, S_ut > 0 and the safety factor > 0 must "
        "be finite (got {}, {}, {}, {})",
        alternating_stress,
        mean_stress,
        ultimate_strength,
        safety_factor));
  }
  const double room = 1.0 / safety_factor - std::max(mean_stress, 0.0) / ultimate_strength;
  if (!(room > 0.0)) {
    throw InvalidInput(fmt::format(
        "the mean stress {:.6g} Pa alone reaches S_ut/SF = {:.6g} Pa: no endurance limit gives "
        "safety factor {}",
        mean_stress,
        ultimate_strength / safety_factor,
        safety_factor));
  }
  return alternating_stress / room;
}

}  // namespace flexure
