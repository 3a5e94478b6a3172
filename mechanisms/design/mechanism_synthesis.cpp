#include "flexure/mechanisms/design/mechanism_synthesis.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <memory>
#include <set>
#include <stdexcept>
#include <string_view>

#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/cfm_comparison.h"
#include "flexure/mechanisms/design/cfm_synthesis.h"
#include "flexure/mechanisms/design/design_status.h"
#include "flexure/mechanisms/design/feasibility.h"
#include "flexure/mechanisms/design/length_search.h"
#include "flexure/mechanisms/design/section_family.h"
#include "flexure/mechanisms/design/subclass_problem.h"
#include "flexure/mechanisms/design/subclass_sizing.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/solver/common/status.h"

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

// The thesis's choice of rows (§8.5): the a rows (16 %) up to d = 16 % of the design stroke, the
// b rows (40 %) beyond. Each row's d has its own lambda, so near 16 % a configuration's a rows may
// all land just above it while its b rows land just below: then the b rows serve. With
// --minimize every admitted row competes at its own length (its stroke limit decides).
class RowSelection {
 public:
  explicit RowSelection(const MechanismSpec& spec) : spec_(spec) {
    for (const cfm::CfmSubclass& row : cfm::thesis_subclasses()) {
      if (admitted(spec, row)) rows_.push_back(&row);
    }
  }
  const std::vector<const cfm::CfmSubclass*>& rows() const { return rows_; }
  bool selected(const cfm::CfmSubclass& row, double l_tot) const {
    if (spec_.minimize != SizeObjective::kNone) return true;
    const auto d_of = [&](const cfm::CfmSubclass& r) {
      return stroke_percent_for(spec_.stroke, l_tot, r.lambda);
    };
    if (row.stroke_percent == 16.0) return d_of(row) <= 16.0;
    if (d_of(row) > 16.0) return true;
    for (const cfm::CfmSubclass* a : rows_) {
      if (std::string_view(a->config) == row.config && a->stroke_percent == 16.0 &&
          d_of(*a) <= 16.0) {
        return false;
      }
    }
    return true;
  }

 private:
  const MechanismSpec& spec_;
  std::vector<const cfm::CfmSubclass*> rows_;
};

// The thesis's sizing (§8.4.2): the longest length, or, where the section is too thick there, the
// longest length at which it fits.
DimensionedDesign size_longest(const MechanismSpec& spec, const SubclassSizer& sizer) {
  const SectionPolicy policy = section_policy(spec);
  DimensionedDesign d = sizer.at(spec.length.upper, policy, SizingDepth::kFull);
  if (d.feasible || d.cure != LengthCure::kShorter) return d;
  const std::optional<double> l =
      sizer.longest_fitting_length(spec.length.lower, spec.length.upper);
  if (!l) return d;
  return sizer.at(*l, policy, SizingDepth::kFull);
}

bool needs_full_search(const MechanismSpec& spec) {
  // The full sizing differs from the PRBM-only one by the exact model alone (its force, and
  // under the computed rule its stresses).
  return spec.exact;
}

// The full condition at one length, with the stress ratio of the least stressed section where
// the stress is what binds (length_search.h).
LengthProbe probe(const MechanismSpec& spec, const DimensionedDesign& d) {
  LengthProbe p;
  p.feasible = d.feasible;
  if (!spec.material.yield_strength || spec.stress_rule != StressRule::kComputed) return p;
  if (d.feasible) {
    const double sf = std::min(d.safety_factor_prbm, d.safety_factor_exact.value_or(1e300));
    if (sf > 0.0) p.stress_ratio = spec.safety_factor / sf;
  } else if (d.binding.rfind("stress", 0) == 0) {
    p.stress_ratio = d.shortfall;
  }
  return p;
}

// The first length in [lower, upper] at which `sizer` is feasible (and its row selected).
std::optional<double> shortest_length(const MechanismSpec& spec,
                                      const SubclassSizer& sizer,
                                      const RowSelection& selection,
                                      double lower,
                                      double upper) {
  const SectionPolicy policy = section_policy(spec);
  const auto cheap = [&](double l) {
    return selection.selected(sizer.row(), l) &&
           sizer.at(l, policy, SizingDepth::kPrbm, SizingPurpose::kCheck).feasible;
  };
  const auto full = [&](double l) {
    if (!selection.selected(sizer.row(), l)) return LengthProbe{};
    if (!needs_full_search(spec)) return LengthProbe{cheap(l), std::nullopt};
    return probe(spec, sizer.at(l, policy, SizingDepth::kFull, SizingPurpose::kCheck));
  };
  return first_feasible_length(cheap, full, lower, upper);
}

