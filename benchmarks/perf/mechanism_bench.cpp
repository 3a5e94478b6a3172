// Speed of one 50-point stroke of a constant-force mechanism (targets, docs/performance.md: PRBM <
// 50 us, exact < 50 ms). Results: docs/mechanisms.md "Speed".
#include <benchmark/benchmark.h>

#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_exact.h"
#include "flexure/mechanisms/mechanism_prbm.h"
#include "flexure/solver/common/gsl_guard.h"

namespace {

using namespace flexure::mechanism;

void BM_PrbmStroke50(benchmark::State& state, const char* name) {
  const MechanismDesign d = find_builtin_mechanism(name);
  for (auto _ : state) {
    PrbmStrokeResult r = prbm_stroke(d, 50);
    benchmark::DoNotOptimize(r.mean_force);
  }
}
BENCHMARK_CAPTURE(BM_PrbmStroke50, lpp, "1A-lpp");
BENCHMARK_CAPTURE(BM_PrbmStroke50, sss, "3A-sss");

// Exact stroke: shooting (Dormand-Prince backend) at 50 positions, each from the previous one.
void BM_ExactStroke50(benchmark::State& state, const char* name) {
  flexure::disable_gsl_abort();
  const MechanismDesign d = find_builtin_mechanism(name);
  const std::vector<double> dx = stroke_displacements(d, 50);
  for (auto _ : state) {
    ExactStrokeResult r = exact_stroke(d, dx);
    if (!r.converged()) state.SkipWithError(r.message.c_str());
    benchmark::DoNotOptimize(r.points.back().force);
  }
}
BENCHMARK_CAPTURE(BM_ExactStroke50, lpp, "1A-lpp")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExactStroke50, spp, "1A-spp")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExactStroke50, psp, "1B-psp")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExactStroke50, plp, "1B-plp")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExactStroke50, ssp, "2A-ssp")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExactStroke50, slp, "2A-slp")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExactStroke50, sps, "2B-sps")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExactStroke50, lps, "2B-lps")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExactStroke50, sss, "3A-sss")->Unit(benchmark::kMillisecond);
// Thesis rows whose cranks carry about their own buckling load (docs/mechanisms.md "Pinned
// middle"); the nested pin-force Newton could not solve them.
BENCHMARK_CAPTURE(BM_ExactStroke50, lps_a90, "lps-a90")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExactStroke50, sps_b86IO, "sps-b86IO")->Unit(benchmark::kMillisecond);
// The modified configurations of paper 004 (fixed-fixed strips, docs/mechanisms.md), one per
// exact-model topology: two-force coupler, pins at both ends, middle pin, serial chain.
BENCHMARK_CAPTURE(BM_ExactStroke50, lppm, "1A-lppm")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExactStroke50, plpm, "1B-plpm")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExactStroke50, lplm, "2B-lplm")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExactStroke50, lllm, "3A-lllm")->Unit(benchmark::kMillisecond);
// The two whose first point needs the thickness homotopy of mechanism_exact_start.cpp.
BENCHMARK_CAPTURE(BM_ExactStroke50, lssm, "3A-lssm")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExactStroke50, lslm, "3A-lslm")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PrbmStroke50, lllm, "3A-lllm");

// Chain-algorithm second opinion on the last stroke point (corrected variant, N = 100, as in
// `flexure mechanism validate`; docs/mechanisms.md "Chain algorithm check").
void BM_ChainCheck100(benchmark::State& state, const char* name) {
  flexure::disable_gsl_abort();
  const MechanismDesign d = find_builtin_mechanism(name);
  const ExactPoint p = ExactMechanismSolver(d).solve(d.stroke);
  if (!p.converged()) state.SkipWithError(p.message.c_str());
  for (auto _ : state) {
    ChainCheck c = chain_algorithm_check(p, 100);
    benchmark::DoNotOptimize(c.tip_error);
  }
}
BENCHMARK_CAPTURE(BM_ChainCheck100, lpp, "1A-lpp")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ChainCheck100, lps, "2B-lps")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ChainCheck100, sss, "3A-sss")->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
