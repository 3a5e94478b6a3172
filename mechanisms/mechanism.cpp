#include "flexure/mechanisms/mechanism.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>

#include "flexure/elements/prbm_element.h"
#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/cfm/slider_crank.h"
#include "flexure/mechanisms/inversion.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/solver/common/names.h"
#include "flexure/solver/common/status.h"

namespace flexure::mechanism {
namespace {

constexpr double kMu = 0.1;  // s flexure length / associated link (thesis Table 8.1)

// Characteristic radius factor of every l segment (Howell §5.2 average, Weight 2001 §2.2).
double long_segment_gamma() { return howell_average_fixed_pinned().constants().gamma; }

void require_positive(double value, const std::string& what) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw InvalidInput(fmt::format("{} must be finite and > 0 (got {})", what, value));
  }
}

const char* pivot_label(int pivot) {
  return pivot == 1 ? "ground pivot 1" : pivot == 2 ? "middle pivot 2" : "slider pivot 3";
}

// The TOML table of a pivot, for messages (mechanism_toml.cpp).
const char* pivot_table(int pivot) {
  return pivot == 1 ? "[ground]" : pivot == 2 ? "[middle]" : "[slider]";
}

// Section shape of one flexible segment against SlenderBeamLimits (lengths already derived).
void check_section(const JointDesign& j, int p) {
  using L = SlenderBeamLimits;
  const double h_over_l = j.thickness / j.length;
  if (h_over_l > L::kMaxThicknessOverLength) {
    throw InvalidInput(fmt::format(
        "{} segment {}: thickness/length = {:.4g} (thickness {:.6g} m, length {:.6g} m) is outside "
        "slender-beam (Euler-Bernoulli) theory, on which the PRBM and the exact model rest; "
        "allowed <= {:g} (docs/mechanisms.md \"Geometry limits\")",
        pivot_label(p),
        pivot_table(p),
        h_over_l,
        j.thickness,
        j.length,
        L::kMaxThicknessOverLength));
  }
  const double b_over_h = j.width / j.thickness;
  if (b_over_h < L::kMinWidthOverThickness) {
    throw InvalidInput(fmt::format(
        "{} segment {}: width/thickness = {:.4g} (width {:.6g} m, thickness {:.6g} m): a strip "
        "narrower than it is thick bends out of the mechanism's plane, which the planar model "
        "does not describe; allowed >= {:g} (docs/mechanisms.md \"Geometry limits\")",
        pivot_label(p),
        pivot_table(p),
        b_over_h,
        j.width,
        j.thickness,
        L::kMinWidthOverThickness));
  }
}

