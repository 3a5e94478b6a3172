#pragma once
// The library's warnings (SolveStatus::warnings, solver/common/status.h) on the tool's one warning
// channel: each text goes through warn(const std::string&) (cli_common.h), which prints
// "flexure: warning: TEXT" on stderr, or hands it to run_command's caller (the Python module
// raises FlexureWarning for it), and under mpirun prints on rank 0 only.
#include <vector>

#include "flexure/solver/common/status.h"

namespace flexure::cli {

// Every warning of `warnings`, in order.
void warn(const std::vector<Warning>& warnings);

}  // namespace flexure::cli
