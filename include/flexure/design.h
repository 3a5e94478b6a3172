#pragma once
// flexure's mechanism design in one include: the constant-force design problem and its synthesis
// by the PRBM (Weight ch. 8), the refinement of a design by the exact model, and the design of
// mechanisms to a specification (force, stroke, material, sections). Link `flexure::mechanisms`
// (or `flexure::flexure`).
#include "flexure/mechanisms.h"
#include "flexure/mechanisms/design/cfm_synthesis.h"
#include "flexure/mechanisms/design/mechanism_synthesis.h"
