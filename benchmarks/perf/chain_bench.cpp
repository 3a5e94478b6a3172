// Speed of Howell's chain algorithm (solver/chain/) on the load case: a uniform cantilever,
// alpha2 = 10, n = 0, N = 100 elements, at an increment count that reaches a tip error <= 1e-4
// (docs/theory-chain.md: the fixed point at N = 100 is within 4e-5 (Howell) and 9e-7 (corrected)
// of the elliptic solution, and one increment plus iteration at full load reaches it).
// Also: the cost of one chain pass, and the cost as N grows (a pass is O(N)).
#include <benchmark/benchmark.h>

#include "flexure/solver/chain/chain_algorithm_solver.h"
#include "flexure/solver/chain/chain_discretisation.h"
#include "flexure/solver/chain/chain_pass.h"

namespace {

using flexure::ChainAlgorithmSolver;
using flexure::ChainVariant;
using flexure::EndLoad;

void BM_ChainCantilever(benchmark::State& state, ChainVariant variant, bool accelerate = true) {
  ChainAlgorithmSolver::Options o;
  o.variant = variant;
  o.accelerate = accelerate;
  o.elements = static_cast<int>(state.range(0));
  o.increments = static_cast<int>(state.range(1));
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
// Howell's plain passes at full load, as in the book (no Anderson acceleration).
void BM_ChainHowellPlain(benchmark::State& state) {
  BM_ChainCantilever(state, ChainVariant::kHowell, false);
}
void BM_ChainCorrected(benchmark::State& state) {
  BM_ChainCantilever(state, ChainVariant::kCorrected);
}

// Arguments: {elements N, increments}.
BENCHMARK(BM_ChainHowell)
    ->Args({100, 1})
    ->Args({100, 10})
    ->Args({200, 1})
    ->Args({400, 1})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ChainHowellPlain)->Args({100, 1})->Args({100, 10})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ChainCorrected)
    ->Args({100, 1})
    ->Args({100, 10})
    ->Args({200, 1})
    ->Args({400, 1})
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
