// What the stability verdict costs a beam answer (issue 27), for docs/performance.md: one
// iteration = one solve_beam (beam/beam_problem.h), as `flexure beam`, `sweep beam`
// and the Python module call it, with the verdict (BeamProblem::judge_stability, the default) and
// without (`--stability off`); and one search for a stable equilibrium (BeamProblem::stable,
// `--stable`). The yardstick, measured in the same run, is the elliptic solve of Howell's
// cantilever n = 0, alpha2 = 3 without the verdict.
//
// Loads (elliptic): 0 = n 0, alpha2 3 (moderate, the stations' 48 elements); 1 = n 1, alpha2 5
// (compressed, margin 0.986: close to 1, so the stations are refined until its error is below
// 1e-9); 2 = n 5, alpha2 10 (compressed harder, margin 0.944, 1500 points); 3 = n -1, alpha2 10
// (tension). Shooting: 4 = n 1, alpha2 5 by the shooting method. Searches: the straight column
// Fx = -3 (a chain, index 1) and the clamped-clamped beam with the tip at (0.9, 0.001), angle 0
// (second mode, index 1).
#include <benchmark/benchmark.h>

#include "flexure/beam/beam_problem.h"

namespace flexure {
namespace {

BeamProblem load_case(std::int64_t code) {
  static const double loads[][2] = {{0.0, 3.0}, {1.0, 5.0}, {5.0, 10.0}, {-1.0, 10.0}, {1.0, 5.0}};
  BeamProblem p;
  p.load_ratio_n = loads[code][0];
  p.value = loads[code][1];
  return p;
}

void BM_SolveBeam(benchmark::State& state) {
  BeamProblem p = load_case(state.range(0));
  p.judge_stability = state.range(1) != 0;
  const BeamMethod method = state.range(0) == 4 ? BeamMethod::kShooting : BeamMethod::kElliptic;
  double margin = 0.0;
  for (auto _ : state) {
    const BeamSolution s = solve_beam(method, p);
    margin = s.stability.margin;
    benchmark::DoNotOptimize(s.tip.theta0);
  }
  state.counters["margin"] = margin;
}
BENCHMARK(BM_SolveBeam)
    ->ArgNames({"load", "verdict"})
    ->ArgsProduct({{0, 1, 2, 3, 4}, {0, 1}})
    ->Unit(benchmark::kMicrosecond);

// The scalar call of the Python module's docs/performance.md table `python_scalar`: `flexure
// beam --alpha2 2` as solve_beam sees it (method auto, which takes the elliptic solution here),
// with the verdict (the default) and without.
void BM_SolveBeamAuto(benchmark::State& state) {
  BeamProblem p;
  p.value = 2.0;
  p.judge_stability = state.range(0) != 0;
  for (auto _ : state) {
    const BeamSolution s = solve_beam(BeamMethod::kAuto, p);
    benchmark::DoNotOptimize(s.tip.theta0);
  }
}
BENCHMARK(BM_SolveBeamAuto)->ArgNames({"verdict"})->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

void BM_StableSearch(benchmark::State& state) {
  BeamProblem p;
  if (state.range(0) == 0) {
    p.chain = uniform_cantilever(EndLoad{-3.0, 0.0, 0.0});
  } else {
    p.boundary = EndCondition::kFixed;
    p.prescribed = TipPrescription{0.9, 0.001, 0.0};
  }
  p.stable = true;
  for (auto _ : state) {
    const BeamSolution s = solve_beam(BeamMethod::kShooting, p);
    if (!s.converged() || !s.stability.stable()) state.SkipWithError("no stable equilibrium");
    benchmark::DoNotOptimize(s.tip.theta0);
  }
}
BENCHMARK(BM_StableSearch)
    ->ArgName("case")
    ->Arg(0)  // straight column, Fx = -3
    ->Arg(1)  // clamped-clamped, second mode
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace flexure

BENCHMARK_MAIN();
