#include "flexure/io/mechanism_stroke_file.h"

#include <fmt/format.h>

#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "flexure/io/mechanism_stroke_shapes.h"
#include "flexure/io/platform/provenance.h"
#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/inversion.h"
#include "flexure/mechanisms/modified_springs.h"
#include "flexure/solver/common/status.h"

namespace flexure::io {
namespace {

using namespace flexure::mechanism;

// The pivot's letter of the configuration string (Weight's thesis Table 8.1): p, s or l.
const char* pivot_letter(PivotType t) {
  return t == PivotType::kPin ? "p" : t == PivotType::kSmall ? "s" : "l";
}

// The meanings of the HDF5 `stability` codes (StabilityKind in its enum order).
std::vector<CodeMeaning> stability_code_meanings() {
  return {{"stability", 0, "stable: the potential energy has a strict minimum"},
          {"stability", 1, "unstable: stability_index directions in which the energy decreases"},
          {"stability",
           2,
           "critical: the lowest eigenvalue is zero within 1e-6 (buckling or limit point)"},
          {"stability", 3, "not_conservative: a follower load (never for a mechanism stroke)"},
          {"stability", 4, "not_checked: no verdict at this point (reason in the JSON output)"}};
}

// /design: everything MechanismDesign holds, in the described form (pivot 1 at the fixed body;
// the JSON "design" object reads the same way), so that the file alone says what was analysed.
void write_design_group(Hdf5Group& root, const MechanismDesign& d) {
  const DescribedDesign m = described_form(d);
  Hdf5Group g = root.create_group("design");
  g.set_attribute(
      "description",
      "the analysed half mechanism, described from its fixed body (docs/mechanisms.md)");
  g.set_attribute("name", d.name);
  g.set_attribute("config", m.config);
  g.set_attribute("class", d.configuration().class_name);
  g.set_attribute("note", d.note);
  g.set_attribute("inverted", std::int64_t{d.inverted ? 1 : 0});
  g.set_attribute("fixed_body", m.fixed_body);
  if (d.inverted) g.set_attribute("inversion_of_config", d.config);
  if (!d.paper_config.empty()) g.set_attribute("paper_config", d.paper_config);
  if (has_fixed_fixed(d)) g.set_attribute("spring_rule", spring_rule_name(d.spring_rule));
  g.write_scalar("r2", m.r2, "m", "PRBM link at the fixed body (pivot 1 to pivot 2)");
  g.write_scalar("r3", m.r3, "m", "PRBM link at the sliding body (pivot 2 to pivot 3)");
  g.write_scalar("E", d.material.E, "Pa", "Young's modulus of the material");
  g.write_scalar("yield_strength",
                 d.material.yield_strength.value_or(0.0),
                 "Pa",
                 "yield strength of the material");
  g.write_scalar("stroke", d.stroke, "m", "slider travel Delta x at the end of the stroke");
  g.write_scalar(
      "toggle_stroke", d.toggle_stroke(), "m", "largest stroke: the toggle position of the PRBM");
  // Per pivot, in the described numbering 1..3 (index 0..2); 0 for a pin.
  Hdf5Group joints = g.create_group("joints");
  joints.set_attribute("description", "one entry per pivot 1..3 (pivot 1 at the fixed body)");
  std::vector<std::string> type, segment, letter;
  std::vector<double> length, thickness, width, spring;
  for (int p = 1; p <= 3; ++p) {
    const JointDesign& j = m.joints[p - 1];
    const bool pin = j.type == PivotType::kPin;
    type.push_back(pivot_letter(j.type));
    segment.push_back(pin                                     ? "pin"
                      : j.segment == SegmentKind::kFixedFixed ? "fixed-fixed"
                      : j.type == PivotType::kLong            ? "fixed-pinned"
                                                              : "small-length");
    letter.push_back(j.segment == SegmentKind::kFixedFixed ? std::string(1, j.paper_letter) : "");
    length.push_back(j.length);
    thickness.push_back(j.thickness);
    width.push_back(j.width);
    spring.push_back(pin ? 0.0 : d.spring_constant(described_pivot(d, p)));
  }
  joints.write_dataset(
      "type", type, "text", "p pin, s small-length flexural pivot, l long segment");
  joints.write_dataset(
      "segment", segment, "text", "pin, small-length, fixed-pinned or fixed-fixed (paper 004)");
  joints.write_dataset("paper_letter",
                       letter,
                       "text",
                       "fixed-fixed segments: the paper's letter l or s; else empty");
  joints.write_dataset("length", length, "m", "flexible length; 0 for a pin");
  joints.write_dataset("thickness", thickness, "m", "in-plane thickness h; 0 for a pin");
  joints.write_dataset("width", width, "m", "out-of-plane width b; 0 for a pin");
  joints.write_dataset(
      "spring_constant", spring, "N m/rad", "PRBM torsional spring constant; 0 for a pin");
}

}  // namespace

void write_mechanism_stroke(Hdf5Group& root,
                            const MechanismAnalysis& a,
                            const MechanismFatigue* fatigue,
                            bool stable,
                            const std::string& stable_search) {
  // --stable and what it did: the JSON keys `stable` and `stable_search` (absent where null).
  root.set_attribute("stable", std::int64_t{stable ? 1 : 0});
  if (!stable_search.empty()) root.set_attribute("stable_search", stable_search);
  const bool exact = a.has_exact && a.exact.converged();
  root.set_attribute("mechanism", a.design.name);
  root.set_attribute("config", described_form(a.design).config);
  root.set_attribute("inverted", std::int64_t{a.design.inverted ? 1 : 0});
  if (has_fixed_fixed(a.design)) {
    root.set_attribute("spring_rule", spring_rule_name(a.design.spring_rule));
    if (!a.design.paper_config.empty()) root.set_attribute("paper_config", a.design.paper_config);
  }
  root.set_attribute("force_of", force_of_label(a.force_of));
  root.set_attribute("percent_constant_force_prbm", a.prbm.percent_constant_force);
  root.set_attribute("force_vanishes_prbm", std::int64_t{a.prbm.force_vanishes ? 1 : 0});
  root.set_attribute("force_changes_sign_prbm", std::int64_t{a.prbm.force_changes_sign ? 1 : 0});
  root.set_attribute("max_stress", a.max_stress_all);
  root.set_attribute("safety_factor", a.safety_factor);
  std::string attribute_units = "percent_constant_force_prbm: %; max_stress: Pa; safety_factor: 1";
  root.write_dataset("displacement",
                     std::span<const double>(a.prbm.displacement),
                     "m",
                     "slider displacement Delta x = k stroke/K, k = 1..K");
  root.write_dataset("force_prbm",
                     std::span<const double>(a.prbm.force),
                     "N",
                     fmt::format("PRBM slider input force of {} (positive pushes the slider "
                                 "inward)",
                                 force_of_label(a.force_of)));
  if (exact) {
    root.write_dataset(
        "force_exact",
        std::span<const double>(a.force_exact),
        "N",
        fmt::format("exact-model (elastica) slider input force of {}", force_of_label(a.force_of)));
    root.set_attribute("percent_constant_force_exact", a.percent_constant_force_exact);
    root.set_attribute("force_vanishes_exact", std::int64_t{a.force_vanishes_exact ? 1 : 0});
    root.set_attribute("force_changes_sign_exact",
                       std::int64_t{a.force_changes_sign_exact ? 1 : 0});
    root.set_attribute("max_force_error", a.max_force_error);
    attribute_units += "; percent_constant_force_exact: %; max_force_error: 1";
  }
  if (a.prbm_validity_limit) {
    root.set_attribute("prbm_validity_limit", *a.prbm_validity_limit);
    attribute_units += "; prbm_validity_limit: m";
  }
  // What is outside Table 5.1 and how large the PRBM's error is there (mechanism_analysis.h); the
  // errors are NaN where the exact model was not solved or no point falls in the group.
  const PrbmStrokeValidity& v = a.prbm_validity;
  root.set_attribute("prbm_validity", describe_validity(v, a.design.stroke));
  if (v.first_outside) {
    root.set_attribute("prbm_validity_reason", v.reason);
    root.set_attribute("prbm_validity_quantity", v.quantity);
    root.set_attribute("prbm_validity_value", v.value);
    root.set_attribute("prbm_validity_table_min", v.table_min);
    root.set_attribute("prbm_validity_table_max", v.table_max);
    attribute_units += fmt::format(
        "; prbm_validity_value, prbm_validity_table_min, prbm_validity_table_max: {}", v.unit);
  }
  root.set_attribute("prbm_points_outside_validity", static_cast<std::int64_t>(v.points_outside));
  root.set_attribute("prbm_force_error_at_validity_limit", v.force_error_at_limit);
  root.set_attribute("prbm_max_force_error_outside_validity", v.max_force_error_outside);
  root.set_attribute("prbm_max_force_error_inside_validity", v.max_force_error_inside);
  attribute_units +=
      "; prbm_force_error_at_validity_limit, prbm_max_force_error_outside_validity, "
      "prbm_max_force_error_inside_validity: 1";
  root.write_dataset("prbm_within_validity",
                     std::span<const int>(v.inside),
                     "1",
                     "per stroke point: 1 inside Howell Table 5.1 (every fixed-pinned segment), 0 "
                     "outside, -1 no table applies (small-length pivots, fixed-fixed segments)");
  if (fatigue != nullptr) {
    const PivotFatigue& c = fatigue->critical();
    root.set_attribute("fatigue_safety_factor", c.check.safety_factor);
    root.set_attribute("alternating_stress", c.check.alternating_stress);
    root.set_attribute("mean_stress", c.check.mean_stress);
    root.set_attribute("endurance_limit", c.check.endurance_limit);
    root.set_attribute("fatigue_critical_pivot",
                       std::int64_t{described_pivot(a.design, fatigue->critical_pivot)});
    attribute_units +=
        "; fatigue_safety_factor: 1 (modified Goodman, Howell eq. 3.110, rest to full stroke); "
        "alternating_stress: Pa; mean_stress: Pa; endurance_limit: Pa (corrected S_e)";
  }
  root.set_attribute("attribute_units", attribute_units);
  for (int p = 0; p < 3; ++p) {
    const int described = described_pivot(a.design, p + 1);
    if (!a.prbm.stress[p].empty()) {
      root.write_dataset(fmt::format("stress_prbm_pivot{}", described),
                         std::span<const double>(a.prbm.stress[p]),
                         "Pa",
                         fmt::format("PRBM largest stress of the flexure at pivot {}: bending by "
                                     "the PRB spring moment plus axial (docs/mechanisms.md)",
                                     described));
    }
    if (exact && a.has_exact_stress && !a.stress_exact[p].empty()) {
      root.write_dataset(fmt::format("stress_exact_pivot{}", described),
                         std::span<const double>(a.stress_exact[p]),
                         "Pa",
                         fmt::format("exact-model largest stress of the flexure at pivot {}: "
                                     "max |M| h/(2I) + |N|/A along the segment",
                                     described));
    }
  }
  // Per stroke point, under each way of driving the slider (docs/stability.md "Mechanisms"):
  // /stability_displacement_control/{prbm,exact}, /stability_force_control/{prbm,exact}.
  std::vector<CodeMeaning> codes;
  const std::vector<StrokeStabilityEntry> entries = stroke_stability_entries(a);
  for (const char* control : {"displacement_control", "force_control"}) {
    std::optional<Hdf5Group> group;
    for (const StrokeStabilityEntry& e : entries) {
      if (e.stroke == nullptr || std::string(e.control) != control) continue;
      if (!group) {
        group.emplace(root.create_group(std::string("stability_") + control));
        group->set_attribute(
            "description",
            std::string(control) == "displacement_control"
                ? "stability of each stroke point with the slider held at its position"
                : "stability of each stroke point under a dead load on the slider equal to its "
                  "force there");
      }
      Hdf5Group g = group->create_group(e.model);
      std::vector<int> kind, index;
      std::vector<double> margin;
      for (const Stability& v : e.stroke->points) {
        kind.push_back(static_cast<int>(v.kind));
        index.push_back(v.index);
        margin.push_back(v.margin);
      }
      const std::string model = std::string(e.model) == "prbm" ? "PRBM" : "exact-model";
      g.write_dataset("stability",
                      std::span<const int>(kind),
                      "1",
                      model +
                          " verdict per stroke point: 0 stable, 1 unstable, 2 critical, 4 not "
                          "checked (root status_meanings)");
      g.write_dataset("stability_index",
                      std::span<const int>(index),
                      "1",
                      model + " number of directions in which the potential energy decreases");
      g.write_dataset("stability_margin",
                      std::span<const double>(margin),
                      "1",
                      model +
                          " lowest eigenvalue of the second variation relative to the "
                          "unloaded stiffness (1 unloaded, 0 critical, < 0 unstable)");
      g.set_attribute("summary", e.stroke->summary);
      codes = stability_code_meanings();
    }
  }
  write_design_group(root, a.design);
  write_stroke_shapes(root, a);  // /shapes: the deformed shapes of the exact stroke
  write_provenance(root, codes);
}

MechanismStrokeFile::MechanismStrokeFile(const std::string& path) {
  try {
    file_ = std::make_unique<AtomicHdf5File>(path);
  } catch (const Hdf5Error& e) {
    throw InvalidInput(fmt::format("--out: {}", e.what()));
  }
}

MechanismStrokeFile::~MechanismStrokeFile() = default;

void MechanismStrokeFile::write(const mechanism::MechanismAnalysis& analysis,
                                const mechanism::MechanismFatigue* fatigue,
                                bool stable,
                                const std::string& stable_search) {
  if (!file_) throw std::logic_error("MechanismStrokeFile::write called twice");
  write_mechanism_stroke(file_->root(), analysis, fatigue, stable, stable_search);
  file_->commit();
  file_.reset();
}

}  // namespace flexure::io
