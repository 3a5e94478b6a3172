#pragma once
// The data tables of the beam layer, compiled in from data/ (cmake/embed_data.cmake; the text
// of each file, unchanged). Parsed with CsvTable where they are used.
#include "flexure/solver/common/embedded_file.h"

namespace flexure::data {

EmbeddedFile method_auto_error_map();  // PRBM error measured by `flexure bench`, for --method auto
EmbeddedFile ladder_auto_error_map();  // the model ladder's error and time (ladder_selector.h)
// The same where the axial force dominates, |n| >= 2 (ladder_selector.h, mechanism flexures).
EmbeddedFile ladder_auto_error_map_axial();
// The guided end's, over (n, alpha2, tip_angle) against the shooting method (ladder_selector.h).
EmbeddedFile ladder_auto_error_map_guided();

}  // namespace flexure::data
