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
#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/solver/common/status.h"

namespace flexure::design {

// The synthesis problem of a constant-force slider mechanism's nondimensional parameters (Weight
// 2001 ch. 2 and 6; docs/design.md): choose R = r3/r2 and, where the configuration has the
// springs, K1 = k2/k1 and K2 = k3/k1, to optimise one objective over a stroke of d % of r2 + r3
// under the thesis's constraints:
//  * the stroke ends before the toggle position (eq. 2.16): R inside toggle_R_interval(d);
//  * Xi' >= pcf_min (eqs. 6.6, 6.8) for the objectives that trade constant force away;
//  * the orientation rules of Table 5.4 / eqs. 6.10-6.11 for every flexible pivot other than the
//    primary one: I (in-plane) D_min <= 1; O (out-of-plane) C >= 1 and 0.5 <= D_equal <= 2;
//    o (possibly out-of-plane) C >= 1 and 0.1 <= D_equal <= 10;
//  * bounds on R, K1, K2.
// Everything is evaluated by the PRBM model (cfm_model.h); no optimiser type appears here.

enum class DesignObjective {
  kMinXi,   // min Xi = Phi_max/Phi_min (eq. 2.17; Table 2.1, Millar et al.)
  kMaxPcf,  // max Xi' = 100 Phi_min/Phi_max (eq. 6.9)
  kMaxPsi,  // max Psi, the stiffness parameter (eq. 6.5; Psi_raw: the same argmax at any d)
  kMinDn,   // min d_N,max, the normal displacement of pivot 2 (eq. 6.7)
};

// "min-xi", "max-pcf", "max-psi", "min-dn".
const char* to_string(DesignObjective objective);
// Throws InvalidInput naming the allowed values.
DesignObjective design_objective_from_string(const std::string& name);

// An orientation rule of the thesis (Table 5.4, eqs. 6.10-6.11), applied to every flexure but the
// primary one; a sub-class name carries them as trailing flags ("slp-a95Io").
enum class OrientationRule {
  kInPlane,             // I: D_min <= 1
  kOutOfPlane,          // O: C >= 1 and 0.5 <= D_equal <= 2
  kPossiblyOutOfPlane,  // o: C >= 1 and 0.1 <= D_equal <= 10
};
// The thesis's flag: 'I', 'O' or 'o'.
char to_char(OrientationRule rule);
// The rules of a flag string ("IO", "o"; empty: none), in its order (the order of the
// constraints). Throws InvalidInput quoting the text and naming the allowed flags I, O and o.
std::vector<OrientationRule> orientation_rules_from_string(const std::string& flags);
// The flags of `rules` in their order ("IO"; empty for none): the JSON's and HDF5's text.
std::string to_string(const std::vector<OrientationRule>& rules);

// The range of R whose toggle stroke is at least d (eq. 2.16 solved for R, docs/design.md):
// q = (1 - d/100)^2, R in [(1 - q)/(1 + q), (1 + q)/(1 - q)] (every R for d = 100 is not allowed:
// throws InvalidInput unless 0 < d < 100).
std::pair<double, double> toggle_R_interval(double stroke_percent);

struct Bounds {
  double lower = 0.0;
  double upper = 0.0;
};

// The limits of the orientation rules (Table 5.4, eqs. 6.10-6.11); the defaults are the thesis's.
// A test may loosen one to the value a printed sub-class itself reaches (docs/errata.md).
struct OrientationLimits {
  double I_D_min_max = 1.0;     // I: D_min <= this
  double C_min = 1.0;           // O and o: C >= this
  Bounds O_D_equal{0.5, 2.0};   // O: D_equal within
  Bounds o_D_equal{0.1, 10.0};  // o: D_equal within
};

struct CfmDesignProblem {
  std::string config;            // spp, lpp, psp, plp, ssp, slp, sps, lps, sss
  double stroke_percent = 16.0;  // d
  DesignObjective objective = DesignObjective::kMaxPcf;
  std::optional<double> pcf_min;             // Xi' >= this (required by max-psi and min-dn)
  std::vector<OrientationRule> orientation;  // empty: no rule (orientation_rules_from_string)
  OrientationLimits orientation_limits;
  // Bounds (searched in log scale); R is further limited by the toggle interval. The thesis
  // states none; these hold every printed optimum (docs/design.md).
  Bounds R{0.05, 20.0};
  Bounds K1{0.1, 15.0};
  Bounds K2{0.01, 20.0};
  std::optional<double> fixed_K1;  // hold K1 (e.g. 1 for Table 2.1's class 3A rows)
  std::optional<double> fixed_K2;
  cfm::CfmOptions model;  // stroke sampling (default_model_options(objective))

