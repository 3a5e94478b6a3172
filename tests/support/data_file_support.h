#pragma once
// Checks of the data tables compiled into the library (cmake/embed_data.cmake): the embedded text
// is the file in the repository (FLEXURE_SOURCE_DIR), byte for byte.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include "flexure/solver/common/embedded_file.h"

namespace flexure::test {

// The bytes of `path` (relative to the repository root); fails the test if it cannot be read.
inline std::string read_repository_file(std::string_view path) {
  const std::string full = std::string(FLEXURE_SOURCE_DIR) + "/" + std::string(path);
  std::ifstream in(full, std::ios::binary);
  EXPECT_TRUE(in.good()) << "cannot read " << full;
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The embedded copy equals the file, and the file is a data file with its comment block.
inline void expect_embedded_equals_file(const EmbeddedFile& file) {
  SCOPED_TRACE(std::string(file.path));
  EXPECT_EQ(file.path.substr(0, 5), "data/");
  const std::string on_disk = read_repository_file(file.path);
  ASSERT_FALSE(on_disk.empty());
  EXPECT_EQ(file.text.size(), on_disk.size());
  EXPECT_TRUE(file.text == on_disk) << "the embedded copy differs from the file; rebuild";
  EXPECT_EQ(on_disk.front(), '#') << "a data file starts with its comment block";
}

}  // namespace flexure::test
