// `flexure dynamics`: frequency sweep of the inverse dynamics of a modified constant-force slider
// mechanism (Ugwuoke & Abolarin, the dynamics paper; docs/dynamics.md).
//
//   flexure dynamics --mechanism NAME|FILE.toml --omega START:STOP:COUNT [--out FILE.h5]
//                    [--stroke-percent 40] [--preload-percent 1] [--samples 1024]
//                    [--friction C1,C2,C3] [--axial-alpha RAD] [--spring-rule RULE]
//                    [--force-of whole|half]
//                    [--zero-slider-mass | --zero-inertia] [--history W1,W2,...]
//                    [--csv FILE.csv] [--json]
//   flexure dynamics --list [--json]
//
// Per frequency: mean, median, min, max and peak-to-peak input force (N; of the whole symmetric
// mechanism unless --force-of half) over one period of Delta x(t) = preload + stroke (1 - cos
// omega t)/2, and the percent constant force 100 min/max. The HDF5 file also holds the force
// history at the --history frequencies (default: the paper's Figs. 11-13, 10.472, 31.416 and
// 62.832 rad/s). The design comes from dynamics/dynamics.h.
#include <fmt/format.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/csv_output.h"
#include "cli/slow_progress.h"
#include "flexure/benchmarks/studies/dynamics_study.h"
#include "flexure/benchmarks/studies/dynamics_study_file.h"
#include "flexure/io/platform/output_path.h"
#include "flexure/io/toml_files.h"
#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/dynamics/dynamics.h"
#include "flexure/mechanisms/materials_fatigue.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/solver/common/status.h"

