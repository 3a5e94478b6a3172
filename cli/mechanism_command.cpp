// `flexure mechanism list | analyze NAME|FILE.toml | validate`: dimensional constant-force slider
// mechanisms computed with the PRBM and with the exact model (docs/mechanisms.md).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "cli/beam_methods.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/csv_output.h"
#include "cli/fatigue_flags.h"
#include "cli/general_mechanism_command.h"
#include "cli/mechanism_argument.h"
#include "cli/mechanism_geometry_output.h"
#include "cli/modulus_output.h"
#include "cli/slow_progress.h"
#include "cli/warning_output.h"
#include "flexure/benchmarks/studies/mechanism_tolerance.h"
#include "flexure/io/mechanism_stroke_file.h"
#include "flexure/io/mechanism_validation_file.h"
#include "flexure/io/platform/mpi_world.h"
#include "flexure/io/platform/output_path.h"
#include "flexure/io/toml_files.h"
#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/general/catalogue_general.h"
#include "flexure/mechanisms/inversion.h"
#include "flexure/mechanisms/materials_fatigue.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/mechanisms/mechanism_catalogue.h"
#include "flexure/mechanisms/mechanism_exact.h"
#include "flexure/mechanisms/mechanism_plate.h"
#include "flexure/mechanisms/mechanism_validation.h"
#include "flexure/mechanisms/mechanism_warnings.h"
#include "flexure/mechanisms/modified_springs.h"
#include "flexure/solver/common/section.h"
#include "flexure/solver/common/status.h"

namespace flexure::cli {
namespace {

using namespace flexure::mechanism;

const char* pivot_letter(PivotType t) {
  return t == PivotType::kPin ? "p" : t == PivotType::kSmall ? "s" : "l";
}

Json or_null(bool present, double value) { return present ? Json(value) : Json(nullptr); }

// --plate and --nu of mechanism analyze over the design's own (file or material) values.
void apply_plate_flags(MechanismDesign& d, const std::string& plate, const std::string& nu) {
  if (!nu.empty()) {
    const io::Quantity q = io::parse_quantity(nu, io::Dimension::kAngle, "--nu");
    if (q.has_unit()) throw InvalidInput("--nu is a plain number without a unit");
    d.set_nu(q.si);
  }
  if (!plate.empty()) d.plate = plate_rule_from_string(plate, "--plate");
  // With plate on or auto the modulus choice checks nu; off, finalise() would refuse it as the
  // design's Material::nu: named here by the flag the user wrote.
  if (!nu.empty() && d.plate == PlateRule::kOff &&
      !(std::isfinite(d.material.nu) && d.material.nu > -1.0 && d.material.nu < 0.5)) {
    throw InvalidInput(fmt::format("--nu must be finite and in (-1, 0.5) (got {})", d.material.nu));
  }
  if (d.plate != PlateRule::kOff && !d.nu_given) {
    throw InvalidInput(
        fmt::format("--plate {} needs Poisson's ratio: give --nu (the design '{}' has none{})",
                    to_string(d.plate),
                    d.name,
                    d.material_id.empty() ? "" : ", nor has its material row"));
  }
}

// Per-pivot values in the DESCRIBED pivot order (inversions: pivot 1 at the fixed slider block).
Json pivot_array(const MechanismDesign& d, const std::array<double, 3>& v, bool present = true) {
  const DescribedDesign m = described_form(d);
  const std::array<double, 3> w = to_described(d, v);
  Json a = Json::array();
  for (int i = 0; i < 3; ++i) {
    a.push_back(present && m.joints[i].type != PivotType::kPin ? Json(w[i]) : Json(nullptr));
  }
  return a;
}

std::vector<int> described_pivots(const MechanismDesign& d, const std::vector<int>& pivots) {
  std::vector<int> out;
  for (int p : pivots) out.push_back(described_pivot(d, p));
  std::sort(out.begin(), out.end());
  return out;
}

Json design_json(const MechanismDesign& d) {
  const DescribedDesign m = described_form(d);
  Json joints = Json::array();
  for (int p = 1; p <= 3; ++p) {
    // Output in the described (mirrored for an inversion) numbering.
    const int stored = described_pivot(d, p);
    const JointDesign& j = m.joints[p - 1];
    Json jj = j.type == PivotType::kPin ? Json{{"type", "p"}}
                                        : Json{{"type", pivot_letter(j.type)},
                                               {"length", j.length},
                                               {"thickness", j.thickness},
                                               {"width", j.width}};
    if (j.type != PivotType::kPin) {
      jj["segment"] = j.segment == SegmentKind::kFixedFixed ? "fixed-fixed"
                      : j.type == PivotType::kLong          ? "fixed-pinned"
                                                            : "small-length";
      jj["spring_constant"] = d.spring_constant(stored);
      if (j.segment == SegmentKind::kFixedFixed) {
        jj["paper_letter"] = std::string(1, j.paper_letter);
      }
    }
    joints.push_back(jj);
  }
  Json out{
      {"name", d.name},
      {"paper_config", d.paper_config.empty() ? Json(nullptr) : Json(d.paper_config)},
      {"spring_rule", has_fixed_fixed(d) ? Json(spring_rule_name(d.spring_rule)) : Json(nullptr)},
      {"config", m.config},
      {"class", d.configuration().class_name},
      {"r2", m.r2},
      {"r3", m.r3},
      {"E", d.modulus.empty() ? d.material.E : d.modulus.front().E},
      {"yield_strength", d.material.yield_strength.value_or(0.0)},
      {"stroke", d.stroke},
      {"toggle_stroke", d.toggle_stroke()},
      {"joints", joints},
      {"note", d.note},
      {"inverted", d.inverted},
      {"fixed_body", m.fixed_body}};
  if (d.inverted) out["inversion_of_config"] = d.config;
  return out;
}

// The PRBM's validity over the stroke (mechanism_analysis.h): what is outside Table 5.1, where, and
// the PRBM's force error there (null where the exact model was not solved).
Json validity_json(const PrbmStrokeValidity& v, double stroke) {
  const auto number = [](double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); };
  Json j;
  j["table"] = v.has_table ? Json("Howell Table 5.1") : Json(nullptr);
  j["no_table"] = v.has_table ? Json(nullptr) : Json(v.no_table);
  j["points"] = v.inside.size();
  j["points_outside"] = v.points_outside;
  j["limit"] = v.limit ? Json(*v.limit) : Json(nullptr);
  j["pivot"] = v.first_outside ? Json(v.pivot) : Json(nullptr);
  j["quantity"] = v.first_outside ? Json(v.quantity) : Json(nullptr);
  j["value"] = v.first_outside ? Json(v.value) : Json(nullptr);
  j["unit"] = v.first_outside ? Json(v.unit) : Json(nullptr);
  j["table_range"] = v.first_outside ? Json::array({v.table_min, v.table_max}) : Json(nullptr);
  Json ranges = Json::array();
  for (const auto& [first, last] : v.outside_ranges) ranges.push_back(Json::array({first, last}));
  j["outside_ranges"] = std::move(ranges);
  j["force_error_at_limit"] = number(v.force_error_at_limit);
  j["max_force_error_outside"] = number(v.max_force_error_outside);
  j["max_force_error_inside"] = number(v.max_force_error_inside);
  j["summary"] = describe_validity(v, stroke);
  return j;
}

// One model's verdicts under one control as parallel arrays (status.h names; JSON keys of
// docs/cli.md "flexure mechanism"), with the stretches in words.
Json stroke_stability_json(const StrokeStability& s) {
  Json kinds = Json::array(), index = Json::array(), margin = Json::array();
  Json not_checked = Json::array();  // {point, reason} where no verdict could be computed
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const Stability& v = s.points[i];
    kinds.push_back(std::string(stability_name(v.kind)));
    index.push_back(v.index);
    margin.push_back(v.margin);
    if (!v.judged()) not_checked.push_back(Json{{"point", i}, {"reason", v.message}});
  }
  return Json{{"stability", kinds},
              {"stability_index", index},
              {"stability_margin", margin},
              {"unstable_points", s.unstable_points},
              {"critical_points", s.critical_points},
              {"not_checked_points", s.not_checked_points},
              {"least_margin",
               static_cast<int>(s.points.size()) > s.not_checked_points ? Json(s.least_margin)
                                                                        : Json(nullptr)},
              {"not_checked", not_checked},
              {"summary", s.summary}};
}

