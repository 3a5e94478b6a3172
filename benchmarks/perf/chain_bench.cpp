// Speed of Howell's chain algorithm (solver/chain/) on the load case: a uniform cantilever,
// alpha2 = 10, n = 0, N = 100 elements (docs/theory-chain.md: the fixed point at N = 100 is within
// 4e-5 (Howell) and 9e-7 (corrected) of the elliptic solution, whatever the increments).
// Arguments {N, initial increments, coarse path}: the defaults are {100, 1, 1} (one increment to
// start with, the load path on a coarse chain); {100, 10, 0} is the former default (10 increments
// on the requested chain), measured in the same run for the ratio in docs/performance.md.
// Also: the cost of one chain pass, and the cost as N grows (a pass is O(N)).
#include <benchmark/benchmark.h>

#include "flexure/solver/chain/chain_algorithm_solver.h"
#include "flexure/solver/chain/chain_discretisation.h"
#include "flexure/solver/chain/chain_pass.h"

namespace {

using flexure::ChainAlgorithmSolver;
using flexure::ChainVariant;
using flexure::EndLoad;

void BM_ChainCantilever(benchmark::State& state,
                        ChainVariant variant,
                        bool accelerate = true,
                        double max_angle_step = ChainAlgorithmSolver::Options{}.max_angle_step) {
  ChainAlgorithmSolver::Options o;
  o.variant = variant;
  o.accelerate = accelerate;
  o.elements = static_cast<int>(state.range(0));
  o.increments = static_cast<int>(state.range(1));
  o.coarse_path = state.range(2) != 0;
  o.max_angle_step = max_angle_step;
  const ChainAlgorithmSolver solver(o);
  const EndLoad load = EndLoad::howell(0.0, 10.0);
  int passes = 0;
  for (auto _ : state) {
    const flexure::ChainResult r = solver.solve(load);
    if (!r.converged()) state.SkipWithError(r.message.c_str());
    passes = r.iterations;
    benchmark::DoNotOptimize(r.tip.theta);
  }
  state.counters["passes"] = passes;
}

void BM_ChainHowell(benchmark::State& state) { BM_ChainCantilever(state, ChainVariant::kHowell); }
// The floor of "one increment": the corrected variant at full load from the unloaded chain with no
// limit on the turn of a step. Not an option to use: on random loads it lands on another branch
// for about 2 % of them (docs/theory-chain.md §4); measured for the ratio only.
void BM_ChainCorrectedOneStepUnguarded(benchmark::State& state) {
  BM_ChainCantilever(state, ChainVariant::kCorrected, true, 1e9);
}
// Howell's plain passes at full load, as in the book (no Anderson acceleration).
void BM_ChainHowellPlain(benchmark::State& state) {
  BM_ChainCantilever(state, ChainVariant::kHowell, false);
}
void BM_ChainCorrected(benchmark::State& state) {
  BM_ChainCantilever(state, ChainVariant::kCorrected);
}

// Arguments: {elements N, initial increments, coarse path (0/1; used by the corrected variant)}.
BENCHMARK(BM_ChainHowell)
    ->Args({100, 1, 1})
    ->Args({100, 10, 1})
    ->Args({200, 1, 1})
    ->Args({400, 1, 1})
    ->ArgNames({"N", "inc", "coarse"})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ChainHowellPlain)
    ->Args({100, 1, 1})
    ->Args({100, 10, 1})
    ->ArgNames({"N", "inc", "coarse"})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ChainCorrected)
    ->Args({100, 1, 1})   // the default
    ->Args({100, 10, 0})  // the former default: 10 increments on the requested chain
    ->Args({100, 1, 0})   // one increment to start with, no coarse path
    ->Args({100, 10, 1})
    ->Args({200, 1, 1})
    ->Args({400, 1, 1})
    ->ArgNames({"N", "inc", "coarse"})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ChainCorrectedOneStepUnguarded)
    ->Args({100, 1, 0})
    ->ArgNames({"N", "inc", "coarse"})
    ->Unit(benchmark::kMicrosecond);

void BM_ChainPass(benchmark::State& state) {
  const flexure::SegmentChain chain = flexure::uniform_cantilever(EndLoad::howell(0.0, 10.0));
  const flexure::ChainDiscretisation d =
      flexure::discretise(chain, static_cast<int>(state.range(0)));
  const flexure::ChainGeometry start = flexure::unloaded_geometry(d);
  flexure::ChainGeometry next;
  const flexure::ChainPassOptions options;
  for (auto _ : state) {
    benchmark::DoNotOptimize(flexure::chain_pass(d, d.loads, start, options, next));
  }
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_ChainPass)->RangeMultiplier(2)->Range(50, 800)->Complexity(benchmark::oN);

}  // namespace

BENCHMARK_MAIN();