// --minimize: the smallest design of one row in the length range.
DimensionedDesign size_smallest(const MechanismSpec& spec,
                                const SubclassSizer& sizer,
                                const RowSelection& selection) {
  const SectionPolicy policy = section_policy(spec);
  const std::optional<double> l0 =
      shortest_length(spec, sizer, selection, spec.length.lower, spec.length.upper);
  if (!l0) return size_longest(spec, sizer);  // the reason, at the longest length
  DimensionedDesign best = sizer.at(*l0, policy, SizingDepth::kFull);
  if (spec.minimize != SizeObjective::kMass || *l0 >= spec.length.upper) return best;
  // Mass: the flexures' volume over the feasible lengths is not monotone (thickest section:
  // V ~ l^(1 - 2n) by eqs. 8.2 and 8.5), so a grid of lengths refined by golden section, with
  // the PRBM-only sizing; the exact model checks the answer (and the shortest design stays the
  // answer where it is lighter or the exact check fails).
  const auto volume = [&](double l) {
    const DimensionedDesign d = sizer.at(l, policy, SizingDepth::kPrbm);
    return d.feasible ? d.flexure_volume : std::numeric_limits<double>::infinity();
  };
  constexpr int kGrid = 9;
  const double ratio = spec.length.upper / *l0;
  std::vector<double> ls(kGrid), vs(kGrid);
  int k_best = 0;
  for (int k = 0; k < kGrid; ++k) {
    ls[k] = *l0 * std::pow(ratio, static_cast<double>(k) / (kGrid - 1));
    vs[k] = volume(ls[k]);
    if (vs[k] < vs[k_best]) k_best = k;
  }
  double a = std::log(ls[std::max(0, k_best - 1)]),
         b = std::log(ls[std::min(kGrid - 1, k_best + 1)]);
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = b - g * (b - a), x2 = a + g * (b - a);
  double f1 = volume(std::exp(x1)), f2 = volume(std::exp(x2));
  for (int it = 0; it < 30 && b - a > 1e-6; ++it) {
    if (f1 <= f2) {
      b = x2;
      x2 = x1;
      f2 = f1;
      x1 = b - g * (b - a);
      f1 = volume(std::exp(x1));
    } else {
      a = x1;
      x1 = x2;
      f1 = f2;
      x2 = a + g * (b - a);
      f2 = volume(std::exp(x2));
    }
  }
  double l_best = f1 <= f2 ? std::exp(x1) : std::exp(x2);
  if (std::min(f1, f2) > vs[k_best]) l_best = ls[k_best];
  // The exact stresses may bind where the PRBM's did not (and thin the section): the lightest of
  // the full sizings at the PRBM's answer, its grid neighbours and the ends.
  for (double l : {l_best,
                   ls[std::max(0, k_best - 1)],
                   ls[std::min(kGrid - 1, k_best + 1)],
                   spec.length.upper}) {
    DimensionedDesign light = sizer.at(l, policy, SizingDepth::kFull);
    if (light.feasible && light.flexure_volume < best.flexure_volume) best = std::move(light);
  }
  return best;
}

double objective_value(const MechanismSpec& spec, const DimensionedDesign& d) {
  switch (spec.minimize) {
    case SizeObjective::kLength:
      return d.l_tot;
    case SizeObjective::kFootprint:
      return d.footprint;
    case SizeObjective::kMass:
      return d.flexure_volume;
    case SizeObjective::kNone:
      break;
  }
  return 0.0;
}

// The strength a design needs by its stress rule (the ranking's tie-break).
double rule_strength(const MechanismSpec& spec, const DimensionedDesign& d) {
  if (spec.stress_rule == StressRule::kThesis) return d.required_yield_strength;
  return std::max(d.required_yield_strength_prbm, d.required_yield_strength_exact.value_or(0.0));
}

