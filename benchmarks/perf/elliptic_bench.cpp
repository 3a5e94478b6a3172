// Elliptic solver timings (Google Benchmark). The numbers quoted in docs/performance.md come from
//   build/benchmarks/elliptic_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only
// Each benchmark cycles through a set of loads so that no result is reused between iterations.
// BM_GslBrentReference is the yardstick: a straightforward solve of the same problem as
// BM_ForwardVerticalLoad with GSL's elliptic integrals and GSL's Brent root finder. The machine is
// shared, so docs/performance.md quotes each path as a ratio to it measured in the same run.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "flexure/solver/elliptic/elliptic_solver.h"
#include "gsl_brent_reference.h"

namespace {

using flexure::EllipticSolver;
using flexure::EndLoad;

constexpr double kPi = std::numbers::pi;

// One forward solve, mu = 0: Howell's cantilever, n = 0, alpha2 between 0.5 and 20.
double vertical_load(int i) { return 0.5 + 19.5 * (i % 997) / 997.0; }

void BM_ForwardVerticalLoad(benchmark::State& state) {
  const EllipticSolver solver;
  int i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(solver.solve(EndLoad::howell(0.0, vertical_load(i++))).tip);
  }
}
BENCHMARK(BM_ForwardVerticalLoad);

using flexure_bench::BM_GslBrentReference;
BENCHMARK(BM_GslBrentReference);

// One forward solve, mu = 0, across load ratios n in [-5, 10] and alpha2 in [0.5, 20].
void BM_ForwardAnyLoadRatio(benchmark::State& state) {
  const EllipticSolver solver;
  int i = 0;
  for (auto _ : state) {
    const double n = -5.0 + 15.0 * (i % 31) / 30.0;
    benchmark::DoNotOptimize(solver.solve(EndLoad::howell(n, vertical_load(i++))).tip);
  }
}
BENCHMARK(BM_ForwardAnyLoadRatio);

// Inverse: alpha2 from the tip angle (explicit for mu = 0), n = 0.
void BM_InverseFromTipAngle(benchmark::State& state) {
  const EllipticSolver solver;
  int i = 0;
  for (auto _ : state) {
    const double theta0 = 0.05 + 1.4 * (i++ % 997) / 997.0;
    benchmark::DoNotOptimize(solver.solve_for_tip_angle(0.0, theta0).load);
  }
}
BENCHMARK(BM_InverseFromTipAngle);

// Inverse: alpha2 from the tip deflection b/l in [0.02, 0.8], n = 0, mu = 0.
void BM_InverseFromDeflection(benchmark::State& state) {
  const EllipticSolver solver;
  int i = 0;
  for (auto _ : state) {
    const double b_over_l = 0.02 + 0.78 * (i++ % 997) / 997.0;
    benchmark::DoNotOptimize(solver.solve_for_deflection(0.0, b_over_l).load);
  }
}
BENCHMARK(BM_InverseFromDeflection);

// Combined force and end moment: continuation along proportional loading, n = 1, alpha2 = 5,
// mu in [-2, 2].
void BM_ForwardWithEndMoment(benchmark::State& state) {
  const EllipticSolver solver;
  int i = 0;
  for (auto _ : state) {
    const double mu = -2.0 + 4.0 * (i++ % 97) / 97.0 + 1e-3;
    benchmark::DoNotOptimize(solver.solve(EndLoad::howell(1.0, 5.0, mu)).tip);
  }
}
BENCHMARK(BM_ForwardWithEndMoment);

// Force and end moment on the goal grid of issue 14: 1000 seeded loads, n in [-5, 10], alpha2 in
// [-20, 20], mu in [-2 pi, 2 pi] (the grid of tests/solver/elliptic_branch_grid_test.cpp, where
// every answer is checked against the shooting solver's continuation).
std::vector<EndLoad> moment_grid() {
  std::mt19937_64 rng(20261214u);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<EndLoad> loads;
  for (int i = 0; i < 1000; ++i) {
    const double n = -5.0 + 15.0 * unit(rng);
    const double alpha2 = -20.0 + 40.0 * unit(rng);
    const double mu = -2.0 * kPi + 4.0 * kPi * unit(rng);
    loads.push_back(EndLoad::howell(n, alpha2, mu));
  }
  return loads;
}

void BM_ForwardWithEndMomentGrid(benchmark::State& state) {
  const EllipticSolver solver;
  const std::vector<EndLoad> loads = moment_grid();
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(solver.solve(loads[i++ % loads.size()]).tip);
  }
}
BENCHMARK(BM_ForwardWithEndMomentGrid);

// Deflected shape at 101 points after a solve.
void BM_Shape101Points(benchmark::State& state) {
  const EllipticSolver solver;
  const auto result = solver.solve(EndLoad::howell(0.0, 5.0));
  for (auto _ : state) benchmark::DoNotOptimize(solver.shape(result, 101));
}
BENCHMARK(BM_Shape101Points);

}  // namespace

BENCHMARK_MAIN();
