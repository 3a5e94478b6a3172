#pragma once
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
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "flexure/mechanisms/cfm/cfm_model.h"

namespace flexure::design {

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

}  // namespace flexure::design
