#pragma once
// `flexure mechanism analyze --method auto --tol T`: model no more than the design needs. The PRBM
// stroke costs microseconds, the exact stroke tens of milliseconds; auto uses the PRBM alone when
// its measured force error for this configuration, with a safety margin, is within the tolerance.
#include <string>
#include <string_view>

#include "flexure/mechanisms/mechanism.h"

namespace flexure::mechanism {

// Worst PRBM force error (relative to the exact model) measured over the full stroke of the
// built-in design of `config` (`flexure mechanism validate --points 50`, docs/validation.md).
// tests/mechanisms/mechanism_method_test.cpp recomputes these so that the table cannot go stale.
double measured_prbm_force_error(const std::string& config);
// The same for a design: its configuration's value, or for a modified configuration of paper 004
// (paper_config set) the value of the built-in design of that configuration under the design's
// spring rule. Throws InvalidInput if none was measured.
double measured_prbm_force_error(const MechanismDesign& design);

// The force error the exact model is known to stay within: tightening every tolerance of its
// solves (integrator rtol 1e-12 -> 1e-13, atol 1e-14 -> 1e-15, pin closure 1e-10 -> 1e-12,
// shooting residual 1e-10 -> 1e-13) moved the slider force of 13 built-in designs (20 stroke points
// each) by at most 4.6e-10 relative (1A-spp 4.2e-10, 1B-plp 4.0e-10; docs/mechanisms.md).
inline constexpr double kExactForceErrorBound = 1e-9;

// Margin applied to the measured error: other dimensions of the same configuration move the error.
inline constexpr double kPrbmErrorMargin = 1.5;

// The models `mechanism analyze --method` chooses from.
enum class MechanismMethod { kAuto, kPrbm, kExact };
// "auto", "prbm", "exact" (the --method names and the JSON key "method").
std::string_view to_string(MechanismMethod method);
// The method of that name; throws InvalidInput listing the names.
MechanismMethod mechanism_method_from_string(std::string_view name);

struct MechanismMethodChoice {
  bool exact = true;                                 // run the exact model (the PRBM always runs)
  MechanismMethod method = MechanismMethod::kExact;  // kPrbm or kExact
  std::string reason;                                // why, with the numbers
};

// `tolerance` is the relative force error allowed. With kAuto, a tolerance below
// kExactForceErrorBound (when the PRBM does not meet it either) throws bench::ToleranceBelowReach
// (beam_problem.h): no model meets it.
MechanismMethodChoice choose_mechanism_method(const MechanismDesign& design,
                                              MechanismMethod method,
                                              double tolerance);
}  // namespace flexure::mechanism
