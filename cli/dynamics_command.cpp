// `flexure dynamics`: frequency sweep of the inverse dynamics of a modified constant-force slider
// mechanism (Ugwuoke & Abolarin, the dynamics paper; docs/dynamics.md).
//
//   flexure dynamics --mechanism NAME|FILE.toml --omega START:STOP:COUNT [--out FILE.h5]
//                    [--stroke-percent 40] [--preload-percent 1] [--samples 1024]
//                    [--friction C1,C2,C3] [--axial-alpha RAD] [--spring-rule RULE]
//                    [--force-of whole|half]
//                    [--zero-slider-mass | --zero-inertia] [--history W1,W2,...] [--json]
//   flexure dynamics --list [--json]
//
// Per frequency: mean, median, min, max and peak-to-peak input force (N; of the whole symmetric
// mechanism unless --force-of half) over one period of Delta x(t) = preload + stroke (1 - cos
// omega t)/2, and the percent constant force 100 min/max. The HDF5 file also holds the force
// history at the --history frequencies (default: the paper's Figs. 11-13, 10.472, 31.416 and
// 62.832 rad/s). The design comes from dynamics/dynamics_design.h.
#include <fmt/format.h>

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/slow_progress.h"
#include "flexure/io/hdf5_file.h"
#include "flexure/io/mechanism_toml.h"
#include "flexure/io/output_path.h"
#include "flexure/io/provenance.h"
#include "flexure/mechanisms/dynamics/cfsm_designs.h"
#include "flexure/mechanisms/dynamics/dynamics_design.h"
#include "flexure/mechanisms/dynamics/forward_dynamics.h"
#include "flexure/mechanisms/dynamics/inverse_dynamics.h"
#include "flexure/mechanisms/force_of.h"
#include "flexure/mechanisms/modified_designs.h"
#include "flexure/solver/common/errors.h"

