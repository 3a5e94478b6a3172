#pragma once
// Synthesis of a constant-force mechanism's nondimensional parameters (docs/design.md): a
// deterministic multistart of NLopt's COBYLA (derivative-free, constrained; Powell 1994) from the
// points of a Halton sequence over the bounds in log scale, the best feasible local optimum
// winning; for min-xi, whose max/min objective has kinks, each local run is polished by
// Nelder-Mead inside the same bounds when no other constraint is active.
#include <optional>
#include <string>
#include <vector>

#include "flexure/mechanisms/design/cfm_design_problem.h"
#include "flexure/solver/common/status.h"

namespace flexure::design {

struct SynthesisOptions {
  int starts = 0;                 // local runs; 0: 8, 16 or 32 for one, two or three variables
  int max_evaluations = 2000;     // per local run
  double xtol_rel = 1e-7;         // local stopping test on log(R), log(K)
  unsigned long seed = 20011208;  // NLopt's random seed (the starts themselves are a sequence)
  void validate() const;
};

struct CfmSynthesisResult : SolveStatus {
  std::vector<std::string> variables;  // the free variables, as problem.variables()
  std::vector<double> x;               // their optimum
  CfmDesignEvaluation best;            // the model at the optimum: R, K1, K2, Phi, Psi, ...
  int evaluations = 0;                 // model evaluations in all
  int starts = 0;                      // local runs
  int feasible_starts = 0;             // local runs that ended feasible
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
