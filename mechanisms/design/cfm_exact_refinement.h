#pragma once
// Optimisation of a constant-force mechanism against the exact model (docs/design.md "Against
// the exact model"; no source did this: the thesis optimised the PRBM only). The objective is the
// exact percent constant force Xi'_exact of `flexure cfm --exact` (cfm_exact.h: the equivalent
// design r2 + r3 = 1 with the PRBM sizing rules of Table 8.1, stroke from the straight position),
// maximised over the problem's free variables from a start (the PRBM optimum or a thesis
// sub-class) by NLopt's COBYLA in log scale, under the problem's toggle, orientation and bounds
// (orientation rules evaluated by the PRBM model, as the thesis defines them). The PRBM's
// Xi' >= pcf_min becomes Xi'_exact >= pcf_min.
//
// The inextensible elastica's force depends on the flexural rigidities only, so at fixed geometry
// Xi'_exact depends on (config, R, K1, K2, d) alone, not on the size or the material: the
// nondimensional optimum serves every dimensioned design of it.
#include <cstddef>
#include <functional>
#include <vector>

#include "flexure/mechanisms/design/cfm_design_problem.h"
#include "flexure/mechanisms/design/cfm_synthesis.h"
#include "flexure/solver/common/status.h"

namespace flexure::design {

struct ExactRefinementOptions {
  int points = 25;            // stroke points of the exact model during the search
  int confirm_points = 50;    // stroke points of the reported start and optimum (cfm --exact's)
  int max_evaluations = 300;  // exact strokes in the search
  double xtol_rel = 1e-4;     // COBYLA's stopping test on log(R), log(K)
  // Integrator steps one exact stroke may spend (ExactMechanismSolver::Options::work_budget): a
  // candidate the exact model cannot follow is given up quickly and counts as Xi' = 0.
  double work_budget = 1e5;
  // Local runs from the points of a Halton sequence over the bounds (log scale), besides the
  // given starts: the exact objective has several optima where the PRBM's has one. Negative: two
  // per free variable (the default of `flexure design cfm --model exact`).
  int sequence_starts = 0;
  // Called after each exact stroke: (done, total), total = 1 + runs (max_evaluations + 1), the
  // most the refinement can take -- the first start's confirmation, then per local run (the
  // starts and the sequence's) at most max_evaluations strokes of the search and its
  // confirmation at confirm_points. A run that stops before its limit moves done to its end, so
  // done never decreases and ends at total. For a progress display; a caller stops a long
  // refinement by throwing from it (the exception propagates out of NLopt unchanged; nothing is
  // returned). Empty: no calls.
  std::function<void(std::size_t done, std::size_t total)> progress;
  void validate() const;
};

struct CfmExactRefinement : SolveStatus {
  std::vector<std::string> variables;  // problem.variables()
  std::vector<double> start, x;        // the free variables at the first start and the optimum
  double start_percent_constant_force_exact = 0.0;  // of the first start, at confirm_points
  double percent_constant_force_exact = 0.0;        // at confirm_points
  CfmDesignEvaluation prbm;  // the PRBM model and the problem's constraints at the optimum
  int evaluations = 0;       // exact strokes
  int starts = 0;            // local runs
  // Every exact stroke of the search in order (objective = Xi'_exact at options.points;
  // full_sampling false; max_violation over the PRBM rules and the Xi' floor).
  std::vector<SynthesisEvaluation> history;
  // converged(): the optimum is feasible, its exact stroke converged, and COBYLA stopped on its
  // tolerance; iterations = evaluations; residual = the largest constraint violation.
};

// Local runs from each of `starts` (and options.sequence_starts more), the best confirmed optimum
// winning. Throws InvalidInput for an invalid problem, options or start (one value per free
// variable, inside the bounds; at least one start).
CfmExactRefinement refine_cfm_exact(const CfmDesignProblem& problem,
                                    const std::vector<std::vector<double>>& starts,
                                    const ExactRefinementOptions& options = {});

// The starts of the refinement of a PRBM optimum `prbm_x` (the free variables): the optimum first,
// then the printed thesis sub-classes of the problem's configuration and stroke whose R lies in the
// toggle interval and whose free variables lie inside the problem's bounds, in table order.
std::vector<std::vector<double>> exact_refinement_starts(const CfmDesignProblem& problem,
                                                         const std::vector<double>& prbm_x);

// The refinement of a PRBM synthesis: refine_cfm_exact from exact_refinement_starts(problem,
// prbm.x). Its start_percent_constant_force_exact is Xi'_exact of the PRBM optimum. Throws
// InvalidInput as above, and when the synthesis found no design (prbm.x empty).
CfmExactRefinement refine_cfm_exact_from_prbm(const CfmDesignProblem& problem,
                                              const CfmSynthesisResult& prbm,
                                              const ExactRefinementOptions& options = {});

// Xi'_exact of one design (the problem's configuration and stroke at the free variables `x`) at
// `points` stroke points; 0 where the exact model does not converge or the force vanishes.
double exact_percent_constant_force(const CfmDesignProblem& problem,
                                    const std::vector<double>& x,
                                    int points,
                                    double work_budget);

}  // namespace flexure::design
