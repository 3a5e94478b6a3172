#pragma once
// The standard benchmark problem set and the methods run on it (docs/benchmarks.md).
#include <string>
#include <vector>

#include "flexure/benchmarks/studies/bench_types.h"

namespace flexure::bench {

// Problems: cantilever_force (n in {-2, -1, 0, 1, 3}, alpha2 up to 20: the (n, alpha2) load plane
// of the stability maps), tip_moment (mu up to 2 pi), force_and_moment, fixed_guided,
// post_buckled_column, cfm_stroke (built-in mechanism 1A-lpp at kCfmPoints slider displacements).
// `quick` uses fewer loads (smoke test, well under a minute).
std::vector<BenchProblem> standard_problems(bool quick);
inline constexpr int kCfmPoints = 50;      // cfm_stroke stroke points, full run
inline constexpr int kCfmQuickPoints = 4;  // cfm_stroke stroke points, --quick

// Methods: elliptic; shooting with both integrators at several rtol; chain at N in
// {10, 20, 50, 100, 200} and several increment counts; PRBM; exact (mechanism problems only).
// `quick` keeps a few of each.
std::vector<BenchMethod> standard_methods(bool quick);

// Whether `method` is run on `problem` (elliptic: free cantilever only; PRBM: where Howell has an
// element for the load case).
bool method_applies(const BenchMethod& method, const BenchProblem& problem);

// Keeps the entries whose name is in the comma-separated `list` ("" or "all": keep everything).
// A name may also be a method family ("shooting", "chain") to keep every method of it. Throws
// InvalidInput naming `what` and the allowed names for an unknown name.
std::vector<BenchProblem> select_problems(const std::vector<BenchProblem>& all,
                                          const std::string& list);
std::vector<BenchMethod> select_methods(const std::vector<BenchMethod>& all,
                                        const std::string& list);

}  // namespace flexure::bench
