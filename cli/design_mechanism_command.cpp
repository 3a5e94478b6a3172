// `flexure design mechanism`: dimensional design of a constant-force mechanism from a
// specification (mechanisms/design/mechanism_synthesis.h; Weight 2001 ch. 8; docs/design.md).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/csv_output.h"
#include "cli/fatigue_flags.h"
#include "cli/mechanism_geometry_output.h"
#include "cli/modulus_output.h"
#include "cli/slow_progress.h"
#include "cli/warning_output.h"
#include "flexure/io/mechanism_geometry_toml.h"
#include "flexure/io/platform/output_path.h"
#include "flexure/io/toml_files.h"
#include "flexure/mechanisms/design/mechanism_synthesis.h"
#include "flexure/mechanisms/materials_fatigue.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_exact_geometry.h"
#include "flexure/solver/common/section.h"
#include "flexure/solver/common/status.h"

namespace flexure::cli {
namespace {

struct DesignMechanismArgs {
  std::string force, stroke, E, yield_strength, length_range, width_range, thickness_range;
  double safety_factor = 0.0;
  bool in_plane = false, out_of_plane = false;
  double pcf_min = 0.0;
  std::vector<std::string> configs;
  std::string rank = "prbm";
  std::string model = "prbm";
  std::string force_of = "half";
  bool no_exact = false;
  int points = 50;
  bool json = false;
  std::string out;
  std::string drawing;  // --drawing FILE.svg|FILE.dxf
  std::string csv;      // --csv FILE: the table of feasible designs
  std::string stress_rule = "computed";
  std::string minimize;
  double max_width_to_thickness = design::SectionBounds{}.max_width_to_thickness;
  double max_width_to_length = design::SectionBounds{}.max_width_to_length;
  bool allow_infeasible = false;
  double force_tolerance_percent = 100.0 * design::MechanismSpec{}.force_tolerance;
  CLI::Option* yield_option = nullptr;
  CLI::Option* pcf_min_option = nullptr;
  std::string material;
  std::string plate, nu;  // the bending modulus (docs/plate-modulus.md)
  bool fatigue = false;
  FatigueFlags fatigue_flags;
};

design::StressRule parse_stress_rule(const std::string& text) {
  if (text == "computed") return design::StressRule::kComputed;
  if (text == "thesis") return design::StressRule::kThesis;
  throw InvalidInput(fmt::format(
      "--stress-rule '{}' is unknown; allowed: computed (the PRBM and exact stresses of each "
      "design), thesis (eq. 8.5 alone, to reproduce the thesis's examples)",
      text));
}

design::SizeObjective parse_minimize(const std::string& text) {
  if (text.empty()) return design::SizeObjective::kNone;
  if (text == "length") return design::SizeObjective::kLength;
  if (text == "footprint") return design::SizeObjective::kFootprint;
  if (text == "mass") return design::SizeObjective::kMass;
  throw InvalidInput(
      fmt::format("--minimize '{}' is unknown; allowed: length, footprint, mass", text));
}

design::LengthRange range_of(const std::string& text, const char* what) {
  const io::QuantityRange r = io::parse_quantity_range(text, io::Dimension::kLength, what);
  return {r.lower.si, r.upper.si};
}

// The bending modulus of --plate and --nu (or the material's nu). auto is refused: the widths
// that decide it are the design's outputs.
ModulusChoice plate_choice(const DesignMechanismArgs& a, const std::string& material_id) {
  const PlateRule rule =
      a.plate.empty() ? PlateRule::kOff : plate_rule_from_string(a.plate, "--plate");
  if (rule == PlateRule::kAuto) {
    throw InvalidInput(
        "design mechanism --plate auto: the strip widths that decide it are what the design "
        "chooses; design with --plate on or off and check with `flexure mechanism analyze "
        "FILE --plate auto`");
  }
  std::optional<double> nu;
  if (!a.nu.empty()) {
    const io::Quantity q = io::parse_quantity(a.nu, io::Dimension::kAngle, "--nu");
    if (q.has_unit()) throw InvalidInput("--nu is a plain number without a unit");
    nu = q.si;
  } else if (!material_id.empty()) {
    nu = find_material(material_id).nu;
  }
  double E = 0.0;
  if (!a.E.empty()) {
    E = io::parse_quantity(a.E, io::Dimension::kStress, "--E").si;
  } else {
    E = find_material(a.material).E;
  }
  if (rule == PlateRule::kOff) nu.reset();
  return choose_modulus(rule, E, nu, {}, {}, {}, "design mechanism");
}

design::MechanismSpec make_spec(const DesignMechanismArgs& a, mechanism::ForceOf of) {
  using io::Dimension;
  design::MechanismSpec s;
  // The specification's force is of `of`; the design equations size one half (eq. 8.2).
  s.force = io::parse_quantity(a.force, Dimension::kForce, "--force").si *
            mechanism::force_of_factor(of, mechanism::ForceOf::kOneHalf);
  s.force_of = of;
  s.stroke = io::parse_quantity(a.stroke, Dimension::kLength, "--stroke").si;
  if (a.E.empty() && a.material.empty()) {
    throw InvalidInput("give the material: --material NAME (`flexure materials`) or --E");
  }
  // --material gives E, S_y, S_ut and S_e'; --E, --yield-strength, --ultimate-strength and
  // --endurance-limit replace its values (with a warning where they differ).
  mechanism::MechanismDesign m;
  if (!a.material.empty()) {
    const MaterialGrade& g = find_material(a.material);
    m.material_id = g.id;
    m.material.E = g.E;
    m.ultimate_strength = g.ultimate_strength;
    m.endurance_limit = g.fatigue_strength;
    m.endurance_cycles = g.fatigue_cycles;
    m.ductile = g.ductile;
    if (!*a.yield_option && g.static_strength()) s.material.yield_strength = g.static_strength();
    s.material.density = g.density;
  }
  if (!a.E.empty()) {
    const io::Quantity E = io::parse_quantity(a.E, Dimension::kStress, "--E");
    warn(io::modulus_warning(E, "--E"));
    if (m.material.E > 0.0 && m.material.E != E.si) {
      warn(fmt::format("--E {:.6g} Pa replaces the {:.6g} Pa of material '{}'",
                       E.si,
                       m.material.E,
                       m.material_id));
    }
    m.material.E = E.si;
  }
  // The plate modulus (docs/plate-modulus.md): the strips are sized with E/(1 - nu^2).
  const ModulusChoice modulus = plate_choice(a, m.material_id);
  s.material.E = modulus.effective_E;
  if (modulus.nu) s.material.nu = *modulus.nu;
  if (*a.yield_option) {
    s.material.yield_strength =
        io::parse_quantity(a.yield_strength, Dimension::kStress, "--yield-strength").si;
  }
  a.fatigue_flags.apply_strengths(m);
  s.material_id = m.material_id;
  s.ultimate_strength = m.ultimate_strength;
  s.endurance_limit = m.endurance_limit;
  s.endurance_cycles = m.endurance_cycles;
  s.ductile = m.ductile;
  if (a.fatigue) s.fatigue = a.fatigue_flags.options();
  require_finite_input(a.safety_factor, "--safety-factor");
  s.safety_factor = a.safety_factor;
  s.length = range_of(a.length_range, "--length-range");
  s.width = a.width_range.empty() ? design::MechanismSpec::free_range()
                                  : range_of(a.width_range, "--width-range");
  s.thickness = a.thickness_range.empty() ? design::MechanismSpec::free_range()
                                          : range_of(a.thickness_range, "--thickness-range");
  if (a.in_plane && a.out_of_plane) {
    throw InvalidInput("--in-plane and --out-of-plane exclude each other; give one or neither");
  }
  s.orientation = a.in_plane       ? design::FlexureOrientation::kInPlane
                  : a.out_of_plane ? design::FlexureOrientation::kOutOfPlane
                                   : design::FlexureOrientation::kAny;
  if (*a.pcf_min_option) s.pcf_min = a.pcf_min;
  s.configs = a.configs;
  if (a.rank == "prbm") {
    s.ranking = design::DesignRanking::kPrbm;
  } else if (a.rank == "exact") {
    s.ranking = design::DesignRanking::kExact;
    if (a.no_exact) throw InvalidInput("--rank exact needs the exact model: drop --no-exact");
  } else {
    throw InvalidInput(fmt::format("--rank '{}' is unknown; allowed: prbm, exact", a.rank));
  }
  s.exact = !a.no_exact;
  if (a.model != "prbm" && a.model != "exact") {
    throw InvalidInput(fmt::format("--model '{}' is unknown; allowed: prbm, exact", a.model));
  }
  if (a.model == "exact" && a.no_exact) {
    throw InvalidInput("--model exact refines against the exact model: drop --no-exact");
  }
  s.points = a.points;
  s.stress_rule = parse_stress_rule(a.stress_rule);
  s.minimize = parse_minimize(a.minimize);
  require_finite_input(a.max_width_to_thickness, "--max-width-to-thickness");
  require_finite_input(a.max_width_to_length, "--max-width-to-length");
  s.bounds.max_width_to_thickness = a.max_width_to_thickness;
  s.bounds.max_width_to_length = a.max_width_to_length;
  require_finite_input(a.force_tolerance_percent, "--force-tolerance");
  s.force_tolerance = a.force_tolerance_percent / 100.0;
  if (a.allow_infeasible && a.model != "exact") {
    throw InvalidInput(
        "--allow-infeasible applies to --model exact (whose refinement may miss the "
        "specification); the PRBM designs listed are feasible");
  }
  if (a.allow_infeasible && a.out.empty()) {
    throw InvalidInput("--allow-infeasible says what --out may write: give --out");
  }
  s.validate();
  return s;
}

Json optional_json(const std::optional<double>& v) { return v ? Json(*v) : Json(nullptr); }

Json design_json(const design::DimensionedDesign& d, double force_factor, double specified_force) {
  const cfm::CfmResult& m = d.model;
  Json j{{"subclass", d.subclass},
         {"config", d.config},
         {"R", m.R},
         {"K1", m.K1},
         {"K2", m.K2},
         {"lambda", m.lambda},
         {"beta", m.beta},
         {"M", d.M},
         {"n", d.n},
         {"Psi", optional_json(m.Psi)},
         {"primary_pivot", m.primary_pivot},
         {"subclass_percent_constant_force", m.percent_constant_force},
         {"subclass_stroke_percent", m.stroke_percent}};
  if (!d.feasible) {
    j["binding"] = d.binding;
    j["shortfall"] = optional_json(d.shortfall);
    j["length_needed"] = optional_json(d.length_needed);
    return j;
  }
  Json pivots = Json::array(), lengths = Json::array(), thicknesses = Json::array(),
       widths = Json::array();
  for (int i = 0; i < 3; ++i) {
    if (d.thickness[i] <= 0.0) continue;
    pivots.push_back(i + 1);
    lengths.push_back(d.segment_length[i]);
    thicknesses.push_back(d.thickness[i]);
    widths.push_back(d.width[i]);
  }
  j["stroke_percent"] = d.stroke_percent;
  j["l_tot"] = d.l_tot;
  j["r2"] = d.r2;
  j["r3"] = d.r3;
  j["flexible_pivots"] = pivots;
  j["segment_lengths"] = lengths;
  j["thicknesses"] = thicknesses;
  j["widths"] = widths;
  j["width"] = d.width[m.primary_pivot - 1];
  j["section_rule"] = d.section_rule;
  j["primary_stress"] = d.primary_stress;
  j["required_yield_strength"] = d.required_yield_strength;
  j["required_yield_strength_prbm"] = d.required_yield_strength_prbm;
  j["required_yield_strength_exact"] = optional_json(d.required_yield_strength_exact);
  j["yield_strength"] = d.design.material.yield_strength.value_or(0.0);
  j["force_prbm"] = d.force_prbm * force_factor;
  j["force_exact"] = d.force_exact ? Json(*d.force_exact * force_factor) : Json(nullptr);
  j["percent_constant_force_prbm"] = d.percent_constant_force_prbm;
  j["percent_constant_force_exact"] = optional_json(d.percent_constant_force_exact);
  j["safety_factor_prbm"] = d.safety_factor_prbm;
  j["safety_factor_exact"] = optional_json(d.safety_factor_exact);
  j["safety_factor_eq_8_5"] = d.design.material.yield_strength.value_or(0.0) / d.primary_stress;
  // Relative to the specified force (both of one half here).
  j["force_error_exact"] =
      d.force_exact ? Json(*d.force_exact / specified_force - 1.0) : Json(nullptr);
  j["footprint"] = d.footprint;
  j["flexure_volume"] = d.flexure_volume;
  j["width_to_thickness"] = d.width_to_thickness;
  j["width_to_length"] = d.width_to_length;
  j["geometry"] = design_geometry_json(d.design);
  if (!d.exact_note.empty()) j["exact_note"] = d.exact_note;
  if (d.fatigue) {
    const FatigueCheck& f = d.fatigue->critical().check;
    j["fatigue_safety_factor"] = f.safety_factor;
    j["alternating_stress"] = f.alternating_stress;
    j["mean_stress"] = f.mean_stress;
    j["endurance_limit"] = f.endurance_limit;
    j["fatigue_critical_pivot"] = d.fatigue->critical_pivot;
  }
  return j;
}

Json refined_json(const design::DimensionedDesign& d, double force_factor, double specified_force) {
  Json j = design_json(d, force_factor, specified_force);
  j["feasible"] = d.feasible;
  j["exact_evaluations"] = d.exact_evaluations;
  return j;
}

Json screens_json(const design::DesignScreens& s, double force_factor) {
  return Json{
      {"stroke_percent_min", s.stroke_percent_min},
      {"stroke_percent_max", s.stroke_percent_max},
      {"omega", s.omega > 0.0 ? Json(s.omega) : Json(nullptr)},
      {"M_max", optional_json(s.M_max)},
      {"M_min", optional_json(s.M_min)},
      {"Psi_min", optional_json(s.Psi_min)},
      {"lpp_subclass", s.lpp_subclass.empty() ? Json(nullptr) : Json(s.lpp_subclass)},
      {"lpp_thickness_max", optional_json(s.lpp_thickness_max)},
      {"lpp_force_max", s.lpp_force_max ? Json(*s.lpp_force_max * force_factor) : Json(nullptr)}};
}

const char* stress_rule_name(design::StressRule r) {
  return r == design::StressRule::kThesis ? "thesis" : "computed";
}

Json bounds_json(const design::SectionBounds& b) {
  return Json{{"max_width_to_thickness", b.max_width_to_thickness},
              {"max_width_to_length", b.max_width_to_length}};
}

// The file's header: what it is, by which rule, and, for a design that misses the specification
// (--allow-infeasible), why.
std::string toml_comment(const design::DimensionedDesign& d,
                         std::size_t feasible,
                         const design::MechanismSpec& spec,
                         bool refined,
                         const std::string& path) {
  std::string text;
  if (!d.feasible) {
    text += fmt::format(
        "NOT FEASIBLE (--allow-infeasible): this design misses the specification: {}\n", d.binding);
  }
  text += fmt::format(
      "Written by flexure design mechanism: {} of {} feasible designs, sub-class {}{}.\n"
      "Specified: {}, safety factor {:g} by the {} stress rule; force_of below.\n"
      "SI units. Analyse with: flexure mechanism analyze {}",
      d.feasible ? "the best" : "refined from the best",
      feasible,
      d.subclass,
      refined ? ", refined against the exact model" : "",
      design::specified_force_text(spec),
      spec.safety_factor,
      stress_rule_name(spec.stress_rule),
      path);
  return text;
}

void run_design_mechanism(const DesignMechanismArgs& args) {
  const mechanism::ForceOf of = mechanism::parse_force_of(args.force_of);
  design::MechanismSpec spec = make_spec(args, of);
  spec.progress = stoppable_progress("design mechanism: sub-classes");
  if (!args.out.empty()) io::check_output_path(args.out);
  if (!args.csv.empty()) io::check_output_path(args.csv, "--csv");
  if (!args.drawing.empty()) check_drawing_path(args.drawing, "--drawing");
  const double factor = mechanism::force_of_factor(mechanism::ForceOf::kOneHalf, of);
  const ModulusChoice modulus =
      plate_choice(args, args.material.empty() ? "" : find_material(args.material).id);
  // The designs carry the modulus as given, the rule and nu: a written file reads back to the
  // same strips (plate = "on" and [material].nu; mechanism analyze applies it).
  const auto as_given = [&](mechanism::MechanismDesign& d) {
    if (!modulus.plate) return;
    d.material.E = modulus.E;
    d.plate = modulus.rule;
    d.set_nu(modulus.nu);
  };
  design::MechanismDesignReport r = design::design_mechanisms(spec);
  // --model exact: the best design refined against the exact model (R, K1, K2 and sizes), solved
  // with the modulus the sizing used (before the designs are shown with the modulus as given).
  std::optional<design::DimensionedDesign> refined;
  if (args.model == "exact" && !r.designs.empty()) {
    design::MechanismSpec refine = spec;
    refine.progress = stoppable_progress("design mechanism --model exact: exact strokes");
    refined = design::refine_design_exact(refine, r.designs.front());
    as_given(refined->design);
  }
  for (auto& d : r.designs) as_given(d.design);
  for (auto& d : r.rejected) as_given(d.design);
  Json rejected = Json::array();
  for (const auto& d : r.rejected) rejected.push_back(design_json(d, factor, spec.force));
  if (r.designs.empty()) {
    // The library's message (design_status.h) and the flags that act on it.
    std::string message = "design mechanism: " + r.message;
    if (r.rejected.empty()) {
      message += " (see --config, --pcf-min, --in-plane/--out-of-plane)";
    } else if (r.length_needed) {
      message += "; give --length-range up to it";
    }
    throw NoConvergenceReport(
        message,
        Json{{"rejected", rejected},
             {"screens", screens_json(r.screens, factor)},
             {"length_needed", optional_json(r.length_needed)},
             {"length_needed_subclass",
              r.length_needed ? Json(r.length_needed_subclass) : Json(nullptr)},
             {"stress_rule", stress_rule_name(spec.stress_rule)}});
  }
  const bool refinement_failed = refined && !refined->feasible;
  const Json designs_json = [&] {
    Json a = Json::array();
    for (const auto& d : r.designs) a.push_back(design_json(d, factor, spec.force));
    return a;
  }();
  const Json summary{
      {"designs", designs_json},
      {"rejected", rejected},
      {"screens", screens_json(r.screens, factor)},
      {"force", spec.force * factor},
      {"force_of", mechanism::force_of_label(of)},
      {"stroke", spec.stroke},
      {"safety_factor", spec.safety_factor},
      {"ranking", args.rank},
      {"model", args.model},
      {"stress_rule", stress_rule_name(spec.stress_rule)},
      {"minimize", args.minimize.empty() ? Json(nullptr) : Json(args.minimize)},
      {"section_bounds", bounds_json(spec.bounds)},
      {"force_tolerance_percent", 100.0 * spec.force_tolerance},
      {"material", spec.material_id.empty() ? Json(nullptr) : Json(spec.material_id)},
      {"modulus_rule", modulus.modulus_rule()},
      {"effective_E", modulus.effective_E},
      {"modulus", Json::array({modulus_choice_json(modulus)})},
      {"fatigue", spec.fatigue.has_value()},
      {"sizing_safety_factor", optional_json(r.sizing_safety_factor)},
      {"refined", refined ? refined_json(*refined, factor, spec.force) : Json(nullptr)},
      {"out", args.out.empty() ? Json(nullptr) : Json(args.out)},
      {"drawing", args.drawing.empty() ? Json(nullptr) : Json(args.drawing)}};
  const design::DimensionedDesign written = design::design_for_output(r, refined);
  if (!args.out.empty() && (!refinement_failed || args.allow_infeasible)) {
    io::write_text_file(
        args.out,
        mechanism::mechanism_toml(
            written.design,
            toml_comment(written, r.designs.size(), spec, refined.has_value(), args.out)) +
            io::geometry_toml(mechanism::mechanism_geometry(written.design)));
  }
  // The drawing of the design that --out writes (the refined one with --model exact).
  const mechanism::MechanismDesign& drawn = written.design;
  if (!args.drawing.empty() && (!refinement_failed || args.allow_infeasible)) {
    // The end of the stroke with the exact model's bent flexures, as `mechanism draw` draws it.
    mechanism::MechanismGeometry g = mechanism::mechanism_geometry(drawn);
    const std::string why_not = mechanism::add_exact_stroke_end(g, drawn);
    if (!why_not.empty()) {
      warn(
          fmt::format("--drawing: the end of the stroke is drawn with the PRBM's pseudo-rigid "
                      "flexures ({})",
                      why_not));
    }
    io::write_mechanism_drawing(args.drawing, g, io::DrawingOptions{}, "--drawing");
  }
  if (refinement_failed) {
    // The answer asked for (the design refined against the exact model) misses the
    // specification: exit 3 with the reason, whatever --allow-infeasible wrote.
    Json reached = summary;
    throw NoConvergenceReport(
        fmt::format(
            "design mechanism --model exact: the refinement of {} against the exact "
            "model is not feasible: {}{}",
            r.designs.front().subclass,
            refined->binding,
            args.out.empty() ? ""
            : args.allow_infeasible
                ? fmt::format("; wrote it to {} anyway (--allow-infeasible), marked NOT "
                              "FEASIBLE",
                              args.out)
                : fmt::format("; nothing written to {} (--allow-infeasible writes it)", args.out)),
        reached);
  }
  // Designs short of the safety factor by their own stresses (design_status.h).
  warn(r.warnings);
  if (!args.csv.empty()) {
    // One row per feasible design, the JSON `designs` keys as columns (docs/cli.md).
    static const std::map<std::string, std::string> kUnits = {
        {"subclass_percent_constant_force", "%"},
        {"subclass_stroke_percent", "% of r2 + r3"},
        {"stroke_percent", "% of r2 + r3"},
        {"l_tot", "m"},
        {"r2", "m"},
        {"r3", "m"},
        {"segment_lengths", "m"},
        {"thicknesses", "m"},
        {"widths", "m"},
        {"width", "m"},
        {"primary_stress", "Pa"},
        {"required_yield_strength", "Pa"},
        {"required_yield_strength_prbm", "Pa"},
        {"required_yield_strength_exact", "Pa"},
        {"yield_strength", "Pa"},
        {"force_prbm", "N"},
        {"force_exact", "N"},
        {"percent_constant_force_prbm", "%"},
        {"percent_constant_force_exact", "%"},
        {"footprint", "m^2"},
        {"flexure_volume", "m^3"},
        // --fatigue: the critical pivot's Goodman check (docs/fatigue.md).
        {"alternating_stress", "Pa"},
        {"mean_stress", "Pa"},
        {"endurance_limit", "Pa"},
        {"length_needed", "m"},
    };
    std::vector<io::CsvColumn> columns = csv_columns_from_records(summary["designs"], kUnits);
    io::mark_force_columns(columns, mechanism::force_of_label(of));  // N (half) or N (whole)
    io::write_csv(args.csv, columns);
  }
  if (args.json) {
    print_json(summary);
    return;
  }
  if (r.sizing_safety_factor) {
    fmt::print(
        "sized at static safety factor {:.3g} so that the cycle rest -> full stroke has fatigue "
        "safety factor {:g} (modified Goodman, S_e of {}; docs/fatigue.md)\n",
        *r.sizing_safety_factor,
        spec.safety_factor,
        spec.material_id.empty() ? std::string("the given S_e'") : spec.material_id);
  }
  fmt::print(
      "{} feasible design{} ({} rejected), {}; forces of {}; safety factor {:g} by the {} "
      "stresses:\n",
      r.designs.size(),
      r.designs.size() == 1 ? "" : "s",
      r.rejected.size(),
      spec.minimize == design::SizeObjective::kNone ? "best first"
                                                    : "smallest " + args.minimize + " first",
      mechanism::force_of_label(of),
      spec.safety_factor,
      spec.stress_rule == design::StressRule::kThesis ? "eq. 8.5 (--stress-rule thesis)"
                                                      : "PRBM and exact");
  for (const auto& d : r.designs) {
    const int p = d.model.primary_pivot;
    std::string size;
    if (spec.minimize == design::SizeObjective::kFootprint) {
      size = fmt::format("; footprint {:.4g} mm^2", d.footprint * 1e6);
    } else if (spec.minimize == design::SizeObjective::kMass) {
      size = fmt::format("; flexure volume {:.4g} mm^3", d.flexure_volume * 1e9);
    }
    fmt::print(
        "  {:<10} l_tot {:.4g} mm, r2 {:.4g} mm, r3 {:.4g} mm, primary h {:.4g} mm, b {:.4g} mm{}; "
        "SF PRBM {:.3g}, exact {} (S_y {:.4g} MPa; eq. 8.5 alone needs {:.4g}); F {:.4g} N "
        "(exact {}), Xi' {:.1f} % (exact {}){}\n",
        d.subclass,
        d.l_tot * 1e3,
        d.r2 * 1e3,
        d.r3 * 1e3,
        d.thickness[p - 1] * 1e3,
        d.width[p - 1] * 1e3,
        size,
        d.safety_factor_prbm,
        d.safety_factor_exact ? fmt::format("{:.3g}", *d.safety_factor_exact) : "n/a",
        d.design.material.yield_strength.value_or(0.0) * 1e-6,
        d.required_yield_strength * 1e-6,
        d.force_prbm * factor,
        d.force_exact ? fmt::format("{:.4g} N", *d.force_exact * factor) : "n/a",
        d.model.percent_constant_force,
        d.percent_constant_force_exact ? fmt::format("{:.1f} %", *d.percent_constant_force_exact)
                                       : "n/a",
        d.fatigue ? fmt::format("; fatigue SF {:.3g} (pivot {}, S_e {:.4g} MPa)",
                                d.fatigue->critical().check.safety_factor,
                                d.fatigue->critical_pivot,
                                d.fatigue->critical().check.endurance_limit * 1e-6)
                  : std::string());
  }
  if (refined) {
    const design::DimensionedDesign& x = *refined;
    const design::DimensionedDesign& best = r.designs.front();
    fmt::print(
        "refined against the exact model: R {:.4f}, K1 {:.4f}, K2 {:.4f}; r2 {:.4g} mm, r3 "
        "{:.4g} mm, primary h {:.4g} mm, b {:.4g} mm; exact F {:.4g} N, Xi' {:.1f} % (was "
        "{:.1f} %), SF exact {:.3g}, PRBM {:.3g} (S_y {:.4g} MPa; {} exact strokes)\n",
        x.model.R,
        x.model.K1,
        x.model.K2,
        x.r2 * 1e3,
        x.r3 * 1e3,
        x.thickness[x.model.primary_pivot - 1] * 1e3,
        x.width[x.model.primary_pivot - 1] * 1e3,
        x.force_exact.value_or(0.0) * factor,
        x.percent_constant_force_exact.value_or(0.0),
        best.percent_constant_force_exact.value_or(0.0),
        x.safety_factor_exact.value_or(0.0),
        x.safety_factor_prbm,
        x.design.material.yield_strength.value_or(0.0) * 1e-6,
        x.exact_evaluations);
  }
  fmt::print("{}", design_geometry_text(drawn, length_unit_of(args.stroke)));
  if (!args.out.empty()) fmt::print("wrote {}\n", args.out);
  if (!args.drawing.empty()) fmt::print("wrote {}\n", args.drawing);
}

}  // namespace

void register_design_mechanism_command(CLI::App& app) {
  CLI::App& design =
      get_or_add_subcommand(app, "design", "Design constant-force mechanisms (docs/design.md)");
  auto a = std::make_shared<DesignMechanismArgs>();
  CLI::App* cmd = design.add_subcommand(
      "mechanism",
      "Dimensional design from a specification: every admissible thesis sub-class sized by "
      "eqs. 8.2, 8.5, 8.6 and Table 8.1, checked by the PRBM and the exact model, ranked");
  cmd->add_option("--force", a->force, "Mean slider force, e.g. 25lbf or 110N (see --force-of)")
      ->required();
  cmd->add_option("--stroke", a->stroke, "Slider travel, e.g. 4in or 100mm")->required();
  cmd->add_option("--material",
                  a->material,
                  "Material from the library (`flexure materials`): E, S_y, S_ut, S_e'");
  cmd->add_option("--E", a->E, "Young's modulus, e.g. 30Msi or 200GPa (or from --material)");
  cmd->add_option("--plate",
                  a->plate,
                  "Bending modulus of the strips: off (E, default) or on (E/(1 - nu^2), wide "
                  "strips; docs/plate-modulus.md)");
  cmd->add_option("--nu", a->nu, "Poisson's ratio for --plate on (default: the material's)");
  cmd->add_flag("--fatigue",
                a->fatigue,
                "Keep only designs with infinite life at --safety-factor (modified Goodman over "
                "rest -> full stroke, Howell §3.3; needs S_ut and S_e')");
  a->fatigue_flags.add_to(*cmd);
  a->yield_option = cmd->add_option(
      "--yield-strength",
      a->yield_strength,
      "Yield strength, e.g. 200ksi; designs that need more are dropped (without it each design "
      "reports the strength it needs)");
  cmd->add_option("--safety-factor", a->safety_factor, "Safety factor on the yield strength (> 0)")
      ->required();
  cmd->add_option("--length-range",
                  a->length_range,
                  "Total link length l_tot of one half, A:B or one value, e.g. 12in:15in")
      ->required();
  cmd->add_option("--width-range",
                  a->width_range,
                  "Flexure width b, A:B or one value (default free: from the force at the "
                  "thickest flexure the stress and the thickness range allow)");
  cmd->add_option("--thickness-range",
                  a->thickness_range,
                  "Flexure thickness h, A:B or one value (default free: from the force at the "
                  "widest flexure)");
  cmd->add_flag("--in-plane",
                a->in_plane,
                "Flexures of equal width (sub-classes with flag I; one-flexure classes always)");
  cmd->add_flag("--out-of-plane",
                a->out_of_plane,
                "Flexures of equal thickness (sub-classes with flag O or o)");
  a->pcf_min_option = cmd->add_option(
      "--pcf-min", a->pcf_min, "Keep sub-classes whose percent constant force Xi' >= X");
  cmd->add_option("--config",
                  a->configs,
                  "Configurations to consider (repeat or comma-separate: lpp,lps); default all")
      ->delimiter(',');
  cmd->add_option("--rank",
                  a->rank,
                  "Order of the designs: prbm (the sub-class's Xi', thesis §8.5) or exact (the "
                  "exact model's Xi' of the dimensioned design); ties by the least S_y")
      ->default_str("prbm");
  cmd->add_option("--force-of",
                  a->force_of,
                  "What --force and the reported forces are the force of: half (one half "
                  "mechanism, the thesis's F) or whole (both halves, 2 F)")
      ->default_str("half");
  cmd->add_flag("--no-exact", a->no_exact, "Skip the exact model (PRBM only, faster)");
  cmd->add_option("--model",
                  a->model,
                  "prbm (the thesis's design, checked by the exact model) or exact (also refine "
                  "the best design against the exact model: R, K1, K2 and the thicknesses; key "
                  "`refined`, and --out writes it)")
      ->default_str("prbm");
  cmd->add_option("--points", a->points, "Stroke points of the PRBM and exact strokes")
      ->default_str("50");
  cmd->add_option(
      "--out", a->out, "Write the best design as TOML that `flexure mechanism analyze` reads");
  cmd->add_option("--stress-rule",
                  a->stress_rule,
                  "computed: size and filter by the PRBM and exact stresses of each design "
                  "(axial stress and clamp moment included; every listed design meets the safety "
                  "factor by both); thesis: eq. 8.5 alone, as thesis ch. 8 (its examples)")
      ->default_str("computed");
  cmd->add_option("--minimize",
                  a->minimize,
                  "length (l_tot), footprint (plan area over the stroke) or mass (the flexures' "
                  "volume): each sub-class at its smallest feasible design in the length range, "
                  "ranked smallest first (default: the longest length, ranked by Xi')");
  cmd->add_option("--max-width-to-thickness",
                  a->max_width_to_thickness,
                  "Largest width/thickness of any flexure (foil beyond; thesis example 1 has 102)")
      ->default_str("200");
  cmd->add_option("--max-width-to-length",
                  a->max_width_to_length,
                  "Largest width of any flexure as a multiple of l_tot (no flexure wider than the "
                  "half mechanism is long)")
      ->default_str("1");
  cmd->add_option("--force-tolerance",
                  a->force_tolerance_percent,
                  "Largest difference, in %, of a design's exact mean force from --force (the "
                  "PRBM sizes the force by eq. 8.2; checked with the exact model)")
      ->default_str("10");
  cmd->add_flag("--allow-infeasible",
                a->allow_infeasible,
                "With --model exact and --out: write the refined design even when it misses the "
                "specification (marked NOT FEASIBLE in the file; the exit code stays 3)");
  cmd->add_option(
      "--drawing",
      a->drawing,
      "Also draw the design written by --out (the best) to scale: FILE.svg or FILE.dxf");
  add_csv_option(cmd, a->csv);
  cmd->add_flag("--json", a->json, "Print one JSON object");
  cmd->callback([a] { run_design_mechanism(*a); });
}

}  // namespace flexure::cli