// Loads of every flexible segment against SlenderBeamLimits, from the PRBM pin force over the
// stroke (the force every flexible segment of the half mechanism carries; an estimate good to
// the PRBM's few per cent, ample for limits with a 200-fold margin over the built-in designs).
void check_loads(const MechanismDesign& d) {
  using L = SlenderBeamLimits;
  constexpr int kSamples = 64;
  double P = 0.0;
  for (double dx : stroke_displacements(d, kSamples)) {
    const PrbmState s = prbm_state(d, dx);
    const double p = std::hypot(s.pin_force_x, s.pin_force_y);
    // A non-finite force (a singular pose) is reported by the PRBM stroke itself (exit 3).
    if (std::isfinite(p)) P = std::max(P, p);
  }
  for (int p = 1; p <= 3; ++p) {
    const JointDesign& j = d.joints[p - 1];
    if (j.type == PivotType::kPin) continue;
    const Section section = j.section();  // a rectangle: its area is known
    const double EI = j.flexural_rigidity(d.material);
    // Each value was finite and > 0, but their product can leave double precision (a 1e-200 m
    // strip has h^3 = 0): the springs would be 0 or inf and the PRBM force 0/0.
    const double k = d.spring_constant(p);
    if (!(std::isfinite(EI) && EI > 0.0 && std::isfinite(k) && k > 0.0)) {
      throw InvalidInput(fmt::format(
          "{} segment {}: flexural rigidity E b h^3/12 = {:.4g} N m^2 and spring constant {:.4g} "
          "N m/rad must be finite and > 0 (E = {:.4g} Pa, b = {:.4g} m, h = {:.4g} m: outside "
          "the range of double precision)",
          pivot_label(p),
          pivot_table(p),
          EI,
          k,
          d.material.E,
          j.width,
          j.thickness));
    }
    const double alpha2 = P * j.length * j.length / EI;
    if (alpha2 > L::kMaxLoadParameter) {
      throw InvalidInput(fmt::format(
          "{} segment {}: load parameter |P| L^2/(EI) = {:.4g} (largest PRBM pin force "
          "{:.4g} N, L = {:.6g} m, EI = {:.4g} N m^2) exceeds {:g}: the segment is far too "
          "slender for the load the other segments put on it, which then sets its stiffness "
          "instead of bending (outside the PRBM and the exact flexure model; docs/mechanisms.md "
          "\"Geometry limits\")",
          pivot_label(p),
          pivot_table(p),
          alpha2,
          P,
          j.length,
          EI,
          L::kMaxLoadParameter));
    }
    const double strain = P / (d.material.E * *section.area());
    if (strain > L::kMaxAxialStrain) {
      throw InvalidInput(fmt::format(
          "{} segment {}: axial strain |P|/(EA) = {:.4g} (largest PRBM pin force {:.4g} N, "
          "A = {:.4g} m^2) exceeds {:g}: outside the inextensible elastica and any elastic "
          "material (docs/mechanisms.md \"Geometry limits\")",
          pivot_label(p),
          pivot_table(p),
          strain,
          P,
          *section.area(),
          L::kMaxAxialStrain));
    }
  }
}

constexpr double kInch = 0.0254;      // m
constexpr double kPsi = 6894.757293;  // Pa

// Nine documented designs (docs/mechanisms.md "Built-in designs"): the design variables R, K1, K2
// of the configuration's sub-class a (16 % stroke, thesis Tables 7.2-7.12), r_tot = r2 + r3 =
// 100 mm, polypropylene (E = 1.4 GPa, S_y = 34.5 MPa, Howell Table A.1 order of magnitude), all
// flexures 10 mm wide, the reference flexure (k1; k2 in class 1B) 0.4 mm thick, the others sized
// at equal width so that k2/k1 = K1 and k3/k1 = K2; then all thicknesses scaled down together
// (ratios kept) where needed for a PRBM safety factor of 1.5; stroke = the sub-class stroke (16 %
// of r_tot, clamped at the toggle position as the thesis does).
MechanismDesign subclass_design(const cfm::CfmSubclass& row, const std::string& name);

}  // namespace

void size_flexures_for_spring_ratios(
    MechanismDesign& d, double width, double reference_thickness, double K1, double K2) {
  const cfm::CfmConfiguration& cfg = cfm::find_cfm_configuration(d.config);
  for (int i = 0; i < 3; ++i) {
    d.joints[i].type = cfg.pivots[i];
    if (cfg.pivots[i] != PivotType::kPin) {
      d.joints[i].width = width;
      d.joints[i].thickness = reference_thickness;
    }
  }
  d.finalise();  // fills the PRBM-rule lengths (s: 0.1 r, l: r/gamma)
  const int ref = cfg.is_class_1B() ? 2 : 1;
  const double k_ref = d.spring_constant(ref);
  const double K[3] = {1.0, cfg.is_class_1B() ? 1.0 : K1, K2};
  for (int p = 1; p <= 3; ++p) {
    if (p == ref || !cfg.has_spring(p)) continue;
    if (!std::isfinite(K[p - 1]) || K[p - 1] <= 0.0) {
      throw InvalidInput(fmt::format(
          "K{} must be finite and > 0 for configuration '{}' (pivot {} is a flexure; got {})",
          p - 1,
          cfg.name,
          p,
          K[p - 1]));
    }
    d.joints[p - 1].thickness *= std::cbrt(K[p - 1] / (d.spring_constant(p) / k_ref));
  }
  d.finalise();
}