namespace flexure::cli {
namespace {

using dynamics::CfsmDesign;
using dynamics::DynamicsDesign;
using dynamics::DynamicsParameters;
using dynamics::ForceSample;
using dynamics::ForceStatistics;
using dynamics::InverseDynamics;
using dynamics::SinusoidalMotion;
using dynamics::SliderCrankDynamics;
using mechanism::ForceOf;

// Samples of the static nominal force (inverse_dynamics.h static_nominal_force): the mean over
// Delta x = k stroke/N, k = 1..N, as `mechanism analyze --points N` samples its stroke.
constexpr int kStaticForcePoints = 1000;

struct DynamicsArgs {
  std::string mechanism;
  std::string omega;
  std::string out;
  double stroke_percent = 40.0;
  CLI::Option* stroke_option = nullptr;
  std::string spring_rule;
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
// table (dynamics_design.h says which springs and masses each gives).
DynamicsDesign resolve_design(const DynamicsArgs& args) {
  std::optional<mechanism::SpringRule> rule;
  if (!args.spring_rule.empty()) rule = mechanism::parse_spring_rule(args.spring_rule);
  const std::string& what = args.mechanism;
  if (what.size() > 5 && what.substr(what.size() - 5) == ".toml") {
    const mechanism::MechanismFile file = mechanism::load_mechanism_file(what);
    warn(file.warnings);
    const dynamics::MassesNeeded needed = args.zero_inertia ? dynamics::MassesNeeded::kNone
                                          : args.zero_slider_mass
                                              ? dynamics::MassesNeeded::kLinksOnly
                                              : dynamics::MassesNeeded::kAll;
    return dynamics::dynamics_design(file.design, file.dynamics, needed, rule);
  }
  try {
    return dynamics::builtin_dynamics_design(what, rule);
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format(
        "--mechanism: {}; or FILE.toml, a mechanism file with a [dynamics] table", e.what()));
  }
}

void run_dynamics(const DynamicsArgs& args) {
  if (args.list) {
    run_list(args);
    return;
  }
  if (args.mechanism.empty()) throw InvalidInput("--mechanism is required (see --list)");
  if (args.omega.empty()) throw InvalidInput("--omega START:STOP:COUNT is required");
  // Without --out nothing is written: the results are printed (all of them with --json).
  if (!args.out.empty()) io::check_output_path(args.out);
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
  // The model computes the whole mechanism (two halves, one slider); one half is exactly half of
  // it with the slider's inertia shared equally (force_of.h).
  const double to_reported = mechanism::force_of_factor(ForceOf::kWholeMechanism, force_of);

  DynamicsParameters p = dynamics::from_bar_links(d.r2, d.r3, d.m2, d.m3, d.m_slider, d.k);
  if (args.zero_slider_mass) p.m_slider = 0.0;
  if (args.zero_inertia) p.m2 = p.m3 = p.m_slider = p.J_C2 = p.J_C3 = 0.0;
  for (std::size_t i = 0; i < args.friction.size(); ++i) {
    require_in_range(args.friction[i], fmt::format("--friction C{} (N m)", i + 1), 0.0, 1e6);
    p.coulomb[i] = args.friction[i];
  }
  p.axial_alpha = args.axial_alpha;
  const SliderCrankDynamics model(p);
  const InverseDynamics inverse(model, {.samples_per_period = args.samples});
  const double r_tot = model.r_tot();
  // A design file's own stroke unless --stroke-percent is given (built-ins: 40 %, Table 6).
  const double stroke = d.stroke && args.stroke_option->count() == 0
                            ? *d.stroke
                            : args.stroke_percent / 100.0 * r_tot;
  SinusoidalMotion motion{args.preload_percent / 100.0 * r_tot, stroke, 0.0};
  model.theta2_at(motion.preload + motion.stroke);  // throws (exit 2) past the toggle position

  // Open the output first: an unwritable path fails before any work (exit 2).
  std::unique_ptr<io::AtomicHdf5File> output;
  try {
    if (!args.out.empty()) output = std::make_unique<io::AtomicHdf5File>(args.out);
  } catch (const io::Hdf5Error& e) {
    throw InvalidInput(fmt::format("--out {}: {}", args.out, e.what()));
  }

  const auto start = std::chrono::steady_clock::now();
  std::vector<double> omegas(range.count);
  for (long i = 0; i < range.count; ++i) omegas[i] = range.at(i);
  std::vector<ForceStatistics> rows = inverse.sweep(motion, omegas, slow_progress("dynamics"));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::vector<double> mean, median, min, max, p2p, pcf;
  for (ForceStatistics& s : rows) {
    require_finite_result(s.mean, fmt::format("mean force at omega = {}", s.omega));
    require_finite_result(s.peak_to_peak, fmt::format("peak-to-peak force at omega = {}", s.omega));
    for (double* f : {&s.mean, &s.median, &s.min, &s.max, &s.peak_to_peak}) *f *= to_reported;
    mean.push_back(s.mean);
    median.push_back(s.median);
    min.push_back(s.min);
    max.push_back(s.max);
    p2p.push_back(s.peak_to_peak);
    pcf.push_back(s.percent_constant_force);
  }
  const double F_nom =
      to_reported * dynamics::static_nominal_force(model, motion.stroke, kStaticForcePoints);
  const double F_nom_paper = to_reported * d.F_nom_paper;
  const std::string force_of_label = mechanism::force_of_label(force_of);
  const bool has_inertia = model.terms(0.0).M > 0.0;
  const double omega_n = has_inertia ? dynamics::linearise(model, 0.0).omega_n : 0.0;

  // The requested time histories (one period each).
  struct History {
    double omega = 0.0;
    std::vector<double> t, delta_x, theta2, force, static_force;
  };
  std::vector<History> histories;
  for (double w : args.history) {
    motion.omega = w;
    History h{w, {}, {}, {}, {}, {}};
    for (const ForceSample& sample : inverse.history(motion)) {
      h.t.push_back(sample.t);
      h.delta_x.push_back(sample.delta_x);
      h.theta2.push_back(sample.theta2);
      h.force.push_back(to_reported * sample.force);
      h.static_force.push_back(to_reported * sample.static_force);
    }
    histories.push_back(std::move(h));
  }

  if (output) {
    // Every force is of what force_of says (--force-of), as in the JSON.
    io::Hdf5Group& root = output->root();
    const auto of = [&](const char* what) { return fmt::format("{} ({})", what, force_of_label); };
    root.write_dataset("omega", omegas, "rad/s", "drive frequency omega of the sinusoidal motion");
    root.write_dataset("mean_force", mean, "N", of("mean input force over one period"));
    root.write_dataset("median_force", median, "N", of("median input force over one period"));
    root.write_dataset("min_force", min, "N", of("smallest input force over one period"));
    root.write_dataset("max_force", max, "N", of("largest input force over one period"));
    root.write_dataset("peak_to_peak_force", p2p, "N", of("max_force - min_force over one period"));
    root.write_dataset("percent_constant_force",
                       pcf,
                       "%",
                       "percent constant force 100 min_force / max_force over one period");
    root.set_attribute("mechanism", d.name);
    root.set_attribute("stroke_m", motion.stroke);
    root.set_attribute("preload_m", motion.preload);
    root.set_attribute("samples_per_period", static_cast<std::int64_t>(args.samples));
    root.set_attribute("zero_slider_mass", static_cast<std::int64_t>(args.zero_slider_mass));
    root.set_attribute("zero_inertia", static_cast<std::int64_t>(args.zero_inertia));
    root.set_attribute("friction_C1", p.coulomb[0]);
    root.set_attribute("friction_C2", p.coulomb[1]);
    root.set_attribute("friction_C3", p.coulomb[2]);
    root.set_attribute("axial_alpha", p.axial_alpha);
    root.set_attribute("static_nominal_force", F_nom);
    if (d.F_nom_paper > 0.0) root.set_attribute("paper_nominal_force", F_nom_paper);
    root.set_attribute("natural_frequency", omega_n);
    root.set_attribute("force_of", force_of_label);
    root.set_attribute("spring_rule", d.spring_rule.value_or("none"));
    root.set_attribute("attribute_units",
                       fmt::format("stroke_m, preload_m: m; friction_C1, friction_C2, friction_C3: "
                                   "N m; axial_alpha: rad; static_nominal_force, "
                                   "paper_nominal_force: N ({}); natural_frequency: rad/s",
                                   force_of_label));
    io::write_provenance(root, {});
    io::Hdf5Group history_group = root.create_group("history");
    history_group.set_attribute("description",
                                "one period of the motion at each --history frequency, groups 0, "
                                "1, ... in the order given");
    for (std::size_t i = 0; i < histories.size(); ++i) {
      const History& h = histories[i];
      io::Hdf5Group g = history_group.create_group(fmt::format("{}", i));
      g.set_attribute("omega", h.omega);
      g.set_attribute("attribute_units", "omega: rad/s");
      g.write_dataset("t", h.t, "s", "time within the period, from 0");
      g.write_dataset("delta_x",
                      h.delta_x,
                      "m",
                      "slider displacement Delta x(t) = preload + stroke (1 - cos omega t)/2");
      g.write_dataset("theta2", h.theta2, "rad", "crank angle theta2 at Delta x(t)");
      g.write_dataset("force", h.force, "N", of("input force of the dynamic model"));
      g.write_dataset(
          "static_force", h.static_force, "N", of("static PRBM force at the same Delta x"));
    }
    output->commit();
  }

  if (args.json) {
    Json history = Json::array();
    for (const History& h : histories) {
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
             {"force_of", force_of_label},
             {"spring_rule", d.spring_rule ? Json(*d.spring_rule) : Json(nullptr)},
             {"spring_constants", d.k},
             {"stroke", motion.stroke},
             {"preload", motion.preload},
             {"history", history},
             {"static_nominal_force", F_nom},
             {"static_nominal_force_points", kStaticForcePoints},
             {"paper_nominal_force", d.F_nom_paper > 0.0 ? Json(F_nom_paper) : Json(nullptr)},
             {"natural_frequency", omega_n},
             {"seconds", seconds},
             {"omega", omegas},
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
        d.F_nom_paper > 0.0 ? fmt::format(" (paper {:.4f} N)", F_nom_paper) : "",
        omega_n,
        force_of_label,
        d.k[0],
        d.k[1],
        d.k[2],
        d.spring_rule ? "spring rule " + *d.spring_rule : std::string("thesis springs"));
    fmt::print("{:>12} {:>12} {:>12} {:>12} {:>8}\n",
               "omega rad/s",
               "mean N",
               "median N",
               "p-p N",
               "PCF %");
    for (const ForceStatistics& s : rows) {
      fmt::print("{:12.4f} {:12.4f} {:12.4f} {:12.4f} {:8.3f}\n",
                 s.omega,
                 s.mean,
                 s.median,
                 s.peak_to_peak,
                 s.percent_constant_force);
    }
    if (output) fmt::print("written to {}\n", args.out);
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
      "--out", args->out, "Output HDF5 file (written atomically); without it nothing is written");
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
