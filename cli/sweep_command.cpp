// `flexure sweep beam`: the end-loaded cantilever over a range of one or two of alpha2, n, mu,
// theta0, b/l (a grid), written to HDF5 (docs/cli.md, docs/hdf5-schema.md).
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <memory>
#include <optional>
#include <tuple>

#include "cli/beam_methods.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/csv_output.h"
#include "cli/physical_flags.h"
#include "cli/slow_progress.h"
#include "flexure/beam/beam_sweep_grid.h"
#include "flexure/benchmarks/studies/beam_sweep_run.h"
#include "flexure/io/platform/mpi_world.h"
#include "flexure/io/platform/output_path.h"
#include "flexure/io/toml_files.h"
#include "flexure/solver/common/names.h"
#include "flexure/solver/common/section.h"
#include "flexure/solver/common/status.h"

namespace flexure::cli {
namespace {

struct SweepBeamArgs {
  // Each a number (fixed) or START:STOP:COUNT (an axis).
  std::string load_ratio_n = "0";
  std::string mu = "0";
  std::string alpha2;
  std::string theta0;
  std::string b_over_l;
  std::string method = "auto";
  std::string out;
  std::string csv;
  std::optional<int> threads;  // default: 2, or 1 per rank under mpirun
  bool compress = false;
  bool json = false;
  std::string stability = "on";  // the verdict per point (docs/stability.md), or off
  // The far end and its prescribed tip (x/l, y/l; metres or with a unit for a physical beam).
  std::string boundary = "free";
  std::string tip_x, tip_y, tip_angle;
  // A physical beam (SI, or with units); its --Fx, --Fy, --M may be ranges (0N:5N:51).
  PhysicalFlags physical;
  std::string chain_file;  // --chain FILE.toml: its tip load swept by --Fx, --Fy, --M
  int shapes = 0;          // --shapes K: the shape of every point at K points, in /shapes
};

// A tip load of a physical sweep: a range START:STOP:COUNT whose ends are forces (moments for
// --M), each plain SI or with a unit (0N:5N:51).
Range parse_load_range(const std::string& text, const char* what, io::Dimension dimension) {
  const auto first = text.find(':');
  const auto second = first == std::string::npos ? std::string::npos : text.find(':', first + 1);
  if (second == std::string::npos) return parse_range(text, what, max_beam_sweep_points());
  const auto value = [&](const std::string& part, const char* end) {
    return io::parse_quantity(part, dimension, fmt::format("{} {}", what, end)).si;
  };
  const double start = value(text.substr(0, first), "START");
  const double stop = value(text.substr(first + 1, second - first - 1), "STOP");
  return parse_range(fmt::format("{:.17g}:{:.17g}:{}", start, stop, text.substr(second + 1)),
                     what,
                     max_beam_sweep_points());
}

// The prescribed tip of --boundary: x/l, y/l (plain), or metres for a physical beam.
TipPrescription sweep_tip(const SweepBeamArgs& args, bool physical) {
  const EndCondition end = end_condition_from_string(args.boundary);
  const PrescribedMask mask = prescribed_mask(end);
  TipPrescription tip;
  const auto length = [&](const std::string& text, bool allowed, const char* flag) {
    if (!allowed) {
      throw InvalidInput(fmt::format("{} is not prescribed by --boundary {}", flag, args.boundary));
    }
    double value = 0.0;
    if (physical) return io::parse_quantity(text, io::Dimension::kLength, flag).si;
    if (!parse_double(text, value) || !std::isfinite(value)) {
      throw InvalidInput(fmt::format(
          "{} = '{}': a tip coordinate of Howell's nondimensional beam is a finite plain number "
          "(x/l, y/l); a length with a unit needs a physical beam (--length, --E, the section)",
          flag,
          text));
    }
    return value;
  };
  if (!args.tip_x.empty()) tip.x = length(args.tip_x, mask.x, "--tip-x");
  if (!args.tip_y.empty()) tip.y = length(args.tip_y, mask.y, "--tip-y");
  if (!args.tip_angle.empty()) {
    if (!mask.theta) {
      throw InvalidInput(
          fmt::format("--tip-angle is not prescribed by --boundary {}", args.boundary));
    }
    tip.theta = io::parse_quantity(args.tip_angle, io::Dimension::kAngle, "--tip-angle").si;
  }
  return tip;
}

// A chain file's sweep: its tip load set by --Fx, --Fy, --M (ranges or values; with units when
// the file is in SI, else plain numbers in the file's units); the file holds the rest.
BeamSweepGrid make_chain_grid(const SweepBeamArgs& args) {
  const io::ChainFile file = io::read_chain_file(args.chain_file);
  warn(file.warnings);
  if (!file.contacts.empty()) {
    // A sweep point would be the free beam's equilibrium, which crosses the surface once loaded
    // onto it: refused rather than answered wrongly.
    throw InvalidInput(fmt::format(
        "sweep beam --chain {}: the file has a [[contact]] (a {}), which a sweep does not solve; "
        "solve each load with `flexure beam --chain FILE` (its load continuation reports "
        "landing, lift-off and the contact forces; docs/contact.md)",
        args.chain_file,
        to_string(file.contacts.front().surface.type)));
  }
  const PhysicalFlags& f = args.physical;
  for (const std::string* other : {&f.length,
                                   &f.E,
                                   &f.I,
                                   &f.width,
                                   &f.thickness,
                                   &f.material,
                                   &f.qx,
                                   &f.qy,
                                   &f.q_follower,
                                   &f.density,
                                   &f.g,
                                   &f.nu,
                                   &f.shear_coefficient,
                                   &f.plate,
                                   &f.curvature,
                                   &f.width_tip,
                                   &f.thickness_tip,
                                   &args.alpha2,
                                   &args.theta0,
                                   &args.b_over_l,
                                   &args.tip_x,
                                   &args.tip_y,
                                   &args.tip_angle}) {
    if (!other->empty()) {
      throw InvalidInput(
          "--chain FILE.toml describes the whole beam (segments, sections, distributed loads, "
          "boundary and tip); sweep its tip load with --Fx, --Fy, --M only");
    }
  }
  if (f.extensible || args.load_ratio_n != "0" || args.mu != "0" || args.boundary != "free") {
    throw InvalidInput(
        "--chain FILE.toml describes the whole beam; do not combine it with --n, --mu, "
        "--boundary or --extensible");
  }
  BeamSweepGrid grid;
  SegmentChain chain = file.chain;
  const std::tuple<SweepParameter, const std::string*, io::Dimension, double*> loads[] = {
      {SweepParameter::kFx, &f.Fx, io::Dimension::kForce, &chain.tip_load.Fx},
      {SweepParameter::kFy, &f.Fy, io::Dimension::kForce, &chain.tip_load.Fy},
      {SweepParameter::kM, &f.M, io::Dimension::kMoment, &chain.tip_load.M}};
  for (const auto& [p, text, dimension, value] : loads) {
    if (text->empty()) continue;
    const char* flag = flag_name(p);
    if (text->find(':') != std::string::npos) {
      const Range r = file.physical ? parse_load_range(*text, flag, dimension)
                                    : parse_range(*text, flag, max_beam_sweep_points());
      grid.axes.push_back({p, r.start, r.stop, r.count});
    } else if (file.physical) {
      *value = io::parse_quantity(*text, dimension, flag).si;
    } else if (!parse_double(*text, *value) || !std::isfinite(*value)) {
      throw InvalidInput(fmt::format(
          "{} = '{}': the chain file is in its own units, so the load is a plain number",
          flag,
          *text));
    }
  }
  grid.chain = chain;
  grid.chain_in_si = file.physical;
  grid.base.given = BeamProblem::Given::kAlpha2;
  grid.validate(max_beam_sweep_points());
  // Every point must be a chain the solvers take (a load on a held coordinate is refused here).
  for (long index : {0L, grid.size() - 1}) grid.at(index).chain->validate();
  return grid;
}

// A physical sweep: the beam of the flags with one or two of --Fx, --Fy, --M as ranges.
BeamSweepGrid make_physical_grid(const SweepBeamArgs& args) {
  for (const std::string* given : {&args.alpha2, &args.theta0, &args.b_over_l}) {
    if (!given->empty()) {
      throw InvalidInput(
          "a physical beam (--length, --E, the section) is swept over its tip loads --Fx, --Fy, "
          "--M in newtons; do not combine it with --alpha2, --theta0 or --b-over-l");
    }
  }
  if (args.load_ratio_n != "0" || args.mu != "0") {
    throw InvalidInput(
        "a physical beam is loaded by --Fx, --Fy, --M in newtons; do not combine it with --n or "
        "--mu");
  }
  PhysicalFlags flags = args.physical;
  BeamSweepGrid grid;
  const std::tuple<SweepParameter, std::string*, io::Dimension> loads[] = {
      {SweepParameter::kFx, &flags.Fx, io::Dimension::kForce},
      {SweepParameter::kFy, &flags.Fy, io::Dimension::kForce},
      {SweepParameter::kM, &flags.M, io::Dimension::kMoment}};
  for (const auto& [p, text, dimension] : loads) {
    if (text->find(':') == std::string::npos) continue;
    const Range r = parse_load_range(*text, flag_name(p), dimension);
    grid.axes.push_back({p, r.start, r.stop, r.count});
    text->clear();  // the beam's own value is set per point
  }
  PhysicalCantilever beam = flags.parse();
  beam.end = end_condition_from_string(args.boundary);
  beam.prescribed = sweep_tip(args, true);
  if (beam.plate == PlateRule::kAuto) {
    throw InvalidInput(
        "--plate auto is decided by one solved beam's curvature; a sweep passes through many: "
        "choose --plate on or off");
  }
  grid.physical = beam;
  grid.base.given = BeamProblem::Given::kAlpha2;
  grid.validate(max_beam_sweep_points());
  // Every point must be a beam the flags allow (a load on a held coordinate is refused here).
  (void)grid.at(0);
  return grid;
}

// An angle range: START and STOP in rad, or each with a unit (30deg:60deg:4); COUNT as in
// parse_range, whose messages it keeps.
Range parse_angle_range(const std::string& text, const std::string& what) {
  const auto first = text.find(':');
  const auto second = first == std::string::npos ? std::string::npos : text.find(':', first + 1);
  if (second == std::string::npos) return parse_range(text, what, max_beam_sweep_points());
  const auto angle = [&](const std::string& part, const char* end) {
    return io::parse_quantity(part, io::Dimension::kAngle, fmt::format("{} {}", what, end)).si;
  };
  const double start = angle(text.substr(0, first), "START");
  const double stop = angle(text.substr(first + 1, second - first - 1), "STOP");
  return parse_range(fmt::format("{:.17g}:{:.17g}:{}", start, stop, text.substr(second + 1)),
                     what,
                     max_beam_sweep_points());
}

// One of the parameters: a fixed value, or an axis when the text has a ':'.
void add_parameter(BeamSweepGrid& grid, SweepParameter p, const std::string& text) {
  const std::string what = flag_name(p);
  // Angles are radians: a value beyond a full turn was probably meant in degrees.
  const auto check_angle = [&](double value) {
    if (p == SweepParameter::kTheta0) warn(io::angle_warning({value, ""}, what));
  };
  if (text.find(':') != std::string::npos) {
    const Range r = p == SweepParameter::kTheta0 ? parse_angle_range(text, what)
                                                 : parse_range(text, what, max_beam_sweep_points());
    grid.axes.push_back({p, r.start, r.stop, r.count});
    check_angle(std::fabs(r.start) > std::fabs(r.stop) ? r.start : r.stop);
    return;
  }
  double value = 0.0;
  if (p == SweepParameter::kTheta0 && !parse_double(text, value)) {
    value = io::parse_quantity(text, io::Dimension::kAngle, what).si;  // 30deg
  } else if (!parse_double(text, value) || !std::isfinite(value)) {
    throw InvalidInput(fmt::format(
        "{} = '{}' is neither a finite number nor a range START:STOP:COUNT", what, text));
  }
  check_angle(value);
  if (p == SweepParameter::kLoadRatioN) {
    grid.base.load_ratio_n = value;
  } else if (p == SweepParameter::kMu) {
    grid.base.mu = value;
  } else {
    grid.base.value = value;
  }
}

// The grid of the flags: the given quantity first, then n, then mu (the datasets' axis order).
BeamSweepGrid make_grid(const SweepBeamArgs& args) {
  BeamSweepGrid grid;
  const std::pair<SweepParameter, const std::string*> given[] = {
      {SweepParameter::kAlpha2, &args.alpha2},
      {SweepParameter::kTheta0, &args.theta0},
      {SweepParameter::kBOverL, &args.b_over_l}};
  int given_count = 0;
  for (const auto& [p, text] : given) {
    if (text->empty()) continue;
    ++given_count;
    grid.base.given = p == SweepParameter::kAlpha2   ? BeamProblem::Given::kAlpha2
                      : p == SweepParameter::kTheta0 ? BeamProblem::Given::kTheta0
                                                     : BeamProblem::Given::kBOverL;
    add_parameter(grid, p, *text);
  }
  if (given_count != 1) {
    throw InvalidInput(
        "give exactly one of --alpha2 (loads), --theta0 or --b-over-l (inverse: the load is "
        "found), each a value or START:STOP:COUNT");
  }
  add_parameter(grid, SweepParameter::kLoadRatioN, args.load_ratio_n);
  add_parameter(grid, SweepParameter::kMu, args.mu);
  grid.base.boundary = end_condition_from_string(args.boundary);
  grid.base.prescribed = sweep_tip(args, false);
  grid.validate(max_beam_sweep_points());
  return grid;
}

void run_sweep_beam(const SweepBeamArgs& args) {
  const auto started = std::chrono::steady_clock::now();
  const int threads = args.threads.value_or(default_beam_sweep_threads());
  require_in_range(threads, "--threads", 1, 64);
  const bool physical = args.physical.given();
  BeamSweepGrid grid = !args.chain_file.empty() ? make_chain_grid(args)
                       : physical               ? make_physical_grid(args)
                                                : make_grid(args);
  // The verdict per point, as `flexure beam` gives it (docs/stability.md; its cost:
  // docs/performance.md, "Stability verdict"), also at the points started from a neighbour.
  grid.base.judge_stability = same_name(args.stability, "on");
  const long count = grid.size();
  // Fails (exit 2) for a method not in this build, before any file is touched.
  BeamMethod requested = beam_method_from_string(args.method);
  // auto: the shooting method where some point is one the elliptic solution of a sweep's auto
  // does not take (BeamSweepGrid::needs_shooting).
  if (requested == BeamMethod::kAuto && grid.needs_shooting()) requested = BeamMethod::kShooting;
  const BeamMethod method = resolve_beam_method(requested);

  // Check and open the output first: an unwritable path is reported before minutes of solving.
  require_out_or_csv(args.out, args.csv);
  if (!args.out.empty()) io::check_output_path(args.out);
  const CsvOutput csv(args.out, args.csv);
  if (args.shapes != 0) {
    // The shapes live in the HDF5 file (its /shapes group and the XDMF sidecar), not in a CSV.
    if (args.out.empty() || csv.hdf5_path() != args.out) {
      throw InvalidInput(
          "--shapes needs --out FILE.h5: the shapes are stored in its /shapes group");
    }
    check_beam_sweep_shapes(count, args.shapes);
  }
  // Under mpirun every rank writes its blocks into the one file (docs/scaling.md).
  if (args.compress && parallel::launched_size() > 1) {
    throw InvalidInput(
        "--compress is not available under mpirun with several ranks: parallel HDF5 writes "
        "compressed datasets only collectively; compress the file afterwards (h5repack -f "
        "SHUF -f GZIP=4)");
  }
  BeamSweepFile file(csv.hdf5_path(), args.compress);
  BeamSweepRunOptions options;
  options.threads = threads;
  options.shape_points = args.shapes;
  // By elapsed time, not by count: silent for the first second, then "sweep beam: k/n (t s)" on a
  // terminal (a shooting sweep of 2000 loads takes about 40 s).
  if (auto progress = stoppable_progress("sweep beam")) {
    options.progress = [progress](long done, long total) {
      progress(static_cast<std::size_t>(done), static_cast<std::size_t>(total));
    };
  }
  const BeamSweepRun table = file.run(grid, method, options);
  // The table as CSV (rank 0 writes it): the swept parameters first.
  std::vector<std::string> csv_axes = {"alpha2"};
  if (!table.stored_axes.empty()) {
    csv_axes.clear();
    for (const std::string& axis : table.stored_axes) csv_axes.push_back("axes/" + axis);
  }
  csv.write(csv_axes, {"shapes"});
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  std::string ranges;
  for (const SweepAxis& axis : grid.axes) {
    ranges += fmt::format("{}{} {} .. {} ({})",
                          ranges.empty() ? "" : " x ",
                          dataset_name(axis.parameter),
                          axis.start,
                          axis.stop,
                          axis.count);
  }
  if (args.json) {
    Json summary;
    summary["out"] = csv.out_json();
    summary["csv"] = csv.csv_json();
    summary["count"] = count;
    summary["converged_count"] = table.converged_count;
    summary["axes"] = grid.axis_names();
    summary["shape"] = grid.shape();
    summary["seconds"] = seconds;
    if (args.shapes > 0) {
      summary["shape_points"] = args.shapes;
      summary["xdmf"] = table.xdmf;
    }
    print_json(summary);
  } else {
    fmt::print("Wrote {} points ({}; method {}) to {}\n",
               count,
               ranges,
               to_string(method),
               csv.written_path());
    if (csv.wanted() && csv.csv_path() != csv.written_path()) {
      fmt::print("  table written to {}\n", csv.csv_path());
    }
    fmt::print("  converged: {} of {}; {:.3f} s\n", table.converged_count, count, seconds);
    if (!table.xdmf.empty()) {
      fmt::print(
          "  shapes ({} points each) in /shapes; XDMF sidecar {}\n", args.shapes, table.xdmf);
    }
  }
  if (table.first_failure >= 0) {
    BeamSolution failed;
    failed.method = method;
    failed.methods_tried = {method};
    failed.alpha2 = std::numeric_limits<double>::quiet_NaN();
    throw NoConvergence(fmt::format(
        "{} of {} points have no converged solution (stored with status 1 and NaN in '{}'); the "
        "first is {}: {}. {}",
        count - table.converged_count,
        count,
        csv.written_path(),
        describe_sweep_point(grid, table.first_failure),
        table.first_failure_message,
        failure_hint(grid.at(table.first_failure), failed)));
  }
}

}  // namespace

void register_sweep_command(CLI::App& app) {
  CLI::App& sweep = get_or_add_subcommand(
      app, "sweep", "Solve a range of loads and write the results to an HDF5 file");
  sweep.require_subcommand(1);

  auto args = std::make_shared<SweepBeamArgs>();
  CLI::App* beam = sweep.add_subcommand(
      "beam",
      "Cantilever with end load over one or two of alpha2, n, mu, theta0, b/l (START:STOP:COUNT; "
      "two make a grid)");
  beam->add_option("--alpha2", args->alpha2, "Load alpha2 = P l^2/EI: a value or START:STOP:COUNT");
  beam->add_option(
      "--theta0",
      args->theta0,
      "Inverse: tip angle theta0 (rad, or with a unit: 30deg), a value or START:STOP:COUNT "
      "(30deg:60deg:4); the load is found");
  beam->add_option(
      "--b-over-l",
      args->b_over_l,
      "Inverse: tip deflection b/l (-1..1), a value or START:STOP:COUNT; the load is found");
  beam->add_option("--n",
                   args->load_ratio_n,
                   "Load ratio n (horizontal load nP, n > 0 compressive): a value or "
                   "START:STOP:COUNT")
      ->default_str("0");
  beam->add_option("--mu", args->mu, "End moment mu = M l/EI: a value or START:STOP:COUNT")
      ->default_str("0");
  add_method_option(*beam, args->method);
  beam->add_option("--out",
                   args->out,
                   "Output HDF5 file (written atomically), or FILE.csv for the table as CSV only; "
                   "--out, --csv or both");
  add_csv_option(beam, args->csv);
  beam->add_option("--shapes",
                   args->shapes,
                   "Store the deformed shape (x, y, angle, N, V, m; fibre stresses of a physical "
                   "beam with a rectangle) at K points of every sweep point in /shapes of --out, "
                   "with an XDMF sidecar; points x K at most 5e6");
  beam->add_option(
          "--threads", args->threads, "Worker threads per process (1-64; 1 per rank under mpirun)")
      ->default_str("2");
  beam->add_option("--stability",
                   args->stability,
                   "The stability verdict of every point (stored in /stability, "
                   "/stability_index, /stability_margin): on (default) or off (faster; the file "
                   "then says not_checked)")
      ->default_str("on")
      ->transform(CLI::IsMember({"on", "off"}, CLI::ignore_case));
  beam->add_flag("--compress",
                 args->compress,
                 "Compress the datasets (shuffle + deflate, chunks of 64 Ki points)");
  beam->add_flag("--json", args->json, "Print one JSON summary object on stdout");
  beam->add_option("--boundary",
                   args->boundary,
                   "Far end: free (loads given), guided (tip angle prescribed), pinned (tip x, y), "
                   "slider (tip y), fixed (all); default free")
      ->default_str("free")
      ->transform(CLI::IsMember({"free", "guided", "pinned", "slider", "fixed"}, CLI::ignore_case));
  beam->add_option("--tip-x",
                   args->tip_x,
                   "Prescribed tip x/l (pinned, fixed); metres or with a unit for a physical beam");
  beam->add_option(
      "--tip-y",
      args->tip_y,
      "Prescribed tip y/l (pinned, slider, fixed); metres or with a unit for a physical beam");
  beam->add_option(
      "--tip-angle", args->tip_angle, "Prescribed tip angle, rad or with a unit (guided, fixed)");
  // The physical beam; its --Fx, --Fy, --M may be ranges with units (0N:5N:51).
  args->physical.add_to(*beam, false);
  beam->add_option("--chain",
                   args->chain_file,
                   "Segment chain TOML file (docs/chain-toml.md) whose tip load --Fx, --Fy, --M "
                   "sweeps (ranges with units for a file in SI)");
  beam->callback([args] { run_sweep_beam(*args); });
}

}  // namespace flexure::cli
