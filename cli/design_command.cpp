// `flexure design cfm`: synthesis of a constant-force mechanism's R, K1, K2 for an objective
// under the thesis's constraints (mechanisms/design/cfm_synthesis.h, docs/design.md).
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include "cli/cfm_cli_support.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/csv_output.h"
#include "cli/slow_progress.h"
#include "flexure/benchmarks/studies/subclass_table.h"
#include "flexure/io/design_history_file.h"
#include "flexure/io/platform/mpi_world.h"
#include "flexure/io/platform/output_path.h"
#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/design/cfm_synthesis.h"
#include "flexure/mechanisms/design/subclass_problem.h"
#include "flexure/mechanisms/design/subclass_rederivation.h"
#include "flexure/solver/common/status.h"

namespace flexure::cli {
namespace {

struct DesignCfmArgs {
  std::string subclass;
  std::string model = "prbm";
  int exact_starts = -1;  // --exact-starts; -1: two per free variable
  std::string out;        // --out run.h5: the convergence history
  std::string csv;        // --csv FILE: the history (or the table) as CSV
  std::string config;
  double d = 0.0;
  std::string objective;
  double pcf_min = 0.0;
  std::string orientation;
  std::string rule_limits;
  double K1 = 0.0;
  double K2 = 0.0;
  std::string sampling = "auto";
  int points = 50;
  int starts = 0;
  int scan_points = 0;
  int coarse_stride = design::SynthesisOptions{}.coarse_stride;
  unsigned long seed = design::SynthesisOptions{}.seed;
  bool json = false;
  bool all_subclasses = false;
  CLI::Option* pcf_min_option = nullptr;
  CLI::Option* config_option = nullptr;
  CLI::Option* d_option = nullptr;
  CLI::Option* objective_option = nullptr;
  CLI::Option* orientation_option = nullptr;
  CLI::Option* K1_option = nullptr;
  CLI::Option* K2_option = nullptr;
  CLI::Option* points_option = nullptr;
};

// --rule-limits "O:C>=0.99,o:D_equal<=10.4": limits of the orientation rules other than the
// thesis's (Table 5.4), written as the constraints are named in the output.
void apply_rule_limits(const std::string& text, design::OrientationLimits& limits) {
  std::size_t begin = 0;
  while (begin < text.size()) {
    const std::size_t end = std::min(text.find(',', begin), text.size());
    const std::string item = text.substr(begin, end - begin);
    begin = end + 1;
    const std::size_t op = item.find_first_of("<>");
    if (op == std::string::npos || op + 2 > item.size() || item[op + 1] != '=') {
      throw InvalidInput(
          fmt::format("--rule-limits item '{}': write RULE:RATIO<=VALUE or RULE:RATIO>=VALUE, e.g. "
                      "O:C>=0.99 or o:D_equal<=10.4",
                      item));
    }
    const std::string key = item.substr(0, op);
    const bool upper = item[op] == '<';
    double value = 0.0;
    try {
      std::size_t used = 0;
      value = std::stod(item.substr(op + 2), &used);
      if (used != item.size() - op - 2) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw InvalidInput(fmt::format("--rule-limits item '{}': the value is not a number", item));
    }
    if (!(std::isfinite(value) && value > 0.0)) {
      throw InvalidInput(fmt::format("--rule-limits item '{}': the value must be > 0", item));
    }
    if (key == "I:D_min" && upper) {
      limits.I_D_min_max = value;
    } else if ((key == "O:C" || key == "o:C") && !upper) {
      limits.C_min = value;  // one limit for both rules, as Table 5.4
    } else if (key == "O:D_equal" || key == "o:D_equal") {
      design::Bounds& b = key[0] == 'O' ? limits.O_D_equal : limits.o_D_equal;
      (upper ? b.upper : b.lower) = value;
    } else {
      throw InvalidInput(fmt::format(
          "--rule-limits item '{}': the rules are I:D_min<=, O:C>=, o:C>=, O:D_equal>= or <=, "
          "o:D_equal>= or <=",
          item));
    }
  }
}

// --exact-starts: 0..1000 and only with --model exact (-1 is the default, two per variable).
void check_exact_starts(const DesignCfmArgs& args) {
  if (args.exact_starts == -1) return;
  if (args.model != "exact") throw InvalidInput("--exact-starts applies to --model exact only");
  require_in_range(args.exact_starts, "--exact-starts", 0, 1000);
}

design::CfmDesignProblem make_problem(const DesignCfmArgs& args) {
  design::CfmDesignProblem p;
  if (!args.subclass.empty()) {
    // The sub-class's own problem (Ch. 7 semantics); --config, --d, --objective, --pcf-min and
    // --orientation would contradict it.
    for (const CLI::Option* o : {args.config_option,
                                 args.d_option,
                                 args.objective_option,
                                 args.pcf_min_option,
                                 args.orientation_option}) {
      if (*o) {
        throw InvalidInput(fmt::format("--subclass sets the problem; drop {}", o->get_name()));
      }
    }
    p = design::subclass_problem(cfm::find_thesis_subclass(args.subclass)).problem;
  } else {
    if (!*args.config_option || !*args.d_option || !*args.objective_option) {
      throw InvalidInput("give --config, --d and --objective (or --subclass NAME)");
    }
    p.config = args.config;
    require_finite_input(args.d, "--d (stroke, % of r2 + r3)");
    p.stroke_percent = args.d;
    p.objective = design::design_objective_from_string(args.objective);
    if (*args.pcf_min_option) {
      require_in_range(args.pcf_min, "--pcf-min (percent constant force)", 1e-9, 100.0 - 1e-9);
      p.pcf_min = args.pcf_min;
    }
    p.orientation = design::orientation_rules_from_string(args.orientation);
  }
  apply_rule_limits(args.rule_limits, p.orientation_limits);
  if (*args.K1_option) p.fixed_K1 = args.K1;
  if (*args.K2_option) p.fixed_K2 = args.K2;
  if (args.model != "prbm" && args.model != "exact") {
    throw InvalidInput(fmt::format("--model '{}' is unknown; allowed: prbm, exact", args.model));
  }
  check_exact_starts(args);
  p.model = design::default_model_options(p.objective);
  if (args.sampling == "thesis") {
    p.model.sampling = cfm::StrokeSampling::kThesisCode;
  } else if (args.sampling == "uniform") {
    p.model.sampling = cfm::StrokeSampling::kUniform;
  } else if (args.sampling != "auto") {
    throw InvalidInput(
        fmt::format("--sampling = '{}' is unknown; allowed: auto, thesis, uniform", args.sampling));
  }
  if (*args.points_option) {
    if (p.model.sampling != cfm::StrokeSampling::kUniform) {
      throw InvalidInput("--points applies to the uniform sampling only (--sampling uniform)");
    }
    require_in_range(args.points, "--points (stroke points)", 2, 100000);
    p.model.points = args.points;
  }
  return p;
}

Json design_json(const design::CfmDesignProblem& p,
                 const design::CfmSynthesisResult& s,
                 unsigned long seed,
                 double seconds) {
  Json j = cfm_result_json(s.best.result, p.model);
  j["objective"] = to_string(p.objective);
  j["objective_value"] = s.best.objective;
  j["pcf_min"] = p.pcf_min ? Json(*p.pcf_min) : Json(nullptr);
  j["orientation"] = to_string(p.orientation);
  j["variables"] = s.variables;
  j["subclass"] = s.nearest_subclass ? Json(*s.nearest_subclass) : Json(nullptr);
  Json constraints = Json::array();
  for (const design::NamedConstraint& c : s.best.constraints) {
    constraints.push_back(Json{{"name", c.name},
                               {"value", c.value},
                               {"bound", c.bound},
                               {"sense", c.upper ? "<=" : ">="},
                               {"satisfied", c.satisfied()}});
  }
  j["constraints"] = std::move(constraints);
  j["evaluations"] = s.evaluations;
  j["full_sampling_evaluations"] = s.fine_evaluations;
  j["starts"] = s.starts;
  j["feasible_starts"] = s.feasible_starts;
  j["seed"] = seed;
  j["converged"] = s.converged();
  j["termination"] = termination_name(s.termination);
  j["message"] = s.message;
  j["seconds"] = seconds;  // wall time of the synthesis alone
  return j;
}

// --model exact: from the PRBM optimum, the printed sub-classes of the same configuration and
// stroke and a Halton sequence, the exact model's percent constant force maximised under the same
// constraints (cfm_synthesis.h).
void run_exact(const DesignCfmArgs& args,
               const design::CfmDesignProblem& problem,
               const design::CfmSynthesisResult& prbm,
               std::chrono::steady_clock::time_point start,
               std::optional<io::DesignHistoryFile>& file) {
  design::ExactRefinementOptions o;
  o.sequence_starts = args.exact_starts;  // -1: two per free variable
  o.progress = stoppable_progress("design cfm " + problem.config + " --model exact: exact strokes");
  const design::CfmExactRefinement r = design::refine_cfm_exact_from_prbm(problem, prbm, o);
  if (!r.converged()) {
    throw NoConvergenceReport(
        fmt::format("design cfm {} --model exact: {}", problem.config, r.message),
        Json{{"R", r.prbm.result.R},
             {"K1", r.prbm.result.K1},
             {"K2", r.prbm.result.K2},
             {"percent_constant_force_exact", r.percent_constant_force_exact},
             {"exact_evaluations", r.evaluations}});
  }
  if (file) file->write(problem, prbm, &r, args.seed);
  // The first start of the refinement is the PRBM optimum.
  const double prbm_exact = r.start_percent_constant_force_exact;
  if (args.json) {
    design::CfmSynthesisResult at_exact = prbm;
    at_exact.best = r.prbm;
    // Wall time of the PRBM synthesis and the exact optimisation together.
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    Json j = design_json(problem, at_exact, args.seed, seconds);
    j["model"] = "exact";
    j["objective"] = "max-pcf-exact";
    j["objective_value"] = r.percent_constant_force_exact;
    j["percent_constant_force_exact"] = r.percent_constant_force_exact;
    j["exact_evaluations"] = r.evaluations;
    j["exact_starts"] = r.starts;
    j["prbm_optimum"] = Json{{"R", prbm.best.result.R},
                             {"K1", prbm.best.result.K1},
                             {"K2", prbm.best.result.K2},
                             {"objective", to_string(problem.objective)},
                             {"objective_value", prbm.best.objective},
                             {"percent_constant_force", prbm.best.result.percent_constant_force},
                             {"percent_constant_force_exact", prbm_exact}};
    j["converged"] = r.converged();
    j["message"] = r.message;
    print_json(j);
    return;
  }
  const cfm::CfmResult& e = r.prbm.result;
  fmt::print("{} ({}), d = {:g} %: exact percent constant force {:.2f} % ({} exact strokes)\n",
             e.config,
             e.class_name,
             problem.stroke_percent,
             r.percent_constant_force_exact,
             r.evaluations);
  fmt::print("  R = {:.4f}, K1 = {:.4f}, K2 = {:.4f} (PRBM Xi' there {:.2f} %)\n",
             e.R,
             e.K1,
             e.K2,
             e.percent_constant_force);
  fmt::print(
      "  PRBM optimum ({} = {:.6g}): R = {:.4f}, K1 = {:.4f}, K2 = {:.4f}, exact Xi' "
      "{:.2f} %\n",
      to_string(problem.objective),
      prbm.best.objective,
      prbm.best.result.R,
      prbm.best.result.K1,
      prbm.best.result.K2,
      prbm_exact);
  for (const design::NamedConstraint& c : r.prbm.constraints) {
    fmt::print(
        "  constraint {}: {:.6g} ({})\n", c.name, c.value, c.satisfied() ? "met" : "VIOLATED");
  }
}

// --all-subclasses: the 68 rows of Ch. 7, each from its own problem (and with --model exact the
// exact optimum too); --out writes the table (docs/hdf5-schema.md).
void run_all_subclasses(const DesignCfmArgs& args) {
  for (const CLI::Option* o : {args.d_option,
                               args.objective_option,
                               args.pcf_min_option,
                               args.orientation_option,
                               args.K1_option,
                               args.K2_option}) {
    if (*o) {
      throw InvalidInput(fmt::format("--all-subclasses takes each sub-class's own problem; drop {}",
                                     o->get_name()));
    }
  }
  if (!args.subclass.empty()) throw InvalidInput("give --subclass or --all-subclasses, not both");
  if (args.model != "prbm" && args.model != "exact") {
    throw InvalidInput(fmt::format("--model '{}' is unknown; allowed: prbm, exact", args.model));
  }
  check_exact_starts(args);
  design::RederivationOptions o;
  o.exact = args.model == "exact";
  o.exact_starts = args.exact_starts;
  o.config = args.config;  // --config: only that configuration's rows
  o.synthesis.starts = args.starts;
  o.synthesis.scan_points = args.scan_points;
  o.synthesis.coarse_stride = args.coarse_stride;
  o.synthesis.seed = args.seed;
  const auto start = std::chrono::steady_clock::now();
  studies::SubclassTableOptions table;
  table.rederivation = o;
  const CsvOutput csv(args.out, args.csv);
  table.out = csv.hdf5_path();
  table.seed = args.seed;
  // Under mpirun the rows are divided over the ranks; rank 0 gets them all back and prints.
  const std::vector<design::SubclassRederivation> rows =
      studies::subclass_table(table, stoppable_progress("design cfm --all-subclasses"));
  csv.write({"name"});
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Json list = Json::array();
  int converged = 0;
  for (const auto& r : rows) {
    converged += r.prbm.converged() ? 1 : 0;
    const cfm::CfmResult& b = r.prbm.best.result;
    Json j{{"name", r.name},
           {"config", r.config},
           {"stroke_percent", r.stroke_percent},
           {"objective", to_string(r.objective)},
           {"printed_objective", r.printed_objective},
           {"objective_value", r.prbm.best.objective},
           {"R", b.R},
           {"K1", b.K1},
           {"K2", b.K2},
           {"percent_constant_force", b.percent_constant_force},
           {"converged", r.prbm.converged()},
           {"evaluations", r.prbm.evaluations},
           {"seconds", r.seconds}};
    if (o.exact) {
      const auto opt = [](const std::optional<double>& v) { return v ? Json(*v) : Json(nullptr); };
      j["printed_percent_constant_force_exact"] = opt(r.printed_percent_constant_force_exact);
      j["percent_constant_force_exact"] = opt(r.percent_constant_force_exact);
      j["exact_R"] = r.exact_R;
      j["exact_K1"] = r.exact_K1;
      j["exact_K2"] = r.exact_K2;
      j["exact_evaluations"] = r.exact_evaluations;
      j["exact_message"] = r.exact_message;
    }
    list.push_back(std::move(j));
  }
  if (args.json) {
    print_json(Json{{"subclasses", list},
                    {"model", args.model},
                    {"rows", rows.size()},
                    {"converged_rows", converged},
                    {"seconds", seconds},
                    {"out", args.out.empty() ? Json(nullptr) : Json(args.out)}});
    return;
  }
  for (const auto& r : rows) {
    fmt::print("{:<12} {:<8} printed {:.6g}, re-derived {:.6g}{}{}\n",
               r.name,
               to_string(r.objective),
               r.printed_objective,
               r.prbm.best.objective,
               r.prbm.converged() ? "" : " (not converged)",
               o.exact ? fmt::format("; exact Xi' {:.2f} -> {}",
                                     r.printed_percent_constant_force_exact.value_or(0.0),
                                     r.percent_constant_force_exact
                                         ? fmt::format("{:.2f}", *r.percent_constant_force_exact)
                                         : "none feasible")
                       : "");
  }
  fmt::print("{} rows, {} converged, {:.1f} s\n", rows.size(), converged, seconds);
}

void run_design_cfm(const DesignCfmArgs& args) {
  if (args.all_subclasses) {
    run_all_subclasses(args);
    return;
  }
  const design::CfmDesignProblem problem = make_problem(args);
  design::SynthesisOptions options;
  options.starts = args.starts;
  options.scan_points = args.scan_points;
  options.coarse_stride = args.coarse_stride;
  options.seed = args.seed;
  options.progress = stoppable_progress("design cfm " + problem.config + ": PRBM synthesis");
  const CsvOutput csv(args.out, args.csv);
  options.record_history = !csv.hdf5_path().empty();
  // The output file is checked and opened before the search (a wrong path fails at once).
  std::optional<io::DesignHistoryFile> file;
  if (!csv.hdf5_path().empty()) {
    io::check_output_path(csv.hdf5_path());
    try {
      file.emplace(csv.hdf5_path());
    } catch (const InvalidInput& e) {
      throw InvalidInput(fmt::format("--out: {}", e.what()));
    }
  }
  const auto start = std::chrono::steady_clock::now();
  const design::CfmSynthesisResult s = design::synthesize_cfm(problem, options);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (s.x.empty()) throw NoConvergence(fmt::format("design cfm: {}", s.message));
  if (!s.converged()) {
    throw NoConvergenceReport(
        fmt::format(
            "design cfm {} {}: {}", problem.config, to_string(problem.objective), s.message),
        Json{{"R", s.best.result.R},
             {"K1", s.best.result.K1},
             {"K2", s.best.result.K2},
             {"objective_value", s.best.objective},
             {"evaluations", s.evaluations}});
  }
  if (args.model == "exact") {
    run_exact(args, problem, s, start, file);
    csv.write({"history/run"}, {"exact_history"});
    return;
  }
  if (file) file->write(problem, s, nullptr, args.seed);
  csv.write({"history/run"}, {"exact_history"});
  if (args.json) {
    print_json(design_json(problem, s, args.seed, seconds));
    return;
  }
  const cfm::CfmResult& r = s.best.result;
  fmt::print("{} ({}), d = {:g} %: {} = {:.6g}\n",
             r.config,
             r.class_name,
             problem.stroke_percent,
             to_string(problem.objective),
             s.best.objective);
  fmt::print("  R = {:.4f}, K1 = {:.4f}, K2 = {:.4f}\n", r.R, r.K1, r.K2);
  fmt::print("  Xi = {:.5f}, Xi' = {:.2f} %, Phi = {:.4f}, Psi_raw = {:.5g}, d_N,max = {:.3f} %\n",
             r.Xi,
             r.percent_constant_force,
             r.Phi,
             r.Psi_raw,
             r.d_N_max);
  fmt::print("  nearest thesis sub-class: {}\n", s.nearest_subclass.value_or("none"));
  for (const design::NamedConstraint& c : s.best.constraints) {
    fmt::print(
        "  constraint {}: {:.6g} ({})\n", c.name, c.value, c.satisfied() ? "met" : "VIOLATED");
  }
  fmt::print("  {} ({:.1f} ms)\n", s.message, 1e3 * seconds);
}

}  // namespace

void register_design_command(CLI::App& app) {
  CLI::App& design =
      get_or_add_subcommand(app, "design", "Design constant-force mechanisms (docs/design.md)");
  auto args = std::make_shared<DesignCfmArgs>();
  CLI::App* cfm = design.add_subcommand(
      "cfm", "Synthesis of R, K1, K2 for an objective under the thesis's constraints (PRBM)");
  args->config_option = cfm->add_option(
      "--config", args->config, "Configuration: spp, lpp, psp, plp, ssp, slp, sps, lps, sss");
  args->d_option = cfm->add_option("--d", args->d, "Design stroke d, % of r2 + r3 (0 < d < 100)");
  args->objective_option = cfm->add_option(
      "--objective",
      args->objective,
      "min-xi (Table 2.1), max-pcf (Xi'), max-psi (stiffness; needs --pcf-min) or min-dn "
      "(normal displacement; needs --pcf-min)");
  cfm->add_flag("--all-subclasses",
                args->all_subclasses,
                "Every thesis sub-class from its own problem (68 rows, or --config's; with "
                "--model exact also the exact optimum); --out writes the table");
  cfm->add_option("--subclass",
                  args->subclass,
                  "A thesis sub-class's own problem instead of --config/--d/--objective (e.g. "
                  "lps-b95I: max Psi with Xi' >= 95 and rule I at d = 40)");
  cfm->add_option("--model",
                  args->model,
                  "prbm, or exact: then maximise the exact model's Xi' from the PRBM optimum, the "
                  "thesis's sub-classes and a Halton sequence, under the same constraints")
      ->default_str("prbm");
  cfm->add_option("--exact-starts",
                  args->exact_starts,
                  "--model exact: local runs from a Halton sequence besides the PRBM optimum and "
                  "the thesis's points (default: two per free variable)");
  args->pcf_min_option =
      cfm->add_option("--pcf-min", args->pcf_min, "Constraint: percent constant force Xi' >= X");
  args->orientation_option =
      cfm->add_option("--orientation",
                      args->orientation,
                      "Orientation rules of the flexures: any of I (in-plane), O (out-of-plane), o "
                      "(possibly out-of-plane), e.g. IO");
  cfm->add_option("--rule-limits",
                  args->rule_limits,
                  "Other limits of the orientation rules, as the constraints are named, e.g. "
                  "\"O:C>=0.99,o:D_equal<=10.4\" (default: the thesis's, Table 5.4)");
  args->K1_option = cfm->add_option("--K1", args->K1, "Hold K1 = k2/k1 at this value");
  args->K2_option = cfm->add_option("--K2", args->K2, "Hold K2 = k3/k1 at this value");
  cfm->add_option("--sampling",
                  args->sampling,
                  "Stroke sampling: auto (uniform 50 points for min-xi, else the thesis's), "
                  "thesis or uniform")
      ->default_str("auto");
  args->points_option =
      cfm->add_option("--points", args->points, "Points of the uniform sampling (default 50)");
  cfm->add_option("--starts",
                  args->starts,
                  "Local optimisations per region of the primary pivot (0: 4 for two variables, "
                  "3 for one or three)")
      ->default_str("0");
  cfm->add_option("--scan-points",
                  args->scan_points,
                  "Points of the global scan (0: 32, 256 or 1024 for one, two or three variables)")
      ->default_str("0");
  cfm->add_option("--coarse-stride",
                  args->coarse_stride,
                  "The search runs on every N-th stroke point and polishes on all (1: all "
                  "throughout)");
  cfm->add_option("--seed", args->seed, "Seed of the optimiser (runs are reproducible)");
  cfm->add_option("--out",
                  args->out,
                  "Write the search's convergence history (every model evaluation; with --model "
                  "exact also every exact stroke) to this HDF5 file");
  add_csv_option(cfm, args->csv);
  cfm->add_flag("--json", args->json, "Print one JSON object");
  cfm->callback([args] { run_design_cfm(*args); });
}

}  // namespace flexure::cli