// A length in mm rounded up to 4 significant digits: fed back, it is at least the length found.
double round_up_4(double m) {
  const double x = m * 1e3;
  const double p = std::pow(10.0, std::floor(std::log10(x)) - 3.0);
  return std::ceil(x / p - 1e-9) * p * 1e-3;
}

// The specification's material onto a design, and with MechanismSpec::fatigue its check: a
// design below the safety factor in fatigue is rejected (docs/fatigue.md). The fatigue check
// runs the design's own analysis (exact where spec.exact), as `mechanism analyze` would.
void apply_spec_material(const MechanismSpec& spec, DimensionedDesign& out) {
  mechanism::MechanismDesign& d = out.design;
  d.material_id = spec.material_id;
  d.ultimate_strength = spec.ultimate_strength;
  d.endurance_limit = spec.endurance_limit;
  d.endurance_cycles = spec.endurance_cycles;
  d.ductile = spec.ductile;
  if (!out.feasible || !spec.fatigue) return;
  mechanism::AnalysisOptions ao;
  ao.points = spec.points;
  ao.exact = spec.exact;
  ao.stability = false;
  const mechanism::MechanismAnalysis a = mechanism::analyze_mechanism(d, ao);
  out.fatigue =
      mechanism::mechanism_fatigue(a, mechanism::design_fatigue_material(d), *spec.fatigue);
  const FatigueCheck& f = out.fatigue->critical().check;
  const double required = spec.fatigue_safety_factor.value_or(spec.safety_factor);
  if (f.safety_factor < required * (1.0 - 1e-9)) {
    reject(out,
           fmt::format("fatigue: pivot {} cycles at sigma_a {:.4g} MPa, sigma_m {:.4g} MPa "
                       "against S_e {:.4g} MPa (S_ut {:.4g} MPa): modified Goodman safety factor "
                       "{:.3g} < {:g} (Howell eq. 3.110)",
                       out.fatigue->critical_pivot,
                       f.alternating_stress * 1e-6,
                       f.mean_stress * 1e-6,
                       f.endurance_limit * 1e-6,
                       *spec.ultimate_strength * 1e-6,
                       f.safety_factor,
                       required),
           required / f.safety_factor);
  }
}

}  // namespace