Json analysis_json(const MechanismAnalysis& a) {
  const bool exact = a.has_exact && a.exact.converged();
  Json j;
  j["design"] = design_json(a.design);
  j["units"] = "SI: m, N, Pa";
  // The bending modulus solved with (docs/plate-modulus.md); design.E is the modulus as given.
  if (!a.design.modulus.empty()) add_modulus_json(j, a.design.modulus);
  // What force_prbm, force_exact and the mean forces are the force of (mechanism.h).
  j["force_of"] = force_of_label(a.force_of);
  j["spring_rule"] =
      has_fixed_fixed(a.design) ? Json(spring_rule_name(a.design.spring_rule)) : Json(nullptr);
  j["displacement"] = a.prbm.displacement;
  j["force_prbm"] = a.prbm.force;
  j["force_exact"] = exact ? Json(a.force_exact) : Json(nullptr);
  j["exact_model"] = a.has_exact;
  j["exact_note"] = a.exact_note;
  j["percent_constant_force_prbm"] = a.prbm.percent_constant_force;
  j["percent_constant_force_exact"] = or_null(exact, a.percent_constant_force_exact);
  // A force that is zero or changes sign within the stroke: the percentages above are then 0
  // (constant_force.h; docs/mechanisms.md "Percent constant force"). force_vanishes is the name
  // `flexure cfm` uses; it and force_changes_sign cover both models.
  j["force_vanishes"] = a.prbm.force_vanishes || (exact && a.force_vanishes_exact);
  j["force_changes_sign"] = a.prbm.force_changes_sign || (exact && a.force_changes_sign_exact);
  j["force_vanishes_prbm"] = a.prbm.force_vanishes;
  j["force_changes_sign_prbm"] = a.prbm.force_changes_sign;
  j["force_vanishes_exact"] = exact ? Json(a.force_vanishes_exact) : Json(nullptr);
  j["force_changes_sign_exact"] = exact ? Json(a.force_changes_sign_exact) : Json(nullptr);
  j["mean_force_prbm"] = a.prbm.mean_force;
  j["mean_force_exact"] = or_null(exact, a.mean_force_exact);
  j["max_force_error"] = or_null(exact, a.max_force_error);
  j["max_force_error_at"] = or_null(exact, a.max_force_error_at);
  j["prbm_validity_limit"] = a.prbm_validity_limit ? Json(*a.prbm_validity_limit) : Json(nullptr);
  j["prbm_validity_reason"] = a.prbm_validity_reason;
  j["prbm_validity"] = validity_json(a.prbm_validity, a.design.stroke);
  j["prbm_within_validity"] = a.prbm_validity.inside;
  j["max_stress"] = a.max_stress_all;
  j["max_stress_per_pivot"] = pivot_array(a.design, a.max_stress);
  j["max_stress_prbm"] = pivot_array(a.design, a.prbm.max_stress);
  // null (not 0) where the exact stresses were not computed (validate skips them).
  j["max_stress_exact"] = pivot_array(a.design, a.max_stress_exact, exact && a.has_exact_stress);
  j["safety_factor"] = a.safety_factor;
  j["yielding_pivots"] = described_pivots(a.design, a.yielding_pivots);
  // Per stroke point, under each way of driving the slider (docs/stability.md "Mechanisms"):
  // {"prbm": {...}, "exact": {...} or null}; absent when not computed.
  for (const StrokeStabilityEntry& e : stroke_stability_entries(a)) {
    j[std::string("stability_") + e.control][e.model] =
        e.stroke != nullptr ? stroke_stability_json(*e.stroke) : Json(nullptr);
  }
  return j;
}

// Why a percent constant force was reported as 0, or empty (constant_force.h).
std::string force_sign_note(bool vanishes, bool changes_sign) {
  return changes_sign ? "force changes sign" : vanishes ? "force vanishes" : "";
}

