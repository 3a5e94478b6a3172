// Speed of `flexure design cfm` (mechanisms/design/cfm_synthesis.h, docs/design.md): one whole
// PRBM synthesis per iteration, the issue-16 goal being < 50 ms per design.
//
// BM_DesignCfm/<sub-class>: a chapter-7 sub-class re-derived from its own objective and
// constraints, as tests/mechanisms/cfm_subclass_synthesis_test.cpp poses it (thesis sampling):
//  - lpp-a95: class 1A, one variable, max Psi under Xi' >= 95;
//  - slp-a99IO: class 2A, two variables, max Psi under Xi' >= 99 and the rules I and O;
//  - lps-b95I: class 2B, two variables, max Psi under Xi' >= 95 and the rule I;
//  - sss-a: class 3A, three variables, max Xi';
//  - sss-b90I: class 3A, three variables, max Psi under Xi' >= 90 and the rule I.
// BM_DesignCfmTable21/<row>: a Table 2.1 row re-optimised for min Xi (50 uniform points), 2B-a
// (two variables) and 3A-b (K1 held at 1).
#include <benchmark/benchmark.h>

#include <string>

#include "flexure/mechanisms/design/cfm_synthesis.h"

namespace {

using flexure::design::CfmDesignProblem;
using flexure::design::DesignObjective;

CfmDesignProblem subclass(const std::string& config,
                          double d,
                          std::optional<double> pcf_min,
                          const std::string& orientation) {
  CfmDesignProblem p;
  p.config = config;
  p.stroke_percent = d;
  p.objective = pcf_min ? DesignObjective::kMaxPsi : DesignObjective::kMaxPcf;
  p.pcf_min = pcf_min;
  p.orientation = flexure::design::orientation_rules_from_string(orientation);
  p.model = flexure::design::default_model_options(p.objective);
  return p;
}

CfmDesignProblem min_xi(const std::string& config, double d, std::optional<double> K1) {
  CfmDesignProblem p;
  p.config = config;
  p.stroke_percent = d;
  p.objective = DesignObjective::kMinXi;
  p.fixed_K1 = K1;
  p.model = flexure::design::default_model_options(p.objective);
  return p;
}

void run(benchmark::State& state, const CfmDesignProblem& problem) {
  int evaluations = 0;
  for (auto _ : state) {
    const auto s = flexure::design::synthesize_cfm(problem);
    if (!s.converged()) state.SkipWithError(s.message.c_str());
    evaluations = s.evaluations;
    benchmark::DoNotOptimize(s.x.data());
  }
  state.counters["evaluations"] = evaluations;
}

const bool kRegistered = [] {
  const std::pair<const char*, CfmDesignProblem> rows[] = {
      {"lpp-a95", subclass("lpp", 16.0, 95.0, "")},
      {"slp-a99IO", subclass("slp", 16.0, 99.0, "IO")},
      {"lps-b95I", subclass("lps", 40.0, 95.0, "I")},
      {"sss-a", subclass("sss", 16.0, std::nullopt, "")},
      {"sss-b90I", subclass("sss", 40.0, 90.0, "I")},
  };
  for (const auto& [name, problem] : rows) {
    benchmark::RegisterBenchmark((std::string("BM_DesignCfm/") + name).c_str(),
                                 [problem = problem](benchmark::State& s) { run(s, problem); })
        ->Unit(benchmark::kMillisecond);
  }
  const std::pair<const char*, CfmDesignProblem> table[] = {
      {"2B-a", min_xi("sps", 16.0, std::nullopt)},
      {"3A-b", min_xi("sss", 40.0, 1.0)},
  };
  for (const auto& [name, problem] : table) {
    benchmark::RegisterBenchmark((std::string("BM_DesignCfmTable21/") + name).c_str(),
                                 [problem = problem](benchmark::State& s) { run(s, problem); })
        ->Unit(benchmark::kMillisecond);
  }
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
