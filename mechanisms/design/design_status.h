#pragma once
// The SolveStatus of the design layer's results (docs/architecture.md, "One result vocabulary"):
// a dimensioned design is kConverged when feasible and kInfeasible (its binding constraint the
// message) when not; a design report is kConverged with at least one feasible design, and carries
// the warnings a designer must see beside the designs (a feasible design short of the safety
// factor by its own stresses, docs/design.md "Stress rules").
#include "flexure/mechanisms/design/mechanism_synthesis.h"

namespace flexure::design {

// termination and message from `feasible` and `binding`.
void stamp_design_status(DimensionedDesign& design);

// Every design's status, the report's termination and message (with nothing feasible: the
// closest design's binding constraint and the length hint), and its safety-factor warning for
// `spec` (the specification as given: with fatigue sizing, its safety factor, not the raised one).
void stamp_report_status(const MechanismSpec& spec, MechanismDesignReport& report);

}  // namespace flexure::design