Json number_or_null(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

// The keys beside the static safety factor: fatigue_safety_factor, alternating_stress,
// mean_stress, endurance_limit (the corrected S_e of the critical pivot), and the details.
void add_fatigue_json(Json& j,
                      const MechanismAnalysis& a,
                      const MechanismFatigueReport& r,
                      const std::string& note) {
  if (!r.fatigue) {
    for (const char* key :
         {"fatigue_safety_factor", "alternating_stress", "mean_stress", "endurance_limit"}) {
      j[key] = nullptr;
    }
    j["fatigue"] = nullptr;
    j["fatigue_note"] = note;
    return;
  }
  const MechanismFatigue& f = *r.fatigue;
  const PivotFatigue& c = f.critical();
  j["fatigue_safety_factor"] = number_or_null(c.check.safety_factor);
  j["alternating_stress"] = c.check.alternating_stress;
  j["mean_stress"] = c.check.mean_stress;
  j["endurance_limit"] = c.check.endurance_limit;
  Json pivots = Json::array();
  for (int p = 1; p <= 3; ++p) {
    const int stored = described_pivot(a.design, p);
    const PivotFatigue& x = f.pivots[stored - 1];
    if (!x.present) {
      pivots.push_back(nullptr);
      continue;
    }
    pivots.push_back(Json{{"safety_factor", number_or_null(x.check.safety_factor)},
                          {"alternating_stress", x.check.alternating_stress},
                          {"mean_stress", x.check.mean_stress},
                          {"sigma_max", x.check.sigma_max},
                          {"sigma_min", x.check.sigma_min},
                          {"endurance_limit", x.check.endurance_limit},
                          {"equivalent_diameter", x.equivalent_diameter},
                          {"c_size", x.strength.factors.size},
                          {"moment_changes_sign", x.moment_changes_sign}});
  }
  j["fatigue"] =
      Json{{"critical_pivot", described_pivot(a.design, f.critical_pivot)},
           {"cycle", "rest (unstressed) to full stroke and back"},
           {"criterion", "modified Goodman (Howell eq. 3.110)"},
           {"infinite_life", c.check.infinite_life && !f.material.fatigue_cycles},
           {"life_at_least",
            f.material.fatigue_cycles && c.check.infinite_life ? Json(*f.material.fatigue_cycles)
                                                               : Json(nullptr)},
           {"cycles_to_failure", number_or_null(c.check.cycles_to_failure)},
           {"yield_safety_factor",
            c.check.yield_safety_factor ? Json(*c.check.yield_safety_factor) : Json(nullptr)},
           {"ultimate_strength", f.material.ultimate_strength},
           {"uncorrected_endurance_limit", f.material.uncorrected_strength},
           {"fatigue_cycles",
            f.material.fatigue_cycles ? Json(*f.material.fatigue_cycles) : Json(nullptr)},
           {"endurance_limit_source", f.material.source},
           {"surface_finish", surface_finish_name(f.options.finish)},
           {"reliability", f.options.reliability},
           {"K_f", f.options.K_f},
           {"c_surf", c.strength.factors.surface},
           {"c_size", c.strength.factors.size},
           {"c_load", c.strength.factors.load},
           {"c_reliab", c.strength.factors.reliability},
           {"c_misc", c.strength.factors.misc},
           {"pivots", pivots}};
  j["fatigue_note"] = nullptr;
}

// The fatigue line of analyze's text: the check (fatigue_summary), or why there is none.
std::string fatigue_text(const MechanismAnalysis& a,
                         const MechanismFatigueReport& r,
                         const std::string& note) {
  if (!r.fatigue) return fmt::format("  fatigue: not checked: {}\n", note);
  return fmt::format("  {}\n", fatigue_summary(a.design, *r.fatigue));
}

std::string percent(double v) { return fmt::format("{:.2f}", 100.0 * v); }

// One design of `mechanism validate`: its JSON object and its Markdown line (the row itself:
// mechanisms/mechanism_validation.h).
std::vector<std::string> format_validation_row(const MechanismValidationRow& row) {
  const MechanismAnalysis& a = row.analysis;
  const MechanismDesign& d = a.design;
  const bool exact = row.exact;
  const std::optional<ChainCheck>& check = row.chain_check;
  const std::string limit =
      a.prbm_validity_limit ? fmt::format("{:.0f}", 100.0 * *a.prbm_validity_limit / d.stroke)
      : has_fixed_fixed(d)  ? std::string("none (fixed-fixed segments: no Theta_max table)")
                            : std::string("never (s pivots only, or within Table 5.1)");
  // A percentage of a force that vanishes is 0 by definition (constant_force.h): say so in the
  // cell, and leave out the difference, which would compare a definition with a ratio.
  const std::string prbm_note = force_sign_note(a.prbm.force_vanishes, a.prbm.force_changes_sign);
  const std::string exact_note =
      exact ? force_sign_note(a.force_vanishes_exact, a.force_changes_sign_exact) : "";
  auto pcf_cell = [](double v, const std::string& note) {
    return note.empty() ? fmt::format("{:.2f}", v) : fmt::format("{:.2f} ({})", v, note);
  };
  // Unstable stroke points (docs/stability.md "Mechanisms"): exact with the slider held, exact
  // under a dead load, PRBM under a dead load (held, the PRBM linkage cannot move).
  const bool exact_stability = row.exact_stability;
  const std::string unstable_cell =
      a.stability_prbm.force_control.points.empty()
          ? std::string("-")
          : fmt::format("{} / {} / {}",
                        exact_stability
                            ? std::to_string(a.stability_exact.displacement_control.unstable_points)
                            : std::string("-"),
                        exact_stability
                            ? std::to_string(a.stability_exact.force_control.unstable_points)
                            : std::string("-"),
                        a.stability_prbm.force_control.unstable_points);
  std::string line = fmt::format(
      "| {} | {} | {} | {} | {} | {} | {} | {} | {:.2f} | {} | {} |\n",
      d.name,
      a.has_exact ? (exact ? "yes" : "did not converge") : "PRBM only",
      pcf_cell(a.prbm.percent_constant_force, prbm_note),
      exact ? pcf_cell(a.percent_constant_force_exact, exact_note) : "-",
      exact && prbm_note.empty() && exact_note.empty()
          ? fmt::format("{:+.2f}", a.prbm.percent_constant_force - a.percent_constant_force_exact)
          : "-",
      exact ? percent(a.max_force_error) : "-",
      exact ? fmt::format("{:.0f}", 100.0 * a.max_force_error_at / d.stroke) : "-",
      limit,
      a.safety_factor,
      check ? (check->converged() ? fmt::format("{:.1e}", check->tip_error / d.r2)
                                  : std::string("did not converge"))
            : std::string("-"),
      unstable_cell);
  Json r = analysis_json(a);
  // The per-point arrays stay in `analyze`; the table keeps the counts, least margin and summary.
  for (const char* control : {"stability_displacement_control", "stability_force_control"}) {
    if (!r.contains(control)) continue;
    for (auto& [model, v] : r[control].items()) {
      if (v.is_null()) continue;
      v.erase("stability");
      v.erase("stability_index");
      v.erase("stability_margin");
    }
  }
  if (check) {
    r["chain_check_converged"] = check->converged();
    r["chain_check_tip_error"] = check->converged() ? Json(check->tip_error) : Json(nullptr);
    r["chain_check_closure_error"] =
        check->converged() ? Json(check->closure_error) : Json(nullptr);
    r["chain_check_elements"] = row.chain_check_elements;
    r["chain_check_at"] = a.exact.points.back().displacement;
  }
  r.erase("displacement");
  r.erase("force_prbm");
  r.erase("force_exact");
  r.erase("prbm_within_validity");
  return {r.dump(), std::move(line)};
}

void print_validation(const MechanismValidationOptions& options,
                      bool json,
                      DesignSet set,
                      const std::string& out,
                      const std::string& csv_path) {
  // --out: created before any design is analysed (a wrong path fails at once); under mpirun every
  // rank writes the designs it analysed into the one file (docs/scaling.md).
  // --csv (or --out FILE.csv): the table of the file as CSV, one row per design (cli/csv_output.h).
  if (!out.empty()) io::check_output_path(out);
  const CsvOutput csv(out, csv_path);
  const std::vector<io::FormattedValidationRow> rows =
      io::validate_mechanisms(set, options, csv.hdf5_path(), format_validation_row);
  if (!csv.hdf5_path().empty()) csv.write({"name"});
  if (!parallel::world().root()) return;
  std::string table =
      "| Mechanism | Exact model | Xi' PRBM % | Xi' exact % | Xi' error (points) | max force "
      "error % | at Delta x / stroke % | PRBM validity limit (Delta x / stroke %) | SF | chain "
      "check tip error / r2 | unstable points: exact held / exact dead load / PRBM dead load |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|\n";
  Json objects = Json::array();
  for (const io::FormattedValidationRow& row : rows) {
    objects.push_back(Json::parse(row.texts.at(0)));
    table += row.texts.at(1);
    warn(row.warnings);
  }
  if (json) {
    print_json(Json{{"points", options.points}, {"mechanisms", objects}});
  } else {
    std::cout << table;
  }
}

// `validate --spring-rules`: the spring rules of the fixed-fixed segments against the exact model
// (docs/validation.md "Modified configurations").
void print_spring_rules(int points, bool json) {
  auto ratio = [](const std::optional<double>& v) {
    return v ? fmt::format("{:.3f}", *v) : std::string("-");
  };
  auto ratios = [&](const std::array<std::optional<double>, 3>& r) {
    return fmt::format("{} / {} / {}", ratio(r[0]), ratio(r[1]), ratio(r[2]));
  };
  std::string table =
      "| Mechanism | max force error %: pure-bending | table2 | table5 | mean F_prbm/F_exact: "
      "pure-bending | table2 | table5 | fitted c (k = c EI/L) | error % with c | k_eq/(EI/L) "
      "pivots 1/2/3, first point | last point |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|\n";
  Json rows = Json::array();
  for (const MechanismDesign& d : modified_designs()) {
    const SpringRuleComparison c = compare_spring_rules(d, points);
    if (!c.converged()) throw NoConvergence(fmt::format("{}: {}", d.name, c.message));
    table += fmt::format(
        "| {} | {:.2f} | {:.2f} | {:.2f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | "
        "{:.2f} | {} | {} |\n",
        d.name,
        100.0 * c.max_force_error[0],
        100.0 * c.max_force_error[1],
        100.0 * c.max_force_error[2],
        c.mean_force_ratio[0],
        c.mean_force_ratio[1],
        c.mean_force_ratio[2],
        c.fitted_factor,
        100.0 * c.fitted_max_error,
        ratios(c.k_ratio_start),
        ratios(c.k_ratio_end));
    auto opt = [](const std::array<std::optional<double>, 3>& r) {
      Json a = Json::array();
      for (const auto& v : r) a.push_back(v ? Json(*v) : Json(nullptr));
      return a;
    };
    rows.push_back(Json{{"name", d.name},
                        {"rules", {"pure-bending", "table2", "table5"}},
                        {"max_force_error", c.max_force_error},
                        {"mean_force_ratio", c.mean_force_ratio},
                        {"fitted_factor", c.fitted_factor},
                        {"fitted_max_error", c.fitted_max_error},
                        {"k_equivalent_ratio_first", opt(c.k_ratio_start)},
                        {"k_equivalent_ratio_last", opt(c.k_ratio_end)}});
  }
  if (json) {
    print_json(Json{{"points", points}, {"spring_rules", rows}});
  } else {
    std::cout << table;
  }
}

}  // namespace

