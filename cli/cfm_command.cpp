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
//                                             mechanism (mechanisms/cfm/cfm_exact.h); with
//                                             --table: PRBM vs exact for the sub-class rows
//
// A stroke past the toggle position is clamped as in the thesis (stroke_percent reports the
// effective stroke) with a warning on stderr.
#include <fmt/format.h>

#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "mechanisms/cfm/cfm_comparison.h"
#include "mechanisms/cfm/cfm_exact.h"
#include "mechanisms/cfm/cfm_model.h"
#include "mechanisms/cfm/cfm_subclasses.h"
#include "solver/common/errors.h"

namespace flexure::cli {
namespace {

using cfm::CfmClassRow;
using cfm::CfmModel;
using cfm::CfmOptions;
using cfm::CfmParameters;
using cfm::CfmResult;
using cfm::CfmSubclass;
using cfm::StrokeSampling;

// Class 1B: the mean of a force rising steeply from Delta x = 0 depends on sampling details at
// ~1e-3 (book digest §6.1: with and without the Delta x -> 0 point the Table 10.1 row is
// bracketed), so 1B class rows get this extra allowance in --table.
constexpr double kClass1BSamplingAllowance = 2e-3;

struct CfmArgs {
  std::string config;
  double R = 0.0;
  double K1 = 0.0;
  double K2 = 0.0;
  double d = 0.0;
  std::string subclass;
  std::string sampling = "auto";
  int points = 50;
  bool curve = false;
  bool list = false;
  bool table = false;
  bool markdown = false;
  bool json = false;
  bool exact = false;
  int exact_points = 50;
  int exact_max_iterations = 0;
  std::string exact_rows = "a";
  CLI::Option* config_option = nullptr;
  CLI::Option* R_option = nullptr;
  CLI::Option* K1_option = nullptr;
  CLI::Option* K2_option = nullptr;
  CLI::Option* d_option = nullptr;
  CLI::Option* points_option = nullptr;
  CLI::Option* exact_points_option = nullptr;
  CLI::Option* exact_max_iterations_option = nullptr;
  CLI::Option* exact_rows_option = nullptr;
};

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

cfm::CfmExactResult solve_exact_or_throw(const CfmResult& r, const CfmArgs& args) {
  cfm::CfmExactResult e = cfm::solve_cfm_exact(r, make_exact_options(args));
  if (!e.converged) throw NoConvergence("cfm --exact: exact model: " + e.message);
  return e;
}

void add_exact_json(Json& j, const cfm::CfmExactResult& e, bool curve) {
  j["Phi_exact"] = e.Phi_exact;
  j["percent_constant_force_exact"] = e.percent_constant_force_exact;
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
  j["Xi"] = r.Xi;
  j["percent_constant_force"] = r.percent_constant_force;
  j["stroke_percent"] = r.stroke_percent;
  j["toggle_stroke_percent"] = r.toggle_stroke_percent;
  j["stroke_clamped"] = r.stroke_clamped;
  j["lambda"] = r.lambda;
  j["beta"] = r.beta;
  j["Phi_min"] = r.Phi_min;
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
  j["converged"] = r.converged;
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

void warn_if_clamped(const CfmResult& r) {
  if (!r.stroke_clamped) return;
  fmt::print(stderr,
             "flexure: warning: stroke d = {:g} % is past the toggle position of R = {:g}; "
             "clamped to {:.4f} % as in the thesis (stroke_percent)\n",
             r.requested_stroke_percent,
             r.R,
             r.stroke_percent);
}

CfmResult evaluate_or_throw(const CfmModel& model, const CfmParameters& p) {
  CfmResult r = model.evaluate(p);
  if (!r.converged) throw NoConvergence("cfm model: " + r.message);
  for (double v : {r.Phi, r.Xi, r.percent_constant_force, r.beta, r.lambda}) {
    require_finite_result(v, "cfm result");
  }
  return r;
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
  fmt::print("  Xi = max/min      = {:.6f}\n", r.Xi);
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
  warn_if_clamped(r);
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
    warn_if_clamped(r);
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
  warn_if_clamped(r);
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

std::string cell(const cfm::PrintedComparison& c, int decimals) {
  return fmt::format(
      "{:.{}f} / {:.{}f}{}", c.computed, decimals + 1, c.printed, decimals, c.within() ? "" : " ✗");
}

Json comparison_json(const cfm::PrintedComparison& c) {
  return Json{{"computed", c.computed},
              {"printed", c.printed},
              {"tolerance", c.tolerance},
              {"within", c.within()}};
}

// Largest |computed - printed|/tolerance of one quantity over the sub-class rows.
struct WorstRatio {
  const char* quantity = "";
  double ratio = 0.0;
  std::string row;
  void update(const cfm::PrintedComparison& c, const std::string& name) {
    const double r = std::abs(c.deviation()) / c.tolerance;
    if (r > ratio) {
      ratio = r;
      row = name;
    }
  }
};

void run_table(const CfmArgs& args) {
  bool all_ok = true;
  std::array<WorstRatio, 6> worst;
  for (std::size_t i = 0; i < worst.size(); ++i) {
    worst[i].quantity = std::array{"Phi", "Xi'", "beta", "lambda", "Psi", "d_N max"}[i];
  }
  Json subclass_rows = Json::array();
  Json class_rows = Json::array();
  if (args.markdown) {
    fmt::print(
        "| Sub-class | d (eff.) | Phi computed / printed | Xi' | beta | lambda | Psi | "
        "d_N max | p | within |\n|---|---|---|---|---|---|---|---|---|---|\n");
  } else if (!args.json) {
    fmt::print("Thesis sub-classes: computed / printed (✗ = outside rounding tolerance)\n");
  }
  for (const CfmSubclass& row : cfm::thesis_subclasses()) {
    const cfm::SubclassComparison c = cfm::compare_with_thesis(row);
    all_ok = all_ok && c.all_within();
    worst[0].update(c.Phi, row.name);
    worst[1].update(c.percent_constant_force, row.name);
    worst[2].update(c.beta, row.name);
    worst[3].update(c.lambda, row.name);
    worst[4].update(c.Psi, row.name);
    worst[5].update(c.d_N_max, row.name);
    const std::string pivot =
        fmt::format("{}/{}{}",
                    c.result.primary_pivot,
                    row.primary_pivot,
                    c.primary_pivot_tie ? " (tie)" : (c.primary_pivot_matches ? "" : " ✗"));
    if (args.json) {
      subclass_rows.push_back(
          {{"name", row.name},
           {"stroke_percent", c.result.stroke_percent},
           {"Phi", comparison_json(c.Phi)},
           {"percent_constant_force", comparison_json(c.percent_constant_force)},
           {"beta", comparison_json(c.beta)},
           {"lambda", comparison_json(c.lambda)},
           {"Psi", comparison_json(c.Psi)},
           {"d_N_max", comparison_json(c.d_N_max)},
           {"primary_pivot", c.result.primary_pivot},
           {"primary_pivot_printed", row.primary_pivot},
           {"primary_pivot_tie", c.primary_pivot_tie},
           {"within", c.all_within()}});
      continue;
    }
    const std::string stroke =
        c.result.stroke_clamped
            ? fmt::format("{:g} → {:.2f}", row.stroke_percent, c.result.stroke_percent)
            : fmt::format("{:g}", row.stroke_percent);
    if (args.markdown) {
      fmt::print("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
                 row.name,
                 stroke,
                 cell(c.Phi, 4),
                 cell(c.percent_constant_force, 1),
                 cell(c.beta, 3),
                 cell(c.lambda, 3),
                 cell(c.Psi, 3),
                 cell(c.d_N_max, 2),
                 pivot,
                 c.all_within() ? "yes" : "**no**");
    } else {
      fmt::print(
          "  {:<11} d {:<12} Phi {:<20} Xi' {:<14} beta {:<22} lambda {:<14} Psi {:<14} "
          "dN {:<16} p {}\n",
          row.name,
          stroke,
          cell(c.Phi, 4),
          cell(c.percent_constant_force, 1),
          cell(c.beta, 3),
          cell(c.lambda, 3),
          cell(c.Psi, 3),
          cell(c.d_N_max, 2),
          pivot);
    }
  }
  if (!args.json) {
    fmt::print("{}Largest |computed - printed| / tolerance over the 68 rows:",
               args.markdown ? "\n" : "");
    for (const WorstRatio& w : worst) {
      fmt::print(
          " {} {:.2f} ({}){}", w.quantity, w.ratio, w.row, &w == &worst.back() ? ".\n" : ";");
    }
  }

  // Thickness and width ratios (Tables 7.7, 7.10, 7.13).
  Json ratio_rows = Json::array();
  std::vector<std::string> ratio_lines;
  for (const cfm::CfmThicknessRatios& row : cfm::thesis_thickness_ratios()) {
    const cfm::RatioComparison c = cfm::compare_with_thesis_ratios(row);
    all_ok = all_ok && c.all_within();
    auto cells = [&](const std::array<std::optional<cfm::PrintedComparison>, 3>& field) {
      std::string text;
      Json values = Json::array();
      for (const std::optional<cfm::PrintedComparison>& v : field) {
        text += text.empty() ? "" : ", ";
        text += v ? cell(*v, row.decimals) : "–";
        values.push_back(v ? comparison_json(*v) : Json(nullptr));
      }
      return std::pair{text, values};
    };
    const auto [C_text, C_json] = cells(c.C);
    const auto [De_text, De_json] = cells(c.D_equal);
    const auto [Dm_text, Dm_json] = cells(c.D_min);
    if (args.json) {
      ratio_rows.push_back({{"name", row.name},
                            {"C", C_json},
                            {"D_equal", De_json},
                            {"D_min", Dm_json},
                            {"within", c.all_within()}});
    } else {
      ratio_lines.push_back(
          fmt::format(fmt::runtime(args.markdown ? "| {} | {} | {} | {} | {} |"
                                                 : "  {:<11} C {}  D_equal {}  D_min {}  {}"),
                      row.name,
                      C_text,
                      De_text,
                      Dm_text,
                      c.all_within() ? "yes" : "**no**"));
    }
  }
  if (!args.json) {
    fmt::print("{}",
               args.markdown ? "\n| Sub-class | C1, C2, C3 | D_equal 1, 2, 3 | D_min 1, 2, 3 | "
                               "within |\n|---|---|---|---|---|\n"
                             : "Thickness and width ratios (Tables 7.7, 7.10, 7.13): computed / "
                               "printed\n");
    for (const std::string& line : ratio_lines) fmt::print("{}\n", line);
  }
  if (args.markdown) {
    fmt::print(
        "\n| Row | class as | d (eff.) | Xi computed / printed | Phi computed / printed | "
        "within |\n|---|---|---|---|---|---|\n");
  } else if (!args.json) {
    fmt::print("Class rows (50 equally spaced points): computed / printed\n");
  }
  for (const auto* table : {&cfm::thesis_table_2_1(), &cfm::howell_table_10_1()}) {
    for (const CfmClassRow& row : *table) {
      const double extra = std::string(row.class_name) == "1B" ? kClass1BSamplingAllowance : 0.0;
      const cfm::ClassRowComparison c = cfm::compare_with_class_row(row, extra);
      const bool within = c.Xi.within() && c.Phi.within();
      if (row.reproducible) all_ok = all_ok && within;
      const std::string verdict = within             ? "yes"
                                  : row.reproducible ? "**no**"
                                                     : "no (printed K2 inconsistent, see text)";
      if (args.json) {
        class_rows.push_back({{"name", row.name},
                              {"stroke_percent", c.result.stroke_percent},
                              {"Xi", comparison_json(c.Xi)},
                              {"Phi", comparison_json(c.Phi)},
                              {"reproducible", row.reproducible},
                              {"within", within}});
        continue;
      }
      const std::string stroke =
          c.result.stroke_clamped
              ? fmt::format("{:g} → {:.2f}", row.stroke_percent, c.result.stroke_percent)
              : fmt::format("{:g}", row.stroke_percent);
      if (args.markdown) {
        fmt::print("| {} | {} | {} | {} | {} | {} |\n",
                   row.name,
                   row.config,
                   stroke,
                   cell(c.Xi, 4),
                   cell(c.Phi, 4),
                   verdict);
      } else {
        fmt::print("  {:<16} d {:<12} Xi {:<22} Phi {:<22} {}\n",
                   row.name,
                   stroke,
                   cell(c.Xi, 4),
                   cell(c.Phi, 4),
                   verdict);
      }
    }
  }
  if (args.json) {
    print_json(
        Json{{"subclasses", subclass_rows}, {"class_rows", class_rows}, {"all_within", all_ok}});
  }
  if (!all_ok) set_exit_code(kExitCheckFailed);
}

// --table --exact: the thesis sub-classes (the nine "a" rows, or all 68) solved with the exact
// model. The thesis optimised the PRBM only, so Phi and Xi' differ; docs/validation.md lists them.
void run_exact_table(const CfmArgs& args) {
  if (args.exact_rows != "a" && args.exact_rows != "all") {
    throw InvalidInput(
        fmt::format("--exact-rows = '{}' is unknown; allowed: a, all", args.exact_rows));
  }
  bool all_converged = true;
  Json rows = Json::array();
  if (args.markdown) {
    fmt::print(
        "| Sub-class | d (eff.) | Phi printed | Phi PRBM | Phi exact | Xi' printed | Xi' PRBM | "
        "Xi' exact | max force error (at d) |\n|---|---|---|---|---|---|---|---|---|\n");
  } else if (!args.json) {
    fmt::print(
        "Thesis sub-classes, PRBM and exact model on {} equally spaced points (Phi, Xi' in %)\n",
        args.exact_points);
  }
  for (const CfmSubclass& row : cfm::thesis_subclasses()) {
    const std::string name = row.name;
    // Sub-class "a" of each configuration: "lpp-a", "slp-aIo" (not "lpp-a99", "slp-a90I").
    const std::size_t dash = name.find('-');
    const bool is_a = name.size() > dash + 1 && name[dash + 1] == 'a' &&
                      (name.size() == dash + 2 || !std::isdigit(name[dash + 2]));
    if (args.exact_rows == "a" && !is_a) continue;
    const CfmResult r = evaluate_or_throw(CfmModel(), cfm::parameters_of(row));
    const cfm::CfmExactResult e = cfm::solve_cfm_exact(r, make_exact_options(args));
    all_converged = all_converged && e.converged;
    const std::string stroke = r.stroke_clamped ? fmt::format("{:.2f}", r.stroke_percent)
                                                : fmt::format("{:g}", r.stroke_percent);
    if (args.json) {
      Json j{{"name", row.name},
             {"stroke_percent", r.stroke_percent},
             {"Phi_printed", row.Phi},
             {"percent_constant_force_printed", row.percent_constant_force},
             {"Phi", r.Phi},
             {"percent_constant_force", r.percent_constant_force},
             {"converged", e.converged}};
      if (e.converged) {
        add_exact_json(j, e, false);
      } else {
        j["exact_message"] = e.message;
      }
      rows.push_back(j);
      continue;
    }
    const std::string phi_exact = e.converged ? fmt::format("{:.4f}", e.Phi_exact) : "–";
    const std::string xi_exact =
        e.converged ? fmt::format("{:.1f}", e.percent_constant_force_exact) : "–";
    const std::string error =
        e.converged
            ? fmt::format(
                  "{:.2f} % ({:.1f})", 100.0 * e.max_force_error, e.max_force_error_at_percent)
            : "not converged (" + e.message.substr(0, e.message.find("): ") + 1) + ")";
    fmt::print(fmt::runtime(args.markdown
                                ? "| {} | {} | {:.4f} | {:.4f} | {} | {:.1f} | {:.1f} | {} | {} |\n"
                                : "  {:<11} d {:<6} Phi {:.4f} / {:.4f} / {:<8} Xi' {:.1f} / "
                                  "{:.1f} / {:<6} error {}\n"),
               row.name,
               stroke,
               row.Phi,
               e.Phi_prbm_mean,
               phi_exact,
               row.percent_constant_force,
               e.percent_constant_force_prbm,
               xi_exact,
               error);
  }
  if (args.json) print_json(Json{{"points", args.exact_points}, {"subclasses", rows}});
  if (!all_converged) set_exit_code(kExitNoConvergence);
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
