// Speed of the stability verdict (solver/chain_model/segment_chain.h), for
// docs/performance.md. One iteration = one verdict from a shape already sampled at the stations
// (BM_Verdict*), or the sampling itself (BM_Shape*), or the independent Jacobi method
// (BM_JacobiReference, a test reference). The yardstick, measured in the same run, is one elliptic
// forward solve of the cantilever load (BM_EllipticSolve), so that the ratios say what a verdict
// adds to a solve.
//
// Cases: Howell's cantilever n = 0, alpha2 = 3 (stable, no constraint); the issue's
// clamped-clamped beam with the tip at (0.9, 0.001): angle 0.01, the first mode (stable, two
// constraints and eta(L) = 0) and angle 0, the antisymmetric second mode (unstable, index 1); the
// straight cantilever under Fx = -30 (index 2). Counter `elements`: the stations' element count.
#include <benchmark/benchmark.h>

#include <vector>

#include "flexure/solver/chain_model/jacobi_stability.h"
#include "flexure/solver/chain_model/segment_chain.h"
#include "flexure/solver/elliptic/elliptic_solver.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {
namespace {

struct Case {
  SegmentChain chain;
  Reaction support;  // the tip support's reaction
  Reaction root;     // the clamp's reaction
  std::vector<double> stations;
  std::vector<ShapePoint> shape;
};

Case cantilever(const EndLoad& load) {
  Case c;
  c.chain = uniform_cantilever(load);
  const EllipticResult e = EllipticSolver().solve(load);
  c.root = Reaction{-load.Fx, -load.Fy, -e.root_moment};
  c.stations = stability_stations(c.chain, c.support);
  c.shape = EllipticSolver().shape_at(e, c.stations);
  return c;
}

Case clamped_clamped(double tip_angle) {
  Case c;
  c.chain = uniform_cantilever(EndLoad{});
  c.chain.end = EndCondition::kFixed;
  c.chain.prescribed = TipPrescription{0.9, 0.001, tip_angle};
  const ShootingResult r = ShootingSolver().solve(c.chain);
  c.support = tip_support_reaction(c.chain, r.tip_load);
  c.root = r.reaction;
  c.stations = stability_stations(c.chain, c.support);
  c.shape = shooting_shape_at(c.chain, r, c.stations);
  return c;
}

const Case& case_at(std::int64_t code) {
  static const Case cases[] = {cantilever(EndLoad::howell(0.0, 3.0)),
                               clamped_clamped(0.01),
                               clamped_clamped(0.0),
                               cantilever(EndLoad{-30.0, 0.0, 0.0})};
  return cases[code];
}

void BM_Verdict(benchmark::State& state) {
  const Case& c = case_at(state.range(0));
  int index = 0;
  for (auto _ : state) {
    const Stability v = equilibrium_stability(c.chain, c.support, c.shape);
    index = v.index;
    benchmark::DoNotOptimize(v.margin);
  }
  state.counters["elements"] = static_cast<double>(c.stations.size() - 1);
  state.counters["index"] = index;
}
BENCHMARK(BM_Verdict)
    ->ArgName("case")
    ->Arg(0)  // cantilever n = 0, alpha2 = 3: stable
    ->Arg(1)  // clamped-clamped first mode: stable, constrained
    ->Arg(2)  // clamped-clamped second mode: unstable
    ->Arg(3)  // straight cantilever, Fx = -30: index 2
    ->Unit(benchmark::kMicrosecond);

void BM_Stations(benchmark::State& state) {
  const Case& c = case_at(state.range(0));
  for (auto _ : state) {
    benchmark::DoNotOptimize(stability_stations(c.chain, c.support).size());
  }
}
BENCHMARK(BM_Stations)->ArgName("case")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// What a caller pays for the samples: the elliptic closed form at the stations, and the shooting
// solution integrated through them.
void BM_ShapeElliptic(benchmark::State& state) {
  const EndLoad load = EndLoad::howell(0.0, 3.0);
  const EllipticResult e = EllipticSolver().solve(load);
  const std::vector<double> s = stability_stations(uniform_cantilever(load), Reaction{});
  for (auto _ : state) benchmark::DoNotOptimize(EllipticSolver().shape_at(e, s).size());
  state.counters["points"] = static_cast<double>(s.size());
}
BENCHMARK(BM_ShapeElliptic)->Unit(benchmark::kMicrosecond);

void BM_ShapeShooting(benchmark::State& state) {
  SegmentChain chain = uniform_cantilever(EndLoad{});
  chain.end = EndCondition::kFixed;
  chain.prescribed = TipPrescription{0.9, 0.001, 0.01};
  const ShootingResult r = ShootingSolver().solve(chain);
  const std::vector<double> s = stability_stations(chain, tip_support_reaction(chain, r.tip_load));
  for (auto _ : state) benchmark::DoNotOptimize(shooting_shape_at(chain, r, s).size());
  state.counters["points"] = static_cast<double>(s.size());
}
BENCHMARK(BM_ShapeShooting)->Unit(benchmark::kMicrosecond);

void BM_JacobiReference(benchmark::State& state) {
  const Case& c = case_at(state.range(0));
  for (auto _ : state) {
    benchmark::DoNotOptimize(JacobiSecondVariation(c.chain, c.root).verdict().margin);
  }
}
BENCHMARK(BM_JacobiReference)->ArgName("case")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_EllipticSolve(benchmark::State& state) {
  const EndLoad load = EndLoad::howell(0.0, 3.0);
  for (auto _ : state) benchmark::DoNotOptimize(EllipticSolver().solve(load).tip.theta0);
}
BENCHMARK(BM_EllipticSolve)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace flexure

BENCHMARK_MAIN();
