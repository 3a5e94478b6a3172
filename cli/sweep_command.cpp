// `flexure sweep beam`: the end-loaded cantilever over a range of alpha2, written to HDF5.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <memory>

#include "cli/beam_methods.h"
#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/slow_progress.h"
#include "flexure/io/beam_sweep.h"
#include "flexure/io/hdf5_file.h"
#include "flexure/io/output_path.h"
#include "flexure/solver/common/errors.h"

namespace flexure::cli {
namespace {

struct SweepBeamArgs {
  double load_ratio_n = 0.0;
  double mu = 0.0;
  std::string alpha2_range;
  std::string method = "auto";
  std::string out;
  int threads = 2;
  bool json = false;
};

// 10^7 points keep the five columns under 400 MB in memory.
constexpr long kMaxSweepCount = 10'000'000;
void run_sweep_beam(const SweepBeamArgs& args) {
  const auto started = std::chrono::steady_clock::now();
  require_finite_input(args.load_ratio_n, "--n (load ratio n)");
  require_finite_input(args.mu, "--mu (end moment M l/EI)");
  require_in_range(args.threads, "--threads", 1, 64);
  const Range range = parse_range(args.alpha2_range, "--alpha2", kMaxSweepCount);
  // Fails (exit 2) for a method not in this build, before any file is touched.
  const BeamMethod method = resolve_beam_method(beam_method_from_string(args.method));
  const double tolerance = beam_method_tolerance(method);

  // Check and open the output first: an unwritable path is reported before minutes of solving.
  io::check_output_path(args.out);
  std::unique_ptr<io::AtomicHdf5File> file;
  try {
    file = std::make_unique<io::AtomicHdf5File>(args.out);
  } catch (const io::Hdf5Error& e) {
    throw InvalidInput(fmt::format("--out: {}", e.what()));
  }

  std::vector<double> alpha2(range.count);
  for (long i = 0; i < range.count; ++i) alpha2[i] = range.at(i);

  BeamProblem problem;
  problem.given = BeamProblem::Given::kAlpha2;
  problem.load_ratio_n = args.load_ratio_n;
  problem.mu = args.mu;
  const io::BeamPointSolver solve_point = [&](double load) {
    BeamProblem at = problem;
    at.value = load;
    BeamSolution solution = solve_beam(method, at);
    io::BeamSweepPoint point;
    point.set_converged(solution.converged());
    point.tip = solution.tip;
    if (solution.method == BeamMethod::kPrbm) point.within_validity = solution.prbm_inside_validity;
    if (!solution.converged()) point.message = std::move(solution.message);
    return point;
  };
  io::BeamSweepOptions options;
  options.threads = args.threads;
  // Chunks of about 1/64 of each thread's share, so that progress moves steadily on slow methods;
  // at most 2048 loads, which amortises the hand-out on fast ones.
  options.chunk = std::clamp(range.count / (64L * args.threads), 1L, 2048L);
  // By elapsed time, not by count: silent for the first second, then "sweep beam: k/n (t s)" on a
  // terminal (a shooting sweep of 2000 loads takes about 40 s).
  if (auto progress = slow_progress("sweep beam")) {
    options.progress = [progress](long done, long total) {
      progress(static_cast<std::size_t>(done), static_cast<std::size_t>(total));
    };
  }
  const io::BeamSweepTable table = io::run_beam_sweep(alpha2, solve_point, options);

  io::write_beam_sweep(
      file->root(),
      table,
      io::BeamSweepMetadata{to_string(method), args.load_ratio_n, args.mu, tolerance});
  file->commit();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  if (args.json) {
    Json summary;
    summary["out"] = args.out;
    summary["count"] = range.count;
    summary["converged_count"] = table.converged_count;
    summary["seconds"] = seconds;
    print_json(summary);
  } else {
    fmt::print("Wrote {} loads (alpha2 {} .. {}, method {}, n = {:g}, mu = {:g}) to {}\n",
               range.count,
               range.start,
               range.stop,
               to_string(method),
               args.load_ratio_n,
               args.mu,
               args.out);
    fmt::print("  converged: {} of {}; {:.3f} s\n", table.converged_count, range.count, seconds);
  }
  if (table.first_failure >= 0) {
    throw NoConvergence(fmt::format(
        "{} of {} loads have no converged solution (stored with status 1 and NaN in '{}'); the "
        "first is alpha2 = {}: {}. {}",
        range.count - table.converged_count,
        range.count,
        args.out,
        table.alpha2[table.first_failure],
        table.first_failure_message,
        other_methods_hint(method)));
  }
}

}  // namespace

void register_sweep_command(CLI::App& app) {
  CLI::App& sweep = get_or_add_subcommand(
      app, "sweep", "Solve a range of loads and write the results to an HDF5 file");
  sweep.require_subcommand(1);

  auto args = std::make_shared<SweepBeamArgs>();
  CLI::App* beam = sweep.add_subcommand(
      "beam", "Cantilever with end load over alpha2 = START:STOP:COUNT (equally spaced)");
  beam->add_option("--n", args->load_ratio_n, "Load ratio n: horizontal load nP, n > 0 compressive")
      ->default_str("0");
  beam->add_option("--mu", args->mu, "End moment mu = M l/EI")->default_str("0");
  beam->add_option("--alpha2", args->alpha2_range, "Loads START:STOP:COUNT (COUNT >= 1)")
      ->required();
  add_method_option(*beam, args->method);
  beam->add_option("--out", args->out, "Output HDF5 file (written atomically)")->required();
  beam->add_option("--threads", args->threads, "Worker threads (1-64)")->default_str("2");
  beam->add_flag("--json", args->json, "Print one JSON summary object on stdout");
  beam->callback([args] { run_sweep_beam(*args); });
}

}  // namespace flexure::cli
