#pragma once
// flexure's pseudo-rigid-body models in one include: the PrbmElement interface and Howell's
// segments (ch. 5) with their tables, the derivation of their constants from the exact elastica,
// the PRBM-vs-exact comparison, and the beam models of the model ladder (linear beam, beam
// constraint model, chained BCM, PRBM 3R). Link `flexure::beam` (or `flexure::flexure`).
//
//   #include <flexure/prbm.h>
//   const flexure::FixedPinnedSegment segment(flexure::FixedPinnedConstants::howell_average());
//   const flexure::TipPose tip = segment.tip(0.5);  // the tip at the PRB angle Theta = 0.5 rad
#include "flexure/beam.h"
#include "flexure/beam/prbm_comparison.h"
#include "flexure/elements/ladder_models.h"
#include "flexure/elements/prbm_element.h"
