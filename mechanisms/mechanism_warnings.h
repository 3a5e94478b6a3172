#pragma once
// The warnings a stroke's results call for (the CLI prints each on stderr with "flexure: warning:
// ", Python raises FlexureWarning): a pivot that yields, a slider force that vanishes or changes
// sign within the stroke, an exact stroke the mechanism cannot hold. The texts name the design, so
// that the lines of `mechanism validate`, which runs many designs, say which one they are about.
#include <string>
#include <vector>

#include "flexure/mechanisms/mechanism_analysis.h"

namespace flexure::mechanism {

// One warning per yielding pivot (described numbering, inversion.h): its largest stress over the
// stroke at or above the yield strength.
std::vector<std::string> yield_warnings(const MechanismAnalysis& analysis);

// One warning per model whose force is zero or changes sign within the stroke: Weight's min/max
// ratio (thesis eq. 5.22) describes a force of one sign, so the percentage is reported as 0
// instead of a negative or noise-sized ratio (constant_force.h; docs/mechanisms.md "Percent
// constant force"). `exact`: the exact force is checked too (the exact stroke ran and converged).
std::vector<std::string> force_vanishing_warnings(const MechanismAnalysis& analysis, bool exact);

// An exact state the mechanism cannot hold with its slider held (docs/stability.md
// "Mechanisms"), and stroke points without a verdict.
std::vector<std::string> stability_warnings(const MechanismAnalysis& analysis);

}  // namespace flexure::mechanism
