// Speed of one 50-point stroke of a constant-force mechanism (targets, docs/performance.md: PRBM <
// 50 us; exact <= 20 ms for every built-in design, 1A-lpp <= 10 ms, 3A-lssm <= 50 ms). Results:
// docs/mechanisms.md "Speed" and docs/performance.md.
//
// BM_ExactStroke50/<design> runs every built-in design (`flexure mechanism list`: the thesis and
// paper-004 designs, Howell's, the inversions). Same-run comparisons: the stroke with the
// Dormand-Prince 5(4) integrator used before GSL's rk8pd (BM_ExactStroke50DormandPrince), and the
// exact stresses of a 50-point stroke from one integration of each solution against the former
// re-solve sampled at 801 points (BM_ExactStresses50).
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/inversion.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_analysis.h"
#include "flexure/mechanisms/mechanism_exact.h"
#include "flexure/solver/common/gsl_guard.h"
#include "flexure/solver/shooting/elastica_integrator.h"

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
BENCHMARK_CAPTURE(BM_PrbmStroke50, lllm, "3A-lllm");

// Exact stroke: the shooting solver at 50 positions, each from a prediction of the previous ones.
void exact_stroke_50(benchmark::State& state,
                     const MechanismDesign& d,
                     const ExactMechanismSolver::Options& options) {
  flexure::disable_gsl_abort();
  const std::vector<double> dx = stroke_displacements(d, 50);
  long steps = 0;
  for (auto _ : state) {
    ExactStrokeResult r = exact_stroke(d, dx, options);
    if (!r.converged()) state.SkipWithError(r.message.c_str());
    steps = r.integrator_steps;
    benchmark::DoNotOptimize(r.points.back().force);
  }
  state.counters["integrator_steps"] = static_cast<double>(steps);
}

ExactMechanismSolver::Options dormand_prince() {
  ExactMechanismSolver::Options o;
  o.shooting.backend = flexure::ElasticaIntegrator::Backend::kDormandPrince;
  return o;
}

// Exact stresses of every point of a 50-point stroke: from one integration of each solution (what
// `mechanism analyze` does) or from a re-solve sampled at 801 points (what it did before).
void BM_ExactStresses50(benchmark::State& state, const char* name, bool sampled) {
  flexure::disable_gsl_abort();
  const MechanismDesign d = find_builtin_mechanism(name);
  const ExactStrokeResult stroke = exact_stroke(d, stroke_displacements(d, 50));
  if (!stroke.converged()) state.SkipWithError(stroke.message.c_str());
  for (auto _ : state) {
    double sum = 0.0;
    for (const ExactPoint& p : stroke.points) {
      const ExactSegmentState st =
          sampled ? exact_segment_state(d, p, 801) : exact_segment_state(d, p);
      sum += st.max_stress[0];
    }
    benchmark::DoNotOptimize(sum);
  }
}
BENCHMARK_CAPTURE(BM_ExactStresses50, lpp_solution, "1A-lpp", false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExactStresses50, lpp_sampled801, "1A-lpp", true)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExactStresses50, lssm_solution, "3A-lssm", false)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExactStresses50, lssm_sampled801, "3A-lssm", true)
    ->Unit(benchmark::kMillisecond);

// Stability verdicts of every point of a 50-point stroke under both controls
// (mechanisms/mechanism_analysis.h): the PRBM's (closed form) and the exact model's (the shape
// integrated again at the stations, the second variation of the chain or of the mechanism's path).
void BM_PrbmStability50(benchmark::State& state, const char* name) {
  MechanismDesign d = find_builtin_mechanism(name);
  d.finalise();
  const std::vector<double> dx = stroke_displacements(d, 50);
  for (auto _ : state) {
    double sum = 0.0;
    for (double x : dx) sum += prbm_point_stability(d, x).force_control.margin;
    benchmark::DoNotOptimize(sum);
  }
}
BENCHMARK_CAPTURE(BM_PrbmStability50, lpp, "1A-lpp");
void BM_ExactStability50(benchmark::State& state, const char* name) {
  flexure::disable_gsl_abort();
  MechanismDesign d = find_builtin_mechanism(name);
  d.finalise();
  const ExactStrokeResult stroke = exact_stroke(d, stroke_displacements(d, 50));
  if (!stroke.converged()) state.SkipWithError(stroke.message.c_str());
  for (auto _ : state) {
    double sum = 0.0;
    for (const ExactPoint& p : stroke.points) {
      const PointStability v = exact_point_stability(d, p);
      sum += v.displacement_control.margin + v.force_control.margin;
    }
    benchmark::DoNotOptimize(sum);
  }
}
// One per topology: two-force coupler, pinned ends, serial chain (pin / flexure at the slider),
// pinned middle; and 3A-lssm.
BENCHMARK_CAPTURE(BM_ExactStability50, lpp, "1A-lpp")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExactStability50, psp, "1B-psp")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExactStability50, ssp, "2A-ssp")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExactStability50, sss, "3A-sss")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExactStability50, lps, "2B-lps")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ExactStability50, lssm, "3A-lssm")->Unit(benchmark::kMillisecond);

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

// Every built-in design, in the order of `flexure mechanism list`, then two thesis rows whose
// cranks carry about their own buckling load (docs/mechanisms.md "Pinned middle").
std::vector<MechanismDesign> listed_designs() {
  std::vector<MechanismDesign> out = builtin_mechanisms();
  out.insert(out.end(), howell_mechanisms().begin(), howell_mechanisms().end());
  for (const auto* list : {&builtin_mechanisms(), &howell_mechanisms()}) {
    for (const MechanismDesign& d : *list) {
      if (config_has_inversion(d.config) && d.paper_config.empty()) out.push_back(invert(d));
    }
  }
  for (const char* row : {"lps-a90", "sps-b86IO"}) out.push_back(find_builtin_mechanism(row));
  return out;
}

void register_exact_strokes() {
  static const std::vector<MechanismDesign> designs = listed_designs();
  for (const MechanismDesign& d : designs) {
    if (exact_support(d) == ExactSupport::kPrbmOnly) continue;
    benchmark::RegisterBenchmark(("BM_ExactStroke50/" + d.name).c_str(),
                                 [&d](benchmark::State& state) {
                                   exact_stroke_50(state, d, ExactMechanismSolver::Options{});
                                 })
        ->Unit(benchmark::kMillisecond);
  }
  static const std::vector<MechanismDesign> compared = {find_builtin_mechanism("1A-lpp"),
                                                        find_builtin_mechanism("3A-lssm")};
  for (const MechanismDesign& d : compared) {
    benchmark::RegisterBenchmark(
        ("BM_ExactStroke50DormandPrince/" + d.name).c_str(),
        [&d](benchmark::State& state) { exact_stroke_50(state, d, dormand_prince()); })
        ->Unit(benchmark::kMillisecond);
  }
}

}  // namespace

int main(int argc, char** argv) {
  register_exact_strokes();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
