#include "cli/warning_output.h"

#include "cli/cli_common.h"

namespace flexure::cli {

void warn(const std::vector<Warning>& warnings) {
  for (const Warning& w : warnings) warn(w.text);
}

}  // namespace flexure::cli