namespace {

// A concrete design of one thesis sub-class (Tables 7.2-7.12): its R, K1, K2 and stroke, with
// r2 + r3 = 100 mm in polypropylene, thinned to a PRBM safety factor of 1.5.
MechanismDesign subclass_design(const cfm::CfmSubclass& row, const std::string& name) {
  const std::string config = row.config;
  const cfm::CfmConfiguration& cfg = cfm::find_cfm_configuration(config);
  MechanismDesign d;
  d.config = config;
  d.name = name;
  d.note = fmt::format(
      "sub-class {} (R = {}, K1 = {}, K2 = {}), r2 + r3 = 100 mm, polypropylene, b = 10 mm, "
      "reference flexure h = 0.4 mm",
      row.name,
      row.R,
      row.K1,
      row.K2);
  const double r_tot = 0.1;
  d.r2 = r_tot / (row.R + 1.0);
  d.r3 = r_tot - d.r2;
  d.material.E = 1.4e9;
  d.material.yield_strength = 34.5e6;
  const double stroke_percent =
      std::min(row.stroke_percent, 0.999 * cfm::toggle_stroke_percent(row.R));
  d.stroke = stroke_percent / 100.0 * r_tot;
  constexpr double kWidth = 0.01;
  constexpr double kReferenceThickness = 0.4e-3;
  size_flexures_for_spring_ratios(d, kWidth, kReferenceThickness, row.K1, row.K2);
  const int ref = cfg.is_class_1B() ? 2 : 1;
  // Thin all flexures together (ratios kept) until the PRBM safety factor is 1.5: the bending
  // stress at a given rotation grows like h (sigma = E h psi/(2 l)), so a few fixed-point steps.
  for (int it = 0; it < 6; ++it) {
    const double sf = prbm_stroke(d, 50).safety_factor;
    if (sf >= 1.5 * (1.0 - 1e-3) && it > 0) break;
    const double scale = std::min(1.0, sf / 1.5);
    if (scale >= 1.0) break;
    for (auto& j : d.joints) j.thickness *= scale;
    d.finalise();
  }
  if (d.joints[ref - 1].thickness < kReferenceThickness) {
    d.note += fmt::format(" thinned to {:.4g} mm for a PRBM safety factor of 1.5",
                          d.joints[ref - 1].thickness * 1e3);
  }
  return d;
}

// Thesis design example 1 (§8.5.1, Tables 8.3/8.4): lpp-b, l_tot = 15 in, b = 5 in,
// h = 0.04865 in, E = 30000 ksi, S_y = 167 ksi (the strength the example requires at SF 1.2),
// stroke 4 in (the text's value; the 7.5 in of Tables 8.3/8.4 is an erratum of the thesis).
MechanismDesign thesis_example_lpp() {
  const cfm::CfmSubclass& row = cfm::find_thesis_subclass("lpp-b");
  MechanismDesign d;
  d.name = "1A-lpp";
  d.config = "lpp";
  d.note =
      "thesis design example 1 (Weight 2001 §8.4, Table 8.4): lpp-b, l_tot = 15 in, b = 5 in, "
      "h = 0.04865 in, E = 30000 ksi, Sy = 167 ksi, stroke 4 in; target F = 25 lbf";
  const double l_tot = 15.0 * kInch;
  // l_tot = r2/gamma + r3 (thesis Table 5.1 lambda for lpp).
  d.r2 = l_tot / (1.0 / long_segment_gamma() + row.R);
  d.r3 = row.R * d.r2;
  d.material.E = 30.0e6 * kPsi;
  d.material.yield_strength = 167.0e3 * kPsi;
  d.stroke = 4.0 * kInch;
  d.joints[0] = JointDesign{PivotType::kLong, 0.0, 0.04865 * kInch, 5.0 * kInch};
  d.finalise();
  return d;
}

}  // namespace

