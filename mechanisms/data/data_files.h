#pragma once
// The data tables of the mechanisms layer, compiled in from data/ (cmake/embed_data.cmake; the
// text of each file, unchanged). Parsed with CsvTable where they are used.
#include "flexure/solver/common/embedded_file.h"

namespace flexure::data {

EmbeddedFile weight_thesis_subclasses();        // Weight 2001, Tables 7.2, 7.4, 7.6, 7.9, 7.12
EmbeddedFile weight_thesis_thickness_ratios();  // Weight 2001, Tables 7.7, 7.10, 7.13
EmbeddedFile weight_table_2_1();                // Weight 2001, Table 2.1
EmbeddedFile howell_table_10_1();               // Howell 2001, Table 10.1
EmbeddedFile materials();                       // Howell 2001, Appendix C (data/materials.csv)
EmbeddedFile paper_table_5();                   // Ugwuoke & Abolarin 2023, Table 5
EmbeddedFile paper_table_6();                   // Ugwuoke & Abolarin 2023, Table 6
EmbeddedFile paper_tables_2_4();                // Ugwuoke & Abolarin 2023, Tables 2 and 4

}  // namespace flexure::data
