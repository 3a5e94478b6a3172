#include "flexure/mechanisms/design/subclass_sizing.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/cfm_comparison.h"
#include "flexure/mechanisms/design/feasibility.h"
#include "flexure/mechanisms/design/subclass_problem.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/solver/common/status.h"

namespace flexure::design {
namespace {

// Relative slack of the range checks: a value computed to rounding on a bound is inside.
constexpr double kSlack = 1e-9;

// Lengths in the messages, in mm (the specification may have come in inches; SI is the contract).
std::string mm(double m) { return fmt::format("{:.4g} mm", m * 1e3); }

bool one_flexure(const cfm::CfmConfiguration& c) {
  int flexures = 0;
  for (auto p : c.pivots) flexures += p != mechanism::PivotType::kPin;
  return flexures == 1;
}

void reject(DimensionedDesign& d,
            std::string why,
            std::optional<double> shortfall,
            LengthCure cure = LengthCure::kNone) {
  d.feasible = false;
  d.binding = std::move(why);
  d.shortfall = shortfall;
  d.cure = cure;
}

// The stroke's PRBM stresses and the exact stresses, largest of every flexure and point.
double largest_exact_stress(const mechanism::MechanismAnalysis& a) {
  return *std::max_element(a.max_stress_exact.begin(), a.max_stress_exact.end());
}

// The design with the family's section t, finalised, and its PRBM stroke; empty with the reason
// where the slender-beam limits refuse it or the PRBM has no finite stroke.
struct PrbmAt {
  bool ok = false;
  std::string why;
  mechanism::PrbmStrokeResult prbm;
};
PrbmAt prbm_at(mechanism::MechanismDesign& d, const SectionFamily& f, double t, int points) {
  PrbmAt r;
  f.apply(t, d);
  try {
    d.finalise();
    r.prbm = mechanism::prbm_stroke(d, points);
  } catch (const InvalidInput& e) {
    r.why = fmt::format("geometry: {}", e.what());
    return r;
  }
  if (!r.prbm.converged()) {
    r.why = fmt::format("PRBM: {}", r.prbm.message);
    return r;
  }
  r.ok = true;
  return r;
}

// The exact stroke and stresses of `d` as it stands (finalised).
struct ExactAt {
  bool ok = false;
  std::string why;
  mechanism::MechanismAnalysis analysis;
  double stress = 0.0;
};
ExactAt exact_at(const mechanism::MechanismDesign& d, int points) {
  ExactAt r;
  mechanism::AnalysisOptions o;
  o.points = points;
  o.stability = false;  // sizing reads forces and stresses only
  try {
    r.analysis = mechanism::analyze_mechanism(d, o);
  } catch (const std::exception& e) {  // InvalidInput or NoConvergence of the exact model
    r.why = e.what();
    return r;
  }
  const mechanism::MechanismAnalysis& a = r.analysis;
  if (!a.has_exact || !a.exact.converged()) {
    r.why = a.has_exact ? a.exact.message : a.exact_note;
    return r;
  }
  if (!a.has_exact_stress) {
    r.why = "the exact stresses were not computed";
    return r;
  }
  r.stress = largest_exact_stress(a);
  r.ok = true;
  return r;
}

// The largest t whose PRBM stresses stay below S. At fixed E I every PRBM stress is
// sigma(t) = a t + c t^2 (mechanism_analysis.h: bending by a spring moment or the clamp moment of
// the pin force, M h/(2I), grows like t at fixed I; the axial |P|/(b h) like t^2 at fixed b h^3),
// so two strokes, at t1 and t1/2, give a and c of every point and pivot exactly.
std::optional<double> prbm_thickness_limit(
    mechanism::MechanismDesign& d, const SectionFamily& f, double t1, double S, int points) {
  const PrbmAt one = prbm_at(d, f, t1, points);
  const PrbmAt half = prbm_at(d, f, 0.5 * t1, points);
  if (!one.ok || !half.ok) return std::nullopt;
  double u = std::numeric_limits<double>::infinity();
  for (int p = 0; p < 3; ++p) {
    const std::vector<double>& s1 = one.prbm.stress[p];
    const std::vector<double>& s2 = half.prbm.stress[p];
    for (std::size_t k = 0; k < s1.size() && k < s2.size(); ++k) {
      // sigma(u t1) = a u + c u^2: sigma(1) = a + c, sigma(1/2) = a/2 + c/4.
      const double c = std::max(0.0, 2.0 * s1[k] - 4.0 * s2[k]);
      const double a = std::max(0.0, s1[k] - c);
      if (a + c <= 0.0) continue;
      u = std::min(u, 2.0 * S / (a + std::sqrt(a * a + 4.0 * c * S)));  // root of a u + c u^2 = S
    }
  }
  return t1 * u;
}

std::string sf_text(double sf) { return fmt::format("{:.4g}", sf); }

}  // namespace

SectionPolicy section_policy(const MechanismSpec& spec) {
  return spec.minimize == SizeObjective::kMass || std::isinf(spec.width.upper)
             ? SectionPolicy::kThickest
             : SectionPolicy::kWidest;
}

StressedSection choose_section(const MechanismSpec& spec,
                               mechanism::MechanismDesign& d,
                               const SectionFamily& f,
                               const SectionInterval& I,
                               SectionPolicy policy,
                               bool exact,
                               std::optional<double> t_thesis,
                               SizingPurpose purpose) {
  StressedSection r;
  if (purpose == SizingPurpose::kCheck) policy = SectionPolicy::kWidest;
  const int points = spec.points;
  const auto fail = [&](std::string why, std::optional<double> shortfall, LengthCure cure) {
    r.feasible = false;
    r.binding = std::move(why);
    r.shortfall = shortfall;
    r.cure = cure;
    return r;
  };
  // Evaluates t into r (PRBM, and the exact model when asked).
  const auto settle = [&](double t) -> bool {
    r.t = t;
    const PrbmAt p = prbm_at(d, f, t, points);
    if (!p.ok) {
      fail(p.why, std::nullopt, LengthCure::kNone);
      return false;
    }
    r.prbm = p.prbm;
    return true;
  };
  const bool computed = spec.stress_rule == StressRule::kComputed;
  if (!computed || !spec.material.yield_strength) {
    double t = policy == SectionPolicy::kWidest ? I.lo : I.hi;
    if (!computed && t_thesis && policy == SectionPolicy::kThickest) {
      t = std::max(I.lo, std::min(I.hi, *t_thesis));
    }
    if (!settle(t)) return r;
    if (exact) {
      const ExactAt e = exact_at(d, points);
      if (e.ok) {
        r.analysis = e.analysis;
      } else {
        r.exact_note = e.why;
        // Without the exact stresses the design cannot carry the strength they need.
        if (computed) return fail(fmt::format("exact model: {}", e.why), std::nullopt, {});
      }
    }
    r.feasible = true;
    return r;
  }

  // kComputed with a yield strength: sigma <= S = S_y/SF by the PRBM and the exact stresses.
  const double SF = spec.safety_factor, S = *spec.material.yield_strength / SF;
  const double S_y = *spec.material.yield_strength;
  // The thickest section aims a rounding below the allowed stress, so that its safety factor
  // reads no less than the one asked for.
  const double S_aim = S * (1.0 - 1e-9);
  if (!settle(I.lo)) return r;
  if (r.prbm.max_stress_all > S) {
    const double sf = S_y / r.prbm.max_stress_all;
    return fail(fmt::format("stress: by its PRBM stresses (axial stress and clamp moment "
                            "included) even the least stressed section that fits (h_p = {}, {}) "
                            "has a safety factor {} < {:g} (it needs S_y >= {:.4g} MPa)",
                            mm(I.lo),
                            I.lo_reason,
                            sf_text(sf),
                            SF,
                            SF * r.prbm.max_stress_all * 1e-6),
                SF / sf,
                LengthCure::kLonger);
  }
  double t = I.lo;
  if (policy == SectionPolicy::kThickest) {
    const std::optional<double> limit = prbm_thickness_limit(d, f, I.lo, S_aim, points);
    t = limit ? std::clamp(*limit, I.lo, I.hi) : I.lo;
    // The slender-beam limits refuse no t in [lo, hi] but the axial strain, which grows with t:
    // the widest section passed them.
    if (!settle(t)) {
      t = I.lo;
      if (!settle(t)) return r;
    }
    // The fit is exact to rounding; t S/sigma(t) is safe whatever sigma's mix of a and c.
    if (r.prbm.max_stress_all > S_aim) {
      t = std::max(I.lo, t * S_aim / r.prbm.max_stress_all);
      if (!settle(t)) return r;
    }
  }
  if (!exact) {
    r.feasible = true;
    return r;
  }
  ExactAt e = exact_at(d, points);
  if (!e.ok) return fail(fmt::format("exact model: {}", e.why), std::nullopt, LengthCure::kNone);
  if (e.stress > S) {
    const auto exact_fail = [&](double t_at, double stress) {
      const double sf = S_y / stress;
      return fail(fmt::format("stress: by its exact stresses (axial stress included) even the "
                              "least stressed section that fits (h_p = {}, {}) has a safety "
                              "factor {} < {:g} (it needs S_y >= {:.4g} MPa)",
                              mm(t_at),
                              I.lo_reason,
                              sf_text(sf),
                              SF,
                              SF * stress * 1e-6),
                  SF / sf,
                  LengthCure::kLonger);
    };
    if (t <= I.lo * (1.0 + kSlack)) return exact_fail(t, e.stress);
    // Every exact stress is a t + c t^2 at each point of each segment too (the elastica depends
    // on E I alone), so t S/sigma(t) is safe; then a few secant steps on log sigma(log t).
    double t_bad = t, s_bad = e.stress;
    double t_ok = std::max(I.lo, t * S_aim / e.stress);
    if (!settle(t_ok)) return r;
    ExactAt e_ok = exact_at(d, points);
    if (!e_ok.ok) return fail(fmt::format("exact model: {}", e_ok.why), std::nullopt, {});
    if (e_ok.stress > S) return exact_fail(t_ok, e_ok.stress);
    for (int it = 0; it < 4 && e_ok.stress < S * (1.0 - 1e-4); ++it) {
      const double slope = std::log(s_bad / e_ok.stress) / std::log(t_bad / t_ok);
      double t_try = t_ok * std::exp(std::log(S_aim / e_ok.stress) / slope) * (1.0 - 1e-6);
      if (!(t_try > t_ok && t_try < t_bad)) break;
      if (!settle(t_try)) break;
      ExactAt e_try = exact_at(d, points);
      if (!e_try.ok) break;
      if (e_try.stress <= S_aim) {
        t_ok = t_try;
        e_ok = std::move(e_try);
      } else {
        t_bad = t_try;
        s_bad = e_try.stress;
      }
    }
    if (!settle(t_ok)) return r;
    e = std::move(e_ok);
  }
  r.analysis = std::move(e.analysis);
  r.feasible = true;
  r.binding.clear();  // a secant step the slender-beam limits refused
  r.shortfall.reset();
  return r;
}

SubclassSizer::SubclassSizer(const MechanismSpec& spec, const cfm::CfmSubclass& row)
    : spec_(spec), row_(row), model_(cfm::CfmModel().evaluate(cfm::parameters_of(row))) {
  const cfm::CfmConfiguration& cfg = cfm::find_cfm_configuration(row.config);
  const std::string flags = subclass_flags(row.name);
  const bool in_plane =
      spec.orientation == FlexureOrientation::kInPlane ||
      (spec.orientation == FlexureOrientation::kAny && flags.find('I') != std::string::npos);
  const bool out_of_plane = !in_plane && flags.find_first_of("Oo") != std::string::npos;
  section_rule_ = one_flexure(cfg) ? "one flexure"
                  : in_plane       ? "equal widths (in-plane)"
                  : out_of_plane   ? "equal thicknesses (out-of-plane)"
                                   : "h = C h_p, b = D_min b_p (eqs. 8.8, 8.9)";
  // The other flexures (eq. 8.7, I_i = D_equal_i I_p; eqs. 8.8-8.10).
  const int p = model_.primary_pivot;
  for (int i = 1; i <= 3; ++i) {
    if (cfg.pivots[i - 1] == mechanism::PivotType::kPin) continue;
    double tau = 1.0, w = 1.0;
    if (i != p) {
      const double D = second_moment_ratio(model_, i);
      if (in_plane) {
        tau = std::cbrt(D);
      } else if (out_of_plane) {
        w = D;
      } else {
        tau = model_.C[i - 1].value_or(1.0);
        w = model_.D_min[i - 1].value_or(D);
      }
    }
    tau_[i - 1] = tau;
    w_[i - 1] = w;
  }
}

mechanism::MechanismDesign SubclassSizer::geometry(double l) const {
  const cfm::CfmConfiguration& cfg = cfm::find_cfm_configuration(row_.config);
  mechanism::MechanismDesign d;
  d.name = row_.name;
  d.config = row_.config;
  // eqs. 8.11-8.14: r_tot = l_tot/lambda, r2 = r_tot/(R + 1), r3 = R r2.
  const double r_tot = l / model_.lambda;
  d.r2 = r_tot / (model_.R + 1.0);
  d.r3 = model_.R * d.r2;
  // The specification's material; nu stays the design's own (MechanismDesign::nu_given: the
  // caller gives it with the plate rule it belongs to).
  d.material.E = spec_.material.E;
  d.material.yield_strength =
      spec_.material.yield_strength.value_or(1.0);  // set once the stresses are known
  d.material.density = spec_.material.density;
  d.stroke = spec_.stroke;
  d.force_of = spec_.force_of;
  for (int i = 0; i < 3; ++i) d.joints[i].type = cfg.pivots[i];
  d.note = fmt::format(
      "flexure design mechanism: sub-class {} (R = {:.4f}, K1 = {:.4f}, K2 = {:.4f}) for {} "
      "over {:.6g} m, SF = {:g}",
      row_.name,
      model_.R,
      model_.K1,
      model_.K2,
      specified_force_text(spec_),
      spec_.stroke,
      spec_.safety_factor);
  return d;
}

SectionFamily SubclassSizer::family(const mechanism::MechanismDesign& g, double l) const {
  SectionFamily f;
  // Eq. 8.2: F = c E b_p h_p^3/l_tot^2.
  f.K = spec_.force * l * l / (force_coefficient(model_).c * spec_.material.E);
  f.tau = tau_;
  f.w = w_;
  for (int i = 0; i < 3; ++i) {
    if (tau_[i] > 0.0) f.length[i] = mechanism::table_8_1_segment_length(g, i + 1);
  }
  return f;
}

std::optional<double> SubclassSizer::longest_fitting_length(double lower, double upper) const {
  const auto gap = [&](double l) {
    const SectionInterval I = section_interval(family(geometry(l), l), spec_, l);
    return I.lo / I.hi;
  };
  if (gap(lower) > 1.0 + kSlack) return std::nullopt;
  if (gap(upper) <= 1.0) return upper;
  double a = lower, b = upper;  // gap(a) <= 1 < gap(b)
  for (int it = 0; it < 200 && b / a - 1.0 > 1e-14; ++it) {
    const double m = std::sqrt(a * b);
    (gap(m) <= 1.0 ? a : b) = m;
  }
  return a;
}

DimensionedDesign SubclassSizer::at(double l,
                                    SectionPolicy policy,
                                    SizingDepth depth,
                                    SizingPurpose purpose) const {
  const MechanismSpec& spec = spec_;
  DimensionedDesign out;
  out.subclass = row_.name;
  out.config = row_.config;
  out.model = model_;
  out.M = row_.M;
  out.n = row_.n;
  out.section_rule = section_rule_;
  const cfm::CfmResult& m = model_;
  const double lambda = m.lambda;
  const double E = spec.material.E, F = spec.force;
  const bool thesis = spec.stress_rule == StressRule::kThesis;

  // The stroke first (eq. 8.6).
  out.stroke_percent = stroke_percent_for(spec.stroke, l, lambda);
  if (out.stroke_percent > m.stroke_percent * (1.0 + kSlack)) {
    reject(out,
           fmt::format("stroke: d = {:.4g} % of r_tot at l_tot = {} (eq. 8.6) exceeds the "
                       "sub-class's design stroke {:.4g} %",
                       out.stroke_percent,
                       mm(l),
                       m.stroke_percent),
           out.stroke_percent / m.stroke_percent,
           LengthCure::kLonger);
    return out;
  }
  // Thesis Method 1 per sub-class (eqs. 8.5, 8.17): even the thinnest primary flexure must stay
  // below S_y/SF by eq. 8.5.
  if (thesis && spec.material.yield_strength && spec.thickness.lower > 0.0) {
    const double omega = *spec.material.yield_strength / E;
    const double h_min = spec.thickness.lower;
    const double M_max =
        stress_screen_M(omega, spec.safety_factor, lambda, out.n, h_min, out.stroke_percent, l);
    if (out.M > M_max * (1.0 + kSlack)) {
      reject(
          out,
          fmt::format("stress: M = {:.4f} exceeds M_max = {:.4f} (eq. 8.17 at h = {}, l_tot = {}, "
                      "d = {:.4g} %): eq. 8.5 alone would take a flexure at most h = {} thick, or "
                      "l_tot = {} long",
                      out.M,
                      M_max,
                      mm(h_min),
                      mm(l),
                      out.stroke_percent,
                      mm(max_primary_thickness(
                          omega, spec.safety_factor, lambda, out.M, out.n, out.stroke_percent, l)),
                      mm(length_for_stress(
                          omega, spec.safety_factor, lambda, out.M, out.n, h_min, spec.stroke))),
          out.M / M_max,
          LengthCure::kLonger);
      return out;
    }
  }

  // The section family at this length (eq. 8.2 fixes b_p h_p^3; eq. 8.7 the other flexures).
  mechanism::MechanismDesign d = geometry(l);
  const SectionFamily f = family(d, l);
  const SectionInterval I = section_interval(f, spec, l);
  if (I.lo > I.hi * (1.0 + kSlack)) {
    // Which way the length helps: the interval at a slightly longer mechanism.
    const double l2 = l * 1.01;
    const SectionInterval I2 = section_interval(family(geometry(l2), l2), spec, l2);
    const double gap = I.lo / I.hi, gap2 = I2.lo / I2.hi;
    reject(out,
           fmt::format("force: {:.4g} N at l_tot = {} (eq. 8.2) needs b_p h_p^3 = {:.4g} mm^4; "
                       "{} needs h_p >= {}, but {} allows h_p <= {}",
                       F,
                       mm(l),
                       f.K * 1e12,
                       I.lo_reason,
                       mm(I.lo),
                       I.hi_reason,
                       mm(I.hi)),
           gap,
           gap2 < gap * (1.0 - 1e-6)   ? LengthCure::kLonger
           : gap2 > gap * (1.0 + 1e-6) ? LengthCure::kShorter
                                       : LengthCure::kNone);
    return out;
  }
  std::optional<double> t_thesis;
  if (thesis && spec.material.yield_strength) {
    t_thesis = max_primary_thickness(*spec.material.yield_strength / E,
                                     spec.safety_factor,
                                     lambda,
                                     out.M,
                                     out.n,
                                     out.stroke_percent,
                                     l);
  }
  const bool exact = spec.exact && depth == SizingDepth::kFull;
  // Under the thesis's rule the exact model only reports: it runs after eq. 8.5 passed.
  StressedSection s = choose_section(spec, d, f, I, policy, exact && !thesis, t_thesis, purpose);
  if (!s.feasible) {
    reject(out, s.binding, s.shortfall, s.cure);
    return out;
  }
  const double h = s.t;
  out.l_tot = l;
  out.r2 = d.r2;
  out.r3 = d.r3;
  for (int i = 0; i < 3; ++i) {
    out.thickness[i] = d.joints[i].thickness;
    out.width[i] = d.joints[i].width;
    out.segment_length[i] = d.joints[i].length;
  }
  out.primary_stress = primary_stress(E, lambda, out.M, out.n, out.stroke_percent, h, l);
  out.required_yield_strength = spec.safety_factor * out.primary_stress;
  out.required_yield_strength_prbm = spec.safety_factor * s.prbm.max_stress_all;
  if (thesis && spec.material.yield_strength &&
      out.required_yield_strength > *spec.material.yield_strength * (1.0 + kSlack)) {
    reject(out,
           fmt::format("stress: needs S_y >= {:.4g} MPa at SF {:g} (eq. 8.5), the material has "
                       "{:.4g} MPa; the primary flexure would have to be h <= {} (has {}{})",
                       out.required_yield_strength * 1e-6,
                       spec.safety_factor,
                       *spec.material.yield_strength * 1e-6,
                       mm(*t_thesis),
                       mm(h),
                       *t_thesis < I.lo ? fmt::format(", the least that {} allows", I.lo_reason)
                                        : std::string()),
           out.required_yield_strength / *spec.material.yield_strength,
           LengthCure::kLonger);
    return out;
  }
  if (thesis && exact) {
    const ExactAt e = exact_at(d, spec.points);
    if (e.ok) {
      s.analysis = e.analysis;
    } else {
      s.exact_note = e.why;
    }
  }
  double exact_stress = 0.0;
  if (s.analysis) {
    const mechanism::MechanismAnalysis& a = *s.analysis;
    // The specified force, by the elastica: eq. 8.2 sized it by the PRBM.
    const double error = a.mean_force_exact / F - 1.0;
    if (!(std::abs(error) <= spec.force_tolerance)) {
      reject(out,
             fmt::format("force: the exact model gives a mean force {:.4g} N, {:+.1f} % from the "
                         "specified {:.4g} N (the PRBM, which eq. 8.2 sizes by, gives {:.4g} N; "
                         "allowed {:g} %, --force-tolerance; --model exact sizes the best design "
                         "by the exact force)",
                         a.mean_force_exact,
                         100.0 * error,
                         F,
                         s.prbm.mean_force,
                         100.0 * spec.force_tolerance),
             std::abs(error) / spec.force_tolerance,
             LengthCure::kNone);
      return out;
    }
    out.force_exact = a.mean_force_exact;
    out.percent_constant_force_exact = a.percent_constant_force_exact;
    exact_stress = largest_exact_stress(a);
    if (exact_stress > 0.0) out.required_yield_strength_exact = spec.safety_factor * exact_stress;
  } else if (exact) {
    out.exact_note = s.exact_note;
  }
  // Without a given yield strength the design carries the strength it needs by every stress the
  // models compute, so that its file analyses without yielding.
  d.material.yield_strength = spec.material.yield_strength.value_or(
      std::max({out.required_yield_strength,
                out.required_yield_strength_prbm,
                out.required_yield_strength_exact.value_or(0.0)}));
  out.force_prbm = s.prbm.mean_force;
  out.percent_constant_force_prbm = s.prbm.percent_constant_force;
  out.safety_factor_prbm = *d.material.yield_strength / s.prbm.max_stress_all;
  if (exact_stress > 0.0) out.safety_factor_exact = *d.material.yield_strength / exact_stress;
  out.footprint = mechanism_footprint(d, l, spec.points);
  out.flexure_volume = flexure_volume(d);
  out.width_to_thickness = max_width_to_thickness(f, h);
  out.width_to_length = max_width(f, h) / l;
  out.design = std::move(d);
  out.feasible = true;
  return out;
}

double mechanism_footprint(const mechanism::MechanismDesign& d, double l_tot, int points) {
  double y_max = 0.0, x_min = 0.0;
  for (double dx : mechanism::stroke_displacements(d, points)) {
    const mechanism::PrbmState s = mechanism::prbm_state(d, dx);
    y_max = std::max(y_max, d.r2 * std::sin(s.theta2));
    x_min = std::min(x_min, d.r2 * std::cos(s.theta2));
  }
  return (l_tot - x_min) * 2.0 * y_max;
}

double flexure_volume(const mechanism::MechanismDesign& d) {
  double v = 0.0;
  for (const mechanism::JointDesign& j : d.joints) {
    if (j.type != mechanism::PivotType::kPin) v += j.width * j.thickness * j.length;
  }
  return 2.0 * v;  // both halves
}

}  // namespace flexure::design