namespace flexure::cli {
namespace {

using dynamics::CfsmDesign;
using dynamics::DynamicsDesign;
using dynamics::ForceStatistics;
using dynamics::SinusoidalMotion;
using mechanism::ForceOf;

struct DynamicsArgs {
  std::string mechanism;
  std::string omega;
  std::string out;
  std::string csv;
  double stroke_percent = 40.0;
  CLI::Option* stroke_option = nullptr;
  std::string spring_rule;
  std::string material;  // --material NAME: E of the springs computed from the strips
  std::string force_of = "whole";
  double preload_percent = 1.0;
  int samples = 1024;
  std::vector<double> friction;
  double axial_alpha = 0.0;
  bool zero_slider_mass = false;
  bool zero_inertia = false;
  std::vector<double> history{10.472, 31.416, 62.832};
  bool list = false;
  bool json = false;
};

void run_list(const DynamicsArgs& args) {
  Json names = Json::array();
  for (const CfsmDesign& d : dynamics::cfsm_designs()) names.push_back(d.name);
  if (args.json) {
    print_json(Json{{"mechanisms", names}});
  } else {
    for (const CfsmDesign& d : dynamics::cfsm_designs()) {
      fmt::print("{:8}  r2 {:.4f} mm  r3 {:.4f} mm  k {:.4f} {:.4f} {:.4f} N m  m_S {:.4f} g\n",
                 d.name,
                 d.r2 * 1e3,
                 d.r3 * 1e3,
                 d.k[0],
                 d.k[1],
                 d.k[2],
                 d.m_slider * 1e3);
    }
  }
}

// The design: a built-in name of the paper's Table 5 or a mechanism TOML file with a [dynamics]
// table (dynamics.h says which springs and masses each gives).
DynamicsDesign resolve_design(const DynamicsArgs& args) {
  std::optional<mechanism::SpringRule> rule;
  if (!args.spring_rule.empty()) rule = mechanism::parse_spring_rule(args.spring_rule);
  const std::string& what = args.mechanism;
  const MaterialGrade* material = args.material.empty() ? nullptr : &find_material(args.material);
  if (what.size() > 5 && what.substr(what.size() - 5) == ".toml") {
    const mechanism::MechanismFile file = mechanism::load_mechanism_file(what);
    warn(file.warnings);
    const dynamics::MassesNeeded needed = args.zero_inertia ? dynamics::MassesNeeded::kNone
                                          : args.zero_slider_mass
                                              ? dynamics::MassesNeeded::kLinksOnly
                                              : dynamics::MassesNeeded::kAll;
    DynamicsDesign d =
        dynamics::dynamics_design(file.design, file.dynamics, needed, rule, material);
    const double E = file.design.material.E;
    if (material != nullptr && E > 0.0 && E != material->E) {
      warn(fmt::format("--material {}: E {:.6g} Pa replaces the file's {:.6g} Pa in the springs",
                       material->id,
                       material->E,
                       E));
    }
    return d;
  }
  // A name is looked up first, so that an unknown one is reported as such, not as a material
  // the printed springs cannot take.
  try {
    dynamics::builtin_dynamics_design(what, rule);
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format(
        "--mechanism: {}; or FILE.toml, a mechanism file with a [dynamics] table", e.what()));
  }
  return dynamics::builtin_dynamics_design(what, rule, material);
}

void run_dynamics(const DynamicsArgs& args) {
  if (args.list) {
    run_list(args);
    return;
  }
  if (args.mechanism.empty()) throw InvalidInput("--mechanism is required (see --list)");
  if (args.omega.empty()) throw InvalidInput("--omega START:STOP:COUNT is required");
  // Without --out (or --csv) nothing is written: the results are printed (all of them with
  // --json). --out FILE.csv, or --csv without --out, writes the frequency table as CSV only.
  if (!args.out.empty()) io::check_output_path(args.out);
  const CsvOutput csv(args.out, args.csv);
  const Range range = parse_range(args.omega, "--omega (rad/s)", 1'000'000);
  require_in_range(range.start, "--omega START (rad/s)", 0.0, 1e6);
  require_in_range(range.stop, "--omega STOP (rad/s)", 0.0, 1e6);
  require_in_range(args.stroke_percent, "--stroke-percent", 1e-6, 100.0);
  require_in_range(args.preload_percent, "--preload-percent", 1e-6, 100.0);
  require_in_range(args.samples, "--samples (per period, even)", 8, 10'000'000);
  require_in_range(args.axial_alpha, "--axial-alpha (rad)", -1.0, 1.0);
  if (args.zero_slider_mass && args.zero_inertia) {
    throw InvalidInput("--zero-slider-mass and --zero-inertia exclude each other");
  }
  if (!args.friction.empty() && args.friction.size() != 3) {
    throw InvalidInput(
        fmt::format("--friction needs three values C1,C2,C3 (N m), got {}", args.friction.size()));
  }
  for (double w : args.history) require_in_range(w, "--history (rad/s)", 0.0, 1e6);
  const ForceOf force_of = mechanism::parse_force_of(args.force_of);
  const DynamicsDesign d = resolve_design(args);
  DynamicsStudyOptions o;
  for (std::size_t i = 0; i < args.friction.size(); ++i) {
    require_in_range(args.friction[i], fmt::format("--friction C{} (N m)", i + 1), 0.0, 1e6);
    o.friction[i] = args.friction[i];
  }
  o.omegas.resize(range.count);
  for (long i = 0; i < range.count; ++i) o.omegas[i] = range.at(i);
  // A design file's own stroke unless --stroke-percent is given (built-ins: 40 %, Table 6).
  if (args.stroke_option->count() > 0 || !d.stroke) o.stroke_percent = args.stroke_percent;
  o.preload_percent = args.preload_percent;
  o.samples = args.samples;
  o.axial_alpha = args.axial_alpha;
  o.zero_slider_mass = args.zero_slider_mass;
  o.zero_inertia = args.zero_inertia;
  o.history_omegas = args.history;
  o.force_of = force_of;
  o.progress = stoppable_progress("dynamics");
  dynamics_study_setup(d, o);  // throws (exit 2) past the toggle position

  // Open the output first: an unwritable path fails before any work (exit 2).
  std::optional<DynamicsStudyFile> output;
  try {
    if (!csv.hdf5_path().empty()) output.emplace(csv.hdf5_path());
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("--out {}: {}", args.out, e.what()));
  }
  const DynamicsStudy study = run_dynamics_study(d, o);
  if (!study.converged()) throw NoConvergence(study.message);
  if (output) output->write(study);
  // The frequency table: one row per omega (the force histories of /history are left out).
  csv.write({"omega"}, {"history"});

  const double F_nom = study.static_nominal_force;
  const double F_nom_paper = study.paper_nominal_force.value_or(0.0);
  const std::string force_of_label = mechanism::force_of_label(force_of);
  const double omega_n = study.natural_frequency;
  const SinusoidalMotion& motion = study.motion;
  std::vector<double> mean, median, min, max, p2p, pcf;
  for (const ForceStatistics& s : study.rows) {
    mean.push_back(s.mean);
    median.push_back(s.median);
    min.push_back(s.min);
    max.push_back(s.max);
    p2p.push_back(s.peak_to_peak);
    pcf.push_back(s.percent_constant_force);
  }

