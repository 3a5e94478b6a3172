#pragma once
// The plate modulus of a mechanism's strips (docs/plate-modulus.md, issue 29 item 7). The design
// has one material, so one modulus: "on" solves with E/(1 - nu^2); "auto" analyses with E,
// takes each flexible strip's largest curvature over the stroke from its largest bending stress
// (kappa = 2 sigma/(E h): sigma = E kappa h/2), and uses the plate modulus when every strip's
// Searle parameter b^2 kappa/h reaches the threshold (a strip below it bends as a beam, and the
// mechanism has one E); the analysis is then repeated with E/(1 - nu^2).
#include "flexure/mechanisms/mechanism_analysis.h"

namespace flexure::mechanism {

// Replaces design.E by the modulus of `design.plate` ("off" or "on"; auto needs an analysis and
// throws) and records the choice in design.modulus. Throws InvalidInput naming the design for a
// plate without nu. Idempotent: a design that already has its choice is left as it is.
void apply_plate_modulus(MechanismDesign& design);

// analyze_mechanism with design.plate applied (off, on, or auto as above); the returned
// analysis' design carries the modulus choices (one per flexible pivot for auto, one otherwise).
MechanismAnalysis analyze_mechanism_with_modulus(MechanismDesign design,
                                                 const AnalysisOptions& options);

}  // namespace flexure::mechanism
