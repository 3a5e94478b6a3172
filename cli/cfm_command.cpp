// `flexure cfm`: the nondimensional PRBM model of the constant-force slider mechanisms (Weight
// 2001, Howell §10.1; docs/cfm.md).
//
//   flexure cfm --config CFG --R R [--K1 K1] [--K2 K2] --d D [--sampling thesis|uniform]
//               [--points N] [--curve] [--json]
//   flexure cfm --subclass NAME [--json]      one of the 68 thesis sub-classes (or a Table 2.1 /
//                                             Table 10.1 row), printed values beside the computed
//   flexure cfm --list [--json]               the built-in sub-classes and table rows
//   flexure cfm --table [--markdown|--json]   every printed row recomputed (exit 1 if one fails)
//   ... --exact [--exact-points N]            also the exact (elastica) model of the same
//                                             mechanism (mechanisms/mechanism_analysis.h); with
//                                             --table: PRBM vs exact for the sub-class rows
//
// A stroke past the toggle position is clamped as in the thesis (stroke_percent reports the
// effective stroke) with a warning (the model's, printed through warn()).
#include <fmt/format.h>

#include <array>
#include <cctype>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli/cfm_cli_support.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/warning_output.h"
#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/cfm_comparison.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/solver/common/status.h"

namespace flexure::cli {
namespace {

using cfm::CfmClassRow;
using cfm::CfmModel;
using cfm::CfmOptions;
using cfm::CfmParameters;
using cfm::CfmResult;
using cfm::CfmSubclass;
using cfm::StrokeSampling;

cfm::CfmExactResult solve_exact_or_throw(const CfmResult& r, const CfmArgs& args) {
  cfm::CfmExactResult e = cfm::solve_cfm_exact(r, make_exact_options(args));
  if (!e.converged()) throw NoConvergence("cfm --exact: exact model: " + e.message);
  warn(e.warnings);  // a force that vanishes or changes sign: Xi' exact reported as 0
  return e;
}

void print_exact_report(const cfm::CfmExactResult& e, bool curve) {
  fmt::print("  exact model ({} equally spaced points, r2 + r3 = 1, E = 1):\n",
             e.stroke_percent.size());
  fmt::print("    Phi exact         = {:.6f}   (PRBM on the same points {:.6f})\n",
             e.Phi_exact,
             e.Phi_prbm_mean);
  fmt::print("    percent constant  = {:.4f} %   (PRBM on the same points {:.4f} %)\n",
             e.percent_constant_force_exact,
             e.percent_constant_force_prbm);
  fmt::print("    max force error   = {:.4f} % of the exact force, at d = {:.3f} %\n",
             100.0 * e.max_force_error,
             e.max_force_error_at_percent);
  if (!curve) return;
  for (std::size_t k = 0; k < e.stroke_percent.size(); ++k) {
    fmt::print("    {:10.5f} %  Phi PRBM = {:.8f}  Phi exact = {:.8f}\n",
               e.stroke_percent[k],
               e.Phi_prbm[k],
               e.Phi_exact_curve[k]);
  }
}

CfmOptions make_options(const CfmArgs& args, StrokeSampling default_sampling) {
  CfmOptions options;
  if (args.sampling == "auto") {
    options.sampling = default_sampling;
  } else if (args.sampling == "thesis") {
    options.sampling = StrokeSampling::kThesisCode;
  } else if (args.sampling == "uniform") {
    options.sampling = StrokeSampling::kUniform;
  } else {
    throw InvalidInput(
        fmt::format("--sampling = '{}' is unknown; allowed: thesis, uniform", args.sampling));
  }
  if (options.sampling != StrokeSampling::kUniform && *args.points_option) {
    throw InvalidInput(
        "--points applies to --sampling uniform only (the thesis sampling has its "
        "own ~1000 points)");
  }
  if (options.sampling == StrokeSampling::kUniform) {
    // At least 2: over one point min F = max F, a meaningless 100 % constant force.
    require_in_range(args.points, "--points (stroke points, uniform sampling)", 2, 10'000'000);
    options.points = args.points;
  }
  options.keep_curve = args.curve;
  return options;
}

std::string sampling_name(const CfmOptions& options) {
  return options.sampling == StrokeSampling::kThesisCode ? "thesis" : "uniform";
}

Json optional_number(const std::optional<double>& value) {
  return value ? Json(*value) : Json(nullptr);
}

Json optional_array(const std::array<std::optional<double>, 3>& values) {
  Json a = Json::array();
  for (const std::optional<double>& v : values) a.push_back(optional_number(v));
  return a;
}

Json kappa_json(const CfmResult& r) {
  Json k = Json::array();
  for (double kappa : r.kappa) k.push_back(kappa > 0.0 ? Json(kappa) : Json(nullptr));
  return k;
}

Json result_json(const CfmResult& r, const CfmOptions& options) {
  Json j;
  j["config"] = r.config;
  j["class"] = r.class_name;
  j["R"] = r.R;
  j["K1"] = r.K1;
  j["K2"] = r.K2;
  j["d"] = r.requested_stroke_percent;
  j["Phi"] = r.Phi;
  // Xi = Phi_max/Phi_min is unbounded when the force vanishes: null, not rounding noise.
  j["Xi"] = r.force_vanishes ? Json(nullptr) : Json(r.Xi);
  j["percent_constant_force"] = r.percent_constant_force;
  j["stroke_percent"] = r.stroke_percent;
  j["toggle_stroke_percent"] = r.toggle_stroke_percent;
  j["stroke_clamped"] = r.stroke_clamped;
  j["lambda"] = r.lambda;
  j["beta"] = r.beta;
  j["Phi_min"] = r.Phi_min;
  j["force_vanishes"] = r.force_vanishes;
  j["Phi_max"] = r.Phi_max;
  j["kappa"] = kappa_json(r);
  j["primary_pivot"] = r.primary_pivot;
  j["Psi_raw"] = r.Psi_raw;
  j["Psi"] = optional_number(r.Psi);
  j["C"] = optional_array(r.C);
  j["D_equal"] = optional_array(r.D_equal);
  j["D_min"] = optional_array(r.D_min);
  j["d_N_max"] = r.d_N_max;
  j["sampling"] = sampling_name(options);
  j["points"] = r.iterations;
  j["converged"] = r.converged();
  j["message"] = r.message;
  j["residual"] = r.residual;
  if (options.keep_curve) {
    Json stroke = Json::array(), phi = Json::array(), theta2 = Json::array(),
         theta3 = Json::array();
    for (const cfm::CfmCurvePoint& p : r.curve) {
      stroke.push_back(p.stroke_percent);
      phi.push_back(p.Phi);
      theta2.push_back(p.theta2);
      theta3.push_back(p.theta3);
    }
    j["curve"] = {{"stroke_percent", stroke}, {"Phi", phi}, {"theta2", theta2}, {"theta3", theta3}};
  }
  return j;
}

void print_report(const CfmResult& r, const CfmOptions& options) {
  fmt::print("Configuration {}-{}  R = {:g}  K1 = {:g}  K2 = {:g}\n",
             r.class_name,
             r.config,
             r.R,
             r.K1,
             r.K2);
  fmt::print("  stroke d          = {:g} % of r2 + r3{}\n",
             r.stroke_percent,
             r.stroke_clamped ? fmt::format(" (requested {:g} %, clamped at the toggle position)",
                                            r.requested_stroke_percent)
                              : "");
  fmt::print("  Phi (mean)        = {:.6f}   {} = F r2/{}\n",
             r.Phi,
             r.class_name == "1B" ? "Phi'" : "Phi",
             r.class_name == "1B" ? "k2" : "k1");
  if (r.force_vanishes) {
    fmt::print("  Xi = max/min      = unbounded (the force vanishes)\n");
  } else {
    fmt::print("  Xi = max/min      = {:.6f}\n", r.Xi);
  }
  fmt::print("  percent constant  = {:.4f} %\n", r.percent_constant_force);
  fmt::print("  lambda            = {:.5f}\n", r.lambda);
  fmt::print("  beta              = {:.5f}\n", r.beta);
  fmt::print("  kappa             = {:.4f} {:.4f} {:.4f}\n", r.kappa[0], r.kappa[1], r.kappa[2]);
  fmt::print("  primary pivot     = {}\n", r.primary_pivot);
  fmt::print("  Psi               = {}  (raw {:.6g})\n",
             r.Psi ? fmt::format("{:.4f}", *r.Psi) : std::string("- (only for d = 16 or 40)"),
             r.Psi_raw);
  fmt::print("  d_N max           = {:.3f} % of r2 + r3\n", r.d_N_max);
  fmt::print("  {} stroke points ({} sampling)\n", r.iterations, sampling_name(options));
  for (const cfm::CfmCurvePoint& p : r.curve) {
    fmt::print("  {:10.5f} %  Phi = {:.8f}  theta2 = {:.8f}  theta3 = {:.8f}\n",
               p.stroke_percent,
               p.Phi,
               p.theta2,
               p.theta3);
  }
}

void run_config(const CfmArgs& args) {
  if (!*args.R_option) throw InvalidInput("--R (r3/r2) is required with --config");
  if (!*args.d_option) throw InvalidInput("--d (stroke, % of r2 + r3, 0 < d <= 100) is required");
  CfmParameters p;
  p.config = args.config;
  p.R = args.R;
  if (*args.K1_option) p.K1 = args.K1;
  if (*args.K2_option) p.K2 = args.K2;
  p.stroke_percent = args.d;
  const CfmOptions options = make_options(args, StrokeSampling::kThesisCode);
  const CfmResult r = evaluate_or_throw(CfmModel(options), p);
  warn(r.warnings);  // a stroke clamped at the toggle, a force that vanishes
  std::optional<cfm::CfmExactResult> e;
  if (args.exact) e = solve_exact_or_throw(r, args);
  if (args.json) {
    Json j = result_json(r, options);
    if (e) add_exact_json(j, *e, args.curve);
    print_json(j);
  } else {
    print_report(r, options);
    if (e) print_exact_report(*e, args.curve);
  }
}

Json printed_subclass_json(const CfmSubclass& row) {
  return Json{
      {"percent_constant_force", row.percent_constant_force},
      {"Phi", row.Phi},
      {"beta", row.beta},
      {"lambda", row.lambda},
      {"Psi", row.Psi},
      {"kappa",
       {optional_number(row.kappa1), optional_number(row.kappa2), optional_number(row.kappa3)}},
      {"primary_pivot", row.primary_pivot},
      {"M", row.M},
      {"n", row.n},
      {"d_N_max", row.d_N_max},
      {"toggle_clamped", row.toggle_clamped}};
}

void run_subclass(const CfmArgs& args) {
  if (const CfmClassRow* row = cfm::find_class_row(args.subclass)) {
    const CfmOptions options = make_options(args, StrokeSampling::kUniform);
    const CfmResult r = evaluate_or_throw(CfmModel(options), cfm::parameters_of(*row));
    warn(r.warnings);  // a stroke clamped at the toggle, a force that vanishes
    std::optional<cfm::CfmExactResult> e;
    if (args.exact) e = solve_exact_or_throw(r, args);
    if (args.json) {
      Json j = result_json(r, options);
      if (e) add_exact_json(j, *e, args.curve);
      j["subclass"] = row->name;
      j["printed"] = {{"Xi", row->Xi},
                      {"Phi", row->Phi},
                      {"K1", optional_number(row->K1)},
                      {"K2", optional_number(row->K2)},
                      {"reproducible", row->reproducible}};
      print_json(j);
    } else {
      fmt::print("{} (class {})\n", row->name, row->class_name);
      print_report(r, options);
      fmt::print("  printed: Xi = {:.4f}, Phi = {:.4f}{}\n",
                 row->Xi,
                 row->Phi,
                 row->reproducible ? "" : "  (not reproducible from the printed inputs, see docs)");
      if (e) print_exact_report(*e, args.curve);
    }
    return;
  }
  const CfmSubclass& row = cfm::find_thesis_subclass(args.subclass);
  const CfmOptions options = make_options(args, StrokeSampling::kThesisCode);
  const CfmResult r = evaluate_or_throw(CfmModel(options), cfm::parameters_of(row));
  warn(r.warnings);  // a stroke clamped at the toggle, a force that vanishes
  std::optional<cfm::CfmExactResult> e;
  if (args.exact) e = solve_exact_or_throw(r, args);
  if (args.json) {
    Json j = result_json(r, options);
    if (e) add_exact_json(j, *e, args.curve);
    j["subclass"] = row.name;
    j["printed"] = printed_subclass_json(row);
    for (const cfm::CfmThicknessRatios& ratios : cfm::thesis_thickness_ratios()) {
      if (std::string(ratios.name) != row.name) continue;
      j["printed"]["C"] = optional_array(ratios.C);
      j["printed"]["D_equal"] = optional_array(ratios.D_equal);
      j["printed"]["D_min"] = optional_array(ratios.D_min);
    }
    print_json(j);
    return;
  }
  fmt::print("Sub-class {}\n", row.name);
  print_report(r, options);
  fmt::print(
      "  printed: Xi' = {:.1f}, Phi = {:.4f}, beta = {:.3f}, lambda = {:.3f}, Psi = {:.3f}, "
      "p = {}, d_N max = {:.2f}\n",
      row.percent_constant_force,
      row.Phi,
      row.beta,
      row.lambda,
      row.Psi,
      row.primary_pivot,
      row.d_N_max);
  if (e) print_exact_report(*e, args.curve);
}

void run_list(const CfmArgs& args) {
  if (args.json) {
    Json subclasses = Json::array();
    for (const CfmSubclass& row : cfm::thesis_subclasses()) {
      subclasses.push_back({{"name", row.name},
                            {"config", row.config},
                            {"class", cfm::find_cfm_configuration(row.config).class_name},
                            {"d", row.stroke_percent},
                            {"R", row.R},
                            {"K1", row.K1},
                            {"K2", row.K2}});
    }
    Json class_rows = Json::array();
    for (const auto* table : {&cfm::thesis_table_2_1(), &cfm::howell_table_10_1()}) {
      for (const CfmClassRow& row : *table) {
        class_rows.push_back({{"name", row.name},
                              {"class", row.class_name},
                              {"config", row.config},
                              {"d", row.stroke_percent},
                              {"R", row.R},
                              {"K1", optional_number(row.K1)},
                              {"K2", optional_number(row.K2)}});
      }
    }
    print_json(Json{{"subclasses", subclasses}, {"class_rows", class_rows}});
    return;
  }
  fmt::print(
      "Thesis sub-classes (Weight 2001, Tables 7.2-7.12), evaluated with the thesis code's "
      "stroke sampling:\n");
  fmt::print("  {:<12} {:<5} {:>4} {:>8} {:>8} {:>8}\n", "name", "class", "d", "R", "K1", "K2");
  for (const CfmSubclass& row : cfm::thesis_subclasses()) {
    fmt::print("  {:<12} {:<5} {:>4g} {:>8.4f} {:>8.4f} {:>8.4f}{}\n",
               row.name,
               cfm::find_cfm_configuration(row.config).class_name,
               row.stroke_percent,
               row.R,
               row.K1,
               row.K2,
               row.toggle_clamped ? "  (stroke clamped at the toggle)" : "");
  }
  fmt::print("Class-level rows (thesis Table 2.1, Howell Table 10.1), 50 equally spaced points:\n");
  for (const auto* table : {&cfm::thesis_table_2_1(), &cfm::howell_table_10_1()}) {
    for (const CfmClassRow& row : *table) {
      fmt::print("  {:<16} {:<3} as {}  d = {:g}  R = {:.4f}{}{}\n",
                 row.name,
                 row.class_name,
                 row.config,
                 row.stroke_percent,
                 row.R,
                 row.K1 ? fmt::format("  K1 = {:.4f}", *row.K1) : "",
                 row.K2 ? fmt::format("  K2 = {:.4f}", *row.K2) : "");
    }
  }
}

void run_cfm(const CfmArgs& args) {
  const int modes = (args.list ? 1 : 0) + (args.table ? 1 : 0) + (!args.subclass.empty() ? 1 : 0) +
                    (*args.config_option ? 1 : 0);
  if (modes != 1) {
    throw InvalidInput(
        "give exactly one of --config CFG (with --R and --d), --subclass NAME, --list, --table");
  }
  // A sub-class, --list and --table fix R, K1, K2 and d themselves; a value given beside them
  // would be silently ignored.
  if (!*args.config_option &&
      (*args.R_option || *args.K1_option || *args.K2_option || *args.d_option)) {
    throw InvalidInput(
        "--R, --K1, --K2 and --d go with --config (a --subclass, --list or --table row has its "
        "own)");
  }
  if (args.markdown && !args.table) throw InvalidInput("--markdown goes with --table");
  if (args.list && args.exact) throw InvalidInput("--exact does not go with --list");
  if (args.list) return run_list(args);
  if (!args.exact &&
      (*args.exact_points_option || *args.exact_max_iterations_option || *args.exact_rows_option)) {
    throw InvalidInput("--exact-points, --exact-max-iterations and --exact-rows go with --exact");
  }
  if (args.table && args.exact) return run_exact_table(args);
  if (args.table) return run_table(args);
  if (!args.subclass.empty()) return run_subclass(args);
  run_config(args);
}

}  // namespace

Json cfm_result_json(const CfmResult& r, const CfmOptions& options) {
  return result_json(r, options);
}

cfm::CfmExactOptions make_exact_options(const CfmArgs& args) {
  cfm::CfmExactOptions options;
  require_in_range(
      args.exact_points, "--exact-points (stroke points of the exact model)", 2, 100000);
  options.points = args.exact_points;
  if (*args.exact_max_iterations_option) {
    // Diagnostic: caps every Newton iteration count of the exact solve (shooting Newton, the
    // middle-pin Newton, continuation steps), e.g. to see where a hard point stops.
    require_in_range(args.exact_max_iterations, "--exact-max-iterations", 1, 1000);
    options.solver.shooting.newton.max_iterations = args.exact_max_iterations;
    options.solver.shooting.continuation.max_steps = args.exact_max_iterations;
    options.solver.max_newton_iterations = args.exact_max_iterations;
  }
  return options;
}

void add_exact_json(Json& j, const cfm::CfmExactResult& e, bool curve) {
  j["Phi_exact"] = e.Phi_exact;
  j["percent_constant_force_exact"] = e.percent_constant_force_exact;
  j["force_vanishes_exact"] = e.force_vanishes_exact;
  j["force_changes_sign_exact"] = e.force_changes_sign_exact;
  j["max_force_error"] = e.max_force_error;
  j["max_force_error_at_stroke_percent"] = e.max_force_error_at_percent;
  j["exact_points"] = e.stroke_percent.size();
  // The PRBM on the exact model's grid (equally spaced points), for a like-for-like comparison.
  j["Phi_prbm_exact_grid"] = e.Phi_prbm_mean;
  j["percent_constant_force_prbm_exact_grid"] = e.percent_constant_force_prbm;
  j["exact_iterations"] = e.iterations;
  j["exact_residual"] = e.residual;
  j["exact_message"] = e.message;
  if (curve) {
    j["exact_curve"] = {{"stroke_percent", e.stroke_percent},
                        {"Phi_prbm", e.Phi_prbm},
                        {"Phi_exact", e.Phi_exact_curve}};
  }
}

CfmResult evaluate_or_throw(const CfmModel& model, const CfmParameters& p) {
  CfmResult r = model.evaluate(p);
  if (!r.converged()) throw NoConvergence("cfm model: " + r.message);
  for (double v : {r.Phi, r.Xi, r.percent_constant_force, r.beta, r.lambda}) {
    require_finite_result(v, "cfm result");
  }
  return r;
}

void register_cfm_command(CLI::App& app) {
  auto args = std::make_shared<CfmArgs>();
  CLI::App* cfm = app.add_subcommand(
      "cfm", "Constant-force slider mechanism, nondimensional PRBM (Weight 2001, Howell §10.1)");
  args->config_option = cfm->add_option(
      "--config", args->config, "Configuration: spp, lpp, psp, plp, ssp, slp, sps, lps, sss");
  args->R_option = cfm->add_option("--R", args->R, "R = r3/r2 (> 0)");
  args->K1_option = cfm->add_option("--K1", args->K1, "K1 = k2/k1 (>= 0; 1B: 1)");
  args->K2_option = cfm->add_option("--K2", args->K2, "K2 = k3/k1 (>= 0)");
  args->d_option = cfm->add_option("--d", args->d, "Stroke d, % of r2 + r3 (0 < d <= 100)");
  cfm->add_option("--subclass", args->subclass, "Evaluate a built-in sub-class, e.g. lpp-b");
  cfm->add_option("--sampling", args->sampling, "Stroke sampling: thesis (default) or uniform")
      ->default_str("auto");
  args->points_option =
      cfm->add_option("--points", args->points, "Points for --sampling uniform")->default_str("50");
  cfm->add_flag("--curve", args->curve, "Also print Phi, theta2, theta3 at every stroke point");
  cfm->add_flag("--list", args->list, "List the built-in sub-classes and table rows");
  cfm->add_flag("--table", args->table, "Recompute every printed row beside the printed values");
  cfm->add_flag("--markdown", args->markdown, "With --table: Markdown tables (docs/cfm.md)");
  cfm->add_flag("--json", args->json, "Print one JSON object");
  cfm->add_flag("--exact",
                args->exact,
                "Also solve the same mechanism with the exact (elastica) model (docs/cfm.md)");
  args->exact_points_option =
      cfm->add_option("--exact-points", args->exact_points, "Stroke points of the exact model")
          ->default_str("50");
  args->exact_max_iterations_option = cfm->add_option(
      "--exact-max-iterations",
      args->exact_max_iterations,
      "Diagnostic cap on every Newton iteration count of the exact solve (1..1000)");
  args->exact_rows_option =
      cfm->add_option("--exact-rows", args->exact_rows, "With --table --exact: a (default) or all")
          ->default_str("a");
  cfm->callback([args] { run_cfm(*args); });
}

}  // namespace flexure::cli
