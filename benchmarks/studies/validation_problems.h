#pragma once
// Reference problems for `flexure validate` and the registry of methods checked against them.
//
// Every reference value is independent of flexure: closed forms (Howell eqs. 2.53, 2.59, 2.64,
// linear beam theory), Howell's worked example (§2.9.2), or tip values computed from Howell's
// eqs. 2.90-2.98 and checked by quadrature (the n = 0 table and the theta0 = 0.6 rad rows of
// docs/validation.md), or an independent continuation (docs/theory-elliptic.md).
//
// To add a method (shooting, chain, PRBM): append a ValidationMethod in validation_methods() with
// a solve function and an `applies` filter for the problems it can handle. To add a problem:
// append a ReferenceProblem in reference_problems() with its source.
#include <functional>
#include <string>
#include <vector>

#include "flexure/beam/beam_problem.h"

namespace flexure {

// One number to compare. rel_error = |computed - reference| / max(|reference|, scale_floor).
struct ReferenceValue {
  std::string quantity;  // alpha, alpha2, a_over_l, b_over_l, theta0
  double reference = 0.0;
  double tolerance = 0.0;    // on rel_error
  double scale_floor = 0.0;  // > 0 where the reference may vanish (then the error is absolute)
};

struct ReferenceProblem {
  std::string name;    // short id shown in the table, e.g. "n=0 table theta0=0.25 inverse"
  std::string source;  // where the reference comes from
  BeamProblem problem;
  std::vector<ReferenceValue> expected;
  // True where the chain algorithm's load increments cannot follow the path (the tip turns by
  // several radians under strong compression with an opposing end moment: it refuses with exit 3,
  // docs/theory-chain.md), so only the elliptic and shooting solvers are checked.
  bool exact_methods_only = false;
};

std::vector<ReferenceProblem> reference_problems();

struct ValidationMethod {
  std::string name;
  std::function<bool(const ReferenceProblem&)> applies;  // false: the method skips the problem
  std::function<BeamSolution(const BeamProblem&)> solve;
  // The method's own stated accuracy (relative); a check passes within the larger of this and
  // the reference's rounding tolerance. 0 for exact methods.
  double accuracy = 0.0;
  std::string accuracy_source;  // where that accuracy is established
};

// Every method available in this build.
std::vector<ValidationMethod> validation_methods();

// The value of `quantity` in a solution (alpha = sqrt(alpha2), Howell eq. 2.83).
double quantity_value(const BeamSolution& solution, const std::string& quantity);

}  // namespace flexure