  if (args.json) {
    Json history = Json::array();
    for (const DynamicsForceHistory& h : study.histories) {
      history.push_back(Json{{"omega", h.omega},
                             {"t", h.t},
                             {"delta_x", h.delta_x},
                             {"theta2", h.theta2},
                             {"force", h.force},
                             {"static_force", h.static_force}});
    }
    print_json(
        Json{{"mechanism", d.name},
             {"out", args.out.empty() ? Json(nullptr) : Json(args.out)},
             {"csv", csv.wanted() ? Json(csv.csv_path()) : Json(nullptr)},
             {"force_of", force_of_label},
             {"spring_rule", d.spring_rule ? Json(to_string(*d.spring_rule)) : Json(nullptr)},
             {"material", d.material ? Json(d.material_id) : Json(nullptr)},
             {"spring_constants", d.k},
             {"stroke", motion.stroke},
             {"preload", motion.preload},
             {"history", history},
             {"static_nominal_force", F_nom},
             {"static_nominal_force_points", study.static_force_points},
             {"paper_nominal_force", study.paper_nominal_force ? Json(F_nom_paper) : Json(nullptr)},
             {"natural_frequency", omega_n},
             {"seconds", study.seconds},
             {"omega", study.omegas},
             {"mean_force", mean},
             {"median_force", median},
             {"peak_to_peak_force", p2p},
             {"percent_constant_force", pcf},
             {"min_force", min},
             {"max_force", max}});
  } else {
    fmt::print(
        "{}: static nominal force {:.4f} N{}, natural frequency {:.4f} rad/s\n"
        "  force of: {}; springs per half {:.6g}, {:.6g}, {:.6g} N m ({})\n",
        d.name,
        F_nom,
        study.paper_nominal_force ? fmt::format(" (paper {:.4f} N)", F_nom_paper) : "",
        omega_n,
        force_of_label,
        d.k[0],
        d.k[1],
        d.k[2],
        d.spring_rule ? fmt::format("spring rule {}", to_string(*d.spring_rule))
                      : std::string("thesis springs"));
    fmt::print("{:>12} {:>12} {:>12} {:>12} {:>8}\n",
               "omega rad/s",
               "mean N",
               "median N",
               "p-p N",
               "PCF %");
    for (const ForceStatistics& s : study.rows) {
      fmt::print("{:12.4f} {:12.4f} {:12.4f} {:12.4f} {:8.3f}\n",
                 s.omega,
                 s.mean,
                 s.median,
                 s.peak_to_peak,
                 s.percent_constant_force);
    }
    if (output && csv.hdf5_path() == args.out) fmt::print("written to {}\n", args.out);
    if (csv.wanted()) fmt::print("table written to {}\n", csv.csv_path());
  }
}

}  // namespace

void register_dynamics_command(CLI::App& app) {
  auto args = std::make_shared<DynamicsArgs>();
  CLI::App* cmd = app.add_subcommand(
      "dynamics", "Frequency sweep of a constant-force slider mechanism's input force (HDF5)");
  cmd->add_option("--mechanism",
                  args->mechanism,
                  "Design of the paper's Table 5 (e.g. 2B-lplm), or FILE.toml: a mechanism file "
                  "with a [dynamics] table (masses)");
  cmd->add_option("--omega", args->omega, "Drive frequencies START:STOP:COUNT, rad/s");
  cmd->add_option(
      "--out",
      args->out,
      "Output HDF5 file (written atomically), or FILE.csv for the frequency table as CSV only; "
      "without it (and --csv) nothing is written");
  add_csv_option(cmd, args->csv);
  args->stroke_option =
      cmd->add_option("--stroke-percent",
                      args->stroke_percent,
                      "Peak-to-peak slider travel, % of r2 + r3 (default: 40, or a FILE.toml's "
                      "stroke)")
          ->default_str("40");
  cmd->add_option("--spring-rule",
                  args->spring_rule,
                  "Springs from the strips' b, h, L, E by the rule of mechanism analyze: "
                  "pure-bending (k = EI/L), table2, table5 (default: the paper's printed Table 5 "
                  "constants, table5-printed; a FILE.toml's own rule)");
  cmd->add_option("--material",
                  args->material,
                  "Material of the strips (`flexure materials`): its E sets the springs computed "
                  "from the strips (with --spring-rule, or a FILE.toml without spring_constants)");
  cmd->add_option("--force-of",
                  args->force_of,
                  "Forces of the whole symmetric mechanism (two halves, one slider) or of one "
                  "half (= whole/2), as mechanism analyze reports")
      ->default_str("whole");
  cmd->add_option("--preload-percent",
                  args->preload_percent,
                  "Slider pre-displacement at full expansion, % of r2 + r3 (> 0)")
      ->default_str("1");
  cmd->add_option("--samples", args->samples, "Time samples per period (even, >= 8)")
      ->default_str("1024");
  cmd->add_option("--friction",
                  args->friction,
                  "Coulomb pin friction C1,C2,C3 per half mechanism, N m (eq. 27)")
      ->delimiter(',');
  cmd->add_option("--axial-alpha",
                  args->axial_alpha,
                  "Angle of axial-force effect alpha of eq. 28, rad (0: off)")
      ->default_str("0");
  cmd->add_flag("--zero-slider-mass", args->zero_slider_mass, "Set the slider mass to zero");
  cmd->add_flag("--zero-inertia", args->zero_inertia, "Set all masses and inertias to zero");
  cmd->add_option("--history", args->history, "Frequencies (rad/s) whose force history is stored")
      ->delimiter(',')
      ->default_str("10.472,31.416,62.832");
  cmd->add_flag("--list", args->list, "List the built-in mechanisms");
  cmd->add_flag("--json", args->json, "Print one JSON object on stdout");
  cmd->callback([args] { run_dynamics(*args); });
}

}  // namespace flexure::cli
