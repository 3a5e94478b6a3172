#pragma once
// A file of the repository compiled into the library (cmake/embed_data.cmake): the data tables
// under data/ travel inside the `flexure` binary, so that it needs no files at run time. The text
// is the file's bytes, unchanged; `path` is its path relative to the repository root, for
// messages and for the tests that compare the two.
#include <string_view>

namespace flexure {

struct EmbeddedFile {
  std::string_view path;  // e.g. "data/weight_table_2_1.csv"
  std::string_view text;  // the whole file
};

}  // namespace flexure
