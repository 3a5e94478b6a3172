#include "cli/general_mechanism_command.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "cli/cli_common.h"
#include "cli/csv_output.h"
#include "cli/slow_progress.h"
#include "flexure/io/general_mechanism_file.h"
#include "flexure/io/platform/hdf5_error.h"
#include "flexure/io/platform/output_path.h"
#include "flexure/io/toml_files.h"
#include "flexure/io/toml_support.h"
#include "flexure/mechanisms/general/general_analysis.h"
#include "flexure/mechanisms/general/stable_selection.h"
#include "flexure/solver/common/section.h"
#include "flexure/solver/common/status.h"

namespace flexure::cli {
namespace {

using namespace flexure::mechanism::general;

// --input START:STOP:COUNT with the units of the input (angle or length; moment or force under
// force control).
void apply_input_range(const std::string& text, Input& input) {
  const auto first = text.find(':');
  const auto second = first == std::string::npos ? first : text.find(':', first + 1);
  if (second == std::string::npos || text.find(':', second + 1) != std::string::npos) {
    throw InvalidInput("--input must be START:STOP:COUNT (e.g. \"-5deg:33deg:77\"), got '" + text +
                       "'");
  }
  const bool angle = input.coordinate == InputCoordinate::kAngle;
  const io::Dimension dimension = input.control == InputControl::kDisplacement
                                      ? (angle ? io::Dimension::kAngle : io::Dimension::kLength)
                                      : (angle ? io::Dimension::kMoment : io::Dimension::kForce);
  input.start = io::parse_quantity(text.substr(0, first), dimension, "--input START").si;
  input.stop =
      io::parse_quantity(text.substr(first + 1, second - first - 1), dimension, "--input STOP").si;
  double count = 0.0;
  if (!parse_double(text.substr(second + 1), count) || count != std::floor(count) || count < 2 ||
      count > 100000) {
    throw InvalidInput("--input COUNT must be a whole number between 2 and 100000, got '" +
                       text.substr(second + 1) + "'");
  }
  input.count = static_cast<int>(count);
}

std::string_view input_unit(const Input& in) {
  return in.coordinate == InputCoordinate::kAngle ? "rad" : "m";
}
std::string_view load_unit(const Input& in) {
  return in.coordinate == InputCoordinate::kAngle ? "N m" : "N";
}

Json number_or_null(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

// --flexure-model SPEC: "MODEL" (every flexure) or "NAME=MODEL,NAME=MODEL"; with --flexure-tol.
void apply_flexure_models(GeneralMechanism& m, const std::string& spec, double tol) {
  if (spec.empty()) {
    if (tol != 0.0) {
      for (Flexure& f : m.flexures) {
        if (f.model == FlexureModel::kAuto) f.tolerance = tol;
      }
    }
    return;
  }
  std::size_t start = 0;
  while (start <= spec.size()) {
    const std::size_t comma = spec.find(',', start);
    const std::string item =
        spec.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const std::size_t eq = item.find('=');
    const std::string name = eq == std::string::npos ? std::string() : item.substr(0, eq);
    const std::string model = eq == std::string::npos ? item : item.substr(eq + 1);
    FlexureModel parsed;
    try {
      parsed = parse_flexure_model(model);
    } catch (const InvalidInput& e) {
      throw InvalidInput(std::string("--flexure-model: ") + e.what());
    }
    if (parsed == FlexureModel::kAuto && tol == 0.0) {
      throw InvalidInput(
          "--flexure-model auto needs --flexure-tol T (the largest mapped tip error per length "
          "of each flexure, e.g. 1e-3)");
    }
    set_flexure_model(m, name, parsed, parsed == FlexureModel::kAuto ? tol : 0.0);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
}

Json flexure_models_json(const std::vector<FlexureModelReport>& reports, bool checked) {
  Json out = Json::array();
  for (const FlexureModelReport& r : reports) {
    Json Fx = Json::array(), Fy = Json::array(), mu = Json::array(), mapped = Json::array();
    for (std::size_t k = 0; k < r.loads.size(); ++k) {
      Fx.push_back(number_or_null(r.loads[k].Fx));
      Fy.push_back(number_or_null(r.loads[k].Fy));
      mu.push_back(number_or_null(r.loads[k].mu));
      mapped.push_back(number_or_null(r.mapped_error[k]));
    }
    Json j{{"name", r.name},
           {"requested", flexure_model_name(r.requested)},
           {"model", flexure_model_name(r.model)},
           {"tolerance", r.requested == FlexureModel::kAuto ? Json(r.tolerance) : Json(nullptr)},
           {"elements",
            r.model == FlexureModel::kCbcm || r.model == FlexureModel::kChain ? Json(r.elements)
                                                                              : Json(nullptr)},
           {"method_reason", r.reason},
           {"expected_error_per_length", number_or_null(r.expected_error_per_length)},
           {"unmapped_points", r.unmapped_points},
           {"tip_load_Fx", Fx},
           {"tip_load_Fy", Fy},
           {"tip_load_mu", mu},
           {"mapped_error_per_length", mapped}};
    if (checked) {
      Json measured = Json::array();
      for (double e : r.measured_error) measured.push_back(number_or_null(e));
      j["measured_error_per_length"] = number_or_null(r.measured_error_per_length);
      j["measured_error"] = measured;
    }
    out.push_back(j);
  }
  return out;
}

Json stability_json(const Stability& s) {
  return Json{{"stability", stability_name(s.kind)}, {"index", s.index}, {"margin", s.margin}};
}

}  // namespace

bool is_general_mechanism_file(const std::string& what) {
  const bool is_file = what.size() > 5 && what.substr(what.size() - 5) == ".toml";
  if (!is_file) {
    return false;
  }
  return is_general_mechanism_toml(io::read_toml_file(what, "mechanism file"), what);
}

namespace {

// Per point: a PointLoad's force and moment as three arrays.
template <typename F>
Json point_load_json(const GeneralPrbmResult& r, F pick) {
  Json fx = Json::array(), fy = Json::array(), moment = Json::array();
  for (const GeneralPrbmPoint& p : r.points) {
    const PointLoad& l = pick(p);
    fx.push_back(number_or_null(l.fx));
    fy.push_back(number_or_null(l.fy));
    moment.push_back(number_or_null(l.moment));
  }
  return Json{{"fx", fx}, {"fy", fy}, {"moment", moment}};
}

// The bodies' poses, the joints' positions and reactions, the ground's reaction and every
// flexure's end loads and largest stress per point (GeneralPrbmPoint; docs/cli.md).
void add_point_results_json(Json& j, const GeneralPrbmResult& r, const GeneralMechanism& m) {
  Json bodies = Json::array();
  for (std::size_t b = 0; b < r.body_names.size(); ++b) {
    Json x = Json::array(), y = Json::array(), phi = Json::array();
    for (const GeneralPrbmPoint& p : r.points) {
      x.push_back(b < p.body_x.size() ? Json(p.body_x[b]) : Json(nullptr));
      y.push_back(b < p.body_y.size() ? Json(p.body_y[b]) : Json(nullptr));
      phi.push_back(b < p.body_phi.size() ? Json(p.body_phi[b]) : Json(nullptr));
    }
    bodies.push_back(Json{{"name", r.body_names[b]}, {"x", x}, {"y", y}, {"phi", phi}});
  }
  j["bodies"] = bodies;
  Json joints = Json::array();
  for (std::size_t k = 0; k < m.joints.size(); ++k) {
    const bool all = std::all_of(
        r.points.begin(), r.points.end(), [&](const auto& p) { return k < p.joints.size(); });
    if (!all) break;
    Json x = Json::array(), y = Json::array();
    for (const GeneralPrbmPoint& p : r.points) {
      x.push_back(p.joints[k].x);
      y.push_back(p.joints[k].y);
    }
    joints.push_back(Json{{"name", m.joints[k].name},
                          {"kind", joint_kind_name(m.joints[k].kind)},
                          {"x", x},
                          {"y", y},
                          {"on_b", point_load_json(r, [&](const auto& p) -> const PointLoad& {
                             return p.joints[k].on_b;
                           })}});
  }
  j["joints"] = joints;
  j["ground_reaction"] =
      point_load_json(r, [](const auto& p) -> const PointLoad& { return p.ground_reaction; });
  Json flexures = Json::array();
  for (std::size_t k = 0; k < m.flexures.size(); ++k) {
    const bool all =
        !r.points.empty() && std::all_of(r.points.begin(), r.points.end(), [&](const auto& p) {
          return k < p.flexures.size();
        });
    if (!all) break;
    Json stress = Json::array(), at = Json::array(), fibre = Json::array(), pos = Json::array(),
         neg = Json::array(), moment = Json::array(), axial = Json::array();
    for (const GeneralPrbmPoint& p : r.points) {
      const FlexurePointResult& f = p.flexures[k];
      stress.push_back(number_or_null(f.max_stress));
      at.push_back(number_or_null(f.max_stress_at));
      fibre.push_back(f.max_stress_fibre);
      pos.push_back(number_or_null(f.stress_pos_fibre));
      neg.push_back(number_or_null(f.stress_neg_fibre));
      moment.push_back(number_or_null(f.moment));
      axial.push_back(number_or_null(f.axial_force));
    }
    flexures.push_back(Json{
        {"name", m.flexures[k].name},
        {"max_stress", stress},
        {"max_stress_at", at},
        {"max_stress_fibre", fibre},
        {"stress_pos_fibre", pos},
        {"stress_neg_fibre", neg},
        {"moment_at_max_stress", moment},
        {"axial_force_at_max_stress", axial},
        {"max_stress_from", r.points.front().flexures[k].max_from},
        {"on_a",
         point_load_json(r, [&](const auto& p) -> const PointLoad& { return p.flexures[k].on_a; })},
        {"on_b", point_load_json(r, [&](const auto& p) -> const PointLoad& {
           return p.flexures[k].on_b;
         })}});
  }
  j["flexures"] = flexures;
}

// One model's arrays, equilibria and limit points.
Json model_json(const GeneralPrbmResult& r) {
  Json input = Json::array(), load = Json::array(), energy = Json::array();
  Json dc = Json::array(), fc = Json::array(), dc_margin = Json::array(), fc_margin = Json::array();
  for (const GeneralPrbmPoint& p : r.points) {
    input.push_back(p.input);
    load.push_back(p.input_load);
    energy.push_back(number_or_null(p.energy));  // null: a model flexure has no shape energy
    dc.push_back(stability_name(p.displacement_control.kind));
    fc.push_back(stability_name(p.force_control.kind));
    dc_margin.push_back(p.displacement_control.margin);
    fc_margin.push_back(p.force_control.margin);
  }
  Json equilibria = Json::array();
  for (const GeneralEquilibrium& e : r.equilibria) {
    Json j{{"input", e.input}, {"energy", number_or_null(e.energy)}};
    j.update(stability_json(e.stability));
    equilibria.push_back(j);
  }
  Json limits = Json::array();
  for (std::size_t i = 0; i < r.limit_inputs.size(); ++i) {
    limits.push_back(Json{{"input", r.limit_inputs[i]}, {"input_load", r.limit_loads[i]}});
  }
  return Json{{"termination", termination_name(r.termination)},
              {"input", input},
              {"input_load", load},
              {"energy", energy},
              {"stability",
               Json{{"displacement_control", dc},
                    {"force_control", fc},
                    {"displacement_control_margin", dc_margin},
                    {"force_control_margin", fc_margin}}},
              {"equilibria", equilibria},
              {"limit_points", limits},
              {"steps", r.iterations}};
}

void print_model(const std::string& title,
                 const GeneralPrbmResult& r,
                 const Input& in,
                 const GeneralMechanism& m) {
  const bool angle = in.coordinate == InputCoordinate::kAngle;
  auto show = [&](double v) {
    return angle ? fmt::format("{:.6g} deg", v * 180.0 / 3.14159265358979323846)
                 : fmt::format("{:.6g} mm", v * 1e3);
  };
  double lo = 0.0, hi = 0.0;
  for (const GeneralPrbmPoint& p : r.points) {
    lo = std::min(lo, p.input_load);
    hi = std::max(hi, p.input_load);
  }
  std::cout << fmt::format("  {}: {} points; input load from {:.6g} to {:.6g} {}\n",
                           title,
                           r.points.size(),
                           lo,
                           hi,
                           load_unit(in));
  std::cout << fmt::format("    equilibria of the unloaded mechanism: {}\n", r.equilibria.size());
  for (const GeneralEquilibrium& e : r.equilibria) {
    std::cout << fmt::format(
        "      {}: {} (energy {:.6g} J{})\n",
        show(e.input),
        stability_name(e.stability.kind),
        e.energy,
        e.stability.judged() ? fmt::format(", margin {:.4g}", e.stability.margin) : std::string());
  }
  for (std::size_t i = 0; i < r.limit_inputs.size(); ++i) {
    std::cout << fmt::format("    limit point at {}: input load {:.6g} {}\n",
                             show(r.limit_inputs[i]),
                             r.limit_loads[i],
                             load_unit(in));
  }
  // Each flexure's largest stress along the path (the JSON's flexures[].max_stress per point).
  for (std::size_t k = 0; k < m.flexures.size(); ++k) {
    const GeneralPrbmPoint* worst = nullptr;
    for (const GeneralPrbmPoint& p : r.points) {
      if (k < p.flexures.size() &&
          (worst == nullptr || p.flexures[k].max_stress > worst->flexures[k].max_stress)) {
        worst = &p;
      }
    }
    if (worst == nullptr) continue;
    const FlexurePointResult& f = worst->flexures[k];
    std::cout << fmt::format(
        "    flexure {}: largest stress {:.6g} MPa at input {}, {:.6g} mm from end a ({})\n",
        m.flexures[k].name,
        f.max_stress * 1e-6,
        show(worst->input),
        f.max_stress_at * 1e3,
        f.max_from);
  }
}

}  // namespace

void analyze_general_mechanism(const GeneralAnalyzeRequest& request) {
  if (!request.foreign_flag.empty()) {
    throw InvalidInput(request.foreign_flag +
                       (request.mechanism
                            ? " does not apply to --model mixed on a constant-force design, which "
                              "takes --flexure-model, --flexure-tol, --check-flexures, --points, "
                              "--out, --csv and --json"
                            : " belongs to the constant-force designs; a general mechanism file "
                              "takes --model, --input, --points, --stable, --out, --csv, --json "
                              "and, with --model mixed, --flexure-model, --flexure-tol and "
                              "--check-flexures"));
  }
  const io::GeneralAnalysisModel model =
      request.model.empty() ? io::GeneralAnalysisModel::kPrbm
                            : io::general_analysis_model_from_string(request.model);
  const bool mixed = model == io::GeneralAnalysisModel::kMixed;
  if (!mixed &&
      (!request.flexure_models.empty() || request.flexure_tol != 0.0 || request.check_flexures)) {
    throw InvalidInput(
        "--flexure-model, --flexure-tol and --check-flexures apply to --model mixed (a model "
        "per flexure)");
  }
  if (request.flexure_tol != 0.0 && !(request.flexure_tol > 0.0 && request.flexure_tol < 1.0)) {
    throw InvalidInput(
        fmt::format("--flexure-tol must be in (0, 1), got {:g}", request.flexure_tol));
  }
  // --out FILE.h5 | FILE.csv and --csv FILE, checked before any work (exit 2).
  std::string hdf5_out = request.out, csv_out = request.csv;
  if (is_csv_path(request.out)) {
    if (!request.csv.empty()) {
      throw InvalidInput(fmt::format(
          "--out {} is a CSV file already; give --csv only with an HDF5 --out", request.out));
    }
    csv_out = request.out;
    hdf5_out.clear();
  }
  if (!hdf5_out.empty()) io::check_output_path(hdf5_out, "--out");
  if (!csv_out.empty()) io::check_output_path(csv_out, request.csv.empty() ? "--out" : "--csv");
  GeneralMechanism m =
      request.mechanism ? *request.mechanism : load_general_mechanism_toml(request.file);
  apply_flexure_models(m, request.flexure_models, request.flexure_tol);
  if (!request.input_range.empty()) {
    apply_input_range(request.input_range, m.input);
  }
  if (request.points > 0) {
    m.input.count = request.points;
  }
  m.validate();
  const Input& in = m.input;
  std::vector<std::pair<std::string, GeneralPrbmResult>> results;
  // Per recorded point of each model's path (a terminal's progress line; the Python module's
  // callable and Ctrl-C).
  if (model == io::GeneralAnalysisModel::kPrbm || model == io::GeneralAnalysisModel::kBoth) {
    GeneralPrbmOptions o;
    o.progress = stoppable_progress(m.name + ": PRBM path points");
    results.emplace_back("prbm", solve_general_prbm(m, o));
  }
  if (model == io::GeneralAnalysisModel::kExact || model == io::GeneralAnalysisModel::kBoth) {
    GeneralExactOptions o;
    o.progress = stoppable_progress(m.name + ": exact path points");
    results.emplace_back("exact", solve_general_exact(m, o));
  }
  if (mixed) {
    GeneralExactOptions o;
    o.measure_flexure_errors = request.check_flexures;
    o.progress = stoppable_progress(m.name + ": mixed model path points");
    results.emplace_back("mixed", solve_general_mixed(m, o));
  }
  for (const auto& [name, r] : results) {
    for (const Warning& w : r.warnings) {
      warn(w.text);
    }
    if (!r.converged()) {
      throw NoConvergence(fmt::format("{}: {}: {}", m.name, name, r.message));
    }
  }
  // --stable: each model's path replaced by its stable equilibria (stable_selection.h).
  std::string stable_search;
  if (request.stable) {
    for (auto& [name, r] : results) {
      StableSelection selection = select_stable_points(m, r);
      if (!selection.stable) {
        throw NoConvergence(fmt::format("{}: {}: --stable: {}", m.name, name, selection.search));
      }
      stable_search += (stable_search.empty() ? "" : "; ") +
                       (results.size() > 1 ? name + ": " : std::string()) + selection.search;
      r = std::move(selection.result);
    }
  }
  const GeneralPrbmResult& first = results.front().second;
  io::GeneralAnalysisOutput output;
  output.mechanism = &m;
  output.model = model;
  for (const auto& [name, r] : results) output.results.emplace_back(name, &r);
  if (request.mechanism) output.design_x0 = request.design_x0;
  output.checked_flexures = request.check_flexures;
  if (!hdf5_out.empty()) {
    try {
      io::write_general_mechanism_hdf5(hdf5_out, output);
    } catch (const io::Hdf5Error& e) {
      throw InvalidInput(fmt::format("--out: {}", e.what()));
    }
  }
  if (!csv_out.empty()) {
    std::string note;
    const auto columns = io::general_mechanism_csv_columns(output, &note);
    if (!note.empty()) warn(note);
    io::write_csv(csv_out, columns, request.csv.empty() ? "--out" : "--csv");
  }
  if (request.json) {
    Json models = Json::object();
    for (const auto& [name, r] : results) {
      models[name] = model_json(r);
      add_point_results_json(models[name], r, m);
      if (name == "mixed") {
        models[name]["flexure_models"] =
            flexure_models_json(r.flexure_models, request.check_flexures);
      }
    }
    // The top-level arrays are the first model's (the PRBM's for "both").
    const Json& top = models[results.front().first];
    Json out{{"name", m.name},
             {"form", "general"},
             {"model", to_string(model)},
             {"input_body", in.body},
             {"input_coordinate", input_coordinate_name(in.coordinate)},
             {"control", input_control_name(in.control)},
             {"input_unit", input_unit(in)},
             {"input_load_unit", load_unit(in)},
             {"degrees_of_freedom", first.degrees_of_freedom},
             {"input", top["input"]},
             {"input_load", top["input_load"]},
             {"energy", top["energy"]},
             {"stability", top["stability"]},
             {"equilibria", top["equilibria"]},
             {"limit_points", top["limit_points"]},
             {"bodies", top["bodies"]},
             {"joints", top["joints"]},
             {"ground_reaction", top["ground_reaction"]},
             {"flexures", top["flexures"]},
             {"models", models}};
    if (mixed) {
      out["flexure_models"] = models["mixed"]["flexure_models"];
    }
    if (request.mechanism) {
      // A constant-force design: the stroke Delta x and the slider force of one half as
      // `mechanism analyze` reports them (the input load holds x; the force pushes inwards).
      out["displacement"] = io::design_stroke_displacement(first, request.design_x0);
      out["force"] = io::design_stroke_force(first);
      out["force_of"] = "half";
    }
    out["stable"] = request.stable;
    out["stable_search"] = request.stable ? Json(stable_search) : Json(nullptr);
    out["out"] = hdf5_out.empty() ? Json(nullptr) : Json(hdf5_out);
    out["csv"] = csv_out.empty() ? Json(nullptr) : Json(csv_out);
    print_json(out);
    return;
  }
  std::cout << fmt::format("{} (general mechanism): input {} of {} ({} control)\n",
                           m.name,
                           input_coordinate_name(in.coordinate),
                           in.body,
                           input_control_name(in.control));
  if (request.stable) std::cout << fmt::format("  --stable: {}\n", stable_search);
  for (const auto& [name, r] : results) {
    print_model(name == "prbm" ? "PRBM" : name, r, in, m);
    for (const FlexureModelReport& f : r.flexure_models) {
      std::cout << fmt::format(
          "    flexure {}: {}{}; expected tip error {}{}\n      {}\n",
          f.name,
          flexure_model_name(f.model),
          f.requested == FlexureModel::kAuto ? fmt::format(" (auto, tol {:g})", f.tolerance)
                                             : std::string(),
          std::isfinite(f.expected_error_per_length)
              ? fmt::format("{:.2g} of its length", f.expected_error_per_length)
              : std::string("not mapped"),
          request.check_flexures && std::isfinite(f.measured_error_per_length)
              ? fmt::format(", measured {:.2g}", f.measured_error_per_length)
              : std::string(),
          f.reason);
    }
  }
}

}  // namespace flexure::cli
