// `flexure models map`: the model ladder's error-and-time map (benchmarks/studies/model_map.h;
// docs/models.md; HDF5 layout in docs/hdf5-schema.md "flexure models map").
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/csv_output.h"
#include "cli/slow_progress.h"
#include "flexure/benchmarks/studies/model_map.h"
#include "flexure/elements/ladder_models.h"
#include "flexure/io/platform/output_path.h"
#include "flexure/io/platform/provenance.h"
#include "flexure/solver/common/names.h"
#include "flexure/solver/common/status.h"
#include "flexure/version.h"

namespace flexure::cli {
namespace {

struct ModelsMapArgs {
  std::string boundary = "free";
  std::string n = "0:1:3";
  std::string alpha2 = "0.25:10:40";
  std::string mu = "-2:2:9";
  std::string tip_angle = "0";
  std::string models;
  int elements = 6;
  int chain_elements = 100;
  std::string constants = "su";
  double min_seconds = 2e-4;
  CLI::Option* mu_option = nullptr;
  std::string out;
  std::string csv;
  bool json = false;
};

Json number_or_null(double value) { return std::isfinite(value) ? Json(value) : Json(nullptr); }

// A value ("2"), a list of values ("0,0.05,0.1": a grid finer where a model's error changes
// fastest, data/ladder_auto_error_map.csv) or a range START:STOP:COUNT.
std::vector<double> axis_of(const std::string& text, const std::string& what) {
  std::vector<double> v;
  if (text.find(',') != std::string::npos) {
    std::size_t start = 0;
    while (start <= text.size()) {
      const std::size_t comma = text.find(',', start);
      const std::string item =
          text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      double x = 0.0;
      if (!parse_double(item, x) || !std::isfinite(x)) {
        throw InvalidInput(fmt::format(
            "{} = '{}': '{}' is not a finite number (give a number, a comma-separated list or "
            "START:STOP:COUNT)",
            what,
            text,
            item));
      }
      if (!v.empty() && !(x > v.back())) {
        throw InvalidInput(
            fmt::format("{} = '{}': a list of values must be strictly ascending", what, text));
      }
      v.push_back(x);
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    return v;
  }
  if (text.find(':') == std::string::npos) {
    double x = 0.0;
    if (!parse_double(text, x) || !std::isfinite(x)) {
      throw InvalidInput(
          fmt::format("{} = '{}': give a finite number, a comma-separated list or START:STOP:COUNT",
                      what,
                      text));
    }
    v.push_back(x);
    return v;
  }
  const Range r = parse_range(text, what, 100'000);
  for (long i = 0; i < r.count; ++i) v.push_back(r.at(i));
  return v;
}

std::vector<BeamMethod> models_of(const std::string& text) {
  std::vector<BeamMethod> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    const std::string name =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (name.empty()) throw InvalidInput(fmt::format("--models '{}': an empty name", text));
    out.push_back(beam_method_from_string(name));  // InvalidInput listing the names
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

void run_models_map(const ModelsMapArgs& a) {
  studies::ModelMapSpec spec;
  spec.boundary = end_condition_from_string(a.boundary);
  spec.n = axis_of(a.n, "--n");
  spec.alpha2 = axis_of(a.alpha2, "--alpha2");
  if (spec.boundary == EndCondition::kGuided) {
    if (*a.mu_option) {
      throw InvalidInput(
          "--mu: a guided end takes its tip moment as the guide's reaction; map the prescribed "
          "tip angle with --tip-angle instead");
    }
    spec.mu = {0.0};
    spec.tip_angle = axis_of(a.tip_angle, "--tip-angle");
  } else {
    spec.mu = axis_of(a.mu, "--mu");
    spec.tip_angle = axis_of(a.tip_angle, "--tip-angle");
  }
  if (!a.models.empty()) spec.models = models_of(a.models);
  spec.cbcm_elements = a.elements;
  spec.chain_elements = a.chain_elements;
  spec.prbm3r_constants = prbm3r_constant_set_from_string(a.constants);
  spec.min_seconds = a.min_seconds;
  spec.validate();
  require_out_or_csv(a.out, a.csv);
  if (!a.out.empty()) io::check_output_path(a.out);  // before the solves: fail fast
  const CsvOutput csv(a.out, a.csv);

  const auto start = std::chrono::steady_clock::now();
  const studies::ModelMap map = studies::compute_model_map(spec, stoppable_progress("models map"));
  studies::write_model_map(map, csv.hdf5_path());
  csv.write({"n", "alpha2", spec.boundary == EndCondition::kGuided ? "tip_angle" : "mu"});
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  if (a.json) {
    Json models = Json::array();
    for (const studies::ModelMapModel& m : map.models) {
      models.push_back(Json{{"method", to_string(m.method)},
                            {"settings", m.settings},
                            {"converged_points", m.converged},
                            {"max_position_error", number_or_null(m.max_position_error)},
                            {"median_position_error", number_or_null(m.median_position_error)},
                            {"median_seconds", number_or_null(m.median_seconds)}});
    }
    print_json(Json{{"out", csv.out_json()},
                    {"csv", csv.csv_json()},
                    {"boundary", to_string(spec.boundary)},
                    {"reference", to_string(spec.reference())},
                    {"dims", {spec.n.size(), spec.alpha2.size(), spec.third_axis().size()}},
                    {"points", spec.point_count()},
                    {"seconds", seconds},
                    {"models", models}});
    return;
  }
  fmt::print("wrote {}: {} points (n x alpha2 x {}: {} x {} x {}), reference {}, {:.1f} s\n",
             csv.written_path(),
             spec.point_count(),
             spec.third_axis_name(),
             spec.n.size(),
             spec.alpha2.size(),
             spec.third_axis().size(),
             to_string(spec.reference()),
             seconds);
  fmt::print("{:<9} {:>10} {:>14} {:>14} {:>12}  {}\n",
             "model",
             "converged",
             "max error/l",
             "median err/l",
             "median s",
             "settings");
  for (const studies::ModelMapModel& m : map.models) {
    fmt::print("{:<9} {:>10} {:>14.3g} {:>14.3g} {:>12.3g}  {}\n",
               to_string(m.method),
               m.converged,
               m.max_position_error,
               m.median_position_error,
               m.median_seconds,
               m.settings);
  }
}

// `flexure models prbm3r-constants`: derives the PR-3R constants against the exact elastica
// (elements/ladder_models.h) and prints data/prbm3r_flexure_constants.csv, or a summary.
void run_prbm3r_constants(bool json) {
  const Prbm3rDerivation d = derive_prbm3r_constants();
  if (!d.converged()) {
    throw NoConvergence(
        fmt::format("the PR-3R constants' optimisation did not converge: {}", d.message));
  }
  if (json) {
    const Prbm3rConstants& c = d.constants;
    print_json(Json{{"gamma", {c.gamma[0], c.gamma[1], c.gamma[2], c.gamma[3]}},
                    {"k", {c.k[0], c.k[1], c.k[2]}},
                    {"objective", d.objective},
                    {"objective_su", d.objective_su},
                    {"max_position_error", d.max_position_error},
                    {"max_position_error_su", d.max_position_error_su},
                    {"loads", d.loads},
                    {"domain", d.domain}});
    return;
  }
  fmt::print(
      "{}",
      prbm3r_constants_csv(
          d,
          fmt::format("flexure {} (git commit {}): {}", kVersion, kGitCommit, io::command_line())));
}

}  // namespace

void register_models_command(CLI::App& app) {
  CLI::App& models = get_or_add_subcommand(
      app, "models", "The model ladder: every model's error and time against the exact solution");
  auto a = std::make_shared<ModelsMapArgs>();
  CLI::App* map = models.add_subcommand(
      "map",
      "Solve a grid of loads with every model (linear, prbm, prbm3r, bcm, cbcm, chain, shooting) "
      "and record each one's tip error against the exact solution and its time per solve (HDF5)");
  map->add_option("--boundary", a->boundary, "Far end: free (default) or guided")
      ->default_str("free");
  map->add_option("--n", a->n, "Load ratio n: a value, a list V1,V2,... or START:STOP:COUNT")
      ->default_str("0:1:3");
  map->add_option("--alpha2",
                  a->alpha2,
                  "Transverse load P l^2/EI: a value, a list V1,V2,... or START:STOP:COUNT")
      ->default_str("0.25:10:40");
  a->mu_option =
      map->add_option("--mu",
                      a->mu,
                      "End moment M l/EI (free end): a value, a list V1,V2,... or START:STOP:COUNT")
          ->default_str("-2:2:9");
  map->add_option(
         "--tip-angle",
         a->tip_angle,
         "Prescribed tip angle of a guided end, rad: a value, a list V1,V2,... or START:STOP:COUNT")
      ->default_str("0");
  map->add_option("--models",
                  a->models,
                  "Comma-separated models (default: linear,prbm,prbm3r,bcm,cbcm,chain,shooting; "
                  "the reference, elliptic for a free end and shooting for a guided one, is not "
                  "repeated)");
  map->add_option("--elements", a->elements, "Chained BCM: number of elements N")->default_str("6");
  map->add_option("--chain-elements", a->chain_elements, "Chain algorithm: number of elements")
      ->default_str("100");
  map->add_option("--constants", a->constants, "PR-3R constants: su, su-moment, su-force, flexure")
      ->default_str("su");
  map->add_option("--min-seconds",
                  a->min_seconds,
                  "Timing: each model's solve is repeated at each point until this much time has "
                  "passed, and the mean taken")
      ->default_str("2e-4");
  map->add_option("--out",
                  a->out,
                  "The HDF5 file of the map (docs/hdf5-schema.md), or FILE.csv for the table as "
                  "CSV only; --out, --csv or both");
  add_csv_option(map, a->csv);
  map->add_flag("--json", a->json, "Print a JSON summary");
  map->callback([a] { run_models_map(*a); });

  auto json = std::make_shared<bool>(false);
  CLI::App* constants = models.add_subcommand(
      "prbm3r-constants",
      "Derive the PR-3R model's constants against the exact elastica (docs/models.md) and print "
      "data/prbm3r_flexure_constants.csv");
  constants->add_flag("--json", *json, "Print the constants, objective and domain as JSON");
  constants->callback([json] { run_prbm3r_constants(*json); });
}

}  // namespace flexure::cli
