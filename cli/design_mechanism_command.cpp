// `flexure design mechanism`: dimensional design of a constant-force mechanism from a
// specification (mechanisms/design/mechanism_synthesis.h; Weight 2001 ch. 8; docs/design.md).
#include <fmt/format.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "flexure/io/mechanism_toml.h"
#include "flexure/io/output_path.h"
#include "flexure/io/quantity.h"
#include "flexure/mechanisms/design/mechanism_synthesis.h"
#include "flexure/mechanisms/force_of.h"
#include "flexure/solver/common/errors.h"

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
  CLI::Option* yield_option = nullptr;
  CLI::Option* pcf_min_option = nullptr;
};

design::LengthRange range_of(const std::string& text, const char* what) {
  const io::QuantityRange r = io::parse_quantity_range(text, io::Dimension::kLength, what);
  return {r.lower.si, r.upper.si};
}

design::MechanismSpec make_spec(const DesignMechanismArgs& a, mechanism::ForceOf of) {
  using io::Dimension;
  design::MechanismSpec s;
  // The specification's force is of `of`; the design equations size one half (eq. 8.2).
  s.force = io::parse_quantity(a.force, Dimension::kForce, "--force").si *
            mechanism::force_of_factor(of, mechanism::ForceOf::kOneHalf);
  s.stroke = io::parse_quantity(a.stroke, Dimension::kLength, "--stroke").si;
  const io::Quantity E = io::parse_quantity(a.E, Dimension::kStress, "--E");
  warn(io::modulus_warning(E, "--E"));
  s.E = E.si;
  if (*a.yield_option) {
    s.yield_strength =
        io::parse_quantity(a.yield_strength, Dimension::kStress, "--yield-strength").si;
  }
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
  s.validate();
  return s;
}

Json optional_json(const std::optional<double>& v) { return v ? Json(*v) : Json(nullptr); }

Json design_json(const design::DimensionedDesign& d, double force_factor) {
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
  j["yield_strength"] = d.design.yield_strength;
  j["force_prbm"] = d.force_prbm * force_factor;
  j["force_exact"] = d.force_exact ? Json(*d.force_exact * force_factor) : Json(nullptr);
  j["percent_constant_force_prbm"] = d.percent_constant_force_prbm;
  j["percent_constant_force_exact"] = optional_json(d.percent_constant_force_exact);
  j["safety_factor_prbm"] = d.safety_factor_prbm;
  j["safety_factor_exact"] = optional_json(d.safety_factor_exact);
  if (!d.exact_note.empty()) j["exact_note"] = d.exact_note;
  return j;
}