const cfm::CfmConfiguration& MechanismDesign::configuration() const {
  return cfm::find_cfm_configuration(config);
}

double associated_link_length(const MechanismDesign& design, int pivot) {
  const auto& cfg = design.configuration();
  if (pivot == 1) return design.r2;
  if (pivot == 3) return design.r3;
  if (design.joints[1].type == PivotType::kLong) {
    return cfg.middle_long_on_r2 ? design.r2 : design.r3;
  }
  return 0.5 * (design.r2 + design.r3);
}

double table_8_1_segment_length(const MechanismDesign& design, int pivot) {
  const JointDesign& j = design.joints[pivot - 1];
  switch (j.type) {
    case PivotType::kPin:
      return 0.0;
    case PivotType::kLong:
      return associated_link_length(design, pivot) / long_segment_gamma();
    case PivotType::kSmall:
      if (j.segment == SegmentKind::kFixedFixed || j.length > 0.0) return j.length;
      return kMu * associated_link_length(design, pivot);
  }
  return 0.0;
}

double MechanismDesign::toggle_stroke() const {
  return cfm::toggle_stroke_percent(R()) / 100.0 * (r2 + r3);
}

double MechanismDesign::spring_constant(int pivot) const {
  const JointDesign& j = joints[pivot - 1];
  const double EI = j.flexural_rigidity(material);
  switch (j.type) {
    case PivotType::kPin:
      return 0.0;
    case PivotType::kSmall:
      if (j.segment == SegmentKind::kFixedFixed) {
        return spring_rule_factor(spring_rule, j) * EI / j.length;  // paper 004 Tables 2/5
      }
      // Howell eq. 5.14. Not PrbmElement::spring_constant, which refuses EI = 0: check_loads
      // reports a product that left double precision with its own message.
      return SmallLengthFlexuralPivot::kStiffnessCoefficient * EI / j.length;
    case PivotType::kLong:
      return howell_average_fixed_pinned().stiffness_coefficient() * EI / j.length;  // eq. 5.72
  }
  return 0.0;
}

void MechanismDesign::finalise() {
  const auto& cfg = cfm::find_cfm_configuration(config);  // throws for an unknown name
  require_positive(r2, "r2 (PRBM crank length, m)");
  require_positive(r3, "r3 (PRBM coupler length, m)");
  // The messages name the design's fields as a design file writes them; material.validate() then
  // checks what they do not (nu, a density), naming Material's field.
  require_positive(material.E, "E (Young's modulus, Pa)");
  require_positive(material.yield_strength.value_or(0.0), "yield_strength (Pa)");
  material.validate();
  require_positive(stroke, "stroke (slider travel, m)");
  for (int p = 1; p <= 3; ++p) {
    JointDesign& j = joints[p - 1];
    if (j.type != cfg.pivots[p - 1]) {
      throw InvalidInput(fmt::format("{}: configuration '{}' needs a{} there",
                                     pivot_label(p),
                                     config,
                                     cfg.pivots[p - 1] == PivotType::kPin     ? " pin (p)"
                                     : cfg.pivots[p - 1] == PivotType::kSmall ? "n s pivot"
                                                                              : "n l segment"));
    }
    if (j.type == PivotType::kPin) continue;
    require_positive(j.thickness, fmt::format("{} thickness (m)", pivot_label(p)));
    require_positive(j.width, fmt::format("{} width (m)", pivot_label(p)));
    const double link = associated_link_length(*this, p);
    if (j.type == PivotType::kLong) {
      j.length = link / long_segment_gamma();  // thesis Table 8.1: l = r/gamma
    } else if (j.segment == SegmentKind::kFixedFixed) {
      // No default: the modified configurations give every segment's length (paper Table 3/5).
      require_positive(j.length, fmt::format("{} fixed-fixed segment length (m)", pivot_label(p)));
    } else {
      if (j.length == 0.0) j.length = kMu * link;
      require_positive(j.length, fmt::format("{} flexure length (m)", pivot_label(p)));
      if (j.length > 0.5 * link) {
        throw InvalidInput(
            fmt::format("{} flexure length must be in (0, {:.6g}] m (half its link, so that the "
                        "small-length pivot model applies); got {:.6g}",
                        pivot_label(p),
                        0.5 * link,
                        j.length));
      }
    }
    check_section(j, p);
  }
  check_fixed_fixed_lengths(*this);
  const double limit = toggle_stroke();
  if (stroke > limit) {
    throw InvalidInput(fmt::format(
        "stroke {:.6g} m is past the toggle position: the limit for R = r3/r2 = {:.6g} is "
        "{:.6g} m ({:.4g} % of r2 + r3)",
        stroke,
        R(),
        limit,
        cfm::toggle_stroke_percent(R())));
  }
  // R = 1: the toggle is the full r2 + r3, where crank and coupler fold onto the ground pivot and
  // the PRBM force is 0/0 (as `flexure cfm` refuses d = 100 % for R = 1, cfm_model.cpp).
  if (R() == 1.0 && stroke >= limit) {
    throw InvalidInput(fmt::format(
        "stroke {:.6g} m with r2 = r3 (R = 1) folds crank and coupler onto the ground pivot at the "
        "toggle position {:.6g} m = r2 + r3, where the PRBM force is 0/0; use a stroke below it",
        stroke,
        limit));
  }
  check_loads(*this);
}