void register_mechanism_command(CLI::App& app) {
  CLI::App& mech = get_or_add_subcommand(
      app, "mechanism", "Constant-force slider mechanisms: PRBM and exact model of one design");
  mech.require_subcommand(1);

  auto list_json = std::make_shared<bool>(false);
  CLI::App* list = mech.add_subcommand("list", "List the built-in mechanism designs");
  list->add_flag("--json", *list_json, "Print one JSON object");
  list->callback([list_json] {
    Json all = Json::array();
    for (const auto& d : mechanism_designs(DesignSet::kAll)) {
      if (*list_json) {
        Json j = design_json(d);
        j["exact_model"] = exact_support(d) != ExactSupport::kPrbmOnly;
        all.push_back(j);
      } else {
        const DescribedDesign m = described_form(d);
        std::cout << fmt::format("{:8} r2 = {:.4g} m, r3 = {:.4g} m, stroke {:.4g} m{}  -- {}\n",
                                 d.name,
                                 m.r2,
                                 m.r3,
                                 d.stroke,
                                 exact_support(d) == ExactSupport::kPrbmOnly ? " (PRBM only)" : "",
                                 d.note);
      }
    }
    if (*list_json) print_json(Json{{"mechanisms", all}});
  });

  struct AnalyzeArgs {
    std::string what;
    int points = 50;
    std::string out;
    std::string csv;
    bool json = false;
    bool no_exact = false;
    std::string method = "auto";
    double tol = 1e-6;
    CLI::Option* tol_option = nullptr;
    std::string spring_rule;
    std::string force_of = "half";
    CLI::Option* force_of_option = nullptr;
    std::string model;           // general mechanism files only
    std::string input_range;     // general mechanism files only
    std::string flexure_models;  // --model mixed
    double flexure_tol = 0.0;
    bool check_flexures = false;
    std::string material;
    std::string plate, nu;  // the bending modulus (docs/plate-modulus.md)
    FatigueFlags fatigue;
    bool stable = false;
  };
  auto args = std::make_shared<AnalyzeArgs>();
  CLI::App* analyze = mech.add_subcommand(
      "analyze", "Force-deflection over the stroke, PRBM and exact, with stresses");
  analyze
      ->add_option("mechanism",
                   args->what,
                   "Built-in name (1A-lpp, 3A-sss, howell-1A-spp-b, ...), a thesis sub-class "
                   "(lpp-b), an inversion (1A-lpp' or 1A-lpp-inv) or FILE.toml")
      ->required();
  analyze->add_option("--points", args->points, "Stroke points (2..100000)")->default_str("50");
  analyze->add_option("--out", args->out, "Write the curves to this HDF5 file (atomic)");
  add_csv_option(analyze, args->csv);
  analyze->add_flag("--json", args->json, "Print one JSON object");
  analyze->add_flag("--prbm-only", args->no_exact, "Skip the exact model (= --method prbm)");
  analyze
      ->add_option("--method",
                   args->method,
                   "auto (PRBM alone when its measured force error x1.5 is within --tol), prbm, "
                   "exact (PRBM and exact)")
      ->default_str("auto")
      ->transform(CLI::IsMember({"auto", "prbm", "exact"}, CLI::ignore_case));
  args->tol_option =
      analyze->add_option("--tol", args->tol, "Relative force error allowed by --method auto")
          ->default_str("1e-6");
  analyze->add_option("--spring-rule",
                      args->spring_rule,
                      "Spring constant of fixed-fixed segments (modified designs): pure-bending "
                      "(k = EI/L, default), table2, table5 (paper 004 Tables 2/5)");
  args->force_of_option =
      analyze
          ->add_option("--force-of",
                       args->force_of,
                       "Forces of one half of the symmetric mechanism (the model's half) or of "
                       "the whole mechanism (two halves on one slider, = 2 x half), as dynamics "
                       "reports; default half, or the design file's force_of")
          ->default_str("half");
  analyze
      ->add_option(
          "--model",
          args->model,
          "General mechanism files ([[body]] form): prbm (default), exact (each flexure an "
          "elastica), both, or mixed (each flexure its own model: the file's model keys, "
          "--flexure-model); mixed also takes a built-in design (its general form)")
      ->transform(CLI::IsMember({"prbm", "exact", "both", "mixed"}, CLI::ignore_case));
  analyze->add_option("--flexure-model",
                      args->flexure_models,
                      "--model mixed: the model of every flexure (exact, prbm, linear, bcm, "
                      "prbm3r, cbcm, chain, auto; cbcm and chain take the file's elements, "
                      "default 6 and 100) or of named ones, NAME=MODEL,... (built-in designs: "
                      "f1, f2, f3 by pivot)");
  analyze->add_option("--flexure-tol",
                      args->flexure_tol,
                      "--model mixed: auto's tolerance, the largest mapped tip error per length "
                      "of a flexure (e.g. 1e-3)");
  analyze->add_flag("--check-flexures",
                    args->check_flexures,
                    "--model mixed: measure each flexure's model against the exact elastica "
                    "under the loads it carries (measured_error_per_length)");
  analyze->add_option("--input",
                      args->input_range,
                      "General mechanism files: the input range START:STOP:COUNT with units "
                      "(\"-5deg:33deg:77\"), replacing the file's [input] range");
  analyze->add_option("--material",
                      args->material,
                      "Material from the library (`flexure materials`): replaces the design's E, "
                      "S_y and gives S_ut, S_e' for the fatigue check");
  analyze->add_option("--plate",
                      args->plate,
                      "Bending modulus of the strips: off (E, default), on (E/(1 - nu^2)), auto "
                      "(by the Searle parameter b^2/(R h); docs/plate-modulus.md)");
  analyze->add_option(
      "--nu", args->nu, "Poisson's ratio for --plate (default: the material's, [material].nu)");
  analyze->add_flag("--stable",
                    args->stable,
                    "Exact model: where the stroke from the PRBM start is unstable with the "
                    "slider held, follow a stable branch instead (serial chains; the JSON's "
                    "stable_search says what was done). A general mechanism file: at every "
                    "input the equilibrium stable under its control (exit 3 where none is found)");
  args->fatigue.add_to(*analyze);
  analyze->callback([args, analyze] {
    require_in_range(args->points, "--points", 2, 100000);
    const bool general_file = is_general_mechanism_file(args->what);
    if (general_file || args->model == "mixed") {
      GeneralAnalyzeRequest request;
      request.file = args->what;
      request.model = args->model;
      request.input_range = args->input_range;
      request.out = args->out;
      request.csv = args->csv;
      request.json = args->json;
      request.points = analyze->count("--points") > 0 ? args->points : 0;
      request.flexure_models = args->flexure_models;
      request.flexure_tol = args->flexure_tol;
      request.check_flexures = args->check_flexures;
      request.stable = args->stable;
      if (!general_file) {
        // A constant-force design in its general form (catalogue_general.h).
        const MechanismDesign d = mechanism_design_argument(args->what);
        request.mechanism = mechanism::general::general_from_design(d, args->points);
        request.design_x0 =
            request.mechanism->input.start + stroke_displacements(d, args->points).front();
        request.points = 0;
      }
      // A general file takes only these; every other option of analyze belongs to the
      // constant-force designs (their method, material, fatigue, output options) and is refused
      // by name, so an option added to that form later is refused here without being listed.
      // Option groups (the fatigue options) are nameless sub-apps holding their own options.
      std::vector<const CLI::App*> holders = {analyze};
      for (const CLI::App* group :
           analyze->get_subcommands([](CLI::App* a) { return a->get_name().empty(); })) {
        holders.push_back(group);
      }
      for (const CLI::App* holder : holders) {
        for (const CLI::Option* option : holder->get_options()) {
          const std::string name = option->get_name();
          if (option->count() == 0 || option->get_positional() || name == "--points" ||
              name == "--json" || name == "--model" || (general_file && name == "--input") ||
              name == "--out" || name == "--csv" || name == "--flexure-model" ||
              name == "--flexure-tol" || name == "--check-flexures" ||
              (general_file && name == "--stable") || name == "--help") {
            continue;
          }
          if (request.foreign_flag.empty()) request.foreign_flag = name;
        }
      }
      analyze_general_mechanism(request);
      return;
    }
    if (!args->model.empty() || !args->input_range.empty()) {
      throw InvalidInput(std::string(args->model.empty() ? "--input" : "--model") +
                         " applies to general mechanism files ([[body]] form, docs/mechanisms.md "
                         "\"General mechanisms\") and, as --model mixed, to a design in its "
                         "general form; the constant-force designs take --method and --points");
    }
    if (!args->flexure_models.empty() || args->flexure_tol != 0.0 || args->check_flexures) {
      throw InvalidInput(
          "--flexure-model, --flexure-tol and --check-flexures apply to --model mixed (a model "
          "per flexure)");
    }
    if (args->no_exact && args->method == "exact") {
      throw InvalidInput("--prbm-only (= --method prbm) contradicts --method exact; give one");
    }
    if (!args->out.empty()) io::check_output_path(args->out);
    const CsvOutput csv(args->out, args->csv);
    MechanismDesign d = mechanism_design_argument(args->what);
    if (!args->spring_rule.empty()) apply_spring_rule(d, parse_spring_rule(args->spring_rule));
    if (!args->material.empty()) apply_material_flag(d, args->material);
    apply_plate_flags(d, args->plate, args->nu);
    args->fatigue.apply_strengths(d);
    const FatigueOptions fatigue_options = args->fatigue.options();
    // A design file's force_of (written by `flexure design mechanism`) unless --force-of is given.
    const ForceOf force_of =
        *args->force_of_option || !d.force_of ? parse_force_of(args->force_of) : *d.force_of;
    std::optional<io::MechanismStrokeFile> file;
    if (!csv.hdf5_path().empty()) file.emplace(csv.hdf5_path());
    refuse_tol_with_named_method(args->tol_option, args->no_exact ? "prbm" : args->method);
    const MechanismMethodChoice choice = [&] {
      try {
        return choose_mechanism_method(
            d,
            args->no_exact ? MechanismMethod::kPrbm : mechanism_method_from_string(args->method),
            args->tol);
      } catch (const bench::ToleranceBelowReach& e) {
        refuse_tolerance_below_reach(e, args->tol);
      }
    }();
    AnalysisOptions o;
    o.points = args->points;
    o.exact = choice.exact;
    o.stable = args->stable;
    o.progress = stoppable_progress(d.name + ": exact model, stroke points and stresses");
    MechanismAnalysis a = analyze_mechanism_with_modulus(d, o);
    report_forces_of(a, force_of);
    if (!a.converged()) throw NoConvergence(a.message);
    warn(a.warnings);  // yield, vanishing force, stability (analysis_warnings)
    const MechanismFatigueReport fatigue = mechanism_fatigue_report(a, fatigue_options);
    warn(fatigue.warnings);  // a finite life
    // Why there is no fatigue check, with the flags that give the missing strengths.
    const std::string fatigue_note = fatigue.fatigue
                                         ? std::string()
                                         : fmt::format(
                                               "{}; give --material NAME (`flexure materials`) or "
                                               "--ultimate-strength and --endurance-limit",
                                               fatigue.not_checked);
    // What --stable did (JSON `stable_search`, HDF5 attribute); empty without --stable.
    const std::string stable_search = !args->stable              ? std::string()
                                      : !a.stable_search.empty() ? a.stable_search
                                      : !(a.has_exact && o.exact)
                                          ? std::string("not done: the exact model did not run")
                                          : std::string();
    if (file) {
      file->write(a, fatigue.fatigue ? &*fatigue.fatigue : nullptr, args->stable, stable_search);
    }
    csv.write({"displacement"}, {"design", "shapes"});  // /shapes: per stored shape, not per point
    if (args->json) {
      Json j = analysis_json(a);
      add_fatigue_json(j, a, fatigue, fatigue_note);
      j["method"] = to_string(choice.method);
      j["method_reason"] = choice.reason;
      j["stable"] = args->stable;
      j["stable_search"] = !stable_search.empty() ? Json(stable_search) : Json(nullptr);
      j["geometry"] = geometry_json(mechanism_geometry(d));
      print_json(j);
      return;
    }
    std::cout << fmt::format("{} ({}): {}\n",
                             d.name,
                             d.paper_config.empty() ? described_form(d).config
                                                    : d.paper_config + ", solved as " + d.config,
                             d.note);
    std::cout << fmt::format("  method: {} ({})\n", to_string(choice.method), choice.reason);
    if (args->stable) {
      std::cout << fmt::format(
          "  --stable: {}\n",
          a.stable_search.empty() ? "not done: the exact model did not run" : a.stable_search);
    }
    auto note = [](bool vanishes, bool changes_sign) {
      const std::string n = force_sign_note(vanishes, changes_sign);
      return n.empty() ? n : " (" + n + ")";
    };
    std::cout << fmt::format("  percent constant force: PRBM {:.2f} %{}{}\n",
                             a.prbm.percent_constant_force,
                             note(a.prbm.force_vanishes, a.prbm.force_changes_sign),
                             a.has_exact && o.exact ? fmt::format(", exact {:.2f} %{}",
                                                                  a.percent_constant_force_exact,
                                                                  note(a.force_vanishes_exact,
                                                                       a.force_changes_sign_exact))
                             : a.exact_note.empty() ? std::string(" (exact model not run)")
                                                    : std::string(" (") + a.exact_note + ")");
    std::cout << fmt::format(
        "  mean force ({}{}): PRBM {:.5g} N{}\n",
        force_of_label(a.force_of),
        has_fixed_fixed(d) ? ", spring rule " + spring_rule_name(d.spring_rule) : "",
        a.prbm.mean_force,
        a.has_exact && o.exact ? fmt::format(", exact {:.5g} N", a.mean_force_exact) : "");
    if (a.has_exact && o.exact) {
      std::cout << fmt::format("  max PRBM force error: {:.3f} % at Delta x = {:.5g} m\n",
                               100.0 * a.max_force_error,
                               a.max_force_error_at);
    }
    std::cout << fmt::format("  PRBM validity: {}\n", describe_validity(a.prbm_validity, d.stroke));
    std::cout << fmt::format("  max stress {:.5g} Pa, safety factor {:.3f}{}\n",
                             a.max_stress_all,
                             a.safety_factor,
                             a.yielding_pivots.empty() ? "" : " (YIELDS)");
    std::cout << fatigue_text(a, fatigue, fatigue_note);
    std::cout << geometry_text(mechanism_geometry(d), "mm");
    const std::vector<StrokeStabilityEntry> entries = stroke_stability_entries(a);
    if (!entries.empty()) {
      std::cout << "  stability (margin: the lowest eigenvalue of the second variation of the "
                   "energy / the unloaded stiffness; docs/stability.md \"Mechanisms\"):\n";
      for (const StrokeStabilityEntry& e : entries) {
        if (e.stroke != nullptr) std::cout << "    " << e.stroke->summary << "\n";
      }
    }
  });

  // `mechanism tolerance`: the sampled study of benchmarks/studies/mechanism_tolerance.h.
  struct ToleranceArgs {
    std::string what, thickness, width, length, E, distribution = "normal", method = "exact", out;
    std::string csv;
    std::string material;  // --material NAME: the nominal design's E and S_y
    std::string force_of = "half";
    CLI::Option* force_of_option = nullptr;
    int samples = 100, points = 50;
    std::uint64_t seed = 1;
    bool json = false;
  };
  auto targs = std::make_shared<ToleranceArgs>();
  CLI::App* tolerance = mech.add_subcommand(
      "tolerance",
      "Manufacturing tolerances: the force, percent constant force and safety factor over "
      "sampled thicknesses, widths, lengths and E, with first-order sensitivities");
  tolerance->add_option("mechanism", targs->what, "Built-in name or FILE.toml (as for analyze)")
      ->required();
  tolerance->add_option(
      "--thickness", targs->thickness, "Spread of every flexure's thickness: 3% or 0.03");
  tolerance->add_option("--width", targs->width, "Spread of every flexure's width: 1% or 0.01");
  tolerance->add_option("--length",
                        targs->length,
                        "Spread of the links r2, r3 and every small-length flexure's length");
  tolerance->add_option("--E", targs->E, "Spread of Young's modulus (one draw per sample)");
  tolerance->add_option("--material",
                        targs->material,
                        "Material from the library (`flexure materials`): the nominal design's E "
                        "and S_y (replacing the design's), about which --E spreads");
  tolerance->add_option("--samples", targs->samples, "Sampled designs (2..100000)")
      ->default_str("100");
  tolerance
      ->add_option("--distribution",
                   targs->distribution,
                   "normal (spread = standard deviation, cut at 3.5) or uniform (spread = "
                   "half-width)")
      ->default_str("normal");
  tolerance->add_option("--seed", targs->seed, "Seed of the draws")->default_str("1");
  tolerance->add_option("--method", targs->method, "exact (PRBM and exact) or prbm")
      ->default_str("exact")
      ->transform(CLI::IsMember({"prbm", "exact"}, CLI::ignore_case));
  tolerance->add_option("--points", targs->points, "Stroke points of each analysis")
      ->default_str("50");
  targs->force_of_option =
      tolerance
          ->add_option("--force-of",
                       targs->force_of,
                       "Mean forces of one half of the symmetric mechanism or of the whole (= 2 x "
                       "half), as mechanism analyze reports; default half, or the design file's "
                       "force_of")
          ->default_str("half");
  tolerance->add_option("--out",
                        targs->out,
                        "Write the samples and statistics to this HDF5 file (one file under "
                        "mpirun), or FILE.csv for the samples as CSV only");
  add_csv_option(tolerance, targs->csv);
  tolerance->add_flag("--json", targs->json, "Print one JSON object");
  tolerance->callback([targs] {
    const auto spread = [](const std::string& text, const char* flag) {
      if (text.empty()) return 0.0;
      const bool percent = text.back() == '%';
      double v = 0.0;
      try {
        std::size_t used = 0;
        const std::string number = percent ? text.substr(0, text.size() - 1) : text;
        v = std::stod(number, &used);
        if (used != number.size()) throw std::invalid_argument(text);
      } catch (const std::exception&) {
        throw InvalidInput(fmt::format("{} '{}' is not a spread: give 3% or 0.03", flag, text));
      }
      return percent ? v / 100.0 : v;
    };
    ToleranceOptions o;
    o.spread.thickness = spread(targs->thickness, "--thickness");
    o.spread.width = spread(targs->width, "--width");
    o.spread.length = spread(targs->length, "--length");
    o.spread.E = spread(targs->E, "--E");
    o.samples = targs->samples;
    o.points = targs->points;
    o.seed = targs->seed;
    o.exact = targs->method == "exact";
    o.distribution = parse_spread_distribution(targs->distribution);
    o.validate();
    // --out FILE.csv: the samples table only (no HDF5 file); --csv FILE: the table as well.
    std::string hdf5_out = targs->out, csv_out = targs->csv;
    if (is_csv_path(targs->out)) {
      if (!targs->csv.empty()) {
        throw InvalidInput(fmt::format(
            "--out {} is a CSV file already; give --csv only with an HDF5 --out", targs->out));
      }
      csv_out = targs->out;
      hdf5_out.clear();
    }
    if (!hdf5_out.empty()) io::check_output_path(hdf5_out);
    if (!csv_out.empty()) io::check_output_path(csv_out, targs->csv.empty() ? "--out" : "--csv");
    MechanismDesign d = mechanism_design_argument(targs->what);
    if (!targs->material.empty()) apply_material_flag(d, targs->material);
    // A design file's force_of (written by `flexure design mechanism`) unless --force-of is given.
    o.force_of =
        *targs->force_of_option || !d.force_of ? parse_force_of(targs->force_of) : *d.force_of;
    const ToleranceStudy s = mechanism_tolerance(d, o);
    warn(s.warnings);  // samples left out
    // Every rank holds the whole study (mechanism_tolerance.h); rank 0 writes the file.
    if (!hdf5_out.empty() && parallel::world().root()) {
      write_tolerance_hdf5(hdf5_out, s);
    }
    if (!csv_out.empty() && parallel::world().root()) {
      io::write_csv(csv_out, tolerance_csv_columns(s), targs->csv.empty() ? "--out" : "--csv");
    }
    if (targs->json) {
      Json j{{"design", s.design},
             {"samples", o.samples},
             {"failed_samples", s.failed_samples},
             {"distribution", spread_distribution_name(o.distribution)},
             {"seed", o.seed},
             {"method", o.exact ? "exact" : "prbm"},
             {"force_of", force_of_label(o.force_of)},
             {"material", d.material_id.empty() ? Json(nullptr) : Json(d.material_id)},
             {"spread",
              Json{{"thickness", o.spread.thickness},
                   {"width", o.spread.width},
                   {"length", o.spread.length},
                   {"E", o.spread.E}}},
             {"parameters", s.parameters},
             {"out", targs->out.empty() ? Json(nullptr) : Json(targs->out)},
             {"csv", csv_out.empty() ? Json(nullptr) : Json(csv_out)}};
      for (const ToleranceStats& q : s.quantities) {
        j[q.name] = Json{{"unit", q.unit},
                         {"nominal", q.nominal},
                         {"mean", q.mean},
                         {"std", q.std},
                         {"p05", q.p05},
                         {"p50", q.p50},
                         {"p95", q.p95},
                         {"first_order_std", q.first_order_std},
                         {"sensitivity",
                          Json{{"thickness", q.sensitivity[0]},
                               {"width", q.sensitivity[1]},
                               {"length", q.sensitivity[2]},
                               {"E", q.sensitivity[3]}}}};
      }
      print_json(j);
      return;
    }
    std::cout << fmt::format(
        "{}: {} samples ({}), spreads thickness {:g} %, width {:g} %, length {:g} %, E {:g} "
        "%{}; forces of {}\n",
        s.design,
        o.samples,
        spread_distribution_name(o.distribution),
        100 * o.spread.thickness,
        100 * o.spread.width,
        100 * o.spread.length,
        100 * o.spread.E,
        s.failed_samples > 0 ? fmt::format(" ({} failed)", s.failed_samples) : "",
        force_of_label(o.force_of));
    std::cout << fmt::format(
        "  {:<30} {:>11} {:>11} {:>10} {:>11} {:>11} {:>10}   dQ/d(rel): "
        "thickness width length E\n",
        "quantity",
        "nominal",
        "mean",
        "std",
        "p05",
        "p95",
        "1st-order");
    for (const ToleranceStats& q : s.quantities) {
      std::cout << fmt::format(
          "  {:<30} {:>11.5g} {:>11.5g} {:>10.3g} {:>11.5g} {:>11.5g} {:>10.3g}   {:.3g} {:.3g} "
          "{:.3g} {:.3g} ({})\n",
          q.name,
          q.nominal,
          q.mean,
          q.std,
          q.p05,
          q.p95,
          q.first_order_std,
          q.sensitivity[0],
          q.sensitivity[1],
          q.sensitivity[2],
          q.sensitivity[3],
          q.unit);
    }
  });

  struct ValidateArgs {
    std::optional<double> toggle_fraction;
    int points = 50;
    bool markdown = false;
    bool json = false;
    std::string designs = "builtin";
    std::string spring_rule;
    bool spring_rules = false;
    std::string out;
    std::string csv;
  };
  auto vargs = std::make_shared<ValidateArgs>();
  CLI::App* validate = mech.add_subcommand(
      "validate", "PRBM vs exact model for every built-in mechanism (docs/validation.md table)");
  validate->add_option("--points", vargs->points, "Stroke points (2..100000)")->default_str("50");
  CLI::Option* toggle_opt = validate->add_option(
      "--toggle-fraction",
      vargs->toggle_fraction,
      "Stroke of every design = this fraction of its toggle stroke, in (0, 1)");
  CLI::Option* markdown_opt =
      validate->add_flag("--markdown", vargs->markdown, "Print the Markdown table");
  CLI::Option* spring_rules_opt = validate->add_flag(
      "--spring-rules",
      vargs->spring_rules,
      "Instead: the spring rules of the modified designs against the exact model");
  CLI::Option* spring_rule_opt = validate->add_option(
      "--spring-rule",
      vargs->spring_rule,
      "Spring rule of the modified designs: pure-bending (default), table2, table5");
  CLI::Option* json_opt = validate->add_flag("--json", vargs->json, "Print one JSON object");
  CLI::Option* out_opt = validate->add_option(
      "--out",
      vargs->out,
      "Also write the table to this HDF5 file (docs/hdf5-schema.md; one file under mpirun), or "
      "to FILE.csv as CSV only");
  CLI::Option* csv_opt = validate->add_option(
      "--csv",
      vargs->csv,
      "Also write the table as CSV, one row per design (a header line of names and [units]; "
      "docs/cli.md \"CSV output\")");
  CLI::Option* designs_opt =
      validate
          ->add_option("--designs",
                       vargs->designs,
                       "builtin (thesis + modified), thesis (the nine designs), modified "
                       "(paper 004), howell (Howell's Table 10.1 designs), inversions, all")
          ->default_str("builtin")
          ->transform(CLI::IsMember(
              {"builtin", "thesis", "modified", "howell", "inversions", "all"}, CLI::ignore_case));
  // Combinations that were silently ignored: one output format; --spring-rules has its own
  // designs (the modified ones), stroke and rules.
  markdown_opt->excludes(json_opt);
  spring_rules_opt->excludes(toggle_opt)
      ->excludes(spring_rule_opt)
      ->excludes(designs_opt)
      ->excludes(out_opt)
      ->excludes(csv_opt);
  validate->callback([vargs] {
    require_in_range(vargs->points, "--points", 2, 100000);
    if (vargs->toggle_fraction) {
      // Below 1: at the toggle itself every built-in set has R = 1 designs (1B-psp, the modified
      // ones), folded flat there with a PRBM force of 0/0 (MechanismDesign::finalise refuses it).
      const double f = *vargs->toggle_fraction;
      if (!(f >= 1e-6 && f < 1.0)) {
        throw InvalidInput(fmt::format(
            "--toggle-fraction = {} is outside the allowed range [1e-06, 1) (at 1 the designs with "
            "R = 1 fold flat, where the PRBM force is 0/0)",
            f));
      }
    }
    if (vargs->spring_rules) {
      print_spring_rules(vargs->points, vargs->json);
      return;
    }
    MechanismValidationOptions options;
    options.points = vargs->points;
    options.toggle_fraction = vargs->toggle_fraction;
    if (!vargs->spring_rule.empty()) options.spring_rule = parse_spring_rule(vargs->spring_rule);
    print_validation(
        options, vargs->json, design_set_from_string(vargs->designs), vargs->out, vargs->csv);
  });
}

}  // namespace flexure::cli
