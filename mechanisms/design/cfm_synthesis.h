#pragma once
// Synthesis of a constant-force mechanism's nondimensional parameters (docs/design.md, "The
// optimiser"), in three deterministic steps over the variables in log scale:
//  1. a global scan: the model at the points of a Halton sequence over the bounds;
//  2. local runs of NLopt's COBYLA (derivative-free, constrained; Powell 1994), or Nelder-Mead
//     where only the bounds constrain a kinked max/min objective (min-xi, max-pcf), from the
//     scan's best distinct points, an infeasible start first brought to feasibility;
//  3. for the thesis code's sampling (~1000 stroke points), steps 1-2 run on a subset of its
//     points (every `coarse_stride`-th, CfmOptions::stride) and the best local optima are
//     polished on the full sampling, which alone decides the answer.
// With max-psi or orientation rules and two or more sprung pivots, steps 1-3 also run in each
// region of the design space where one pivot is the primary one (Table 5.4's rules and eq. 5.19's
// Psi jump where it changes; within a region they are smooth). The answer is the best design of
// the full sampling met at any evaluation: feasible first, then by objective.
#include <optional>
#include <string>
#include <vector>

#include "flexure/mechanisms/design/cfm_design_problem.h"
#include "flexure/solver/common/status.h"

namespace flexure::design {

struct SynthesisOptions {
  int starts = 0;       // local runs of step 2 per region; 0: 4 for two variables, else 3
  int scan_points = 0;  // Halton points of step 1; 0: 32, 256 or 1024 by variables
  int polish = 0;       // local optima polished on the full sampling (step 3); 0: 2
  // Step 3's coarse sampling takes every coarse_stride-th stroke point; 1 (or a sampling of fewer
  // than 10 coarse_stride points, such as Table 2.1's 50) runs everything on the full sampling.
  int coarse_stride = 20;
  // The coarse steps may ask Xi' >= pcf_min + pcf_margin (the coarse Xi' is never below the full
  // sampling's, a subset of its points). 0: the two agree to 3e-4 points of Xi' at the 68
  // sub-classes' optima and the polish starts with a restoration where needed.
  double pcf_margin = 0.0;
  int max_evaluations = 2000;     // per local run
  double xtol_rel = 1e-6;         // final stopping test: absolute on log(R), log(K), i.e. relative
  unsigned long seed = 20011208;  // NLopt's random seed (the scan is a fixed sequence)
  bool record_history = false;    // fill CfmSynthesisResult::history (`design cfm --out`)
  void validate() const;
};

// One distinct model evaluation of a synthesis, in the order they were made (the convergence
// history `flexure design cfm --out` writes).
struct SynthesisEvaluation {
  int run = -1;               // local run (-1: the global scan)
  bool full_sampling = true;  // the requested stroke sampling (else the coarse one of step 2)
  bool valid = false;         // the model accepted the point
  double R = 0.0, K1 = 0.0, K2 = 0.0;
  double objective = 0.0;      // in the problem's sense (0 where not valid)
  double max_violation = 0.0;  // largest normalised constraint violation as posed (<= 0: met)
  bool feasible = false;
};

struct CfmSynthesisResult : SolveStatus {
  std::vector<std::string> variables;        // the free variables, as problem.variables()
  std::vector<double> x;                     // their optimum
  CfmDesignEvaluation best;                  // the model at the optimum: R, K1, K2, Phi, Psi, ...
  int evaluations = 0;                       // distinct model evaluations in all (every sampling)
  int fine_evaluations = 0;                  // of them on the full (requested) sampling
  int starts = 0;                            // local runs of step 2
  int feasible_starts = 0;                   // local runs of step 2 that ended feasible
  std::vector<SynthesisEvaluation> history;  // with SynthesisOptions::record_history
  // The thesis sub-class (Ch. 7) of the same configuration and stroke whose R and K lie within
  // 1 % of the optimum, if any.
  std::optional<std::string> nearest_subclass;
  // converged(): a feasible optimum from a local run that met its stopping test (not its
  // evaluation limit); iterations = evaluations; residual = the largest constraint violation.
};

// Throws InvalidInput for an invalid problem or options.
CfmSynthesisResult synthesize_cfm(const CfmDesignProblem& problem,
                                  const SynthesisOptions& options = {});

}  // namespace flexure::design
