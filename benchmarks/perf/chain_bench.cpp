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
// The cost as the requested N grows past what the load needs (alpha2 = 10 needs about 23 elements
// by the self-check of 0.2 rad per element): N = 10 and 20 are refined to 40. predict:1 predicts
// the refinement from the coarse chain (the default), predict:0 solves, fails the check and solves
// again on 2N (and 4N), as before issue 27.
void BM_ChainElements(benchmark::State& state) {
  ChainAlgorithmSolver::Options o;
  o.elements = static_cast<int>(state.range(0));
  o.predict_elements = state.range(1) != 0;
  const ChainAlgorithmSolver solver(o);
  const EndLoad load = EndLoad::howell(0.0, 10.0);
  int elements = 0;
  for (auto _ : state) {
    const flexure::ChainResult r = solver.solve(load);
    if (!r.converged()) state.SkipWithError(r.message.c_str());
    elements = r.elements;
    benchmark::DoNotOptimize(r.tip.theta);
  }
  state.counters["elements"] = elements;
}
BENCHMARK(BM_ChainElements)
    ->ArgsProduct({{10, 20, 30, 40, 80}, {1, 0}})
    ->ArgNames({"N", "predict"})
    ->Unit(benchmark::kMicrosecond);

// A guided end under compression, the loads of issue 27 (N = 100): case 0 took 14.6 s (1.4 million
// passes), cases 1 and 2 gave up after 8-10 s. constrained:1 is the default (the passes meet the
// tip angle as they go, chain_constrained.h); constrained:0, the shooting method as printed, is
// timed on case 0 only (once, for the ratio).
void BM_ChainGuided(benchmark::State& state) {
  static const double kLoads[3][3] = {{3.662974688762594, 12.458088565233949, -0.42576506449933227},
                                      {1.656626959124937, 8.95598052442481, 0.06897238676232442},
                                      {4.132632167956947, 14.966530943697453, 0.456109405479435}};
  const double* l = kLoads[state.range(0)];
  flexure::SegmentChain chain = flexure::uniform_cantilever(EndLoad{-l[0] * l[1], l[1], 0.0});
  chain.end = flexure::EndCondition::kGuided;
  chain.prescribed.theta = l[2];
  ChainAlgorithmSolver::Options o;
  o.constrained_passes = state.range(1) != 0;
  const ChainAlgorithmSolver solver(o);
  int passes = 0;
  for (auto _ : state) {
    const flexure::ChainResult r = solver.solve(chain);
    if (!r.converged()) state.SkipWithError(r.message.c_str());
    passes = r.iterations;
    benchmark::DoNotOptimize(r.tip.theta);
  }
  state.counters["passes"] = passes;
}
BENCHMARK(BM_ChainGuided)
    ->Args({0, 1})
    ->Args({1, 1})
    ->Args({2, 1})
    ->ArgNames({"case", "constrained"})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ChainGuided)
    ->Args({0, 0})
    ->ArgNames({"case", "constrained"})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

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
