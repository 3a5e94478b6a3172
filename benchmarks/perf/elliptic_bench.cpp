// Elliptic solver timings (Google Benchmark). The numbers quoted in docs/performance.md come from
//   build/benchmarks/elliptic_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only
// Each benchmark cycles through a set of loads so that no result is reused between iterations.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "flexure/solver/elliptic/elliptic_solver.h"

namespace {

using flexure::EllipticSolver;
using flexure::EndLoad;

// One forward solve, mu = 0: Howell's cantilever, n = 0, alpha2 between 0.5 and 20.
void BM_ForwardVerticalLoad(benchmark::State& state) {
  const EllipticSolver solver;
  int i = 0;
  for (auto _ : state) {
    const double alpha2 = 0.5 + 19.5 * (i++ % 997) / 997.0;
    benchmark::DoNotOptimize(solver.solve(EndLoad::howell(0.0, alpha2)).tip);
  }
}
BENCHMARK(BM_ForwardVerticalLoad);

// One forward solve, mu = 0, across load ratios n in [-5, 10] and alpha2 in [0.5, 20].
void BM_ForwardAnyLoadRatio(benchmark::State& state) {
  const EllipticSolver solver;
  int i = 0;
  for (auto _ : state) {
    const double n = -5.0 + 15.0 * (i % 31) / 30.0;
    const double alpha2 = 0.5 + 19.5 * (i++ % 997) / 997.0;
    benchmark::DoNotOptimize(solver.solve(EndLoad::howell(n, alpha2)).tip);
  }
}
BENCHMARK(BM_ForwardAnyLoadRatio);

// Inverse: alpha2 from the tip angle (explicit for mu = 0).
void BM_InverseFromTipAngle(benchmark::State& state) {
  const EllipticSolver solver;
  int i = 0;
  for (auto _ : state) {
    const double theta0 = 0.05 + 1.4 * (i++ % 997) / 997.0;
    benchmark::DoNotOptimize(solver.solve_for_tip_angle(0.0, theta0).load);
  }
}
BENCHMARK(BM_InverseFromTipAngle);

// Combined force and end moment: continuation along proportional loading.
void BM_ForwardWithEndMoment(benchmark::State& state) {
  const EllipticSolver solver;
  int i = 0;
  for (auto _ : state) {
    const double mu = -2.0 + 4.0 * (i++ % 97) / 97.0 + 1e-3;
    benchmark::DoNotOptimize(solver.solve(EndLoad::howell(1.0, 5.0, mu)).tip);
  }
}
BENCHMARK(BM_ForwardWithEndMoment);

// Deflected shape at 101 points after a solve.
void BM_Shape101Points(benchmark::State& state) {
  const EllipticSolver solver;
  const auto result = solver.solve(EndLoad::howell(0.0, 5.0));
  for (auto _ : state) benchmark::DoNotOptimize(solver.shape(result, 101));
}
BENCHMARK(BM_Shape101Points);

}  // namespace

BENCHMARK_MAIN();
