#pragma once
// The points of a beam sweep (`flexure sweep beam`, beam_sweep_grid.h), each solved as
// solve_beam() would solve it alone, but sweeps by the shooting method start a point from the
// solution at its neighbour where that provably gives the same answer: Newton from the
// neighbour's unknowns (extrapolated from the last three) instead of a continuation from zero load.
//
// Which answer: solve_beam returns the equilibrium reached by proportional loading from zero (the
// continuation's first arrival at load factor 1). Where no load path in a region of loads passes a
// limit point or a bifurcation point, that answer is a smooth function of the load there (the
// implicit function theorem along each path), so Newton from a neighbour's answer that stays on
// its smooth stretch of branch (ShootingSolver::solve_near's checks: the same sign of det dg/dz,
// full steps that shrink at least 4x, most of the move predicted, no jump of the tip) finds it. A
// neighbour's answer is used when
//   * the equilibrium is unique at this load (unique_equilibrium_bound < 1, shooting_solver.h):
//     any converged Newton finds it;
//   * this load lies on the same ray from zero as the neighbour's, farther out: the load path to
//     this point passes through the neighbour's answer and continues from it (its limit points
//     are the neighbour's);
//   * both loads are a dead tip force alone (mu = 0, Howell's free cantilever) on the same side
//     of the beam (alpha2 of one sign): such load paths pass no limit point and their answers have
//     no inflection point (measured: tests/beam/beam_sweep_solver_test.cpp, 19 781 loads by the
//     elliptic solver's own continuation, n in [-20, 45], alpha2 in (0, 150]), and the answer found
//     from the neighbour must have none either.
// Every other point is solved from zero load. With an end moment a load path can fold, and a fold
// that rises past load factor 1 as the load changes moves the answer to another branch without a
// trace at the end point, so no check at the end point can keep a sweep over mu, or over alpha2 or
// n with mu != 0, on the proportional-loading branch. A warm start that fails a check falls back to
// the solve from zero. docs/performance.md ("Shooting sweeps") has the measured cost;
// tests/beam/beam_sweep_solver_test.cpp compares every point with the solve from zero.
//
// The stability verdict of a compressed cantilever (compressed_cantilever_stability.h) starts its
// search for the margin from the margin extrapolated along the line (cubic, from the last four
// judged points): one integration of the Jacobi equation per point instead of four to seven,
// the same verdict (tests/beam/beam_sweep_solver_test.cpp).
//
// solve() is safe to call from several threads at once: each thread keeps its own last solutions
// (the sweep hands each thread runs of consecutive points).
#include <atomic>
#include <memory>
#include <mutex>
#include <thread>
#include <unordered_map>
#include <vector>

#include "flexure/beam/beam_problem.h"
#include "flexure/beam/beam_sweep_grid.h"

namespace flexure {

class BeamSweepSolver {
 public:
  // `method` as resolved for the sweep (resolve_beam_method). Neighbours further apart than
  // `max_gap` points along the fastest axis are not used.
  BeamSweepSolver(BeamSweepGrid grid, BeamMethod method, long max_gap = 16);

  // The point `index` of the grid (row-major); the same contract as solve_beam.
  BeamSolution solve(long index) const;

  // How the points were solved so far.
  struct Counts {
    long from_neighbour = 0;     // warm starts kept
    long from_zero = 0;          // solved by solve_beam (including refused warm starts)
    long neighbour_refused = 0;  // warm starts tried and refused by a check
  };
  Counts counts() const;

  const BeamSweepGrid& grid() const { return grid_; }

 private:
  // A converged shooting solution that is the proportional-loading answer at its load.
  struct Solved {
    long index = -1;
    std::vector<double> coordinates;
    double Fx = 0.0, Fy = 0.0, M = 0.0;  // the chain's tip load
    ShootingResult result;
    double margin = 0.0;  // its stability margin (NaN when not judged)
  };
  struct Memory {
    std::vector<Solved> last;  // the thread's last solutions (up to four), oldest first
  };
  Memory& memory() const;
  bool warm_candidate() const;
  BeamSolution solve_shooting_point(long index, const BeamProblem& problem) const;
  void remember(Memory& m,
                long index,
                const SegmentChain& chain,
                const ShootingResult& r,
                const BeamSolution& solution) const;

  BeamSweepGrid grid_;
  BeamMethod method_;
  long max_gap_;
  mutable std::mutex mutex_;
  mutable std::unordered_map<std::thread::id, Memory> memories_;
  mutable std::atomic<long> from_neighbour_{0}, from_zero_{0}, refused_{0};
};

}  // namespace flexure
