#pragma once
// The data tables of the elements layer, compiled in from data/ (cmake/embed_data.cmake; the text
// of each file, unchanged). Parsed with CsvTable where they are used.
#include "flexure/solver/common/embedded_file.h"

namespace flexure::data {

EmbeddedFile howell_table_5_1();  // Howell 2001, Table 5.1: fixed-pinned segment
EmbeddedFile howell_table_5_2();  // Howell 2001, Table 5.2: initially curved cantilever
EmbeddedFile howell_table_5_3();  // Howell 2001, Table 5.3: initially curved pinned-pinned
// Su 2009: the PR-3R model's published constants (ladder_models.h).
EmbeddedFile su_prbm3r_constants();
// The PR-3R constants derived by flexure (ladder_models.h).
EmbeddedFile prbm3r_flexure_constants();

}  // namespace flexure::data
