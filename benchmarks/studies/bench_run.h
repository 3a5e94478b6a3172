#pragma once
// `flexure bench`: runs every selected method on every selected problem, measures the error against
// the reference and the median time per solve, and writes the HDF5 results file.
//
// Resuming. The results file is written whole or not at all (io::AtomicHdf5File). While a run is in
// progress, every finished (problem, method) group is also saved, again atomically, to the
// checkpoint file `<out>.partial` (same schema, root attribute complete = 0). With resume = true
// the groups of the checkpoint, or of a previous complete `<out>` when there is no checkpoint, are
// reused when their load points are exactly the ones of this run; everything else is computed. On
// success `<out>` is written and the checkpoint removed.
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "flexure/benchmarks/studies/bench_types.h"

namespace flexure::bench {

struct BenchOptions {
  std::string out;            // results file
  bool quick = false;         // the smoke-test problem set (well under a minute)
  std::string problems;       // comma-separated problem names ("" = all)
  std::string methods;        // comma-separated method or family names ("" = all)
  bool resume = false;        // reuse finished groups of <out>.partial or <out>
  int stop_after_groups = 0;  // > 0: stop after computing this many groups (simulates an
                              // interruption; the checkpoint is left behind)
  std::function<void(const std::string&)> progress;  // one line per finished group
};

struct BenchSummary {
  bool complete = false;  // <out> written
  int groups_computed = 0;
  int groups_reused = 0;
  std::vector<MethodRun> runs;  // every group, reference groups included
  // Over every load point of every group: the solves, and those that did not converge or threw
  // (status kStatusNotConverged or kStatusError, as the file's status datasets record them).
  int solves() const;
  int failed_solves() const;
};

std::string checkpoint_path(const std::string& out);

// Before minutes of solving: the output file and its checkpoint can be written. Throws
// InvalidInput "OPTION PATH: reason" naming `option` (the caller's name for options.out, "--out"
// for the tool) for a path that cannot be written or a file HDF5 cannot create there.
void check_bench_outputs(const BenchOptions& options, const std::string& option = "--out");

// Throws InvalidInput for unknown problem or method names or an incompatible resume file;
// io::Hdf5Error when a file cannot be written.
BenchSummary run_benchmark(const BenchOptions& options);

// Statistics of one group over its load points. Over zero points a statistic has no value: NaN
// (printed "n/a", JSON null, HDF5 NaN; docs/hdf5-schema.md), never a 0 that reads as "exact".
struct RunStatistics {
  int points = 0;     // load points of the group
  int converged = 0;  // status 0 or 3 (converged, with or without a reference there)
  int measured = 0;   // status 0 with a finite error: the points the error statistics cover
  double max_relative_error = std::numeric_limits<double>::quiet_NaN();  // over `measured`
  double median_seconds = std::numeric_limits<double>::quiet_NaN();      // over all points
};
RunStatistics run_statistics(const MethodRun& run);

// One line for the progress output: "3/3 converged, max relative error 1.2e-09, median time ...";
// "max relative error n/a (no converged point with a reference)" when no error was measured.
std::string summarize(const MethodRun& run);

// Solves every load of `problem` with `method` (or the reference when `reference` is null) and
// fills errors against `reference`.
MethodRun run_method(const BenchProblem& problem,
                     const BenchMethod* method,
                     const MethodRun* reference,
                     bool quick);

}  // namespace flexure::bench
