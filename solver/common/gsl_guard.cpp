#include "flexure/solver/common/gsl_guard.h"

#include <gsl/gsl_errno.h>

#include <mutex>

namespace flexure {

void disable_gsl_abort() {
  static std::once_flag flag;
  std::call_once(flag, [] { gsl_set_error_handler_off(); });
}

}  // namespace flexure
