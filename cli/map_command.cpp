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
#include "cli/slow_progress.h"
#include "flexure/benchmarks/studies/cfm_map.h"
#include "flexure/io/hdf5_file.h"
#include "flexure/io/output_path.h"
#include "flexure/io/provenance.h"
#include "flexure/solver/common/errors.h"

namespace flexure::cli {
namespace {

struct MapCfmArgs {
  std::string config, R, d, K1, K2;
  std::string model = "prbm";
  int points = 50;
  std::string out;
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

void write_map(io::AtomicHdf5File& file,
               const studies::CfmMapSpec& spec,
               const studies::CfmMap& m) {
  io::Hdf5Group& root = file.root();
  root.set_attribute("config", spec.config);
  root.set_attribute("model", spec.exact ? "exact" : "prbm");
  root.set_attribute("mpi_ranks", std::int64_t{1});
  root.set_attribute("exact_points", static_cast<std::int64_t>(spec.points));
  root.set_attribute("description",
                     "design-space map over R x d x K1 x K2 (row-major, K2 fastest; a missing "
                     "spring's axis has one entry 0)");
  const auto axis = [&](const char* name, const std::vector<double>& v, const char* text) {
    const std::vector<double> values = v.empty() ? std::vector<double>{0.0} : v;
    root.write_dataset(name, std::span<const double>(values), "1", text);
  };
  axis("R", spec.R, "R = r3/r2, axis 0");
  root.write_dataset("d", std::span<const double>(spec.d), "%", "design stroke d, axis 1");
  axis("K1", spec.K1, "K1 = k2/k1, axis 2 (0: no such variable)");
  axis("K2", spec.K2, "K2 = k3/k1, axis 3 (0: no such variable)");
  std::vector<hsize_t> dims(m.dims.begin(), m.dims.end());
  const auto grid =
      [&](const char* name, const std::vector<double>& v, const char* units, const char* text) {
        root.write_dataset(name, std::span<const double>(v), dims, units, text);
      };
  grid("Phi", m.Phi, "1", "PRBM mean of Phi = F r2/k1 (class 1B: k2) over the stroke");
  grid("percent_constant_force", m.percent_constant_force, "%", "PRBM Xi' = 100 min F/max F");
  grid("Psi_raw", m.Psi_raw, "1", "PRBM stiffness parameter Psi before normalisation (eq. 5.19)");
  grid("toggle_stroke_percent",
       m.toggle_stroke_percent,
       "%",
       "stroke limit of R (the toggle position, eq. 2.16)");
  grid("effective_stroke_percent",
       m.effective_stroke_percent,
       "%",
       "the stroke evaluated: d, or the toggle stroke where d is past it");
  root.write_dataset("stroke_clamped",
                     std::span<const int>(m.stroke_clamped),
                     dims,
                     "1",
                     "1 where d was past the toggle position and the stroke was clamped");
  root.write_dataset("status",
                     std::span<const int>(m.status),
                     dims,
                     "1",
                     "0 ok, 1 exact model not converged or refused (exact values 0), 2 PRBM model "
                     "refused the point");
  if (spec.exact) {
    grid("percent_constant_force_exact",
         m.percent_constant_force_exact,
         "%",
         "exact-model Xi' (0 where it vanishes or changes sign, or status != 0)");
    grid("Phi_exact", m.Phi_exact, "1", "exact-model mean Phi");
    grid("max_force_error",
         m.max_force_error,
         "1",
         "largest |F_prbm - F_exact|/|F_exact| over the stroke points");
  }
  io::write_provenance(root,
                       {{"status", studies::kMapOk, "ok"},
                        {"status",
                         studies::kMapExactNotConverged,
                         "the exact model did not converge or refused the point (exact values 0; "
                         "PRBM values valid)"},
                        {"status", studies::kMapInvalid, "the model refused the point"}});
  file.commit();
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
  spec.validate();
  io::check_output_path(a.out);
  std::optional<io::AtomicHdf5File> file;
  try {
    file.emplace(a.out);
  } catch (const io::Hdf5Error& e) {
    throw InvalidInput(fmt::format("--out: {}", e.what()));
  }
  const studies::CfmMap m = studies::cfm_map(spec, slow_progress("map cfm " + spec.config));
  write_map(*file, spec, m);
  std::size_t ok = 0, not_converged = 0, invalid = 0;
  for (int s : m.status) {
    (s == studies::kMapOk ? ok : (s == studies::kMapInvalid ? invalid : not_converged)) += 1;
  }
  const std::vector<double>& pcf =
      spec.exact ? m.percent_constant_force_exact : m.percent_constant_force;
  const auto best = std::max_element(pcf.begin(), pcf.end()) - pcf.begin();
  if (a.json) {
    print_json(Json{{"out", a.out},
                    {"config", spec.config},
                    {"model", a.model},
                    {"dims", m.dims},
                    {"points", m.status.size()},
                    {"ok", ok},
                    {"exact_not_converged", not_converged},
                    {"invalid", invalid},
                    {"best_percent_constant_force", pcf[best]},
                    {"best_index", best}});
    return;
  }
  fmt::print(
      "wrote {}: {} points ({} x {} x {} x {}), {} ok, {} exact not converged, {} refused; "
      "best {} Xi' {:.2f} %\n",
      a.out,
      m.status.size(),
      m.dims[0],
      m.dims[1],
      m.dims[2],
      m.dims[3],
      ok,
      not_converged,
      invalid,
      a.model,
      pcf[best]);
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
  cfm->add_option("--out", a->out, "The HDF5 file of the map (docs/hdf5-schema.md)")->required();
  cfm->add_flag("--json", a->json, "Print a JSON summary");
  cfm->callback([a] { run_map_cfm(*a); });
}

}  // namespace flexure::cli
