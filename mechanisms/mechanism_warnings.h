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

// The three above on the library's one warning channel (SolveStatus::warnings,
// solver/common/status.h), in this order: yield (WarningKind::kYield), vanishing forces
// (kForceVanishes; the exact force where the exact stroke ran and converged), stability (kOther).
// analyze_mechanism puts them into MechanismAnalysis::warnings and report_forces_of renews them
// (their forces are in the unit reported), so the CLI prints them and Python raises a
// FlexureWarning for each.
std::vector<Warning> analysis_warnings(const MechanismAnalysis& analysis);

}  // namespace flexure::mechanism
