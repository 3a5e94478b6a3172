#include "flexure/mechanisms/design/mechanism_synthesis.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <set>

#include "flexure/mechanisms/cfm/cfm_comparison.h"
#include "flexure/mechanisms/cfm/cfm_configuration.h"
#include "flexure/mechanisms/cfm/cfm_subclasses.h"
#include "flexure/mechanisms/design/cfm_exact_refinement.h"
#include "flexure/mechanisms/design/feasibility.h"
#include "flexure/mechanisms/design/subclass_problem.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/mechanisms/mechanism_prbm.h"
#include "flexure/solver/common/errors.h"

namespace flexure::design {
namespace {

// Relative slack of the range checks: a value computed to rounding on a bound is inside.
constexpr double kSlack = 1e-9;

void check_positive(double v, const char* what) {
  if (!(std::isfinite(v) && v > 0.0)) {
    throw InvalidInput(fmt::format("{} = {} must be a finite number > 0", what, v));
  }
}

// `free_allowed`: [0, inf] stands for "not given" (MechanismSpec::free_range()).
void check_range(const LengthRange& r, const char* what, bool free_allowed = false) {
  if (free_allowed && r.lower == 0.0 && std::isinf(r.upper)) return;
  check_positive(r.lower, what);
  check_positive(r.upper, what);
  if (r.lower > r.upper) {
    throw InvalidInput(
        fmt::format("{} {:.6g}:{:.6g} m is inverted: the lower end must not exceed the upper",
                    what,
                    r.lower,
                    r.upper));
  }
}

bool one_flexure(const cfm::CfmConfiguration& c) {
  int flexures = 0;
  for (auto p : c.pivots) flexures += p != mechanism::PivotType::kPin;
  return flexures == 1;
}

bool admitted(const MechanismSpec& spec, const cfm::CfmSubclass& row) {
  if (!spec.configs.empty() &&
      std::find(spec.configs.begin(), spec.configs.end(), row.config) == spec.configs.end()) {
    return false;
  }
  if (spec.pcf_min && row.percent_constant_force < *spec.pcf_min) return false;
  const std::string flags = subclass_flags(row.name);
  if (one_flexure(cfm::find_cfm_configuration(row.config))) return true;
  switch (spec.orientation) {
    case FlexureOrientation::kInPlane:
      return flags.find('I') != std::string::npos;
    case FlexureOrientation::kOutOfPlane:
      return flags.find_first_of("Oo") != std::string::npos;
    case FlexureOrientation::kAny:
      return true;
  }
  return true;
}

void reject(DimensionedDesign& d, std::string why, std::optional<double> shortfall) {
  d.feasible = false;
  d.binding = std::move(why);
  d.shortfall = shortfall;
}

// Lengths in the messages, in mm (the specification may have come in inches; SI is the contract).
std::string mm(double m) { return fmt::format("{:.4g} mm", m * 1e3); }

// Sizes the sub-class `row` for the specification (see the header's sizing rule).
DimensionedDesign size_subclass(const MechanismSpec& spec, const cfm::CfmSubclass& row) {
  DimensionedDesign out;
  out.subclass = row.name;
  out.config = row.config;
  out.model = cfm::CfmModel().evaluate(cfm::parameters_of(row));
  out.M = row.M;
  out.n = row.n;
  const cfm::CfmResult& m = out.model;
  const cfm::CfmConfiguration& cfg = cfm::find_cfm_configuration(row.config);
  const double lambda = m.lambda;
  const int p = m.primary_pivot;
  const ForceCoefficient fc = force_coefficient(m);
  const double F = spec.force, E = spec.E;

  // The stroke first (eq. 8.6): it is shortest in % at the longest length.
  const double d_at_max = stroke_percent_for(spec.stroke, spec.length.upper, lambda);
  if (d_at_max > m.stroke_percent * (1.0 + kSlack)) {
    reject(out,
           fmt::format("stroke: d = {:.4g} % of r_tot at the longest l_tot = {} (eq. 8.6) exceeds "
                       "the sub-class's design stroke {:.4g} %; the travel needs l_tot >= {}",
                       d_at_max,
                       mm(spec.length.upper),
                       m.stroke_percent,
                       mm(100.0 * spec.stroke * lambda / m.stroke_percent)),
           d_at_max / m.stroke_percent);
    return out;
  }
  // Method 1 per sub-class (eqs. 8.5, 8.17): even the thinnest primary flexure at the longest
  // length (the least stressed design) must stay below S_y/SF.
  if (spec.yield_strength && spec.thickness.lower > 0.0) {
    const double omega = *spec.yield_strength / E;
    const double l_max = spec.length.upper, h_min = spec.thickness.lower;
    const double d_max = stroke_percent_for(spec.stroke, l_max, lambda);
    const double M_max =
        stress_screen_M(omega, spec.safety_factor, lambda, out.n, h_min, d_max, l_max);
    if (out.M > M_max * (1.0 + kSlack)) {
      reject(out,
             fmt::format("stress: M = {:.4f} exceeds M_max = {:.4f} (eq. 8.17 at h = {}, "
                         "l_tot = {}, d = {:.4g} %): the flexure may be at most h = {} thick, or "
                         "l_tot at least {} long (eq. 8.5)",
                         out.M,
                         M_max,
                         mm(h_min),
                         mm(l_max),
                         d_max,
                         mm(max_primary_thickness(
                             omega, spec.safety_factor, lambda, out.M, out.n, d_max, l_max)),
                         mm(length_for_stress(
                             omega, spec.safety_factor, lambda, out.M, out.n, h_min, spec.stroke))),
             out.M / M_max);
      return out;
    }
  }
  // Longest length, widest primary flexure; the thickness from the force (eq. 8.2). With the
  // width free, the thickest flexure the stress (eq. 8.5) and the thickness range allow, and the
  // width from the force (thesis example 2, eq. 8.19).
  // Where the section rule makes another flexure wider than the primary one (b_i = D b_p with
  // D > 1: equal thicknesses, or the C/D_min rule), that flexure takes the widest width.
  double l = spec.length.upper, b = spec.width.upper;
  {
    const std::string row_flags = subclass_flags(row.name);
    const bool equal_widths =
        spec.orientation == FlexureOrientation::kInPlane ||
        (spec.orientation == FlexureOrientation::kAny && row_flags.find('I') != std::string::npos);
    const bool equal_h = !equal_widths && row_flags.find_first_of("Oo") != std::string::npos;
    double widest = 1.0;
    for (int i = 1; i <= 3 && !equal_widths; ++i) {
      if (i == p || cfg.pivots[i - 1] == mechanism::PivotType::kPin) continue;
      widest = std::max(
          widest,
          equal_h ? second_moment_ratio(m, i) : m.D_min[i - 1].value_or(second_moment_ratio(m, i)));
    }
    b /= widest;
  }
  double h = 0.0;
  if (std::isinf(b)) {
    h = spec.thickness.upper;
    if (spec.yield_strength) {
      h = std::min(h,
                   max_primary_thickness(*spec.yield_strength / E,
                                         spec.safety_factor,
                                         lambda,
                                         out.M,
                                         out.n,
                                         stroke_percent_for(spec.stroke, l, lambda),
                                         l));
    }
    b = width_for_force(fc, F, E, h, l);
  } else {
    h = thickness_for_force(fc, F, E, b, l);
  }
  if (h < spec.thickness.lower * (1.0 - kSlack)) {
    h = spec.thickness.lower;
    b = width_for_force(fc, F, E, h, l);
    if (b < spec.width.lower * (1.0 - kSlack)) {
      const double F_min = design_force(fc, E, spec.width.lower, h, l);
      reject(out,
             fmt::format("force: the thinnest, narrowest primary flexure (h = {}, b = {}) at the "
                         "longest length {} already gives {:.4g} N > {:.4g} N (eq. 8.2)",
                         mm(h),
                         mm(spec.width.lower),
                         mm(l),
                         F_min,
                         F),
             F_min / F);
      return out;
    }
  } else if (h > spec.thickness.upper * (1.0 + kSlack)) {
    h = spec.thickness.upper;
    l = length_for_force(fc, F, E, b, h);
    if (l < spec.length.lower * (1.0 - kSlack)) {
      const double h_at_min = thickness_for_force(fc, F, E, b, spec.length.lower);
      reject(out,
             fmt::format("force: {:.4g} N needs a primary flexure h = {} (b = {}, l_tot = {}; "
                         "eq. 8.2), beyond the thickness range's {}",
                         F,
                         mm(h_at_min),
                         mm(b),
                         mm(spec.length.lower),
                         mm(spec.thickness.upper)),
             h_at_min / spec.thickness.upper);
      return out;
    }
  }
  if (!(std::isfinite(h) && std::isfinite(b) && h > 0.0 && b > 0.0)) {
    reject(out,
           fmt::format("force: the section is not finite (h = {:g} m, b = {:g} m)", h, b),
           std::nullopt);
    return out;
  }
  out.l_tot = l;
  out.stroke_percent = stroke_percent_for(spec.stroke, l, lambda);  // eq. 8.6
  if (out.stroke_percent > m.stroke_percent * (1.0 + kSlack)) {
    reject(out,
           fmt::format("stroke: d = {:.4g} % of r_tot at l_tot = {} (eq. 8.6) exceeds the "
                       "sub-class's design stroke {:.4g} %",
                       out.stroke_percent,
                       mm(l),
                       m.stroke_percent),
           out.stroke_percent / m.stroke_percent);
    return out;
  }
  out.primary_stress = primary_stress(E, lambda, out.M, out.n, out.stroke_percent, h, l);

  // The other flexures (eq. 8.7, I_i = D_equal_i I_p; eqs. 8.8-8.10).
  const std::string flags = subclass_flags(row.name);
  const bool in_plane =
      spec.orientation == FlexureOrientation::kInPlane ||
      (spec.orientation == FlexureOrientation::kAny && flags.find('I') != std::string::npos);
  const bool out_of_plane = !in_plane && flags.find_first_of("Oo") != std::string::npos;
  out.section_rule = one_flexure(cfg) ? "one flexure"
                     : in_plane       ? "equal widths (in-plane)"
                     : out_of_plane   ? "equal thicknesses (out-of-plane)"
                                      : "h = C h_p, b = D_min b_p (eqs. 8.8, 8.9)";
  for (int i = 1; i <= 3; ++i) {
    if (cfg.pivots[i - 1] == mechanism::PivotType::kPin) continue;
    double hi = h, bi = b;
    if (i != p) {
      const double D = second_moment_ratio(m, i);
      if (in_plane) {
        hi = h * std::cbrt(D);
      } else if (out_of_plane) {
        bi = b * D;
      } else {
        hi = h * m.C[i - 1].value_or(1.0);
        bi = b * m.D_min[i - 1].value_or(D);
      }
    }
    out.thickness[i - 1] = hi;
    out.width[i - 1] = bi;
    const auto outside = [&](double v, const LengthRange& r) {
      return v < r.lower * (1.0 - kSlack) || v > r.upper * (1.0 + kSlack);
    };
    if (outside(hi, spec.thickness) || outside(bi, spec.width)) {
      const bool thick = outside(hi, spec.thickness);
      const double v = thick ? hi : bi;
      const LengthRange& r = thick ? spec.thickness : spec.width;
      reject(out,
             fmt::format("{}: pivot {} needs {} = {} ({}), outside the range {}:{}",
                         thick ? "thickness" : "width",
                         i,
                         thick ? "h" : "b",
                         mm(v),
                         out.section_rule,
                         mm(r.lower),
                         mm(r.upper)),
             std::max(v / r.upper, r.lower / v));
      return out;
    }
  }

  // The mechanism (Table 8.1 segment lengths by MechanismDesign::finalise, eqs. 8.11-8.14).
  mechanism::MechanismDesign& d = out.design;
  d.name = row.name;
  d.config = row.config;
  const double r_tot = l / lambda;
  d.r2 = r_tot / (m.R + 1.0);
  d.r3 = m.R * d.r2;
  out.r2 = d.r2;
  out.r3 = d.r3;
  d.E = E;
  d.yield_strength = spec.yield_strength.value_or(spec.safety_factor * out.primary_stress);
  d.stroke = spec.stroke;
  for (int i = 0; i < 3; ++i) {
    d.joints[i].type = cfg.pivots[i];
    d.joints[i].thickness = out.thickness[i];
    d.joints[i].width = out.width[i];
  }
  d.note = fmt::format(
      "flexure design mechanism: sub-class {} (R = {:.4f}, K1 = {:.4f}, K2 = {:.4f}) for "
      "F = {:.6g} N over {:.6g} m, SF = {:g}",
      row.name,
      m.R,
      m.K1,
      m.K2,
      F,
      spec.stroke,
      spec.safety_factor);
  try {
    d.finalise();
  } catch (const InvalidInput& e) {
    reject(out, fmt::format("geometry: {}", e.what()), std::nullopt);
    return out;
  }
  for (int i = 0; i < 3; ++i) out.segment_length[i] = d.joints[i].length;

  const mechanism::PrbmStrokeResult prbm = mechanism::prbm_stroke(d, spec.points);
  out.required_yield_strength = spec.safety_factor * out.primary_stress;
  out.required_yield_strength_prbm = spec.safety_factor * prbm.max_stress_all;
  if (spec.yield_strength && out.required_yield_strength > *spec.yield_strength * (1.0 + kSlack)) {
    reject(out,
           fmt::format("stress: needs S_y >= {:.4g} MPa at SF {:g} (eq. 8.5), the material has "
                       "{:.4g} MPa; the primary flexure would have to be h <= {} (has {})",
                       out.required_yield_strength * 1e-6,
                       spec.safety_factor,
                       *spec.yield_strength * 1e-6,
                       mm(max_primary_thickness(*spec.yield_strength / E,
                                                spec.safety_factor,
                                                lambda,
                                                out.M,
                                                out.n,
                                                out.stroke_percent,
                                                l)),
                       mm(h)),
           out.required_yield_strength / *spec.yield_strength);
    return out;
  }
  if (!spec.yield_strength) {
    d.yield_strength = out.required_yield_strength;
    d.finalise();
  }
  out.force_prbm = prbm.mean_force;
  out.percent_constant_force_prbm = prbm.percent_constant_force;
  out.safety_factor_prbm = d.yield_strength / prbm.max_stress_all;
  out.feasible = true;
  return out;
}

void evaluate_exact(DimensionedDesign& out, int points, double safety_factor) {
  mechanism::AnalysisOptions o;
  o.points = points;
  try {
    const mechanism::MechanismAnalysis a = mechanism::analyze_mechanism(out.design, o);
    if (!a.has_exact || !a.exact.converged()) {
      out.exact_note = a.has_exact ? a.exact.message : a.exact_note;
      return;
    }
    out.force_exact = a.mean_force_exact;
    out.percent_constant_force_exact = a.percent_constant_force_exact;
    if (a.has_exact_stress) {
      const double s = *std::max_element(a.max_stress_exact.begin(), a.max_stress_exact.end());
      if (s > 0.0) {
        out.safety_factor_exact = out.design.yield_strength / s;
        out.required_yield_strength_exact = safety_factor * s;
      }
    }
  } catch (const std::exception& e) {  // InvalidInput or NoConvergence of the exact model
    out.exact_note = e.what();
  }
}

}  // namespace

void MechanismSpec::validate() const {
  check_positive(force, "force");
  check_positive(stroke, "stroke");
  check_positive(E, "E");
  if (yield_strength) check_positive(*yield_strength, "yield strength");
  check_positive(safety_factor, "safety factor");
  // Physical ranges wide enough for any mechanism (MEMS to machinery) that keep every derived
  // size finite in double precision.
  const auto within = [](double v, double lo, double hi, const char* what, const char* unit) {
    if (v < lo || v > hi) {
      throw InvalidInput(
          fmt::format("{} = {:g} {} lies outside [{:g}, {:g}] {}", what, v, unit, lo, hi, unit));
    }
  };
  within(force, 1e-9, 1e9, "force", "N");
  within(stroke, 1e-9, 1e3, "stroke", "m");
  within(E, 1e3, 1e13, "E", "Pa");
  if (yield_strength) within(*yield_strength, 1.0, 1e12, "yield strength", "Pa");
  within(safety_factor, 1e-3, 1e3, "safety factor", "");
  for (const auto& [r, what] : {std::pair{&length, "length range"},
                                std::pair{&width, "width range"},
                                std::pair{&thickness, "thickness range"}}) {
    if (r->lower == 0.0 && std::isinf(r->upper)) continue;  // free
    within(r->lower, 1e-9, 1e3, what, "m");
    within(r->upper, 1e-9, 1e3, what, "m");
  }
  check_range(length, "length range");
  check_range(width, "width range", true);
  check_range(thickness, "thickness range", true);
  if (std::isinf(width.upper) && std::isinf(thickness.upper) && !yield_strength) {
    throw InvalidInput(
        "with the width free, the thickness needs a bound: give --width-range, "
        "--thickness-range or --yield-strength");
  }
  if (pcf_min && !(*pcf_min > 0.0 && *pcf_min < 100.0)) {
    throw InvalidInput(fmt::format("pcf-min = {} must lie in (0, 100)", *pcf_min));
  }
  for (const std::string& c : configs) cfm::find_cfm_configuration(c);  // throws, listing names
  if (points < 2 || points > 10000) {
    throw InvalidInput(fmt::format("points = {} must lie in [2, 10000]", points));
  }
}

DesignScreens design_screens(const MechanismSpec& spec) {
  spec.validate();
  DesignScreens s;
  // lambda of the screens: the configuration's when one is asked for (thesis example 2: 1.05 for
  // sss), else 1 (example 3; Table 8.2's 1.00/1.12 would not give its M_min = 1.83).
  double lambda_low = 1.0, lambda_high = 1.0;
  if (spec.configs.size() == 1) {
    lambda_low = std::numeric_limits<double>::infinity();
    lambda_high = 0.0;
    for (const cfm::CfmSubclass& row : cfm::thesis_subclasses()) {
      if (row.config != spec.configs.front()) continue;
      lambda_low = std::min(lambda_low, row.lambda);
      lambda_high = std::max(lambda_high, row.lambda);
    }
  }
  s.stroke_percent_min = stroke_percent_for(spec.stroke, spec.length.upper, lambda_low);
  s.stroke_percent_max = stroke_percent_for(spec.stroke, spec.length.lower, lambda_high);
  if (!spec.yield_strength) return s;
  s.omega = *spec.yield_strength / spec.E;  // eq. 4.18
  constexpr double kScreenExponent = 0.5;   // n of the thesis's screens (Table 8.2, ex. 2, 3)
  if (spec.thickness.lower > 0.0) {
    s.M_max = stress_screen_M(s.omega,
                              spec.safety_factor,
                              lambda_low,
                              kScreenExponent,
                              spec.thickness.lower,
                              s.stroke_percent_min,
                              spec.length.upper);
  }
  if (std::isfinite(spec.thickness.upper)) {
    s.M_min = stress_screen_M(s.omega,
                              spec.safety_factor,
                              lambda_high,
                              kScreenExponent,
                              spec.thickness.upper,
                              s.stroke_percent_max,
                              spec.length.lower);
  }
  if (std::isinf(spec.width.upper)) return s;  // Method 2 needs the widest flexure
  // Method 2: the strongest lpp of the same design stroke at the longest, widest, thickest
  // section that the stress allows.
  const double d_lpp = stroke_percent_for(spec.stroke, spec.length.upper, 1.0);
  s.lpp_subclass = d_lpp <= 16.0 ? "lpp-a" : "lpp-b";
  const cfm::CfmSubclass& lpp = cfm::find_thesis_subclass(s.lpp_subclass);
  const cfm::CfmResult m = cfm::CfmModel().evaluate(cfm::parameters_of(lpp));
  const double d = stroke_percent_for(spec.stroke, spec.length.upper, m.lambda);
  s.lpp_thickness_max = max_primary_thickness(
      s.omega, spec.safety_factor, m.lambda, lpp.M, lpp.n, d, spec.length.upper);
  s.lpp_force_max = design_force(
      force_coefficient(m), spec.E, spec.width.upper, *s.lpp_thickness_max, spec.length.upper);
  s.Psi_min = spec.force / *s.lpp_force_max;
  return s;
}

MechanismDesignReport design_mechanisms(const MechanismSpec& spec) {
  spec.validate();
  MechanismDesignReport report;
  report.screens = design_screens(spec);
  // The sub-class of the design stroke (thesis §8.5): a (16 %) up to 16 %, b (40 %) beyond. Each
  // row's d has its own lambda, so near 16 % a configuration's a rows may all land just above it
  // while its b rows land just below: then the b rows serve.
  const auto d_of = [&](const cfm::CfmSubclass& row) {
    return stroke_percent_for(spec.stroke, spec.length.upper, row.lambda);
  };
  std::set<std::string> a_fits;
  for (const cfm::CfmSubclass& row : cfm::thesis_subclasses()) {
    if (admitted(spec, row) && row.stroke_percent == 16.0 && d_of(row) <= 16.0) {
      a_fits.insert(row.config);
    }
  }
  for (const cfm::CfmSubclass& row : cfm::thesis_subclasses()) {
    if (!admitted(spec, row)) continue;
    const bool a_row = row.stroke_percent == 16.0;
    if (a_row ? d_of(row) > 16.0 : (d_of(row) <= 16.0 && a_fits.count(row.config) > 0)) continue;
    DimensionedDesign design = size_subclass(spec, row);
    (design.feasible ? report.designs : report.rejected).push_back(std::move(design));
  }
  if (spec.exact) {
    for (DimensionedDesign& d : report.designs) evaluate_exact(d, spec.points, spec.safety_factor);
  }
  // Without a given yield strength the design carries the strength it needs by every stress the
  // models compute (eq. 8.5 leaves out axial and clamp stresses), so that its file analyses
  // without yielding.
  if (!spec.yield_strength) {
    for (DimensionedDesign& d : report.designs) {
      const double needed = std::max({d.required_yield_strength,
                                      d.required_yield_strength_prbm,
                                      d.required_yield_strength_exact.value_or(0.0)});
      const double scale = needed / d.design.yield_strength;
      d.design.yield_strength = needed;
      d.safety_factor_prbm *= scale;
      if (d.safety_factor_exact) *d.safety_factor_exact *= scale;
    }
  }
  const auto key = [&](const DimensionedDesign& d) {
    if (spec.ranking == DesignRanking::kExact) return d.percent_constant_force_exact.value_or(-1.0);
    return d.model.percent_constant_force;
  };
  std::stable_sort(report.designs.begin(), report.designs.end(), [&](const auto& a, const auto& b) {
    if (key(a) != key(b)) return key(a) > key(b);
    return a.required_yield_strength < b.required_yield_strength;
  });
  std::stable_sort(
      report.rejected.begin(), report.rejected.end(), [](const auto& a, const auto& b) {
        const double x = a.shortfall.value_or(std::numeric_limits<double>::infinity());
        const double y = b.shortfall.value_or(std::numeric_limits<double>::infinity());
        return x < y;
      });
  return report;
}

DimensionedDesign refine_design_exact(const MechanismSpec& spec,
                                      const DimensionedDesign& prbm_design) {
  spec.validate();
  if (!prbm_design.feasible) {
    throw InvalidInput(
        fmt::format("refine_design_exact: {} is not a feasible design", prbm_design.subclass));
  }
  const cfm::CfmSubclass& row = cfm::find_thesis_subclass(prbm_design.subclass);
  // The sub-class's constraints (Ch. 7: digits = Xi' floor, flags = orientation rules) at the
  // design's own stroke; the objective is the exact Xi'.
  SubclassProblem sub = subclass_problem(row);
  CfmDesignProblem& problem = sub.problem;
  problem.stroke_percent = prbm_design.stroke_percent;
  const std::vector<double>& start = sub.printed;
  ExactRefinementOptions o;
  o.sequence_starts = static_cast<int>(2 * start.size());
  const CfmExactRefinement r = refine_cfm_exact(problem, {start}, o);
  if (!r.converged()) {
    DimensionedDesign failed = prbm_design;
    failed.exact_evaluations = r.evaluations;
    reject(failed,
           fmt::format("exact optimisation: {} (best exact Xi' {:.2f} %{})",
                       r.message,
                       r.percent_constant_force_exact,
                       problem.pcf_min ? fmt::format(", floor {:g} %", *problem.pcf_min) : ""),
           std::nullopt);
    return failed;
  }

  DimensionedDesign out = prbm_design;
  out.exact_evaluations = r.evaluations;
  out.model = cfm::CfmModel().evaluate(parameters_at(problem, r.x));
  const cfm::CfmResult& m = out.model;
  const cfm::CfmConfiguration& cfg = cfm::find_cfm_configuration(row.config);
  mechanism::MechanismDesign& d = out.design;
  const double r_tot = out.l_tot / m.lambda;
  d.r2 = r_tot / (m.R + 1.0);
  d.r3 = m.R * d.r2;
  out.r2 = d.r2;
  out.r3 = d.r3;
  out.stroke_percent = stroke_percent_for(spec.stroke, out.l_tot, m.lambda);
  d.note = fmt::format(
      "flexure design mechanism --model exact: sub-class {} refined against the exact model "
      "(R = {:.4f}, K1 = {:.4f}, K2 = {:.4f}) for F = {:.6g} N over {:.6g} m, SF = {:g}",
      row.name,
      m.R,
      m.K1,
      m.K2,
      spec.force,
      spec.stroke,
      spec.safety_factor);
  // Thicknesses by eq. 8.7 from the primary one of the PRBM design (the primary pivot may move),
  // widths as the section rule had them; then one scale for the exact force.
  const int p = m.primary_pivot;
  const double h_p = prbm_design.thickness[prbm_design.model.primary_pivot - 1];
  const double b_p = prbm_design.width[prbm_design.model.primary_pivot - 1];
  const bool equal_h = out.section_rule.find("thicknesses") != std::string::npos;
  // The refined design keeps equal thicknesses, or else takes equal widths (the C/D_min rule of
  // the sub-class does not carry over to other R, K).
  if (!equal_h && out.section_rule != "one flexure") out.section_rule = "equal widths (in-plane)";
  for (int i = 1; i <= 3; ++i) {
    if (cfg.pivots[i - 1] == mechanism::PivotType::kPin) continue;
    const double D = i == p ? 1.0 : second_moment_ratio(m, i);
    d.joints[i - 1].thickness = equal_h ? h_p : h_p * std::cbrt(D);
    d.joints[i - 1].width = equal_h ? b_p * D : b_p;
    d.joints[i - 1].length = 0.0;  // Table 8.1 again for the new links
  }
  mechanism::AnalysisOptions ao;
  ao.points = spec.points;
  const auto analyse = [&]() -> std::optional<mechanism::MechanismAnalysis> {
    try {
      d.finalise();
      mechanism::MechanismAnalysis a = mechanism::analyze_mechanism(d, ao);
      if (!a.has_exact || !a.exact.converged() || !(a.mean_force_exact > 0.0)) {
        out.exact_note = a.has_exact ? a.exact.message : a.exact_note;
        return std::nullopt;
      }
      return a;
    } catch (const std::exception& e) {
      out.exact_note = e.what();
      return std::nullopt;
    }
  };
  std::optional<mechanism::MechanismAnalysis> a = analyse();
  for (int it = 0; a && it < 3 && std::abs(a->mean_force_exact / spec.force - 1.0) > 1e-6; ++it) {
    const double scale = std::cbrt(spec.force / a->mean_force_exact);
    for (auto& j : d.joints) j.thickness *= scale;
    a = analyse();
  }
  if (!a) {
    reject(out, fmt::format("exact model: {}", out.exact_note), std::nullopt);
    return out;
  }
  for (int i = 0; i < 3; ++i) {
    out.thickness[i] = d.joints[i].thickness;
    out.width[i] = d.joints[i].width;
    out.segment_length[i] = d.joints[i].length;
  }
  const double s_exact = *std::max_element(a->max_stress_exact.begin(), a->max_stress_exact.end());
  out.force_exact = a->mean_force_exact;
  out.percent_constant_force_exact = a->percent_constant_force_exact;
  out.required_yield_strength_exact = spec.safety_factor * s_exact;
  out.force_prbm = a->prbm.mean_force;
  out.percent_constant_force_prbm = a->prbm.percent_constant_force;
  out.required_yield_strength_prbm = spec.safety_factor * a->prbm.max_stress_all;
  out.primary_stress = primary_stress(spec.E,
                                      m.lambda,
                                      prbm_design.M,
                                      prbm_design.n,
                                      out.stroke_percent,
                                      out.thickness[p - 1],
                                      out.l_tot);
  out.required_yield_strength = spec.safety_factor * out.primary_stress;
  if (!spec.yield_strength) d.yield_strength = *out.required_yield_strength_exact;
  out.safety_factor_exact = d.yield_strength / s_exact;
  out.safety_factor_prbm = d.yield_strength / a->prbm.max_stress_all;
  const auto outside = [](double v, const LengthRange& r) {
    return v < r.lower * (1.0 - kSlack) || v > r.upper * (1.0 + kSlack);
  };
  for (int i = 0; i < 3; ++i) {
    if (out.thickness[i] <= 0.0) continue;
    if (outside(out.thickness[i], spec.thickness) || outside(out.width[i], spec.width)) {
      reject(out,
             fmt::format("range: pivot {} of the refined design needs h = {}, b = {}",
                         i + 1,
                         mm(out.thickness[i]),
                         mm(out.width[i])),
             std::nullopt);
      return out;
    }
  }
  if (spec.yield_strength && *out.required_yield_strength_exact > *spec.yield_strength) {
    reject(out,
           fmt::format("stress: the refined design needs S_y >= {:.4g} MPa by its exact "
                       "stresses at SF {:g}; the material has {:.4g} MPa",
                       *out.required_yield_strength_exact * 1e-6,
                       spec.safety_factor,
                       *spec.yield_strength * 1e-6),
           *out.required_yield_strength_exact / *spec.yield_strength);
    return out;
  }
  out.feasible = true;
  return out;
}

}  // namespace flexure::design
