// Speed of the shooting solver (CVODES + sensitivity Newton), for docs/performance.md.
//
// Cases: Howell's cantilever n = 0, alpha2 = 3 (direct Newton, and the default kAuto strategy,
// which continues from zero because alpha2 = 3 is above the uniqueness bound), a pure end moment
// mu = 2 pi, and a fixed-guided beam (P = 10; two shooting intervals). Tolerance rtol 1e-9
// (atol 1e-11) as the speed target asks, and the reference rtol 1e-12; integrator CVODES
// (the reference), the built-in Dormand-Prince 5(4) (the fast path before GSL's) or GSL's
// Prince-Dormand 8(7) (the default), side by side so that docs/performance.md can quote ratios
// measured in one run. One iteration = one complete solve.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <numbers>

#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/shooting/elastica_integrator.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {
namespace {

ElasticaIntegrator::Backend backend_at(std::int64_t code) {
  switch (code) {
    case 0:
      return ElasticaIntegrator::Backend::kCvodes;
    case 1:
      return ElasticaIntegrator::Backend::kDormandPrince;
    case 3:
      return ElasticaIntegrator::Backend::kArkodeErk;
    default:
      return ElasticaIntegrator::Backend::kRk8pd;
  }
}

ShootingSolver::Options options_at(const benchmark::State& state, ShootingStrategy strategy) {
  const double rtol = state.range(0) == 9 ? 1e-9 : 1e-12;
  ShootingSolver::Options o;
  o.backend = backend_at(state.range(1));
  o.rtol = rtol;
  o.atol = 1e-2 * rtol;
  // The residual cannot be driven below the integration error.
  o.newton.residual_tolerance = std::max(1e-10, 10.0 * rtol);
  o.strategy = strategy;
  return o;
}

void run(benchmark::State& state, const SegmentChain& chain, ShootingSolver::Options options) {
  const ShootingSolver solver(options);
  int iterations = 0;
  long steps = 0;
  for (auto _ : state) {
    const ShootingResult r = solver.solve(chain);
    if (!r.converged()) state.SkipWithError(r.message.c_str());
    iterations = r.iterations;
    steps = r.integrator_steps;
    benchmark::DoNotOptimize(r.tip.x);
  }
  state.counters["newton_iterations"] = iterations;
  state.counters["integrator_steps"] = static_cast<double>(steps);
}

void BM_CantileverDirect(benchmark::State& state) {
  run(state,
      uniform_cantilever(EndLoad::howell(0.0, 3.0)),
      options_at(state, ShootingStrategy::kDirect));
}
void BM_CantileverContinuation(benchmark::State& state) {
  run(state,
      uniform_cantilever(EndLoad::howell(0.0, 3.0)),
      options_at(state, ShootingStrategy::kAuto));
}
void BM_EndMomentTwoPi(benchmark::State& state) {
  run(state,
      uniform_cantilever(EndLoad{0.0, 0.0, 2.0 * std::numbers::pi}),
      options_at(state, ShootingStrategy::kAuto));
}
void BM_GuidedBeam(benchmark::State& state) {
  SegmentChain chain;
  chain.segments.push_back(FlexibleSegment{1.0, 1.0, {}, 0.0});
  chain.end = EndCondition::kGuided;
  chain.tip_load.Fy = 10.0;
  run(state, chain, options_at(state, ShootingStrategy::kAuto));
}
void BM_GuidedBeamDirect(benchmark::State& state) {
  SegmentChain chain;
  chain.segments.push_back(FlexibleSegment{1.0, 1.0, {}, 0.0});
  chain.end = EndCondition::kGuided;
  chain.tip_load.Fy = 10.0;
  run(state, chain, options_at(state, ShootingStrategy::kDirect));
}

// Arguments: {9 -> rtol 1e-9 | 12 -> rtol 1e-12,
//             0 -> CVODES | 1 -> Dormand-Prince 5(4) | 2 -> GSL rk8pd | 3 -> ARKODE ERK 13-7-8}.
#define FLEXURE_SHOOTING_ARGS \
  ArgsProduct({{9, 12}, {0, 1, 2, 3}})->ArgNames({"rtol_exp", "rk"})->Unit(benchmark::kMicrosecond)
BENCHMARK(BM_CantileverDirect)->FLEXURE_SHOOTING_ARGS;
BENCHMARK(BM_CantileverContinuation)->FLEXURE_SHOOTING_ARGS;
BENCHMARK(BM_EndMomentTwoPi)->FLEXURE_SHOOTING_ARGS;
BENCHMARK(BM_GuidedBeam)->FLEXURE_SHOOTING_ARGS;
BENCHMARK(BM_GuidedBeamDirect)->FLEXURE_SHOOTING_ARGS;

}  // namespace
}  // namespace flexure

BENCHMARK_MAIN();
