// Nondimensional PRBM constant-force mechanism model speed (docs/cfm.md).
//
// Description:
//  1. BM_PrbmStroke50: one 50-point PRBM stroke (Howell §10.1 sampling) of a 3A-sss mechanism,
//     all three springs active, with mean Phi, Xi', beta, lambda, Psi and d_N. Target
//     (docs/performance.md): under 50 us.
//  2. BM_PrbmStroke50Curve: the same with the curve kept (one allocation of 50 points).
//  3. BM_ThesisStroke: the thesis code's ~1000-point sampling (what the tables use).
//  4. BM_AllSubclasses: the 68 thesis sub-classes, thesis sampling.
#include <benchmark/benchmark.h>

#include "flexure/mechanisms/cfm/cfm_model.h"

namespace {

using flexure::cfm::CfmModel;
using flexure::cfm::CfmOptions;
using flexure::cfm::CfmParameters;
using flexure::cfm::StrokeSampling;

const CfmParameters kSss3Aa{"sss", 2.6633, 1.0, 12.6704, 16.0};  // Howell Table 10.1, 3A

CfmModel uniform(int points, bool keep_curve) {
  CfmOptions options;
  options.sampling = StrokeSampling::kUniform;
  options.points = points;
  options.keep_curve = keep_curve;
  return CfmModel(options);
}

void BM_PrbmStroke50(benchmark::State& state) {
  const CfmModel model = uniform(50, false);
  for (auto _ : state) benchmark::DoNotOptimize(model.evaluate(kSss3Aa));
}
BENCHMARK(BM_PrbmStroke50)->Unit(benchmark::kMicrosecond);

void BM_PrbmStroke50Curve(benchmark::State& state) {
  const CfmModel model = uniform(50, true);
  for (auto _ : state) benchmark::DoNotOptimize(model.evaluate(kSss3Aa));
}
BENCHMARK(BM_PrbmStroke50Curve)->Unit(benchmark::kMicrosecond);

void BM_ThesisStroke(benchmark::State& state) {
  const CfmModel model;
  for (auto _ : state) benchmark::DoNotOptimize(model.evaluate(kSss3Aa));
}
BENCHMARK(BM_ThesisStroke)->Unit(benchmark::kMicrosecond);

void BM_AllSubclasses(benchmark::State& state) {
  const CfmModel model;
  for (auto _ : state) {
    for (const auto& row : flexure::cfm::thesis_subclasses()) {
      const auto& c = flexure::cfm::find_cfm_configuration(row.config);
      CfmParameters p{row.config, row.R, std::nullopt, std::nullopt, row.stroke_percent};
      if (c.has_spring(2) && !c.is_class_1B()) p.K1 = row.K1;
      if (c.has_spring(3)) p.K2 = row.K2;
      benchmark::DoNotOptimize(model.evaluate(p));
    }
  }
}
BENCHMARK(BM_AllSubclasses)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
