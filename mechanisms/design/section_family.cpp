#include "flexure/mechanisms/design/section_family.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace flexure::design {
namespace {

std::string mm(double m) { return fmt::format("{:.4g} mm", m * 1e3); }

}  // namespace

void SectionFamily::apply(double t, mechanism::MechanismDesign& design) const {
  for (int i = 0; i < 3; ++i) {
    if (tau[i] <= 0.0) continue;
    design.joints[i].thickness = thickness(i, t);
    design.joints[i].width = width(i, t);
  }
}

SectionFamily family_of(const mechanism::MechanismDesign& design, int primary) {
  SectionFamily f;
  const mechanism::JointDesign& p = design.joints[primary - 1];
  f.K = p.width * p.thickness * p.thickness * p.thickness;
  for (int i = 0; i < 3; ++i) {
    const mechanism::JointDesign& j = design.joints[i];
    if (j.type == mechanism::PivotType::kPin) continue;
    f.tau[i] = j.thickness / p.thickness;
    f.w[i] = j.width / p.width;
    f.length[i] = mechanism::table_8_1_segment_length(design, i + 1);
  }
  return f;
}

SectionInterval section_interval(const SectionFamily& f, const MechanismSpec& spec, double l_tot) {
  SectionInterval s;
  s.lo = 0.0;
  s.hi = std::numeric_limits<double>::infinity();
  s.lo_reason = "nothing";
  s.hi_reason = "nothing";
  const auto lower = [&](double t, std::string why) {
    if (t > s.lo) {
      s.lo = t;
      s.lo_reason = std::move(why);
    }
  };
  const auto upper = [&](double t, std::string why) {
    if (t < s.hi) {
      s.hi = t;
      s.hi_reason = std::move(why);
    }
  };
  using L = mechanism::SlenderBeamLimits;
  const SectionBounds& B = spec.bounds;
  for (int i = 0; i < 3; ++i) {
    if (f.tau[i] <= 0.0) continue;
    const double tau = f.tau[i], Kw = f.K * f.w[i];
    const int pivot = i + 1;
    // Widths: b_i = Kw/t^3 falls as t grows.
    if (std::isfinite(spec.width.upper)) {
      lower(std::cbrt(Kw / spec.width.upper),
            fmt::format(
                "pivot {} at the width range's upper end b = {}", pivot, mm(spec.width.upper)));
    }
    lower(std::cbrt(Kw / (B.max_width_to_length * l_tot)),
          fmt::format("pivot {} at the widest section bound b = {:g} l_tot = {} "
                      "(--max-width-to-length)",
                      pivot,
                      B.max_width_to_length,
                      mm(B.max_width_to_length * l_tot)));
    // b_i/h_i = Kw/(tau t^4) <= r.
    lower(std::pow(Kw / (B.max_width_to_thickness * tau), 0.25),
          fmt::format("pivot {} at the section bound b/h = {:g} (--max-width-to-thickness)",
                      pivot,
                      B.max_width_to_thickness));
    if (spec.thickness.lower > 0.0) {
      lower(spec.thickness.lower / tau,
            fmt::format("pivot {} at the thickness range's lower end h = {}",
                        pivot,
                        mm(spec.thickness.lower)));
    }
    if (std::isfinite(spec.thickness.upper)) {
      upper(spec.thickness.upper / tau,
            fmt::format("pivot {} at the thickness range's upper end h = {}",
                        pivot,
                        mm(spec.thickness.upper)));
    }
    if (spec.width.lower > 0.0) {
      upper(std::cbrt(Kw / spec.width.lower),
            fmt::format(
                "pivot {} at the width range's lower end b = {}", pivot, mm(spec.width.lower)));
    }
    // The slender-beam limits of MechanismDesign::finalise (docs/mechanisms.md "Geometry
    // limits"): h/L <= 0.5 and b/h >= 1, a rounding inside (finalise checks them exactly).
    constexpr double kInside = 1.0 - 1e-12;
    if (f.length[i] > 0.0) {
      upper(kInside * L::kMaxThicknessOverLength * f.length[i] / tau,
            fmt::format("pivot {} at the slender-beam limit thickness/length = {:g} (L = {})",
                        pivot,
                        L::kMaxThicknessOverLength,
                        mm(f.length[i])));
    }
    upper(kInside * std::pow(Kw / (L::kMinWidthOverThickness * tau), 0.25),
          fmt::format("pivot {} at the slender-beam limit width/thickness = {:g}",
                      pivot,
                      L::kMinWidthOverThickness));
  }
  return s;
}

double max_width_to_thickness(const SectionFamily& f, double t) {
  double r = 0.0;
  for (int i = 0; i < 3; ++i) {
    if (f.tau[i] > 0.0) r = std::max(r, f.width(i, t) / f.thickness(i, t));
  }
  return r;
}

double max_width(const SectionFamily& f, double t) {
  double b = 0.0;
  for (int i = 0; i < 3; ++i) {
    if (f.tau[i] > 0.0) b = std::max(b, f.width(i, t));
  }
  return b;
}

}  // namespace flexure::design