const std::vector<MechanismDesign>& builtin_mechanisms() {
  static const std::vector<MechanismDesign> designs = [] {
    std::vector<MechanismDesign> list;
    for (const auto& cfg : cfm::cfm_configurations()) {
      list.push_back(cfg.name == "lpp" ? thesis_example_lpp()
                                       : subclass_design(cfm::find_thesis_subclass(cfg.name + "-a"),
                                                         cfg.class_name + "-" + cfg.name));
    }
    // The eleven modified configurations of paper 004 (builtin_designs.h).
    for (const auto& d : modified_designs()) list.push_back(d);
    return list;
  }();
  return designs;
}

MechanismDesign find_builtin_mechanism(const std::string& name) {
  const std::string key = to_lower(name);
  // Inversions (inversion.h): NAME' or NAME-inv of any design below, or the mirrored
  // configuration string of a built-in design ("ppl", "1A-ppl" = "1A-lpp'").
  if (const auto base = inversion_base_name(name)) return invert(find_builtin_mechanism(*base));
  for (const auto& d : builtin_mechanisms()) {
    const auto& cfg = d.configuration();
    const std::string mirrored = mirrored_config(d.config);
    if (config_has_inversion(d.config) &&
        (key == mirrored || key == to_lower(cfg.class_name) + "-" + mirrored)) {
      return invert(d);
    }
  }
  if (auto howell = find_howell_mechanism(name)) return *howell;
  std::string names;
  for (const auto& d : builtin_mechanisms()) {
    if (key == to_lower(d.name) || (d.paper_config.empty() && key == d.config)) return d;
    // A modified design also by its pivot string alone ("lplm"), unique among the eleven.
    if (!d.paper_config.empty() && key == d.paper_config) return d;
    names += (names.empty() ? "" : ", ") + d.name;
  }
  // Every sub-class of the thesis tables by its name (lpp-b, lps-a95I, ...), sized like the
  // built-in designs.
  for (const cfm::CfmSubclass& row : cfm::thesis_subclasses()) {
    if (key == to_lower(row.name)) return subclass_design(row, row.name);
  }
  for (const auto& d : howell_mechanisms()) names += ", " + d.name;
  throw InvalidInput(
      fmt::format("unknown mechanism '{}' (built-in: {}; any thesis sub-class name such as lpp-b "
                  "(flexure cfm --list); an inversion NAME' or NAME-inv of a spp, lpp, plp, ssp, "
                  "slp or lps design such as 1A-lpp'; or a .toml file)",
                  name,
                  names));
}

}  // namespace flexure::mechanism
