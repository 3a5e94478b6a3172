#include <fmt/format.h>

#include <cmath>
#include <map>

#include "flexure/beam/beam_problem.h"
#include "flexure/mechanisms/builtin_designs.h"
#include "flexure/mechanisms/mechanism.h"
#include "flexure/mechanisms/mechanism_exact.h"
#include "flexure/solver/common/status.h"

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

double measured_prbm_force_error(const MechanismDesign& design) {
  if (design.paper_config.empty()) {
    // Fixed-fixed s segments under a paper rule are not the thesis's s pivots: nothing measured.
    if (has_fixed_fixed(design) && design.spring_rule != SpringRule::kPureBending) {
      throw InvalidInput(fmt::format("no measured PRBM error for '{}' with spring rule {}",
                                     design.name,
                                     spring_rule_name(design.spring_rule)));
    }
    return measured_prbm_force_error(design.config);
  }
  // flexure mechanism validate --points 50 --spring-rule RULE (docs/validation.md "Modified
  // configurations"), max PRBM force error of each built-in modified design per spring rule.
  static const std::map<std::string, double> kModified = {
      {"lppm/pure-bending", 0.0419}, {"plpm/pure-bending", 0.1316}, {"llpm/pure-bending", 0.1279},
      {"slpm/pure-bending", 0.1293}, {"lplm/pure-bending", 0.0559}, {"lpsm/pure-bending", 0.0356},
      {"lssm/pure-bending", 0.1034}, {"slsm/pure-bending", 0.1353}, {"llsm/pure-bending", 0.1341},
      {"lslm/pure-bending", 0.0631}, {"lllm/pure-bending", 0.1541}, {"lppm/table2", 0.3396},
      {"plpm/table2", 0.4132},       {"llpm/table2", 0.3276},       {"slpm/table2", 0.3573},
      {"lplm/table2", 0.3620},       {"lpsm/table2", 0.2414},       {"lssm/table2", 0.3850},
      {"slsm/table2", 0.3980},       {"llsm/table2", 0.3058},       {"lslm/table2", 0.3656},
      {"lllm/table2", 0.1570},       {"lppm/table5", 0.4082},       {"plpm/table5", 0.1929},
      {"llpm/table5", 0.3595},       {"slpm/table5", 0.2905},       {"lplm/table5", 0.2761},
      {"lpsm/table5", 0.5272},       {"lssm/table5", 0.3280},       {"slsm/table5", 0.2215},
      {"llsm/table5", 0.3943},       {"lslm/table5", 0.3531},       {"lllm/table5", 1.3139},
  };
  const auto it = kModified.find(design.paper_config + "/" + spring_rule_name(design.spring_rule));
  if (it == kModified.end()) {
    throw InvalidInput(fmt::format("no measured PRBM error for the modified design '{}' ({})",
                                   design.name,
                                   design.paper_config));
  }
  return it->second;
}

std::string_view to_string(MechanismMethod method) {
  switch (method) {
    case MechanismMethod::kAuto:
      return "auto";
    case MechanismMethod::kPrbm:
      return "prbm";
    case MechanismMethod::kExact:
      return "exact";
  }
  return "exact";
}

MechanismMethod mechanism_method_from_string(std::string_view name) {
  for (MechanismMethod m :
       {MechanismMethod::kAuto, MechanismMethod::kPrbm, MechanismMethod::kExact}) {
    if (name == to_string(m)) return m;
  }
  throw InvalidInput(fmt::format("method '{}' is unknown (allowed: auto, prbm, exact)", name));
}

MechanismMethodChoice choose_mechanism_method(const MechanismDesign& design,
                                              MechanismMethod method,
                                              double tolerance) {
  if (!(tolerance > 0.0) || !std::isfinite(tolerance)) {
    throw InvalidInput(fmt::format("the tolerance must be finite and > 0 (got {})", tolerance));
  }
  MechanismMethodChoice c;
  if (method == MechanismMethod::kPrbm) {
    c = {false, MechanismMethod::kPrbm, "requested: prbm"};
  } else if (method == MechanismMethod::kExact) {
    c = {true, MechanismMethod::kExact, "requested: exact"};
  } else {
    // A fixed-fixed pattern outside the paper's eleven has no measured error: exact.
    double measured = INFINITY;
    try {
      measured = measured_prbm_force_error(design);
    } catch (const InvalidInput&) {
    }
    const double expected = kPrbmErrorMargin * measured;
    const bool prbm_suffices = expected <= tolerance;
    if (!prbm_suffices && tolerance < kExactForceErrorBound &&
        exact_support(design) != ExactSupport::kPrbmOnly) {
      throw bench::ToleranceBelowReach(
          fmt::format("the tolerance {:.3g} is below the force error of both models: the PRBM's "
                      "{} and the exact model's {:.0e} (its force moves by up to 4.6e-10 when "
                      "every tolerance of its solves is tightened); ask for a tolerance of at "
                      "least {:.0e}",
                      tolerance,
                      std::isfinite(measured)
                          ? fmt::format("{:.3g} (measured, x{} margin)", expected, kPrbmErrorMargin)
                          : std::string("(not measured for this design)"),
                      kExactForceErrorBound,
                      kExactForceErrorBound),
          kExactForceErrorBound,
          "exact");
    }
    c = {!prbm_suffices,
         prbm_suffices ? MechanismMethod::kPrbm : MechanismMethod::kExact,
         fmt::format("auto: PRBM force error measured {:.3g} for {} designs, x{} margin = {:.3g} "
                     "{} tol {:.3g}",
                     measured,
                     design.paper_config.empty()
                         ? design.config
                         : design.paper_config + " (" + spring_rule_name(design.spring_rule) + ")",
                     kPrbmErrorMargin,
                     expected,
                     prbm_suffices ? "<=" : ">",
                     tolerance)};
  }
  if (c.exact && exact_support(design) == ExactSupport::kPrbmOnly) {
    c = {false,
         MechanismMethod::kPrbm,
         c.reason + "; but this design has no exact model, so the PRBM is used"};
  }
  return c;
}

}  // namespace flexure::mechanism
