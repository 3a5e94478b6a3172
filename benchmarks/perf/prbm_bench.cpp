// PRB constant derivation speed (docs/prbm.md).
//
// Description:
//  1. BM_DeriveTable51: derive gamma, Theta_max(gamma), c_theta, K_theta for all 17 rows of
//  Howell's
//     Table 5.1 from the exact elliptic solver (0.1 deg tip-angle sampling). The target
//     (docs/prbm.md) is < 1 s.
//  2. BM_DeriveFixedPinnedRow: one row, n = 0 and n = 10 (the longest path, phi = 174.3 deg).
//  3. BM_DeriveEndMoment: the end-moment constants from the closed-form circular path.
//  4. BM_ExactTip: one exact tip from EllipticSolver::solve_for_tip_angle (the unit of work).
#include <benchmark/benchmark.h>

#include "flexure/elements/prbm_element.h"
#include "flexure/solver/elliptic/elliptic_solver.h"

namespace {

void BM_DeriveTable51(benchmark::State& state) {
  for (auto _ : state) {
    for (const auto& row : flexure::table_5_1()) {
      benchmark::DoNotOptimize(flexure::derive_fixed_pinned(row.load_ratio_n));
    }
  }
}
BENCHMARK(BM_DeriveTable51)->Unit(benchmark::kMillisecond);

void BM_DeriveFixedPinnedRow(benchmark::State& state) {
  const double n = static_cast<double>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(flexure::derive_fixed_pinned(n));
}
BENCHMARK(BM_DeriveFixedPinnedRow)->Arg(0)->Arg(10)->Unit(benchmark::kMillisecond);

void BM_DeriveEndMoment(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(flexure::derive_end_moment());
}
BENCHMARK(BM_DeriveEndMoment)->Unit(benchmark::kMillisecond);

void BM_ExactTip(benchmark::State& state) {
  const flexure::EllipticSolver solver;
  double theta0 = 0.1;
  for (auto _ : state) {
    benchmark::DoNotOptimize(solver.solve_for_tip_angle(1.0, theta0));
    theta0 = theta0 > 2.0 ? 0.1 : theta0 + 1e-3;
  }
}
BENCHMARK(BM_ExactTip)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
