// Speed of a beam sweep by the shooting method (`flexure sweep beam --method shooting`), per point,
// against the GSL + Brent yardstick of gsl_brent_reference.h in the same run (issue 27: within 10x
// of it per point). The goal case is the reproducer: n = 0, mu = 0, alpha2 from 0.5 to 10
// in 500 points. One iteration = one point; the points are taken in order and the sweep starts
// over after the last (as a thread of `sweep beam` takes them).
//   BM_ShootingSweep/warm:1  BeamSweepSolver, the sweep's solver: each point from its neighbour
//                            where that gives the same answer (beam_sweep_solver.h)
//   BM_ShootingSweep/warm:0  every point from zero load, inflections counted without a shape
//   BM_ShootingSweepShape401 every point from zero load with the 401-point shape the inflection
//                            count used to take (the sweep before issue 27)
// Other sweeps: /case:1 a compressive n = 2 over alpha2 0.5:10 (the load path folds), /case:2 an
// end-moment sweep mu 0:8 at alpha2 = 2, n = 1 (off the ray: every point from zero load).
// /verdict:1 with the stability verdict of every point (the default of `sweep beam`), /verdict:0
// without it (`--stability off`).
//   BM_JacobiVerdict         the verdict alone of the compressed sweep (/case:1): the Jacobi
//                            equation along each point's solution
//                            (compressed_cantilever_stability.h) from the margin the sweep predicts
//                            from the last four points' margins (guess:1, as `sweep beam` does) or
//                            from the straight column's guess (guess:0, a single answer)
#include <benchmark/benchmark.h>

#include <optional>
#include <vector>

#include "flexure/beam/beam_sweep_solver.h"
#include "flexure/solver/shooting/compressed_cantilever_stability.h"
#include "flexure/solver/shooting/shooting_solver.h"
#include "gsl_brent_reference.h"

namespace {

using namespace flexure;

BeamSweepGrid sweep_case(long which) {
  BeamSweepGrid grid;
  grid.base.given = BeamProblem::Given::kAlpha2;
  switch (which) {
    case 1:
      grid.base.load_ratio_n = 2.0;
      grid.axes = {{SweepParameter::kAlpha2, 0.5, 10.0, 500}};
      break;
    case 2:
      grid.base.load_ratio_n = 1.0;
      grid.base.value = 2.0;
      grid.axes = {{SweepParameter::kMu, 0.0, 8.0, 500}};
      break;
    default:
      grid.axes = {{SweepParameter::kAlpha2, 0.5, 10.0, 500}};
      break;
  }
  grid.validate(1'000'000);
  return grid;
}

void BM_ShootingSweep(benchmark::State& state) {
  BeamSweepGrid grid = sweep_case(state.range(1));
  grid.base.judge_stability = state.range(2) != 0;
  const bool warm = state.range(0) != 0;
  const BeamSweepSolver solver(grid, warm ? BeamMethod::kShooting : BeamMethod::kShooting);
  const long count = grid.size();
  long i = 0;
  double iterations = 0.0;
  for (auto _ : state) {
    const long index = i++ % count;
    const BeamSolution s =
        warm ? solver.solve(index) : solve_beam(BeamMethod::kShooting, grid.at(index));
    if (!s.converged()) state.SkipWithError(s.message.c_str());
    iterations += s.iterations;
    benchmark::DoNotOptimize(s.tip.theta0);
  }
  state.counters["newton"] = iterations / std::max<long>(1, i);
  if (warm) {
    const BeamSweepSolver::Counts c = solver.counts();
    const double all = static_cast<double>(c.from_neighbour + c.from_zero);
    state.counters["from_neighbour"] = all > 0 ? c.from_neighbour / all : 0.0;
  }
}
BENCHMARK(BM_ShootingSweep)
    ->ArgsProduct({{1, 0}, {0, 1, 2}, {1, 0}})
    ->ArgNames({"warm", "case", "verdict"})
    ->Unit(benchmark::kMicrosecond);

// The sweep before issue 27: each point from zero load with a 401-point shape for the inflection
// count (the solver's result converted as solve_beam does).
void BM_ShootingSweepShape401(benchmark::State& state) {
  BeamSweepGrid grid = sweep_case(0);
  grid.base.judge_stability = false;
  const long count = grid.size();
  long i = 0;
  for (auto _ : state) {
    const BeamProblem problem = grid.at(i++ % count);
    ShootingSolver::Options options = beam_shooting_options(problem, 401);
    options.count_inflections = false;
    const ShootingResult r = solve_shooting(problem.to_chain(problem.value), options);
    if (!r.converged()) state.SkipWithError(r.message.c_str());
    benchmark::DoNotOptimize(r.tip.theta);
  }
}
BENCHMARK(BM_ShootingSweepShape401)->Unit(benchmark::kMicrosecond);

// The verdict alone: the 500 solutions of the compressed sweep (/case:1) solved once, then each
// judged in order, with the guess the sweep would give it (the Lagrange polynomial through the
// last four margins, beam_sweep_solver.cpp) or none.
void BM_JacobiVerdict(benchmark::State& state) {
  const bool guessed = state.range(0) != 0;
  struct Point {
    SegmentChain chain;
    ShootingResult result;
    std::optional<double> guess;
  };
  static const std::vector<Point> points = [] {
    const BeamSweepGrid grid = sweep_case(1);
    std::vector<Point> out;
    std::vector<double> alpha2, margin;
    for (long i = 0; i < grid.size(); ++i) {
      const BeamProblem problem = grid.at(i);
      Point p{problem.to_chain(problem.value), {}, std::nullopt};
      p.result = solve_shooting(p.chain, beam_shooting_options(problem, 0));
      const std::size_t k = std::min<std::size_t>(4, margin.size());
      if (k > 0) {
        double guess = 0.0;
        for (std::size_t a = margin.size() - k; a < margin.size(); ++a) {
          double w = 1.0;
          for (std::size_t b = margin.size() - k; b < margin.size(); ++b) {
            if (a != b) w *= (problem.value - alpha2[b]) / (alpha2[a] - alpha2[b]);
          }
          guess += w * margin[a];
        }
        p.guess = guess;
      }
      const std::optional<Stability> v =
          compressed_cantilever_stability(p.chain, p.result, {}, p.guess);
      alpha2.push_back(problem.value);
      margin.push_back(v ? v->margin : 0.0);
      out.push_back(std::move(p));
    }
    return out;
  }();
  std::size_t i = 0;
  for (auto _ : state) {
    const Point& p = points[i++ % points.size()];
    const std::optional<Stability> v =
        compressed_cantilever_stability(p.chain, p.result, {}, guessed ? p.guess : std::nullopt);
    if (!v) state.SkipWithError("the Jacobi verdict declined");
    benchmark::DoNotOptimize(v);
  }
}
BENCHMARK(BM_JacobiVerdict)->Arg(1)->Arg(0)->ArgName("guess")->Unit(benchmark::kMicrosecond);

using flexure_bench::BM_GslBrentReference;
BENCHMARK(BM_GslBrentReference);

}  // namespace

BENCHMARK_MAIN();
