#include <fmt/format.h>

#include "flexure/solver/common/status.h"

namespace flexure {

void require_finite(double value, const std::string& what) {
  if (!std::isfinite(value)) {
    throw InvalidInput(fmt::format("{} must be a finite number (got {})", what, value));
  }
}

}  // namespace flexure
