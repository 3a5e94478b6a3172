// Speed of `flexure sweep beam`: solve N loads alpha2 in [0, 10] (n = 0, mu = 0) with the elliptic
// solver and write the five columns to an HDF5 file atomically (temp name + rename), as the tool
// does (io/beam_sweep.h). Variants: N = 10^4 and 10^6, 1 or 2 threads; plus the solve alone and
// the HDF5 write alone, to see where the time goes. Goal: 10^6 points in under 5 s.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "flexure/io/beam_sweep.h"
#include "flexure/io/platform/hdf5_file.h"
#include "flexure/solver/common/gsl_guard.h"
#include "flexure/solver/elliptic/elliptic_solver.h"

namespace {

using namespace flexure;

constexpr double kMaxAlpha2 = 10.0;

std::vector<double> loads(long count) {
  std::vector<double> alpha2(count);
  for (long i = 0; i < count; ++i) alpha2[i] = kMaxAlpha2 * i / std::max(1L, count - 1);
  return alpha2;
}

io::BeamSweepPoint solve_elliptic(double alpha2) {
  static const EllipticSolver solver;
  const EllipticResult result = solver.solve(EndLoad::howell(0.0, alpha2, 0.0));
  io::BeamSweepPoint point;
  point.set_converged(result.converged());
  point.tip = result.tip;
  return point;
}

// A scratch directory for the output files, removed at exit.
const std::filesystem::path& scratch_dir() {
  static const std::filesystem::path dir = [] {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "flexure-sweep-bench-XXXXXX").string();
    std::filesystem::path made = ::mkdtemp(pattern.data());
    std::atexit([] {
      std::error_code ignored;
      std::filesystem::remove_all(scratch_dir(), ignored);
    });
    return made;
  }();
  return dir;
}

void write_file(const io::BeamSweepTable& table) {
  io::AtomicHdf5File file((scratch_dir() / "sweep.h5").string());
  io::write_beam_sweep(
      file.root(), table, io::BeamSweepMetadata{BeamMethod::kElliptic, 0.0, 0.0, 1e-14});
  file.commit();
}

// Whole command: solve + write. Args: {count, threads}.
void BM_SweepToHdf5(benchmark::State& state) {
  disable_gsl_abort();
  const std::vector<double> alpha2 = loads(state.range(0));
  io::BeamSweepOptions options;
  options.threads = static_cast<int>(state.range(1));
  for (auto _ : state) {
    const io::BeamSweepTable table = io::run_beam_sweep(alpha2, solve_elliptic, options);
    if (table.converged_count != state.range(0)) state.SkipWithError("a point did not converge");
    write_file(table);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_SweepToHdf5)
    ->Args({10'000, 1})
    ->Args({10'000, 2})
    ->Args({1'000'000, 1})
    ->Args({1'000'000, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

// What the tool does since sweeps stream: solve and write 64 Ki points at a time (memory flat);
// optionally compressed. Args: {count, threads, compress}.
void BM_StreamedSweep(benchmark::State& state) {
  disable_gsl_abort();
  const long count = state.range(0);
  const std::vector<double> alpha2 = loads(count);
  io::BeamSweepOptions options;
  options.threads = static_cast<int>(state.range(1));
  io::Hdf5DatasetOptions layout;
  layout.compress = state.range(2) != 0;
  for (auto _ : state) {
    io::AtomicHdf5File file((scratch_dir() / "streamed.h5").string());
    io::BeamSweepWriter writer(
        file.root(), count, io::BeamSweepMetadata{BeamMethod::kElliptic, 0.0, 0.0, 1e-14}, layout);
    const io::BeamSweepSummary summary = io::stream_beam_sweep(
        count,
        [&](long i) {
          io::BeamSweepPoint point = solve_elliptic(alpha2[i]);
          point.alpha2 = alpha2[i];
          return point;
        },
        options,
        writer);
    if (summary.converged_count != count) state.SkipWithError("a point did not converge");
    file.commit();
  }
  state.SetItemsProcessed(state.iterations() * count);
}
BENCHMARK(BM_StreamedSweep)
    ->Args({1'000'000, 1, 0})
    ->Args({1'000'000, 2, 0})
    ->Args({1'000'000, 2, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

// The solve alone.
void BM_SweepSolveOnly(benchmark::State& state) {
  disable_gsl_abort();
  const std::vector<double> alpha2 = loads(state.range(0));
  io::BeamSweepOptions options;
  options.threads = static_cast<int>(state.range(1));
  for (auto _ : state) {
    benchmark::DoNotOptimize(io::run_beam_sweep(alpha2, solve_elliptic, options));
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_SweepSolveOnly)
    ->Args({1'000'000, 1})
    ->Args({1'000'000, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

// The HDF5 write alone (five columns of 10^6 entries, ~36 MB).
void BM_SweepWriteOnly(benchmark::State& state) {
  const std::vector<double> alpha2 = loads(state.range(0));
  const io::BeamSweepTable table = io::run_beam_sweep(alpha2, [](double a) {
    io::BeamSweepPoint point;
    point.set_converged(true);
    point.tip = TipPose{1.0, a / 3, a / 2};
    return point;
  });
  for (auto _ : state) write_file(table);
  state.SetBytesProcessed(state.iterations() * state.range(0) * (4 * 8 + 4));
}
BENCHMARK(BM_SweepWriteOnly)->Arg(1'000'000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
