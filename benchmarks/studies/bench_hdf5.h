#pragma once
// Benchmark results <-> HDF5 (layout: docs/hdf5-schema.md). Writing goes through
// io::AtomicHdf5File, so a file is complete or absent; reading uses the HDF5 C API directly.
#include <string>
#include <vector>

#include "flexure/benchmarks/studies/bench_types.h"

namespace flexure::bench {

// File-level attributes (root group) besides the provenance every file has
// (io/platform/provenance.h: tool_version, git_commit, command_line, creation_time,
// status_meanings).
struct BenchFileInfo {
  std::string machine;  // host name, OS, CPU architecture, hardware threads
  bool quick = false;
  bool complete = true;  // false for the checkpoint of an unfinished run
};

// Writes every run, grouped by problem in the order of `problems`, atomically to `path`.
void write_bench_file(const std::string& path,
                      const BenchFileInfo& info,
                      const std::vector<BenchProblem>& problems,
                      const std::vector<MethodRun>& runs);

// Reads every /<problem>/<method> group written by write_bench_file. Throws io::Hdf5Error when
// the file cannot be opened or a group lacks a dataset of the schema.
std::vector<MethodRun> read_bench_runs(const std::string& path);
// The root attribute `quick` (0/1) of a benchmark file.
bool read_bench_quick_flag(const std::string& path);

// Machine description for BenchFileInfo.
std::string describe_machine();

}  // namespace flexure::bench