Json refined_json(const design::DimensionedDesign& d, double force_factor) {
  Json j = design_json(d, force_factor);
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

void run_design_mechanism(const DesignMechanismArgs& args) {
  const mechanism::ForceOf of = mechanism::parse_force_of(args.force_of);
  const design::MechanismSpec spec = make_spec(args, of);
  if (!args.out.empty()) io::check_output_path(args.out);
  const double factor = mechanism::force_of_factor(mechanism::ForceOf::kOneHalf, of);
  const design::MechanismDesignReport r = design::design_mechanisms(spec);
  Json rejected = Json::array();
  for (const auto& d : r.rejected) rejected.push_back(design_json(d, factor));
  if (r.designs.empty()) {
    std::string message = "design mechanism: no sub-class meets the specification";
    if (!r.rejected.empty()) {
      message += fmt::format("; the closest, {}, fails on {}",
                             r.rejected.front().subclass,
                             r.rejected.front().binding);
    } else {
      message +=
          " (no sub-class passed the filters --config, --pcf-min, --in-plane/--out-of-plane "
          "for this stroke)";
    }
    throw NoConvergenceReport(
        message, Json{{"rejected", rejected}, {"screens", screens_json(r.screens, factor)}});
  }
  // --model exact: the best design refined against the exact model (R, K1, K2 and sizes).
  std::optional<design::DimensionedDesign> refined;
  if (args.model == "exact") refined = design::refine_design_exact(spec, r.designs.front());
  if (!args.out.empty()) {
    const bool use_refined = refined && refined->feasible;
    const design::DimensionedDesign& best = use_refined ? *refined : r.designs.front();
    if (refined && !refined->feasible) {
      warn(fmt::format("--out: the refined design is not feasible ({}); writing the PRBM design",
                       refined->binding));
    }
    io::write_text_file(
        args.out,
        mechanism::mechanism_toml(
            best.design,
            fmt::format("Written by flexure design mechanism: the best of {} feasible designs, "
                        "sub-class {}{}.\nSI units. Analyse with: flexure mechanism analyze {}",
                        r.designs.size(),
                        best.subclass,
                        use_refined ? ", refined against the exact model" : "",
                        args.out)));
  }
  if (args.json) {
    Json designs = Json::array();
    for (const auto& d : r.designs) designs.push_back(design_json(d, factor));
    print_json(Json{{"designs", designs},
                    {"rejected", rejected},
                    {"screens", screens_json(r.screens, factor)},
                    {"force", spec.force * factor},
                    {"force_of", mechanism::force_of_label(of)},
                    {"stroke", spec.stroke},
                    {"safety_factor", spec.safety_factor},
                    {"ranking", args.rank},
                    {"model", args.model},
                    {"refined", refined ? refined_json(*refined, factor) : Json(nullptr)},
                    {"out", args.out.empty() ? Json(nullptr) : Json(args.out)}});
    return;
  }
  fmt::print("{} feasible design{} ({} rejected), best first; forces of {}:\n",
             r.designs.size(),
             r.designs.size() == 1 ? "" : "s",
             r.rejected.size(),
             mechanism::force_of_label(of));
  for (const auto& d : r.designs) {
    const int p = d.model.primary_pivot;
    fmt::print(
        "  {:<10} l_tot {:.4g} mm, r2 {:.4g} mm, r3 {:.4g} mm, primary h {:.4g} mm, b {:.4g} mm; "
        "S_y needed {:.4g} MPa; F {:.4g} N (exact {}), Xi' {:.1f} % (exact {})\n",
        d.subclass,
        d.l_tot * 1e3,
        d.r2 * 1e3,
        d.r3 * 1e3,
        d.thickness[p - 1] * 1e3,
        d.width[p - 1] * 1e3,
        d.required_yield_strength * 1e-6,
        d.force_prbm * factor,
        d.force_exact ? fmt::format("{:.4g} N", *d.force_exact * factor) : "n/a",
        d.model.percent_constant_force,
        d.percent_constant_force_exact ? fmt::format("{:.1f} %", *d.percent_constant_force_exact)
                                       : "n/a");
  }
  const design::DimensionedDesign& best = r.designs.front();
  if (best.safety_factor_exact && *best.safety_factor_exact < spec.safety_factor) {
    warn(fmt::format(
        "{}: eq. 8.5 leaves out the axial and clamp stresses; by the exact stresses its safety "
        "factor is {:.3g}, not {:g} (S_y >= {:.4g} MPa would give it)",
        best.subclass,
        *best.safety_factor_exact,
        spec.safety_factor,
        best.required_yield_strength_exact.value_or(0.0) * 1e-6));
  }
  if (refined) {
    const design::DimensionedDesign& x = *refined;
    if (x.feasible) {
      fmt::print(
          "refined against the exact model: R {:.4f}, K1 {:.4f}, K2 {:.4f}; r2 {:.4g} mm, r3 "
          "{:.4g} mm, primary h {:.4g} mm; exact F {:.4g} N, Xi' {:.1f} % (was {:.1f} %), S_y "
          "needed {:.4g} MPa ({} exact strokes)\n",
          x.model.R,
          x.model.K1,
          x.model.K2,
          x.r2 * 1e3,
          x.r3 * 1e3,
          x.thickness[x.model.primary_pivot - 1] * 1e3,
          x.force_exact.value_or(0.0) * factor,
          x.percent_constant_force_exact.value_or(0.0),
          best.percent_constant_force_exact.value_or(0.0),
          x.required_yield_strength_exact.value_or(0.0) * 1e-6,
          x.exact_evaluations);
    } else {
      fmt::print("refined against the exact model: not feasible: {}\n", x.binding);
    }
  }
  if (!args.out.empty()) fmt::print("wrote {}\n", args.out);
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
  cmd->add_option("--E", a->E, "Young's modulus, e.g. 30Msi or 200GPa")->required();
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
  cmd->add_flag("--json", a->json, "Print one JSON object");
  cmd->callback([a] { run_design_mechanism(*a); });
}

}  // namespace flexure::cli
