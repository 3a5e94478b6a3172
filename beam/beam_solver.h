#pragma once
// A beam solver in the library's one calling style (a solver object with validated Options, a
// result that derives from SolveStatus): the method and its numerical settings here, the problem
// (what is loaded and what is given) in BeamProblem.
//
//   flexure::BeamSolver::Options options;
//   options.method = flexure::BeamMethod::kShooting;
//   const flexure::BeamSolver solver(options);  // InvalidInput for a bad setting, naming it
//   flexure::BeamProblem problem;
//   problem.value = 3.0;  // alpha2 = P l^2/EI
//   const flexure::BeamSolution s = solver.solve(problem);
//
// solve_beam(method, problem) stays the shorthand; it reads the same settings from the
// problem's fields (elements, increments, chain_variant, integrator, tolerance, ...), which
// BeamSolver::solve overwrites with the Options.
#include <string>

#include "flexure/beam/beam_method.h"
#include "flexure/beam/beam_problem.h"
#include "flexure/solver/chain/chain_algorithm_solver.h"
#include "flexure/solver/shooting/shooting_solver.h"

namespace flexure {

class BeamSolver {
 public:
  struct Options {
    BeamMethod method = BeamMethod::kAuto;
    // auto: the relative tip error allowed when it chooses a method (method_selector.h).
    double auto_tolerance = 1e-6;
    // Shooting: the integrator of the flexible segments (GSL's Prince-Dormand 8(7) by default).
    IntegratorBackend integrator = IntegratorBackend::kRk8pd;
    int elements = 100;  // chain algorithm: N elements (Howell sec. 5.11)
    int increments = 1;  // chain algorithm: load increments to start with (halved on failure)
    ChainVariant chain_variant = ChainVariant::kCorrected;
    int shape_points = 0;  // 0: no shape; otherwise >= 2 points from s = 0 to s = 1
    // The model ladder (beam_ladder.h): the chained BCM's elements, the PR-3R constants, the
    // slenderness L/t of the BCM and CBCM (0: inextensible).
    int cbcm_elements = 6;
    std::string prbm3r_constants = "su";
    double slenderness = 0.0;
    bool judge_stability = true;  // the stability verdict of the answer (docs/stability.md)
    bool stable = false;          // return a stable equilibrium (BeamProblem::stable)
    // Throws InvalidInput naming the setting and its allowed range.
    void validate() const;
  };

  BeamSolver() : BeamSolver(Options{}) {}
  explicit BeamSolver(Options options);

  const Options& options() const { return options_; }
  // solve_beam(options.method, problem) with the problem's settings replaced by the Options.
  BeamSolution solve(const BeamProblem& problem) const;

 private:
  Options options_;
};

// The Options a problem's own settings amount to (for a caller of solve_beam moving to
// BeamSolver).
BeamSolver::Options beam_solver_options(BeamMethod method, const BeamProblem& problem);

}  // namespace flexure
