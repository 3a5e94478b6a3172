#pragma once
// The error of a failed HDF5 operation (hdf5_file.h throws it; its message names the file, the
// object and what failed), in a header of its own so that code that only maps it to an exit code
// (the tool: an unwritable --out is exit 2, docs/cli.md) includes no HDF5 header.
#include <stdexcept>

namespace flexure::io {

class Hdf5Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace flexure::io
