// `flexure map cfm`: the design-space map of one constant-force configuration
// (benchmarks/studies/cfm_map.h; docs/design.md "Design-space maps"; HDF5 layout in
// docs/hdf5-schema.md).
#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/csv_output.h"
#include "cli/slow_progress.h"
#include "flexure/benchmarks/studies/cfm_map.h"
#include "flexure/io/platform/output_path.h"
#include "flexure/io/platform/provenance.h"
#include "flexure/solver/common/status.h"

namespace flexure::cli {
namespace {

struct MapCfmArgs {
  std::string config, R, d, K1, K2;
  std::string model = "prbm";
  int points = 50;
  std::string out;
  std::string csv;
  bool json = false;
};

// A value ("2") or a range START:STOP:COUNT.
std::vector<double> axis_of(const std::string& text, const std::string& what) {
  if (text.empty()) return {};
  std::vector<double> v;
  if (text.find(':') == std::string::npos) {
    double x = 0.0;
    if (!parse_double(text, x)) {
      throw InvalidInput(fmt::format("{} '{}': give a number or START:STOP:COUNT", what, text));
    }
    v.push_back(x);
    return v;
  }
  const Range r = parse_range(text, what, 1'000'000);
  for (long i = 0; i < r.count; ++i) v.push_back(r.at(i));
  return v;
}

void run_map_cfm(const MapCfmArgs& a) {
  studies::CfmMapSpec spec;
  spec.config = a.config;
  spec.R = axis_of(a.R, "--R");
  spec.d = axis_of(a.d, "--d");
  spec.K1 = axis_of(a.K1, "--K1");
  spec.K2 = axis_of(a.K2, "--K2");
  if (a.model != "prbm" && a.model != "exact") {
    throw InvalidInput(fmt::format("--model '{}' is unknown; allowed: prbm, exact", a.model));
  }
  spec.exact = a.model == "exact";
  spec.points = a.points;
  require_out_or_csv(a.out, a.csv);
  const CsvOutput csv(a.out, a.csv);
  const studies::CfmMapSummary m =
      studies::write_cfm_map(spec, csv.hdf5_path(), stoppable_progress("map cfm " + spec.config));
  csv.write({"R", "d", "K1", "K2"});
  if (a.json) {
    print_json(Json{{"out", csv.out_json()},
                    {"csv", csv.csv_json()},
                    {"config", spec.config},
                    {"model", a.model},
                    {"dims", m.dims},
                    {"points", m.points},
                    {"ok", m.ok},
                    {"exact_not_converged", m.exact_not_converged},
                    {"invalid", m.invalid},
                    {"best_percent_constant_force", m.best_percent_constant_force},
                    {"best_index", m.best_index}});
    return;
  }
  fmt::print(
      "wrote {}: {} points ({} x {} x {} x {}), {} ok, {} exact not converged, {} refused; "
      "best {} Xi' {:.2f} %\n",
      csv.written_path(),
      m.points,
      m.dims[0],
      m.dims[1],
      m.dims[2],
      m.dims[3],
      m.ok,
      m.exact_not_converged,
      m.invalid,
      a.model,
      m.best_percent_constant_force);
}

}  // namespace

void register_map_command(CLI::App& app) {
  CLI::App& map = get_or_add_subcommand(app, "map", "Design-space maps (docs/design.md)");
  auto a = std::make_shared<MapCfmArgs>();
  CLI::App* cfm = map.add_subcommand(
      "cfm", "Map of a configuration's Phi, Xi' (PRBM and exact), stroke limit and force error");
  cfm->add_option(
         "--config", a->config, "Configuration: spp, lpp, psp, plp, ssp, slp, sps, lps, sss")
      ->required();
  cfm->add_option("--R", a->R, "R = r3/r2: a value or START:STOP:COUNT")->required();
  cfm->add_option("--d", a->d, "Design stroke, % of r2 + r3: a value or START:STOP:COUNT")
      ->required();
  cfm->add_option("--K1", a->K1, "K1 = k2/k1 where the configuration has it: a value or a range");
  cfm->add_option("--K2", a->K2, "K2 = k3/k1 where the configuration has it: a value or a range");
  cfm->add_option("--model", a->model, "prbm, or exact (also the exact model at every point)")
      ->default_str("prbm");
  cfm->add_option("--exact-points", a->points, "Stroke points of the exact model")
      ->default_str("50");
  cfm->add_option("--out",
                  a->out,
                  "The HDF5 file of the map (docs/hdf5-schema.md), or FILE.csv for the table as "
                  "CSV only; --out, --csv or both");
  add_csv_option(cfm, a->csv);
  cfm->add_flag("--json", a->json, "Print a JSON summary");
  cfm->callback([a] { run_map_cfm(*a); });
}

}  // namespace flexure::cli
