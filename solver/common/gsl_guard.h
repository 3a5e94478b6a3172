#pragma once
// GSL's default error handler aborts the process. flexure checks every GSL status it uses, so the
// handler is switched off once, process-wide, before any GSL call.
namespace flexure {
void disable_gsl_abort();
}  // namespace flexure