  // Throws InvalidInput naming the first inconsistent field.
  void validate() const;
  // The free variables in order: "R", then "K1" and "K2" where the configuration has the spring
  // and it is not fixed.
  std::vector<std::string> variables() const;
};

// Table 2.1's sampling (50 equally spaced points) for min-xi, the thesis code's for the rest
// (the Ch. 7 tables).
cfm::CfmOptions default_model_options(DesignObjective objective);

enum class ConstraintKind {
  kToggle,  // stroke <= toggle stroke (held by the bounds of R)
  kPcf,     // Xi' >= pcf_min, in percent
  kRatio,   // a thickness or width ratio C, D_equal or D_min (positive, compared in log scale)
};

// One constraint's value at a design, without its name (what an optimiser evaluates many times).
struct ConstraintValue {
  double value = 0.0;
  double bound = 0.0;
  bool upper = true;  // value <= bound (else value >= bound)
  ConstraintKind kind = ConstraintKind::kToggle;
  bool satisfied() const { return upper ? value <= bound + 1e-9 : value >= bound - 1e-9; }
  double violation() const { return upper ? value - bound : bound - value; }  // <= 0: met
  // The violation in units that compare across constraints (<= 0: met): log(value/bound) for a
  // ratio (missing C >= 1 by 1 % counts 0.01 as missing D <= 2 by 1 % does), the shortfall of
  // Xi' over the room the bound leaves below 100 % ((bound - Xi')/(100 - bound): 0.1 below 99
  // weighs as 1 below 90), the plain violation otherwise.
  double normalised_violation() const;
};

struct NamedConstraint : ConstraintValue {
  std::string name;  // e.g. "Xi' >= 95", "pivot 2 I: D_min <= 1"
};

struct CfmDesignEvaluation {
  cfm::CfmResult result;
  double objective = 0.0;                    // in the problem's sense (Xi, Xi', Psi_raw or d_N,max)
  std::vector<NamedConstraint> constraints;  // fixed count for a problem
  bool feasible() const;
};

// The parameters of the free variables `x` (in variables() order) for the model.
cfm::CfmParameters parameters_at(const CfmDesignProblem& problem, const std::vector<double>& x);

// Evaluates the design at the free variables `x`. Throws InvalidInput where the model refuses
// the point.
CfmDesignEvaluation evaluate_design(const CfmDesignProblem& problem,
                                    const cfm::CfmModel& model,
                                    const std::vector<double>& x);

// The objective in the problem's sense at a model result.
double objective_value(const CfmDesignProblem& problem, const cfm::CfmResult& result);

// The thickness and width ratios C_i, D_equal_i, D_min_i (eqs. 5.31-5.36) of every flexure were
// pivot `primary` (1..3) the primary one; those of result.primary_pivot are result.C, D_equal,
// D_min. Empty for a pin. (The primary pivot changes across the design space, and with it the
// flexures the orientation rules apply to: a synthesis looks at each choice on its own.)
struct OrientationRatios {
  std::array<std::optional<double>, 3> C;
  std::array<std::optional<double>, 3> D_equal;
  std::array<std::optional<double>, 3> D_min;
};
OrientationRatios orientation_ratios(const cfm::CfmResult& result, int primary);

// The constraints' values at a model result in evaluate_design's order (its names aside), the
// orientation rules taken relative to pivot `primary` (1..3), into `out` (resized).
void constraint_values(const CfmDesignProblem& problem,
                       const cfm::CfmResult& result,
                       int primary,
                       std::vector<ConstraintValue>& out);

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
  // Called after each scan point of step 1 and each local run of steps 2 and 3 with (done,
  // total): total = the scan points plus the most local runs steps 2 and 3 can make (fewer are
  // run where the scan has fewer distinct starts), and (total, total) at the end; done never
  // decreases. For a progress display; a caller stops a synthesis by throwing from it (the
  // Python module does on Ctrl-C). Never called from inside NLopt. Empty: none.
  std::function<void(std::size_t done, std::size_t total)> progress;
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

// Optimisation of a constant-force mechanism against the exact model (docs/design.md "Against
// the exact model"; no source did this: the thesis optimised the PRBM only). The objective is the
// exact percent constant force Xi'_exact of `flexure cfm --exact` (mechanism_analysis.h,
// solve_cfm_exact: the equivalent design r2 + r3 = 1 with the PRBM sizing rules of Table 8.1,
// stroke from the straight position), maximised over the problem's free variables from a start (the
// PRBM optimum or a thesis sub-class) by NLopt's COBYLA in log scale, under the problem's toggle,
// orientation and bounds (orientation rules evaluated by the PRBM model, as the thesis defines
// them). The PRBM's Xi' >= pcf_min becomes Xi'_exact >= pcf_min.
//
// The inextensible elastica's force depends on the flexural rigidities only, so at fixed geometry
// Xi'_exact depends on (config, R, K1, K2, d) alone, not on the size or the material: the
// nondimensional optimum serves every dimensioned design of it.

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
