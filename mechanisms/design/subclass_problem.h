#pragma once
// The synthesis problem a thesis sub-class answers (Weight 2001 ch. 6-7; docs/design.md): its
// name config-{a|b}{digits}{flags} reads as the stroke (a = 16 %, b = 40 %, or the toggle-clamped
// stroke the row really has: 37.04 % and 26.62 %), and, with digits, "max Psi with Xi' >= digits
// and the orientation flags I, O, o as constraints"; without digits, "max Xi'" (the flags are then
// labels only).
#include <string>
#include <vector>

#include "flexure/mechanisms/cfm/cfm_model.h"
#include "flexure/mechanisms/design/cfm_synthesis.h"

namespace flexure::design {

struct SubclassProblem {
  CfmDesignProblem problem;
  std::vector<double> printed;  // the row's free variables (problem.variables() order)
};

// Throws InvalidInput for an unknown sub-class (cfm::find_thesis_subclass).
SubclassProblem subclass_problem(const cfm::CfmSubclass& row);

// The trailing orientation flags of a sub-class name ("slp-a95Io" -> "Io").
std::string subclass_flags(const std::string& name);

}  // namespace flexure::design
