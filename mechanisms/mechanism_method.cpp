#include "mechanisms/mechanism_method.h"

#include <fmt/format.h>

#include <map>

#include "mechanisms/mechanism_exact.h"
#include "solver/common/errors.h"

namespace flexure::mechanism {

double measured_prbm_force_error(const std::string& config) {
  // flexure mechanism validate --points 50 (docs/validation.md), max PRBM force error per design.
  static const std::map<std::string, double> kMeasured = {
      {"spp", 0.0070},
      {"lpp", 0.0512},
      {"psp", 0.0348},
      {"plp", 0.1395},
      {"ssp", 0.0483},
      {"slp", 0.0937},
      {"sps", 0.0165},
      {"lps", 0.0208},
      {"sss", 0.0646},
  };
  const auto it = kMeasured.find(config);
  if (it == kMeasured.end()) {
    throw InvalidInput(fmt::format("no measured PRBM error for configuration '{}'", config));
  }
  return it->second;
}

MechanismMethodChoice choose_mechanism_method(const MechanismDesign& design,
                                              const std::string& method,
                                              double tolerance) {
  if (!(tolerance > 0.0) || !std::isfinite(tolerance)) {
    throw InvalidInput(fmt::format("--tol must be finite and > 0 (got {})", tolerance));
  }
  MechanismMethodChoice c;
  if (method == "prbm") {
    c = {false, "prbm", "requested with --method prbm"};
  } else if (method == "exact") {
    c = {true, "exact", "requested with --method exact"};
  } else if (method != "auto") {
    throw InvalidInput(
        fmt::format("--method '{}' is unknown (allowed: auto, prbm, exact)", method));
  } else {
    const double expected = kPrbmErrorMargin * measured_prbm_force_error(design.config);
    if (expected <= tolerance) {
      c = {false,
           "prbm",
           fmt::format("auto: PRBM force error measured {:.3g} for {} designs, x{} margin = {:.3g} "
                       "<= tol {:.3g}",
                       measured_prbm_force_error(design.config),
                       design.config,
                       kPrbmErrorMargin,
                       expected,
                       tolerance)};
    } else {
      c = {true,
           "exact",
           fmt::format("auto: PRBM force error measured {:.3g} for {} designs, x{} margin = {:.3g} "
                       "> tol {:.3g}",
                       measured_prbm_force_error(design.config),
                       design.config,
                       kPrbmErrorMargin,
                       expected,
                       tolerance)};
    }
  }
  if (c.exact && exact_support(design) == ExactSupport::kPrbmOnly) {
    c = {false, "prbm", c.reason + "; but this design has no exact model, so the PRBM is used"};
  }
  return c;
}

}  // namespace flexure::mechanism
