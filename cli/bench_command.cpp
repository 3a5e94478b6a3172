// `flexure bench`: the standard benchmark (accuracy against time of every method on every
// problem), written to HDF5 (docs/hdf5-schema.md, docs/benchmarks.md).
#include <errno.h>  // program_invocation_name (GNU): the program as the user ran it
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/csv_output.h"
#include "flexure/benchmarks/studies/bench_run.h"
#include "flexure/io/platform/temp_file_cleanup.h"
#include "flexure/solver/common/status.h"

namespace flexure::cli {
namespace {

struct BenchArgs {
  bench::BenchOptions options;
  bool json = false;
};

// `text` as one shell word: unchanged when it holds only safe characters, else in single quotes.
std::string shell_word(const std::string& text) {
  const bool safe = !text.empty() && text.find_first_not_of(
                                         "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                         "0123456789_-+=./:,@%") == std::string::npos;
  if (safe) return text;
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// The command that continues this run: the same program, output and selection with --resume
// (--stop-after, a test device, is left out).
std::string resume_command(const BenchArgs& args) {
  const bench::BenchOptions& o = args.options;
  std::string command = shell_word(program_invocation_name) + " bench --out " + shell_word(o.out);
  if (o.quick) command += " --quick";
  if (!o.problems.empty()) command += " --problems " + shell_word(o.problems);
  if (!o.methods.empty()) command += " --methods " + shell_word(o.methods);
  if (args.json) command += " --json";
  return command + " --resume";
}

void run_bench(BenchArgs& args) {
  bench::BenchOptions options = args.options;
  refuse_csv_out(options.out,
                 "a group per problem and method, with a checkpoint for --resume; --json prints "
                 "a summary");
  // Fail fast (exit 2) on an unwritable path, before minutes of solving; the checkpoint is
  // written next to it after every finished group.
  bench::check_bench_outputs(options);
  // Interrupted (Ctrl-C, SIGTERM, SIGHUP): the checkpoint of the finished groups stays; say how to
  // continue. Before the first group has finished there is no checkpoint yet.
  const std::string checkpoint = bench::checkpoint_path(options.out);
  const std::string resume = resume_command(args);
  io::set_interrupt_note(
      fmt::format("\nflexure bench: interrupted; the finished groups are kept in {}. Resume "
                  "with:\n  {}\n",
                  checkpoint,
                  resume),
      checkpoint,
      fmt::format("\nflexure bench: interrupted before the first group finished (no checkpoint). "
                  "Run again with:\n  {}\n",
                  resume));
  options.progress = [](const std::string& line) {
    std::fprintf(stderr, "%s\n", line.c_str());
    std::fflush(stderr);
  };
  const auto start = std::chrono::steady_clock::now();
  const bench::BenchSummary summary = bench::run_benchmark(options);
  io::set_interrupt_note({});
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const int points = summary.solves();
  const int failed = summary.failed_solves();
  const std::string written = summary.complete ? options.out : bench::checkpoint_path(options.out);
  if (args.json) {
    Json out;
    out["file"] = written;
    out["complete"] = summary.complete;
    out["groups_computed"] = summary.groups_computed;
    out["groups_reused"] = summary.groups_reused;
    out["solves"] = points;
    out["failed_solves"] = failed;
    out["seconds"] = seconds;
    // Per group, as the progress lines print them; null where a statistic covers no point (a
    // group in which nothing converged has no error, not an error of 0).
    Json groups = Json::array();
    for (const bench::MethodRun& run : summary.runs) {
      const bench::RunStatistics s = bench::run_statistics(run);
      const auto number_or_null = [](double v) {
        return std::isfinite(v) ? Json(v) : Json(nullptr);
      };
      groups.push_back(Json{{"problem", run.problem},
                            {"method", run.method},
                            {"points", s.points},
                            {"converged_points", s.converged},
                            {"measured_points", s.measured},
                            {"max_relative_error", number_or_null(s.max_relative_error)},
                            {"median_seconds", number_or_null(s.median_seconds)}});
    }
    out["groups"] = std::move(groups);
    out["resume_command"] = summary.complete ? Json(nullptr) : Json(resume);
    print_json(out);
  } else {
    fmt::print("{} {}: {} groups computed, {} reused; {} loads solved, {} failed; {:.1f} s\n",
               summary.complete ? "Wrote" : "Stopped early; checkpoint in",
               written,
               summary.groups_computed,
               summary.groups_reused,
               points,
               failed,
               seconds);
    if (!summary.complete) fmt::print("Resume with: {}\n", resume);
  }
}

}  // namespace

void register_bench_command(CLI::App& app) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* bench = app.add_subcommand(
      "bench",
      "Benchmark every method on the standard problems: error against the reference and median "
      "time per solve, written to HDF5 (docs/benchmarks.md)");
  bench->add_option("--out", args->options.out, "Results HDF5 file (written whole or not at all)")
      ->required();
  bench->add_flag("--quick", args->options.quick, "Small problem set (smoke test, < 1 minute)");
  bench->add_option("--problems",
                    args->options.problems,
                    "Comma-separated problems: cantilever_force, tip_moment, force_and_moment, "
                    "fixed_guided, post_buckled_column, cfm_stroke (default all)");
  bench->add_option("--methods",
                    args->options.methods,
                    "Comma-separated methods or families: elliptic, shooting, chain, prbm, exact "
                    "(mechanism model, cfm_stroke only), or "
                    "names such as shooting_cvodes_rtol1e-09, chain_N050_inc05 (default all)");
  bench->add_flag("--resume",
                  args->options.resume,
                  "Reuse the finished groups of FILE.partial (an interrupted run) or FILE");
  bench
      ->add_option("--stop-after",
                   args->options.stop_after_groups,
                   "Stop after computing this many groups, leaving FILE.partial (tests --resume)")
      ->check(CLI::NonNegativeNumber);
  bench->add_flag("--json", args->json, "Print one JSON summary object on stdout");
  bench->callback([args] { run_bench(*args); });
}

}  // namespace flexure::cli
