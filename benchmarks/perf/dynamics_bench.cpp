// Speed of the inverse-dynamics frequency sweep (target: a 200-frequency sweep in under 2 s,
// docs/dynamics.md): 2B-lplm of the paper's Table 5, 40 % stroke, 1 % preload, 1024 samples per
// period (the CLI default), 200 frequencies from 0 to 100 rad/s. Also one forward-dynamics run for
// scale.
#include <benchmark/benchmark.h>

#include <numbers>

#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/dynamics/dynamics.h"

namespace {

using namespace flexure::dynamics;

SliderCrankDynamics lplm() {
  const CfsmDesign& d = find_cfsm_design("2B-lplm");
  return SliderCrankDynamics(from_bar_links(d.r2, d.r3, d.m2, d.m3, d.m_slider, d.k));
}

void BM_Sweep200Frequencies(benchmark::State& state) {
  const InverseDynamics inverse(lplm(), {.samples_per_period = static_cast<int>(state.range(0))});
  const double r_tot = inverse.model().r_tot();
  const SinusoidalMotion motion{0.01 * r_tot, 0.40 * r_tot, 0.0};
  std::vector<double> omegas(200);
  for (int i = 0; i < 200; ++i) omegas[i] = 100.0 * i / 199.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(inverse.sweep(motion, omegas));
  }
  state.SetItemsProcessed(state.iterations() * 200);
}
BENCHMARK(BM_Sweep200Frequencies)->Arg(1024)->Arg(4096)->Unit(benchmark::kMillisecond);

void BM_ForwardTenPeriods(benchmark::State& state) {
  const SliderCrankDynamics model = lplm();
  const double period = 2.0 * std::numbers::pi / linearise(model, 0.0).omega_n;
  ForwardOptions options;
  options.rtol = 1e-10;
  const ForwardDynamics forward(model, options);
  std::vector<double> times(100);
  for (int i = 0; i < 100; ++i) times[i] = 10 * period * (i + 1) / 100.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(forward.integrate(0.6, 0.0, times, nullptr));
  }
}
BENCHMARK(BM_ForwardTenPeriods)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