void MechanismSpec::validate() const {
  check_positive(force, "force");
  check_positive(stroke, "stroke");
  check_positive(material.E, "E");
  if (material.yield_strength) check_positive(*material.yield_strength, "yield strength");
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
  within(material.E, 1e3, 1e13, "E", "Pa");
  if (material.yield_strength) within(*material.yield_strength, 1.0, 1e12, "yield strength", "Pa");
  material.validate();  // nu and the density, naming Material's field
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
  if (std::isinf(width.upper) && std::isinf(thickness.upper) && !material.yield_strength) {
    throw InvalidInput(
        "with the width free, the thickness needs a bound: give --width-range, "
        "--thickness-range or --yield-strength");
  }
  if (pcf_min && !(*pcf_min > 0.0 && *pcf_min < 100.0)) {
    throw InvalidInput(fmt::format("pcf-min = {} must lie in (0, 100)", *pcf_min));
  }
  for (const std::string& c : configs) cfm::find_cfm_configuration(c);  // throws, listing names
  if (fatigue) {
    fatigue->validate();
    if (!ultimate_strength || !endurance_limit) {
      throw InvalidInput(fmt::format(
          "the fatigue check needs the material's ultimate strength S_ut and endurance limit S_e'"
          "{} (Howell eqs. 3.74, 3.110)",
          material_id.empty()
              ? std::string()
              : fmt::format(
                    " ('{}' lacks {})", material_id, !ultimate_strength ? "S_ut" : "S_e'")));
    }
  }
  if (points < 2 || points > 10000) {
    throw InvalidInput(fmt::format("points = {} must lie in [2, 10000]", points));
  }
  if (!(std::isfinite(bounds.max_width_to_thickness) && bounds.max_width_to_thickness >= 1.0 &&
        bounds.max_width_to_thickness <= 1e6)) {
    throw InvalidInput(fmt::format(
        "max width/thickness = {} must lie in [1, 1e6] (a strip narrower than it is thick bends "
        "out of the plane; docs/mechanisms.md \"Geometry limits\")",
        bounds.max_width_to_thickness));
  }
  if (!(std::isfinite(force_tolerance) && force_tolerance > 0.0 && force_tolerance <= 1.0)) {
    throw InvalidInput(
        fmt::format("force tolerance = {} % must lie in (0, 100]", 100.0 * force_tolerance));
  }
  if (!(std::isfinite(bounds.max_width_to_length) && bounds.max_width_to_length > 0.0 &&
        bounds.max_width_to_length <= 1e3)) {
    throw InvalidInput(
        fmt::format("max width/length = {} must lie in (0, 1e3]", bounds.max_width_to_length));
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
  if (!spec.material.yield_strength) return s;
  s.omega = *spec.material.yield_strength / spec.material.E;  // eq. 4.18
  constexpr double kScreenExponent = 0.5;  // n of the thesis's screens (Table 8.2, ex. 2, 3)
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
  s.lpp_force_max = design_force(force_coefficient(m),
                                 spec.material.E,
                                 spec.width.upper,
                                 *s.lpp_thickness_max,
                                 spec.length.upper);
  s.Psi_min = spec.force / *s.lpp_force_max;
  return s;
}

namespace {

// design_mechanisms without the report's status.
MechanismDesignReport size_designs(const MechanismSpec& spec) {
  spec.validate();
  if (spec.fatigue && !spec.fatigue_safety_factor) {
    // Size for fatigue: a flexure cycling 0 -> sigma_max has sigma_m = sigma_a = sigma_max/2, so
    // the Goodman line (Howell eq. 3.110) allows sigma_max = 2 S_e S_ut/((S_e + S_ut) SF)
    // (eq. 3.128 at SF = 1); S_e at c_size = 1 (flexures thinner than 2.8 mm), K_f on the stress
    // of a brittle material. The static safety factor that keeps sigma_max there sizes the
    // designs; the check of each design (its own size factor and stresses) decides.
    MechanismSpec sized = spec;
    sized.fatigue_safety_factor = spec.safety_factor;
    std::optional<double> raised;
    if (spec.material.yield_strength) {
      FatigueMaterial m;
      m.ultimate_strength = *spec.ultimate_strength;
      m.uncorrected_strength = *spec.endurance_limit;
      m.fatigue_cycles = spec.endurance_cycles;
      m.ductile = spec.ductile;
      const PartFatigueStrength s = part_fatigue_strength(m, *spec.fatigue, 1e-3);
      const double allowed = 2.0 * s.corrected * m.ultimate_strength /
                             ((s.corrected + m.ultimate_strength) * spec.safety_factor) /
                             s.stress_factor;
      raised = std::max(spec.safety_factor, *spec.material.yield_strength / allowed);
      sized.safety_factor = *raised;
    }
    MechanismDesignReport r = size_designs(sized);
    r.sizing_safety_factor = raised;
    return r;
  }
  MechanismDesignReport report;
  report.screens = design_screens(spec);
  const RowSelection selection(spec);
  std::size_t total = 0, done = 0;
  for (const cfm::CfmSubclass* row : selection.rows()) {
    total += selection.selected(*row, spec.length.upper) ? 1 : 0;
  }
  for (const cfm::CfmSubclass* row : selection.rows()) {
    if (!selection.selected(*row, spec.length.upper)) {
      // --minimize takes every row; the thesis's choice by the longest length.
      continue;
    }
    const SubclassSizer sizer(spec, *row);
    DimensionedDesign design = spec.minimize == SizeObjective::kNone
                                   ? size_longest(spec, sizer)
                                   : size_smallest(spec, sizer, selection);
    apply_spec_material(spec, design);
    (design.feasible ? report.designs : report.rejected).push_back(std::move(design));
    if (spec.progress) spec.progress(++done, total);
  }
  // Nothing feasible: the shortest length at which a sub-class is feasible by the full sizing
  // (so the length hint, fed back, is feasible). A scan up from the longest length over every
  // admitted row (rows the thesis's choice left out at l_max may serve a longer mechanism), each
  // row that turns feasible searched down to its first feasible length.
  if (report.designs.empty()) {
    const double cap = std::min(1e3, 100.0 * spec.length.upper);
    const SectionPolicy policy = section_policy(spec);
    std::vector<std::pair<const cfm::CfmSubclass*, double>> found;
    std::set<const cfm::CfmSubclass*> searched;
    std::vector<std::unique_ptr<SubclassSizer>> sizers;
    for (const cfm::CfmSubclass* row : selection.rows()) {
      sizers.push_back(std::make_unique<SubclassSizer>(spec, *row));
    }
    double best = std::numeric_limits<double>::infinity();
    for (double l = spec.length.upper; l < std::min(cap, best);) {
      const double next = std::min({cap, l * 1.25, best});
      if (spec.progress) spec.progress(total, total);
      for (const auto& sizer : sizers) {
        const cfm::CfmSubclass* row = &sizer->row();
        if (searched.count(row) > 0 || !selection.selected(*row, next) ||
            !sizer->at(next, policy, SizingDepth::kPrbm, SizingPurpose::kCheck).feasible) {
          continue;
        }
        searched.insert(row);
        if (const std::optional<double> m =
                shortest_length(spec, *sizer, selection, l * (1.0 + 1e-12), cap)) {
          found.emplace_back(row, *m);
          if (*m < best) {
            best = *m;
            report.length_needed = *m;
            report.length_needed_subclass = row->name;
          }
        }
      }
      l = next;
    }
    for (DimensionedDesign& d : report.rejected) {
      for (const auto& [row, m] : found) {
        if (row->name != d.subclass) continue;
        d.length_needed = m;
        d.binding +=
            fmt::format("; l_tot >= {} makes it feasible (full sizing)", mm(round_up_4(m)));
      }
    }
  }
  const auto key = [&](const DimensionedDesign& d) {
    if (spec.ranking == DesignRanking::kExact) return d.percent_constant_force_exact.value_or(-1.0);
    return d.model.percent_constant_force;
  };
  std::stable_sort(report.designs.begin(), report.designs.end(), [&](const auto& a, const auto& b) {
    if (spec.minimize != SizeObjective::kNone) {
      const double x = objective_value(spec, a), y = objective_value(spec, b);
      if (x != y) return x < y;
    }
    if (key(a) != key(b)) return key(a) > key(b);
    return rule_strength(spec, a) < rule_strength(spec, b);
  });
  std::stable_sort(
      report.rejected.begin(), report.rejected.end(), [](const auto& a, const auto& b) {
        const double x = a.shortfall.value_or(std::numeric_limits<double>::infinity());
        const double y = b.shortfall.value_or(std::numeric_limits<double>::infinity());
        return x < y;
      });
  return report;
}

}  // namespace

MechanismDesignReport design_mechanisms(const MechanismSpec& spec) {
  MechanismDesignReport report = size_designs(spec);
  stamp_report_status(spec, report);
  return report;
}

double length_hint(double l_tot) { return round_up_4(l_tot); }

std::string specified_force_text(const MechanismSpec& spec) {
  if (spec.force_of == mechanism::ForceOf::kOneHalf) {
    return fmt::format("F = {:.6g} N (one half)", spec.force);
  }
  return fmt::format(
      "F = {:.6g} N for the whole symmetric mechanism ({:.6g} N per half)",
      spec.force * mechanism::force_of_factor(mechanism::ForceOf::kOneHalf, spec.force_of),
      spec.force);
}

namespace {

// refine_design_exact without the design's status.
DimensionedDesign refine_against_exact(const MechanismSpec& spec,
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
  o.progress = spec.progress;  // per exact stroke (ExactRefinementOptions::progress)
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
  d.force_of = spec.force_of;
  d.note = fmt::format(
      "flexure design mechanism --model exact: sub-class {} refined against the exact model "
      "(R = {:.4f}, K1 = {:.4f}, K2 = {:.4f}) for {} over {:.6g} m, SF = {:g}",
      row.name,
      m.R,
      m.K1,
      m.K2,
      specified_force_text(spec),
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
  ao.stability = false;  // sizing reads forces and stresses only
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
  // The sections that make this exact force (section_family.h: the elastica depends on E I
  // alone), inside the ranges and SectionBounds.
  const SectionFamily family = family_of(d, p);
  const SectionInterval interval = section_interval(family, spec, out.l_tot);
  const double t_now = d.joints[p - 1].thickness;
  if (interval.lo > interval.hi * (1.0 + kSlack) ||
      (spec.stress_rule == StressRule::kThesis &&
       (t_now < interval.lo * (1.0 - kSlack) || t_now > interval.hi * (1.0 + kSlack)))) {
    reject(out,
           fmt::format("range: the refined design's section (h_p = {} for the exact force) does "
                       "not fit: {} needs h_p >= {}, {} allows h_p <= {}",
                       mm(t_now),
                       interval.lo_reason,
                       mm(interval.lo),
                       interval.hi_reason,
                       mm(interval.hi)),
           interval.lo / interval.hi);
    return out;
  }
  if (spec.stress_rule == StressRule::kComputed) {
    // The thickness by the PRBM and exact stresses, as the PRBM design was sized.
    StressedSection s =
        choose_section(spec, d, family, interval, section_policy(spec), true, std::nullopt);
    if (!s.feasible) {
      reject(out, fmt::format("the refined design: {}", s.binding), s.shortfall);
      return out;
    }
    a = std::move(s.analysis);
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
  out.primary_stress = primary_stress(spec.material.E,
                                      m.lambda,
                                      prbm_design.M,
                                      prbm_design.n,
                                      out.stroke_percent,
                                      out.thickness[p - 1],
                                      out.l_tot);
  out.required_yield_strength = spec.safety_factor * out.primary_stress;
  if (!spec.material.yield_strength) {
    d.material.yield_strength =
        spec.stress_rule == StressRule::kThesis
            ? *out.required_yield_strength_exact
            : std::max(*out.required_yield_strength_exact, out.required_yield_strength_prbm);
  }
  out.safety_factor_exact = d.material.yield_strength.value_or(0.0) / s_exact;
  out.safety_factor_prbm = d.material.yield_strength.value_or(0.0) / a->prbm.max_stress_all;
  const double h_primary = out.thickness[p - 1];
  out.footprint = mechanism_footprint(d, out.l_tot, spec.points);
  out.flexure_volume = flexure_volume(d);
  out.width_to_thickness = max_width_to_thickness(family, h_primary);
  out.width_to_length = max_width(family, h_primary) / out.l_tot;
  if (spec.stress_rule == StressRule::kThesis && spec.material.yield_strength &&
      *out.required_yield_strength_exact > *spec.material.yield_strength) {
    reject(out,
           fmt::format("stress: the refined design needs S_y >= {:.4g} MPa by its exact "
                       "stresses at SF {:g}; the material has {:.4g} MPa",
                       *out.required_yield_strength_exact * 1e-6,
                       spec.safety_factor,
                       *spec.material.yield_strength * 1e-6),
           *out.required_yield_strength_exact / *spec.material.yield_strength);
    return out;
  }
  out.feasible = true;
  apply_spec_material(spec, out);
  return out;
}

}  // namespace

DimensionedDesign refine_design_exact(const MechanismSpec& spec,
                                      const DimensionedDesign& prbm_design) {
  DimensionedDesign out = refine_against_exact(spec, prbm_design);
  stamp_design_status(out);
  return out;
}

std::vector<SafetyShortfall> designs_short_of_safety_factor(const MechanismDesignReport& report,
                                                            double safety_factor) {
  std::vector<SafetyShortfall> out;
  for (const DimensionedDesign& d : report.designs) {
    const double sf = std::min(d.safety_factor_prbm,
                               d.safety_factor_exact.value_or(std::numeric_limits<double>::max()));
    if (sf < safety_factor * (1.0 - 1e-9)) out.push_back({d.subclass, sf});
  }
  return out;
}

DimensionedDesign design_for_output(const MechanismDesignReport& report,
                                    const std::optional<DimensionedDesign>& refined) {
  if (report.designs.empty()) {
    throw std::logic_error("design_for_output: the report has no feasible design");
  }
  if (!refined) return report.designs.front();
  DimensionedDesign out = *refined;
  if (!refined->feasible) {
    // A refinement that failed before dimensioning (the optimisation) leaves the PRBM design,
    // whose exact force misses the specification.
    const bool prbm_design = refined->design.r2 == report.designs.front().design.r2;
    out.binding = fmt::format("the refinement against the exact model failed: {}{}",
                              refined->binding,
                              prbm_design ? "; this is the PRBM design" : "");
    out.design.note = "NOT FEASIBLE: " + out.binding + ". " + out.design.note;
  }
  stamp_design_status(out);
  return out;
}

}  // namespace flexure::design
